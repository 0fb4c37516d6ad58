// Batch mode of `lac` (docs/cli.md "Batch mode"): the cost of the command line around the solves.
// 10 000 G1 problems `lac g1 --points "a0 a1 a2" --alpha A` (control triangles as G1 Hermite data),
// generated deterministically (seed 1), timed three ways, each run R times alternating:
//   (a) in process: solve_g1_hermite and the same output module (cli/report.hpp) as the command, one
//       compact JSON line per problem, written in 64 KiB blocks to stdout (/dev/null);
//   (b) lac::cli::run("lac g1 --batch FILE") in this process, stdout to /dev/null;
//   (c) the lac executable of this build folder as a subprocess, stdout to /dev/null.
// Target: (b) / (a) < 1.5 by the medians. A plain timing program (not Google Benchmark): each
// measurement is one pass over all rows.
//   bench_cli_batch [--rows N] [--repeats R] [--write FILE]
//   --write FILE: only write the rows file (points,alpha) and exit.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/g1_hermite_args.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace {

struct Problem {
  lac::ControlTriangle t;
  double alpha;
};

/// Triangles a0 = 0, a1 = (x, 0), a2 = (1, y) and α in [-2, 2] outside (−0.1, 0.1): most with a curve, some not.
std::vector<Problem> problems(int n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> x(0.3, 0.7), y(0.1, 0.6), alpha(-2, 2);
  std::vector<Problem> v(n);
  for (Problem& p : v) {
    const double a1 = x(rng), a2 = y(rng), drawn = alpha(rng);
    const double al = std::abs(drawn) < 0.1 ? drawn + std::copysign(0.1, drawn) : drawn;  // the G1 solver's α range
    p = {{{0, 0}, {a1, 0}, {1, a2}}, al};
  }
  return v;
}

std::string number(double v) { return lac::format_number(v); }

void write_rows(const std::vector<Problem>& ps, const std::string& path) {
  std::ofstream out(path);
  out << "points,alpha\n";
  for (const Problem& p : ps)
    out << "\"" << number(p.t.a0.real()) << "," << number(p.t.a0.imag()) << " " << number(p.t.a1.real()) << ","
        << number(p.t.a1.imag()) << " " << number(p.t.a2.real()) << "," << number(p.t.a2.imag()) << "\","
        << number(p.alpha) << "\n";
}

double seconds_of(const auto& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// (a): the library and the report module, no command line.
void in_process(const std::vector<Problem>& ps) {
  lac::cli::G1HermiteArgs args;
  std::string text;
  long row = 0;
  for (const Problem& p : ps) {
    const lac::G1HermiteProblem problem{p.t.a0, std::arg(p.t.a1 - p.t.a0), p.t.a2, std::arg(p.t.a2 - p.t.a1), p.alpha};
    const lac::cli::Report r = lac::cli::g1_hermite_report(problem, args, {p.t.a0, p.t.a1, p.t.a2});
    text.append("{\"row\":").append(std::to_string(++row)).append(",").append(r.json.dump(), 1).append("\n");
    if (text.size() > (1 << 16)) std::cout << text, text.clear();
  }
  std::cout << text << std::flush;
}

void stats(const char* name, std::vector<double> t, int rows) {
  std::sort(t.begin(), t.end());
  const double median = t[t.size() / 2];
  std::printf("%-34s median %.4f s  min %.4f  max %.4f  (%.1f us/row)\n", name, median, t.front(), t.back(),
              1e6 * median / rows);
}

}  // namespace

int main(int argc, char** argv) {
  int rows = 10000, repeats = 7;
  std::string write;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--rows")) rows = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeats")) repeats = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--write")) write = argv[i + 1];
  }
  const std::vector<Problem> ps = problems(rows);
  if (!write.empty()) {
    write_rows(ps, write);
    return 0;
  }
  const std::string file = (std::filesystem::temp_directory_path() / "lac_bench_cli_batch.csv").string();
  write_rows(ps, file);
  const std::string lac = (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "lac").string();
  // Results go to /dev/null; the table to the terminal (a copy of stdout).
  const int terminal = dup(1);
  if (!std::freopen("/dev/null", "w", stdout)) return 1;
  std::vector<double> a, b, c;
  for (int k = 0; k < repeats; ++k) {
    a.push_back(seconds_of([&] { in_process(ps); }));
    b.push_back(seconds_of([&] {
      std::string s0 = "lac", s1 = "g1", s2 = "--batch", s3 = file;
      char* args[] = {s0.data(), s1.data(), s2.data(), s3.data(), nullptr};
      lac::cli::run(4, args);
      std::cout.flush();
    }));
    c.push_back(seconds_of([&] {
      if (std::system((lac + " g1 --batch " + file + " > /dev/null").c_str()) == -1) std::abort();
    }));
  }
  std::fflush(stdout);
  dup2(terminal, 1);
  std::printf("%d G1 rows, %d alternating runs each\n", rows, repeats);
  stats("(a) solve + report, in process", a, rows);
  stats("(b) lac::cli::run g1 --batch FILE", b, rows);
  stats("(c) lac g1 --batch FILE (process)", c, rows);
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end()), std::sort(c.begin(), c.end());
  std::printf("ratio of medians (b)/(a) = %.3f, (c)/(a) = %.3f (target < 1.5)\n", b[b.size() / 2] / a[a.size() / 2],
              c[c.size() / 2] / a[a.size() / 2]);
  std::filesystem::remove(file);
  return 0;
}

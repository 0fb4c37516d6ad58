// lac beside the Clothoids library (github.com/ebertolazzi/Clothoids, Bertolazzi–Frego), in one
// process: time per solve and successes of lac::solve_g1_hermite and lac::solve_g2 (default
// options) at nine α, and of the peer's G1 (ClothoidCurve::build_G1) and three-arc G2
// (G2solve3arc::build) at α = −1, where an LA curve is a clothoid. Writes <out-dir>/peer_speed.md
// and .csv. Built only with -DLAC_PEER_CLOTHOIDS_DIR (docs/peer_speed.md); the peer is reached
// through bench/peer/clothoids_adapter.hpp.
//
// Problem sets: G1, the 2000-problem set of tests/support/g1_problem_set.hpp (P0 = (0,0),
// P1 = (1,0), θ0, θ1 uniform in (−π/2, π/2), splitmix64); G2, the 1000 problems of
// experiments/g2_random.cpp (same angles, κ0, κ1 uniform in (−3, 3), std::mt19937_64 seed
// 20130501). Every call is timed alone with steady_clock, `--repeats` times, and the least time
// kept per problem; at α = −1 the lac call and the peer call alternate within each repetition.
// A solve counts as verified when its own flag says success AND its curve, evaluated afterwards
// (outside the timing), meets the end conditions within lac::kDefaultAccept (chord units, rad).
#include <sched.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench/peer/clothoids_adapter.hpp"
#include "io/table.hpp"
#include "lac/common/accuracy.hpp"
#include "lac/constructions/g1_hermite.hpp"
#include "lac/constructions/g2_hermite.hpp"
#include "lac/integrators/gk_tanh_sinh.hpp"
#include "tests/support/g1_problem_set.hpp"

namespace {

using namespace lac;
using clock_type = std::chrono::steady_clock;
constexpr double kPi = std::numbers::pi;

double wrap(double a) {  // to (−π, π]
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

struct G2Data {
  double t0, k0, t1, k1;
};

/// One (set, library, α) row.
struct Row {
  Row(std::string set_, std::string library_, std::string options_, double alpha_)
      : set(std::move(set_)), library(std::move(library_)), options(std::move(options_)), alpha(alpha_) {}
  std::string set, library, options;
  double alpha = -1;
  int problems = 0, flagged = 0, ok = 0, verified = 0, verified_tight = 0;
  std::vector<double> us, fail_us;  // least time per problem; of the problems without a verified solve
  double worst_error = 0;           // largest independent error among verified solves
  std::map<std::string, int> failures;  // problems not verified, by reason
  bool add(double t_us, bool flag, bool status_ok, double error, const std::string& reason) {
    ++problems;
    us.push_back(t_us);
    flagged += flag;
    ok += status_ok;
    const bool good = flag && error <= kDefaultAccept;
    if (good) {
      ++verified;
      verified_tight += error <= 1e-10;
      worst_error = std::max(worst_error, error);
    } else {
      fail_us.push_back(t_us);
      ++failures[flag ? "error > 1e-6" : reason];
    }
    return good;
  }
  std::string failure_text() const {
    std::string out;
    for (const auto& [why, n] : failures) out += (out.empty() ? "" : ", ") + why + " " + std::to_string(n);
    return out.empty() ? "—" : out;
  }
  double median() const { return quantile(us, 0.5); }
};

/// Microseconds from `t0` to now.
double since(clock_type::time_point t0) {
  return std::chrono::duration<double, std::micro>(clock_type::now() - t0).count();
}

/// Times one call of solve() (its result's construction included, the destruction of the previous
/// result not) and keeps the result in `out`.
template <class R, class Solve>
double timed(R& out, Solve&& solve) {
  const auto t0 = clock_type::now();
  R r = solve();
  const double t = since(t0);
  out = std::move(r);
  return t;
}

// Independent checks of lac's curves: end point by adaptive Gauss–Kronrod / tanh-sinh (not the
// solve's Gauss–Legendre kernel), end angle and curvature in closed form.
double lac_g1_error(const G1HermiteResult& r, double theta1) {
  if (!r.usable()) return INFINITY;
  const double L = r.curve.length();
  const PositionResult p = position_at(r.curve, L, GkTanhSinh{});
  if (!usable(p.status)) return INFINITY;
  return std::max(std::abs(p.point.position - std::complex<double>(1, 0)), std::abs(wrap(r.curve.theta_at(L) - theta1)));
}

double lac_g2_error(const G2Result& r, const G2Data& d) {
  if (!r.usable()) return INFINITY;
  const double L = r.curve.length();
  const PositionResult p = position_at(r.curve, L, GkTanhSinh{});
  if (!usable(p.status)) return INFINITY;
  double e = std::max({std::abs(p.point.position - std::complex<double>(1, 0)),
                       std::abs(wrap(r.curve.theta_at(L) - d.t1)), std::abs(r.curve.kappa_at(L) - d.k1),
                       std::abs(wrap(r.curve.theta_at(0) - d.t0)), std::abs(r.curve.kappa_at(0) - d.k0)});
  for (const Joint& j : r.curve.joints(GkTanhSinh{}))
    e = std::max({e, j.position_gap, std::abs(j.angle_gap), std::abs(j.curvature_gap)});
  return e;
}

// The peer's curves evaluated by the peer (chord 1, so positions need no scaling). For G2 the
// last piece is built backwards from P1, so its end meets P1 by construction: the joints carry
// the residual.
double peer_error(const lac_peer::Check& c, double t0, double t1, const double* k0 = nullptr,
                  const double* k1 = nullptr) {
  double e = std::max({std::hypot(c.end_x - 1, c.end_y), std::hypot(c.start_x, c.start_y),
                       std::abs(wrap(c.end_theta - t1)), std::abs(wrap(c.start_theta - t0)), c.joint_position_gap,
                       c.joint_angle_gap, c.joint_kappa_gap});
  if (k0) e = std::max({e, std::abs(c.start_kappa - *k0), std::abs(c.end_kappa - *k1)});
  return std::isfinite(e) && std::isfinite(c.length) && c.length > 0 ? e : INFINITY;
}

std::string cpu_model() {
  const std::string m = io::machine_description();  // "Machine: <cpu>; compiler ..."
  const auto a = m.find(": "), b = m.find(';');
  return a == std::string::npos || b == std::string::npos ? "unknown CPU" : m.substr(a + 2, b - a - 2);
}

std::string today_utc() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&now));
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lac beside the Clothoids library: time per solve and successes (G1 Hermite, G2 Hermite)"};
  std::string out_dir = "results", peer_commit = LAC_PEER_COMMIT, only;
  int repeats = 5, g1_count = test::kG1ProblemCount, g2_count = 1000, cpu = 0;
  double slow_us = 1000;
  std::vector<double> alphas{-3, -2, -1, -0.5, 0, 0.5, 1, 2, 3};
  app.add_option("--out-dir", out_dir, "Folder for peer_speed.md and peer_speed.csv")->capture_default_str();
  app.add_option("--peer-commit", peer_commit, "Commit of the Clothoids build linked in")->capture_default_str();
  app.add_option("--repeats", repeats, "Timed calls per solve; the least is kept")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--slow-us", slow_us, "A call slower than this (us) is not repeated")->capture_default_str();
  app.add_option("--g1-count", g1_count, "G1 problems")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--g2-count", g2_count, "G2 problems")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--alphas", alphas, "Slopes alpha for lac (each in [-5, 5]; -1 adds the peer)")->capture_default_str();
  app.add_option("--cpu", cpu, "Pin the process to this CPU (-1: do not pin)")->capture_default_str();
  app.add_option("--only", only, "Profiling: run only this part (lac-g2, lac-g1, peer-g2, peer-g1) at alpha -1, "
                                 "--repeats times over the set, and write nothing")
      ->check(CLI::IsMember({"", "lac-g2", "lac-g1", "peer-g2", "peer-g1"}));
  CLI11_PARSE(app, argc, argv);

  if (cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    if (sched_setaffinity(0, sizeof set, &set) != 0) {
      std::cerr << "bench_peer_speed: cannot pin to CPU " << cpu << "\n";
      return 1;
    }
  }

  const std::vector<test::G1Angles> g1_set = test::g1_problem_set(g1_count);
  std::vector<G2Data> g2_set(static_cast<size_t>(g2_count));
  {
    std::mt19937_64 rng(20130501);  // experiments/g2_random.cpp
    std::uniform_real_distribution<double> angle(-kPi / 2, kPi / 2), curvature(-3, 3);
    for (auto& p : g2_set) p = {angle(rng), curvature(rng), angle(rng), curvature(rng)};
  }
  const G1HermiteOptions g1_options{};
  const G2Options g2_options{};

  if (!only.empty()) {  // a plain loop for perf record
    long good = 0;
    for (int r = 0; r < repeats; ++r) {
      for (const auto& a : g1_set) {
        if (only == "lac-g1") good += solve_g1_hermite({{0, 0}, a.theta0, {1, 0}, a.theta1, -1.0}, g1_options).usable();
        if (only == "peer-g1") good += lac_peer::g1(0, 0, a.theta0, 1, 0, a.theta1);
      }
      for (const auto& d : g2_set) {
        if (only == "lac-g2") good += solve_g2({{{0, 0}, d.t0, d.k0}, {{1, 0}, d.t1, d.k1}, -1.0}, g2_options).usable();
        if (only == "peer-g2") good += lac_peer::g2(0, 0, d.t0, d.k0, 1, 0, d.t1, d.k1);
      }
    }
    std::cout << only << ": " << good << " successful calls\n";
    return 0;
  }

  // Up to `repeats` calls of each solver on one problem (alternating when there are two); the
  // least time of each, and the last call's outcome through `keep`.
  const auto least = [&](std::vector<std::function<double()>> calls) {
    std::vector<double> best(calls.size(), INFINITY);
    for (int r = 0; r < repeats; ++r) {
      bool slow = false;
      for (size_t k = 0; k < calls.size(); ++k) {
        const double t = calls[k]();
        best[k] = std::min(best[k], t);
        slow = slow || t > slow_us;
      }
      if (slow) break;  // a slow failure: one call says enough
    }
    return best;
  };

  std::vector<Row> rows;
  std::string disagreements;  // α = −1: problems one library solves (verified) and the other does not
  const auto disagree = [&](const std::string& set, size_t i, bool lac_good, bool peer_good, const std::string& data,
                            const std::string& lac_status) {
    if (lac_good == peer_good) return;
    disagreements += "| " + set + " | " + std::to_string(i) + " | " + data + " | " +
                     (lac_good ? "verified" : lac_status) + " | " + (peer_good ? "verified" : "failed") + " |\n";
  };
  for (double alpha : alphas) {
    const bool with_peer = alpha == -1;
    Row lac_row{"G1", "lac", "solve_g1_hermite, default options", alpha};
    Row peer_row{"G1", "Clothoids", "ClothoidCurve::build_G1, tol 1e-12", alpha};
    for (size_t i = 0; i < g1_set.size(); ++i) {
      const test::G1Angles& a = g1_set[i];
      G1HermiteResult r;
      bool peer_flag = false;
      std::vector<std::function<double()>> calls{[&] {
        return timed(r, [&] { return solve_g1_hermite({{0, 0}, a.theta0, {1, 0}, a.theta1, alpha}, g1_options); });
      }};
      if (with_peer)
        calls.emplace_back([&] { return timed(peer_flag, [&] { return lac_peer::g1(0, 0, a.theta0, 1, 0, a.theta1); }); });
      const std::vector<double> t = least(calls);
      const std::string status(to_string(r.summary.status));
      const bool lac_good =
          lac_row.add(t[0], r.usable(), r.summary.status == Status::ok, lac_g1_error(r, a.theta1), status);
      if (with_peer) {
        const bool peer_good =
            peer_row.add(t[1], peer_flag, peer_flag, peer_error(lac_peer::g1_check(), a.theta0, a.theta1), "failed");
        disagree("G1", i, lac_good, peer_good, "θ0 " + io::fmt(a.theta0, 17) + ", θ1 " + io::fmt(a.theta1, 17), status);
      }
    }
    rows.push_back(lac_row);
    if (with_peer) rows.push_back(peer_row);
    std::cerr << "G1 alpha " << alpha << ": lac " << lac_row.verified << "/" << lac_row.problems << " verified, median "
              << lac_row.median() << " us\n";
  }
  for (double alpha : alphas) {
    const bool with_peer = alpha == -1;
    Row lac_row{"G2", "lac", "solve_g2, default options", alpha};
    Row peer_row{"G2", "Clothoids", "G2solve3arc::build, defaults", alpha};
    for (size_t i = 0; i < g2_set.size(); ++i) {
      const G2Data& d = g2_set[i];
      G2Result r;
      bool peer_flag = false;
      std::vector<std::function<double()>> calls{[&] {
        return timed(r, [&] { return solve_g2({{{0, 0}, d.t0, d.k0}, {{1, 0}, d.t1, d.k1}, alpha}, g2_options); });
      }};
      if (with_peer)
        calls.emplace_back(
            [&] { return timed(peer_flag, [&] { return lac_peer::g2(0, 0, d.t0, d.k0, 1, 0, d.t1, d.k1); }); });
      const std::vector<double> t = least(calls);
      const std::string status(to_string(r.summary.status));
      const bool lac_good = lac_row.add(t[0], r.usable(), r.summary.status == Status::ok, lac_g2_error(r, d), status);
      if (with_peer) {
        const bool peer_good = peer_row.add(
            t[1], peer_flag, peer_flag, peer_error(lac_peer::g2_check(), d.t0, d.t1, &d.k0, &d.k1), "failed");
        disagree("G2", i, lac_good, peer_good,
                 "θ0 " + io::fmt(d.t0, 17) + ", κ0 " + io::fmt(d.k0, 17) + ", θ1 " + io::fmt(d.t1, 17) + ", κ1 " +
                     io::fmt(d.k1, 17),
                 status);
      }
    }
    rows.push_back(lac_row);
    if (with_peer) rows.push_back(peer_row);
    std::cerr << "G2 alpha " << alpha << ": lac " << lac_row.verified << "/" << lac_row.problems << " verified, median "
              << lac_row.median() << " us\n";
  }
  // lac's G2 without the re-evaluation of the result (G2Options::verify = false), at α = −1:
  // the solve alone, as the peer returns it.
  {
    G2Options o;
    o.verify = false;
    Row row{"G2", "lac", "solve_g2, verify = false", -1};
    for (const auto& d : g2_set) {
      G2Result r;
      const std::vector<double> t =
          least({[&] { return timed(r, [&] { return solve_g2({{{0, 0}, d.t0, d.k0}, {{1, 0}, d.t1, d.k1}, -1.0}, o); }); }});
      row.add(t[0], r.usable(), r.summary.status == Status::ok, lac_g2_error(r, d),
              std::string(to_string(r.summary.status)));
    }
    rows.push_back(row);
  }

  const auto median_of = [&](const std::string& set, const std::string& lib, const std::string& opt, double alpha) {
    for (const Row& r : rows)
      if (r.set == set && r.library == lib && r.alpha == alpha && r.options.find(opt) != std::string::npos)
        return r.median();
    return double(NAN);
  };
  const double g1_peer = median_of("G1", "Clothoids", "", -1), g2_peer = median_of("G2", "Clothoids", "", -1);

  io::Table t;
  t.columns = {"set",          "library",         "solver and options", "α",          "problems",  "own flag",
               "status ok",    "verified",        "verified ≤ 1e-10",   "median µs",  "p90 µs",    "lac/peer median",
               "failed solves", "failed, by status", "failed median µs", "failed p90 µs",     "worst verified error"};
  for (const Row& r : rows) {
    const double peer = r.set == "G1" ? g1_peer : g2_peer;
    const bool ratio = r.library == "lac" && r.alpha == -1 && std::isfinite(peer);
    const bool any_fail = !r.fail_us.empty();
    t.add_row({r.set, r.library, r.options, io::fmt(r.alpha), std::to_string(r.problems), std::to_string(r.flagged),
               r.library == "lac" ? std::to_string(r.ok) : "—", std::to_string(r.verified),
               std::to_string(r.verified_tight), io::fmt(r.median()), io::fmt(quantile(r.us, 0.9)),
               ratio ? io::fmt(r.median() / peer) : "—", std::to_string(r.fail_us.size()),
               r.failure_text(), any_fail ? io::fmt(quantile(r.fail_us, 0.5)) : "—", any_fail ? io::fmt(quantile(r.fail_us, 0.9)) : "—",
               r.verified ? io::sci(r.worst_error, 2) : "—"});
  }

  // The targets this comparison was set up for, each against its measured value.
  std::string targets;
  const auto target = [&](const std::string& what, double value, double bound, const std::string& unit) {
    targets += "| " + what + " | " + io::fmt(value) + unit + " | ≤ " + io::fmt(bound) + unit + " | " +
               (value <= bound ? "met" : "not met") + " |\n";
  };
  double g1_worst = 0, g2_worst = 0, fail_p90 = 0;
  int g2_m1_verified = 0;
  for (const Row& r : rows) {
    if (r.library != "lac" || r.options.find("default") == std::string::npos) continue;
    (r.set == "G1" ? g1_worst : g2_worst) = std::max(r.set == "G1" ? g1_worst : g2_worst, r.median());
    if (r.set == "G2" && !r.fail_us.empty()) fail_p90 = std::max(fail_p90, quantile(r.fail_us, 0.9));
    if (r.set == "G2" && r.alpha == -1) g2_m1_verified = r.verified;
  }
  target("G1, α = −1: lac median / Clothoids median", median_of("G1", "lac", "default", -1) / g1_peer, 1.3, "×");
  target("G1, every α: largest lac median", g1_worst, 3, " µs");
  target("G2, α = −1: lac median / Clothoids median", median_of("G2", "lac", "default", -1) / g2_peer, 2, "×");
  target("G2, α = −1: lac problems not verified", g2_count - g2_m1_verified, 0, "");
  target("G2, every α: largest lac median", g2_worst, 15, " µs");
  target("G2, every α: largest p90 of lac's failed solves", fail_p90, 1000, " µs");

  io::ResultDoc doc;
  doc.title = "lac beside the Clothoids library: time per solve and successes";
  doc.command = io::command_line(argc, argv);
  doc.description =
      "Measured " + today_utc() + " on " + cpu_model() + ", one process pinned to one CPU" +
      (cpu >= 0 ? " (" + std::to_string(cpu) + ")" : std::string(" (not pinned)")) +
      ". Peer: [Clothoids](https://github.com/ebertolazzi/Clothoids) commit `" + peer_commit +
      "`, built outside this repository by the same compiler with the same optimisation flags, `-O3 -DNDEBUG` (scripts/peer_speed.sh, docs/peer_speed.md). " +
      "G1: " + std::to_string(g1_count) +
      " problems, P0 = (0,0), P1 = (1,0), θ0, θ1 uniform in (−π/2, π/2) (tests/support/g1_problem_set.hpp); G2: " +
      std::to_string(g2_count) +
      " problems, the same angles and κ0, κ1 uniform in (−3, 3) (std::mt19937_64 seed 20130501, as "
      "experiments/g2_random.cpp). The peer solves only α = −1 (an LA curve of slope −1 is a clothoid); its G2 "
      "is three clothoids (Bertolazzi–Frego 2018), lac's a triple LA curve (004 §3).\n\n"
      "Times: each solve called " +
      std::to_string(repeats) +
      " times (once when a call takes more than " + io::fmt(slow_us) +
      " µs), steady_clock around each call, the least kept per problem; at α = −1 the lac and peer calls alternate. "
      "Median and p90 are over the problems. lac's G2 default re-evaluates the result by its segment kernel "
      "with the kernel's error bound (`verify`), part of its time; the last row is the same solve without it.\n\n"
      "Columns: *own flag* — lac: status usable; Clothoids: G1 returned without exception, G2 returned an "
      "iteration count. *verified* — own flag and the curve, evaluated afterwards, meets the data within 1e-6 "
      "(lac::kDefaultAccept; chord = 1): end point and end tangent angle (G1), plus both end curvatures and "
      "the joints' position, angle and curvature gaps (G2). lac's end point is integrated by gk-tanh-sinh, "
      "not the solve's kernel; the peer's curves are evaluated by the peer (its last G2 piece is built "
      "backwards from P1, so its joints carry the residual). *failed* — problems not verified; their times. "
      "*lac/peer median* — lac's median over the peer's, α = −1.\n\n" +
      io::machine_description();
  doc.notes = "## Targets\n\n| target | measured | bound | |\n|---|---|---|---|\n" + targets +
              "\n## α = −1: problems only one library solves\n\n" +
              (disagreements.empty() ? std::string("None: both verify the same problems.\n")
                                     : "Problem index in its set (from 0), data (P0 = (0,0), P1 = (1,0)), outcome.\n\n"
                                       "| set | problem | data | lac | Clothoids |\n|---|---|---|---|---|\n" +
                                           disagreements);
  io::write_result_table(out_dir, "peer_speed", doc, t);
  std::cout << t.markdown() << "\n" << targets;
  return 0;
}

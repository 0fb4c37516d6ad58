// lac.solve_batch: many G1 or G2 Hermite problems, or control-triangle G1 / compound problems, from numpy columns (scalars broadcast), solved in
// parallel with the GIL released, returned as columns named as the CLI's report keys
// (docs/cli.md "Schema"). The rows are independent, so any split of them (threads here, Dask
// chunks in lac/distributed.py) gives the same results.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "bindings.hpp"
#include "lac/constructions/triangle_g1.hpp"

namespace lacpy {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr size_t kStatusWidth = 17;  // longest status name: "tolerance_not_met"

/// A numeric column of n rows: a scalar (broadcast) or an array of n values.
struct Column {
  const double* data = nullptr;
  double scalar = 0;
  py::array_t<double, py::array::c_style | py::array::forcecast> keep;
  double operator[](size_t i) const { return data ? data[i] : scalar; }
};

/// A point column: (x, y) broadcast, an (n, 2) array, or a complex array of n.
struct PointColumn {
  Column x, y;
  std::complex<double> operator[](size_t i) const { return {x[i], y[i]}; }
};

ssize_t rows_of(py::handle h, bool point) {
  py::array a = py::array::ensure(h);
  if (!a) return -1;
  if (point) {
    if (a.ndim() == 1 && a.shape(0) == 2 && !PyComplex_Check(h.ptr()) && a.dtype().kind() != 'c') return 0;  // one point
    if (a.dtype().kind() == 'c') return a.ndim() == 0 ? 0 : a.shape(0);
    return a.ndim() == 2 ? a.shape(0) : -1;
  }
  return a.ndim() == 0 ? 0 : (a.ndim() == 1 ? a.shape(0) : -1);
}

Column column(py::handle h, size_t n, const char* name) {
  Column c;
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a) lac::throw_input_error("solve_batch", name, "expected numbers");
  if (a.ndim() == 0 || a.size() == 1) {
    c.scalar = *a.data();
  } else {
    if (a.ndim() != 1 || size_t(a.shape(0)) != n)
      lac::throw_input_error("solve_batch", name, "expected a scalar or an array of " + std::to_string(n) + " rows");
    c.keep = a;
    c.data = c.keep.data();
  }
  return c;
}

PointColumn point_column(py::handle h, size_t n, const char* name) {
  py::array a = py::array::ensure(h);
  if (!a) lac::throw_input_error("solve_batch", name, "expected points");
  if (a.dtype().kind() == 'c') {
    auto z = py::array_t<std::complex<double>, py::array::c_style | py::array::forcecast>::ensure(h);
    py::module_ np = py::module_::import("numpy");
    return {column(np.attr("real")(z), n, name), column(np.attr("imag")(z), n, name)};
  }
  auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  if (d.ndim() == 1 && d.shape(0) == 2) return {column(py::float_(d.at(0)), n, name), column(py::float_(d.at(1)), n, name)};
  if (d.ndim() != 2 || d.shape(1) != 2 || size_t(d.shape(0)) != n)
    lac::throw_input_error("solve_batch", name, "expected (x, y), an (n, 2) array or a complex array of n rows");
  py::object xs = d[py::make_tuple(py::slice(0, n, 1), 0)], ys = d[py::make_tuple(py::slice(0, n, 1), 1)];
  return {column(xs, n, name), column(ys, n, name)};
}

/// A numpy column of n values and its buffer, filled with the GIL released.
template <class T>
struct OutColumn {
  py::array_t<T> array;
  T* data;
  OutColumn(size_t n, T fill) : array(py::ssize_t(n)), data(array.mutable_data()) { std::fill(data, data + n, fill); }
};

/// The output columns of every row, written straight into numpy arrays (allocated with the GIL
/// held); messages are rare (rows not ok) and kept sparse.
struct Out {
  std::vector<uint8_t> status;   ///< lac::Status, or kInvalid: the row's input was rejected
  OutColumn<double> length, kappa0, kappa1, seconds, error, accept;
  OutColumn<int> iterations;
  OutColumn<long> evaluations;
  std::optional<OutColumn<double>> lambda0;  ///< triangle, compound: Λ of segment 0 (TrianglePiece::lambda_user)
  std::mutex mutex;
  std::vector<std::pair<size_t, std::string>> messages;
  static constexpr uint8_t kInvalid = 255;  ///< status "invalid_input", as the CLI's batch

  explicit Out(size_t n)
      : status(n), length(n, kNaN), kappa0(n, kNaN), kappa1(n, kNaN), seconds(n, 0), error(n, kNaN), accept(n, kNaN),
        iterations(n, 0), evaluations(n, 0) {}
  void message(size_t i, const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex);
    messages.emplace_back(i, text);
  }
  template <class R>
  void set(size_t i, const R& r) {
    const lac::Summary& s = r.summary;
    status[i] = uint8_t(s.status);
    if (!s.message.empty()) message(i, s.message);
    if (r.usable() && !r.curve.segments().empty()) {
      length.data[i] = r.curve.length();  // κ as the CLI's report (cli/report_curves.cpp)
      kappa0.data[i] = r.curve.kappa_at(0);
      kappa1.data[i] = r.curve.kappa_at(r.curve.length());
    }
    seconds.data[i] = s.seconds;
    error.data[i] = s.error ? *s.error : kNaN;
    accept.data[i] = s.accept;
    iterations.data[i] = s.iterations;
    evaluations.data[i] = s.evaluations;
  }
  void set_input_error(size_t i, const std::string& what) {
    status[i] = kInvalid;
    message(i, what);
  }
};

/// Runs row(i) for i in [0, n) on `threads` threads (0: all cores), in chunks from a shared counter.
template <class F>
void parallel_rows(size_t n, int threads, F&& row) {
  size_t t = threads > 0 ? size_t(threads) : std::max(1u, std::thread::hardware_concurrency());
  t = std::min(t, std::max<size_t>(1, n / 16));
  if (t <= 1) {
    for (size_t i = 0; i < n; ++i) row(i);
    return;
  }
  std::atomic<size_t> next{0};
  constexpr size_t kChunk = 64;
  auto work = [&] {
    for (size_t b; (b = next.fetch_add(kChunk)) < n;)
      for (size_t i = b; i < std::min(n, b + kChunk); ++i) row(i);
  };
  std::vector<std::thread> pool;
  for (size_t k = 1; k < t; ++k) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
}

py::dict solve_batch(const std::string& kind, py::dict data, int threads, py::kwargs kwargs) {
  const bool g1 = kind == "g1" || kind == "g1_hermite";
  const bool g2 = kind == "g2" || kind == "g2_hermite";
  const bool triangle = kind == "triangle";
  const bool compound = kind == "compound";
  if (!g1 && !g2 && !triangle && !compound)
    lac::throw_input_error("solve_batch", "kind", "'" + kind + "' is not one of g1 | g2 | triangle | compound");
  const std::vector<std::string> points = triangle || compound ? std::vector<std::string>{"a0", "a1", "a2"}
                                                               : std::vector<std::string>{"p0", "p1"};
  const std::vector<std::string> numbers =
      g1         ? std::vector<std::string>{"theta0", "theta1", "alpha"}
      : g2       ? std::vector<std::string>{"theta0", "kappa0", "theta1", "kappa1", "alpha"}
      : triangle ? std::vector<std::string>{"alpha"}
                 : std::vector<std::string>{"alpha0", "alpha1", "r"};
  auto listed = [](const std::vector<std::string>& v, const std::string& k) {
    return std::find(v.begin(), v.end(), k) != v.end();
  };
  // Rows: the length of the array columns (all equal); other keys are options (scalars).
  py::dict options(kwargs);
  ssize_t n = -1;
  for (auto item : data) {
    const std::string key = py::str(item.first);
    const bool is_point = listed(points, key), is_number = listed(numbers, key);
    if (!is_point && !is_number) {
      options[item.first] = item.second;
      continue;
    }
    const ssize_t r = rows_of(item.second, is_point);
    if (r < 0) lac::throw_input_error("solve_batch", key, "expected a scalar, a point or a 1-D array of rows");
    if (r > 0) {
      if (n >= 0 && r != n)
        lac::throw_input_error("solve_batch", key, "has " + std::to_string(r) + " rows, other columns " + std::to_string(n));
      n = r;
    }
  }
  if (n < 0) n = 1;
  for (const std::string& p : points)
    if (!data.contains(p)) lac::throw_input_error("solve_batch", p, p + " is required");
  for (const std::string& p : numbers)
    if (!data.contains(p) && !(g2 && p == "alpha") && !(compound && p == "r"))
      lac::throw_input_error("solve_batch", p, p + " is required");
  const size_t rows = size_t(n);
  std::map<std::string, PointColumn> P;
  std::map<std::string, Column> N;
  for (const std::string& p : points) P.emplace(p, point_column(data[p.c_str()], rows, p.c_str()));
  for (const std::string& p : numbers)
    N.emplace(p, data.contains(p) ? column(data[p.c_str()], rows, p.c_str()) : Column{nullptr, p == "r" ? 0.5 : -1.0, {}});

  Out out(rows);
  auto run = [&](auto&& solve_row) {
    py::gil_scoped_release release;
    parallel_rows(rows, threads, [&](size_t i) {
      try {
        out.set(i, solve_row(i));
      } catch (const lac::InputError& e) {
        out.set_input_error(i, e.what());
      }
    });
  };
  const auto start = std::chrono::steady_clock::now();
  if (g1) {
    const lac::G1HermiteOptions o = g1_options(options, "solve_batch");
    const auto &p0 = P.at("p0"), &p1 = P.at("p1");
    const auto &theta0 = N.at("theta0"), &theta1 = N.at("theta1"), &alpha = N.at("alpha");
    run([&](size_t i) { return lac::solve_g1_hermite({p0[i], theta0[i], p1[i], theta1[i], alpha[i]}, o); });
  } else if (g2) {
    const lac::G2Options o = g2_options(options, "solve_batch");
    const auto &p0 = P.at("p0"), &p1 = P.at("p1");
    const auto &theta0 = N.at("theta0"), &theta1 = N.at("theta1"), &alpha = N.at("alpha");
    const auto &kappa0 = N.at("kappa0"), &kappa1 = N.at("kappa1");
    run([&](size_t i) { return lac::solve_g2({{p0[i], theta0[i], kappa0[i]}, {p1[i], theta1[i], kappa1[i]}, alpha[i]}, o); });
  } else {
    const lac::TriangleOptions o = triangle_options(options, "solve_batch");
    const auto &a0 = P.at("a0"), &a1 = P.at("a1"), &a2 = P.at("a2");
    out.lambda0.emplace(rows, kNaN);
    if (triangle) {
      const auto& alpha = N.at("alpha");
      run([&](size_t i) {
        auto g = lac::solve_g1({a0[i], a1[i], a2[i]}, alpha[i], o);
        out.lambda0->data[i] = g.info.pieces.empty() ? kNaN : g.info.pieces[0].lambda_user;
        return g;
      });
    } else {
      const auto &alpha0 = N.at("alpha0"), &alpha1 = N.at("alpha1"), &r = N.at("r");
      run([&](size_t i) {
        auto g = lac::solve_compound({a0[i], a1[i], a2[i]}, alpha0[i], alpha1[i], r[i], o);
        out.lambda0->data[i] = g.info.pieces.empty() ? kNaN : g.info.pieces[0].lambda_user;
        return g;
      });
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // status: fixed-width unicode, written directly (no Python string per row).
  py::array status(py::dtype("<U" + std::to_string(kStatusWidth)), std::vector<py::ssize_t>{py::ssize_t(rows)});
  auto* chars = static_cast<uint32_t*>(status.mutable_data());
  std::fill(chars, chars + rows * kStatusWidth, 0u);
  auto usable = py::array_t<bool>(py::ssize_t(rows));
  bool* use = usable.mutable_data();
  for (size_t i = 0; i < rows; ++i) {
    const bool invalid = out.status[i] == Out::kInvalid;
    const auto st = lac::Status(out.status[i]);
    const std::string_view s = invalid ? std::string_view("invalid_input") : lac::to_string(st);
    for (size_t k = 0; k < s.size(); ++k) chars[i * kStatusWidth + k] = uint32_t(s[k]);
    use[i] = !invalid && lac::usable(st);
  }
  py::array message(py::dtype("O"), std::vector<py::ssize_t>{py::ssize_t(rows)});
  auto** objs = static_cast<PyObject**>(message.mutable_data());
  for (size_t i = 0; i < rows; ++i) {
    Py_XDECREF(objs[i]);
    objs[i] = py::none().release().ptr();
  }
  for (const auto& [i, text] : out.messages) {
    Py_XDECREF(objs[i]);
    objs[i] = py::str(text).release().ptr();
  }
  py::dict d;
  d["status"] = status;
  d["message"] = message;
  d["length"] = out.length.array;
  d["kappa0"] = out.kappa0.array;
  d["kappa1"] = out.kappa1.array;
  d["iterations"] = out.iterations.array;
  d["evaluations"] = out.evaluations.array;
  d["seconds"] = out.seconds.array;
  d["error"] = out.error.array;
  d["accept"] = out.accept.array;
  d["usable"] = usable;
  if (out.lambda0) d["lambda0_user"] = out.lambda0->array;
  d["_wall_seconds"] = wall;
  return d;
}

/// The same G1 solves in a plain C++ loop on one thread, nothing stored: the baseline of
/// python/bench/bench_batch.py. Returns the wall seconds.
double g1_loop_seconds(py::array_t<double> x0, py::array_t<double> y0, py::array_t<double> th0, py::array_t<double> x1,
                       py::array_t<double> y1, py::array_t<double> th1, double alpha) {
  const size_t n = size_t(th0.size());
  auto X0 = x0.unchecked<1>(), Y0 = y0.unchecked<1>(), T0 = th0.unchecked<1>(), X1 = x1.unchecked<1>(),
       Y1 = y1.unchecked<1>(), T1 = th1.unchecked<1>();
  py::gil_scoped_release release;
  const auto start = std::chrono::steady_clock::now();
  double sink = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto r = lac::solve_g1_hermite({{X0(i), Y0(i)}, T0(i), {X1(i), Y1(i)}, T1(i), alpha});
    sink += r.usable() ? r.curve.length() : 0.0;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sink == -1 ? -s : s;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("_solve_batch", &solve_batch, py::arg("kind"), py::arg("data"), py::kw_only(), py::arg("threads") = 0,
        "Local batch solve (lac.solve_batch without a client).");
  m.def("_g1_loop_seconds", &g1_loop_seconds, "Benchmark baseline: the G1 solves in a plain C++ loop, one thread.");
}

}  // namespace lacpy

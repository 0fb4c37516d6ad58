// solve_nonlinear reproduces the hand-written solvers of the G2 construction
// (constructions/detail/g2_system.cpp solve_newton, constructions/detail/ceres_solver.cpp) with the
// options below: copies of those loops run on small nonlinear systems, and every point either
// evaluates, and the final iterate, must agree bit for bit. Also: the Ceres → Status mapping.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "lac/solvers/detail/ceres_support.hpp"
#include "lac/solvers/nonlinear.hpp"

namespace lac {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using Vec3 = Eigen::Vector3d;
using Points = std::vector<Eigen::VectorXd>;

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

void expect_same_points(const Points& a, const Points& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(same_bits(a[i], b[i])) << "point " << i << ": " << a[i].transpose() << " vs " << b[i].transpose();
}

// ---- G2 Newton: a copy of constructions/detail/g2_system.cpp solve_newton (the residual and the
// unknowns z generalized, the loop as it is).
struct G2NewtonCopy {
  Status status = Status::no_solution;
  std::string message;
  Vec3 z;
  int iterations = 0;
  bool stopped_in_iteration = false;  // added: the loop broke after its Jacobian (singular, no descent)
};

G2NewtonCopy g2_newton_copy(const std::function<Vec3(const Vec3&)>& residual, Vec3 z, double tolerance, int max_iterations) {
  G2NewtonCopy out;
  auto eval = [&](const Vec3& v) { return residual(v); };
  auto norm = [](const Vec3& r) { return r.allFinite() ? r.lpNorm<Eigen::Infinity>() : HUGE_VAL; };
  Vec3 r = eval(z);
  double rn = norm(r);
  if (!std::isfinite(rn)) {
    out.status = Status::numerical_failure;
    out.message = "newton: the initial estimate gives a non-finite curve";
    out.z = z;
    return out;
  }
  out.status = Status::max_iterations;
  out.message = "newton: iteration cap reached";
  for (out.iterations = 0; out.iterations < max_iterations; ++out.iterations) {
    if (rn <= tolerance) {
      out.status = Status::ok;
      out.message.clear();
      break;
    }
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j) {  // forward differences
      Vec3 zj = z;
      const double step = 1e-7 * std::max(1.0, std::abs(z(j)));
      zj(j) += step;
      J.col(j) = (eval(zj) - r) / step;
    }
    const Vec3 dz = J.fullPivLu().solve(-r);
    if (!dz.allFinite()) {
      out.status = Status::numerical_failure;
      out.message = "newton: singular Jacobian";
      out.stopped_in_iteration = true;
      break;
    }
    // Backtracking: halve the step until the residual decreases (at most 30 halvings).
    double lambda = 1.0;
    bool moved = false;
    for (int k = 0; k < 30; ++k, lambda *= 0.5) {
      Vec3 zt = z + lambda * dz;
      if (std::abs(zt(0) - z(0)) > 2.0) continue;  // length may change by e^2 per step at most
      const Vec3 rt = eval(zt);
      const double nt = norm(rt);
      if (nt < rn) {
        z = zt, r = rt, rn = nt, moved = true;
        break;
      }
    }
    if (!moved) {
      out.status = rn <= 1e3 * tolerance ? Status::ok : Status::no_solution;
      out.message = rn <= 1e3 * tolerance ? "" : "newton: no descent from here (residual " + std::to_string(rn) + ")";
      out.stopped_in_iteration = true;
      break;
    }
  }
  if (out.status == Status::max_iterations && rn <= tolerance) out.status = Status::ok, out.message.clear();
  out.z = z;
  return out;
}

/// The options that make solve_nonlinear(newton, …) the G2 Newton iteration.
NonlinearOptions g2_newton_options(double tolerance, int max_iterations) {
  NonlinearOptions o;
  o.residual_tolerance = tolerance;
  o.norm = ResidualNorm::max;  // acceptance and the tolerance on max |r_i|
  o.newton.max_iterations = max_iterations;
  o.newton.max_evaluations = std::numeric_limits<long>::max();
  o.newton.fd_step = 1e-7;                  // h_j = 1e-7·max(1, |z_j|), forward only
  o.newton.backward_differences = false;
  o.newton.reject_singular = false;         // only a non-finite step stops
  o.newton.max_step = kInf;                 // no scaling of the step
  o.newton.max_trial_change = Vec3(2, kInf, kInf);  // a trial changing log h by more than 2 is skipped
  o.newton.max_halvings = 29;               // 30 trials: 1, 1/2, …, 2^-29
  o.newton.step_tolerance = 0;
  o.newton.stall_factor = 1e3;              // no descent but max |r| ≤ 1e3·tolerance: converged
  return o;
}

// G2's no-descent (no_solution) and singular-Jacobian (numerical_failure) stops are stalls.
Status g2_status_in_the_new_scheme(const G2NewtonCopy& g2) {
  if (g2.status == Status::no_solution || (g2.status == Status::numerical_failure && g2.stopped_in_iteration))
    return Status::not_converged;
  return g2.status;
}

struct NewtonCase {
  const char* name;
  std::function<Vec3(const Vec3&)> r;
  Vec3 z0;
  double tolerance;
  int max_iterations;
  bool jacobian_undefined = false;  // ours stops at the first undefined difference, G2 after all three
};

TEST(NonlinearReproduction, NewtonTakesTheG2NewtonIterates) {
  const std::vector<NewtonCase> cases = {
      // the first step (49 in z0) is skipped five times by the trial limit
      {"exp-cubic-sine", [](const Vec3& z) { return Vec3(std::exp(z[0]) - 50, z[1] * z[1] * z[1] + z[1] - z[0], std::sin(z[2]) + z[1] * z[2] - 0.5); },
       Vec3(0, 0, 0), 1e-12, 50},
      // a residual floor between the tolerance and 1e3 times it: accepted at the stall
      {"floor", [](const Vec3& z) { return Vec3(std::exp(z[0]) - 50, z[1] * z[1] * z[1] + z[1] - z[0], std::sin(z[2]) + z[1] * z[2] - 0.5); },
       Vec3(0, 0, 0), 1e-17, 50},
      // no root: stalls (G2: no_solution)
      {"no-root", [](const Vec3& z) { return Vec3(std::exp(z[0]) - 3, z[1] * z[1] + 1, z[2] + z[0]); }, Vec3(0.2, 0.7, 0), 1e-12, 50},
      // e^(e^z0) overflows on long trial steps: non-finite trials are rejected
      {"overflow", [](const Vec3& z) { return Vec3(std::exp(std::exp(z[0])) - 1e6, z[1] - z[0], z[2] * z[2] - 2); },
       Vec3(-3, 1, 1), 1e-12, 50},
      // the iteration cap
      {"cap", [](const Vec3& z) { return Vec3(std::exp(z[0]) - 50, z[1] * z[1] * z[1] + z[1] - z[0], std::sin(z[2]) + z[1] * z[2] - 0.5); },
       Vec3(0, 0, 0), 1e-12, 3},
      // a forward difference overflows: G2 goes on with an infinite Jacobian column (here: no descent),
      // ours stops at the undefined difference (both without moving)
      {"jacobian overflow", [](const Vec3& z) { return Vec3(std::exp(std::exp(z[0])) - 1, z[1], z[2] - 1); },
       Vec3(std::log(709.7827) - 3e-7, 0.5, 0), 1e-12, 50, true},
      // not finite at the start
      {"non-finite start", [](const Vec3& z) { return Vec3(std::exp(std::exp(z[0])), z[1], z[2]); }, Vec3(800, 0, 0), 1e-12, 50},
  };
  for (const NewtonCase& c : cases) {
    SCOPED_TRACE(c.name);
    Points copy_points, our_points;
    const G2NewtonCopy g2 = g2_newton_copy(
        [&](const Vec3& z) {
          copy_points.push_back(z);
          return c.r(z);
        },
        c.z0, c.tolerance, c.max_iterations);
    const NonlinearResidual residual{3, [&](ConstVectorMap z, VectorMap r) {
                                       our_points.push_back(z);
                                       r = c.r(Vec3(z));
                                       return true;
                                     }};
    const NonlinearResult ours =
        solve_nonlinear(NonlinearMethod::newton, residual, c.z0, g2_newton_options(c.tolerance, c.max_iterations));
    if (c.jacobian_undefined) {
      ASSERT_LT(our_points.size(), copy_points.size());
      copy_points.resize(our_points.size());
    }
    expect_same_points(copy_points, our_points);
    EXPECT_TRUE(same_bits(g2.z, ours.x));
    EXPECT_EQ(g2_status_in_the_new_scheme(g2), ours.status) << g2.message << " | " << ours.message;
    // The G2 loop does not count the iteration it stops in.
    EXPECT_EQ(ours.iterations, g2.iterations + (g2.stopped_in_iteration ? 1 : 0));
    std::printf("  %-16s G2 %-17s ours %-17s iterations %d/%d, evaluations %zu\n", c.name,
                std::string(to_string(g2.status)).c_str(), std::string(to_string(ours.status)).c_str(), g2.iterations,
                ours.iterations, our_points.size());
  }
}

// ---- G2 Ceres: a copy of the setup in constructions/detail/ceres_solver.cpp (10 unknowns, 10
// residuals, central differences) on a toy system.
constexpr int kTen = 10;

struct TenResidual {
  Points* points;
  bool operator()(const double* x, double* r) const {
    points->push_back(Eigen::Map<const Eigen::VectorXd>(x, kTen));
    if (x[0] > 4) return false;  // an undefined region, as for a non-representable curve
    for (int i = 0; i < kTen; ++i) {
      const double next = x[(i + 1) % kTen];
      r[i] = x[i] + 0.3 * std::sin(next) + 0.05 * x[i] * x[i] * x[i] - (1.0 + 0.1 * i);
    }
    r[kTen - 1] += std::exp(0.2 * x[0]) - 1;
    for (int k = 0; k < kTen; ++k)
      if (!std::isfinite(r[k])) return false;
    return true;
  }
};

TEST(NonlinearReproduction, CeresTakesTheG2CeresIterates) {
  for (int max_iterations : {3, 100}) {
    SCOPED_TRACE(max_iterations);
    const double tolerance = 1e-13;
    Points copy_points, our_points;
    double x[kTen];
    for (int i = 0; i < kTen; ++i) x[i] = 0.5 * i - 2;
    const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(x, kTen);
    ceres::Problem problem;
    auto* cost = new ceres::NumericDiffCostFunction<TenResidual, ceres::CENTRAL, kTen, kTen>(new TenResidual{&copy_points});
    problem.AddResidualBlock(cost, nullptr, x);
    ceres::Solver::Options so;
    so.minimizer_type = ceres::TRUST_REGION;
    so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = max_iterations;
    so.function_tolerance = 1e-30;
    so.gradient_tolerance = 1e-30;
    so.parameter_tolerance = 1e-16;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    so.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    double r[kTen];
    Points dummy;
    const bool finite = TenResidual{&dummy}(x, r);
    double worst = 0;
    for (double v : r) worst = std::max(worst, std::abs(v));
    G2NewtonCopy g2;  // only its status
    g2.status = finite && worst <= tolerance                                ? Status::ok
                : summary.termination_type == ceres::NO_CONVERGENCE ? Status::max_iterations
                                                                    : Status::no_solution;

    NonlinearOptions o;
    o.residual_tolerance = tolerance;
    o.norm = ResidualNorm::max;  // success: the largest |r_i| ≤ tolerance
    o.ceres.max_iterations = max_iterations;
    o.ceres.function_tolerance = 1e-30;
    o.ceres.gradient_tolerance = 1e-30;
    o.ceres.parameter_tolerance = 1e-16;
    o.ceres.stop_at_tolerance = false;  // only Ceres' own tests stop it
    // fd_relative_step 1e-6 and initial_trust_region 1e4 are Ceres' defaults, as in the G2 setup
    const TenResidual ten{&our_points};
    const NonlinearResidual residual{kTen, [&](ConstVectorMap z, VectorMap out) { return ten(z.data(), out.data()); }};
    const NonlinearResult ours = solve_nonlinear(NonlinearMethod::ceres, residual, x0, o);
    // ours evaluates the start once before Ceres and the end once after it
    ASSERT_EQ(our_points.size(), copy_points.size() + 2);
    EXPECT_TRUE(same_bits(our_points.front(), x0));
    expect_same_points(copy_points, Points(our_points.begin() + 1, our_points.end() - 1));
    EXPECT_TRUE(same_bits(Eigen::Map<const Eigen::VectorXd>(x, kTen), ours.x));
    EXPECT_EQ(ours.iterations, static_cast<int>(summary.iterations.size()));
    EXPECT_EQ(g2_status_in_the_new_scheme(g2), ours.status) << ours.message;
    EXPECT_EQ(ours.status, max_iterations == 3 ? Status::max_iterations : Status::ok);
  }
}

// ---- The one Ceres → Status mapping.
TEST(CeresStatus, EveryTerminationTypeMapsToOneStatus) {
  ceres::Solver::Summary s;
  s.message = "the message";
  struct Row {
    ceres::TerminationType type;
    Status as_nd, as_1d;  // convergence_is_success false / true, target not met
  };
  const Row rows[] = {
      {ceres::CONVERGENCE, Status::not_converged, Status::ok},
      {ceres::NO_CONVERGENCE, Status::max_iterations, Status::max_iterations},
      {ceres::FAILURE, Status::not_converged, Status::not_converged},
      {ceres::USER_SUCCESS, Status::not_converged, Status::not_converged},
      {ceres::USER_FAILURE, Status::not_converged, Status::not_converged},
  };
  for (const Row& row : rows) {
    s.termination_type = row.type;
    SCOPED_TRACE(static_cast<int>(row.type));
    for (bool convergence_is_success : {false, true}) {
      const detail::CeresVerdict met = detail::ceres_verdict(s, true, convergence_is_success);
      EXPECT_EQ(met.status, Status::ok);
      EXPECT_TRUE(met.message.empty());
      const detail::CeresVerdict v = detail::ceres_verdict(s, false, convergence_is_success);
      EXPECT_EQ(v.status, convergence_is_success ? row.as_1d : row.as_nd);
      EXPECT_EQ(v.message.empty(), v.status == Status::ok);
      if (v.status != Status::ok) {
        EXPECT_EQ(v.message, "ceres: the message");
      }
    }
  }
}

}  // namespace
}  // namespace lac

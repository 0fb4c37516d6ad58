// Regression tests for the reproduction of 002 Appendices A and B (docs/p002.md): our numbers
// against the 40-digit reference (tests/reference/p002_truncation.csv) and the paper's typed cells
// (experiments/data/p002_appendix_b.csv). Each test prints its worst case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "lac/curves/planar/la_position.hpp"
#include "experiments/p002_data.hpp"

namespace {

// Tolerances and documented bands, in one place (docs/p002.md "Tests").
constexpr double kOrderLow = 3.9, kOrderHigh = 4.1;      // RK4 observed order where truncation dominates
constexpr double kTruncationDominates = 100;              // error above this many eps |C|: rounding negligible
constexpr double kPaperFactorLow = 1, kPaperFactorHigh = 12;  // ours / paper at h = 0.1, 0.01 (documented 2.8-11.9)
constexpr double kGkRelative = 1e-14;                     // our G-K endpoint, Appendix B rows
constexpr double kAppendixATarget = 1e-13;                // target: best method endpoint, relative
constexpr double kWrongReferenceFactor = 1e3;             // flagged paper G-K cells exceed ours by at least this
constexpr double kEps = std::numeric_limits<double>::epsilon();

std::filesystem::path reference_csv() { return std::filesystem::path(LAC_REFERENCE_DIR) / "p002_truncation.csv"; }

struct PaperB {
  std::string alpha_text;
  double lambda;
  double rk4[3];
  double gk;
};

std::vector<PaperB> paper_b() {
  std::vector<PaperB> out;
  for (auto& r : lac::p002::CsvRows::read(lac::p002::default_appendix_b_csv()).rows)
    out.push_back({r.at("alpha_text"), std::stod(r.at("lambda")),
                   {std::stod(r.at("rk4_h0.1")), std::stod(r.at("rk4_h0.01")), std::stod(r.at("rk4_h0.001"))},
                   std::stod(r.at("gk"))});
  return out;
}

constexpr double kSteps[3] = {0.1, 0.01, 0.001};

double rk4_theta_error(const lac::p002::ReferenceEnd& ref, double h) {
  const lac::LaCurve curve(ref.alpha, ref.lambda);
  const auto r = lac::position_at(curve, lac::Parameter::theta, ref.theta_end, lac::Rk4{.h = h}, lac::Form::theta);
  return std::abs(r.point.position - ref.c);
}

TEST(P002Reference, HasEveryCell) {
  const auto all = lac::p002::read_reference(reference_csv());
  EXPECT_EQ(lac::p002::reference_set(all, "appendix_a").size(), 18u);
  EXPECT_EQ(lac::p002::reference_set(all, "appendix_b").size(), 9u);
  EXPECT_EQ(lac::p002::reference_set(all, "appendix_b_s").size(), 9u);
  for (const auto& p : paper_b()) EXPECT_NO_THROW(lac::p002::find_reference(all, "appendix_b", p.alpha_text, p.lambda));
}

// Appendix B, best reading (θ-form, h in θ): classical RK4 is 4th order wherever truncation dominates.
TEST(P002AppendixB, Rk4ObservedOrderIsFour) {
  const auto all = lac::p002::read_reference(reference_csv());
  double worst_deviation = 0;
  std::string worst;
  int checked = 0;
  for (const auto& ref : lac::p002::reference_set(all, "appendix_b")) {
    double e[3];
    for (int j = 0; j < 3; ++j) e[j] = rk4_theta_error(ref, kSteps[j]);
    for (int j = 1; j < 3; ++j) {
      if (e[j] < kTruncationDominates * kEps * ref.abs_c) continue;  // rounding-limited cell
      const double order = std::log(e[j - 1] / e[j]) / std::log(kSteps[j - 1] / kSteps[j]);
      ++checked;
      EXPECT_GE(order, kOrderLow) << ref.alpha_text << " " << ref.lambda << " h=" << kSteps[j];
      EXPECT_LE(order, kOrderHigh) << ref.alpha_text << " " << ref.lambda << " h=" << kSteps[j];
      if (std::abs(order - 4) > worst_deviation) {
        worst_deviation = std::abs(order - 4);
        worst = ref.alpha_text + " Lambda=" + std::to_string(ref.lambda) + " h=" + std::to_string(kSteps[j]) +
                " order=" + std::to_string(order);
      }
    }
  }
  EXPECT_GE(checked, 9);  // at least every row between h = 0.1 and 0.01
  std::printf("worst RK4 order (%d pairs): %s\n", checked, worst.c_str());
}

// Our cells stay within the documented band of the paper's where the paper's reference is sound.
TEST(P002AppendixB, Rk4WithinDocumentedFactorOfPaper) {
  const auto all = lac::p002::read_reference(reference_csv());
  double lo = 1e300, hi = 0;
  for (const auto& p : paper_b()) {
    const auto& ref = lac::p002::find_reference(all, "appendix_b", p.alpha_text, p.lambda);
    for (int j = 0; j < 2; ++j) {  // h = 0.1, 0.01: above rounding and the paper's reference floor
      if (p.alpha_text == "10/9" && p.lambda == 100 && j == 1) continue;  // reference-limited (flagged)
      const double ratio = rk4_theta_error(ref, kSteps[j]) / p.rk4[j];
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
      EXPECT_GE(ratio, kPaperFactorLow) << p.alpha_text << " " << p.lambda << " h=" << kSteps[j];
      EXPECT_LE(ratio, kPaperFactorHigh) << p.alpha_text << " " << p.lambda << " h=" << kSteps[j];
    }
  }
  std::printf("ours/paper at h = 0.1, 0.01: %.3g .. %.3g\n", lo, hi);
}

// The paper's G-K cells for alpha = 10/9, Lambda = 10 and 100 are far above what a double G-K
// achieves: its IGF reference was wrong there (docs/p002.md).
TEST(P002AppendixB, GaussKronrodAccurateAndPaperReferenceWrongWhereFlagged) {
  const auto all = lac::p002::read_reference(reference_csv());
  const lac::GaussKronrod gk;
  double worst = 0;
  for (const auto& p : paper_b()) {
    const auto& ref = lac::p002::find_reference(all, "appendix_b", p.alpha_text, p.lambda);
    const lac::LaCurve curve(ref.alpha, ref.lambda);
    const auto r = lac::position_at(curve, lac::Parameter::theta, ref.theta_end, gk, lac::Form::theta);
    const double err = std::abs(r.point.position - ref.c);
    worst = std::max(worst, err / ref.abs_c);
    EXPECT_LE(err, kGkRelative * ref.abs_c) << p.alpha_text << " " << p.lambda;
    if (p.alpha_text == "10/9" && p.lambda >= 10) {
      EXPECT_GE(p.gk, kWrongReferenceFactor * err) << p.lambda;
    }
  }
  std::printf("worst G-K relative error on Appendix B rows: %.3g\n", worst);
}

double worst_appendix_a_error(const lac::AnyQuadrature& m, bool require_ok) {
  const auto rows = lac::p002::reference_set(lac::p002::read_reference(reference_csv()), "appendix_a");
  double worst = 0;
  for (const auto& ref : rows) {
    const lac::LaCurve curve(ref.alpha, ref.lambda);
    const auto r = lac::position_at(curve, lac::Parameter::theta, ref.theta_end, m);
    const double rel = std::abs(r.point.position - ref.c) / ref.abs_c;
    worst = std::max(worst, rel);
    EXPECT_LE(rel, kAppendixATarget) << lac::describe(m) << " alpha=" << ref.alpha_text;
    if (require_ok) {
      EXPECT_EQ(r.status, lac::Status::ok) << lac::describe(m) << " alpha=" << ref.alpha_text;
    }
  }
  return worst;
}

TEST(P002AppendixA, GaussKronrodEndpointsMeetTarget) {
  std::printf("gauss-kronrod tol=1e-14 worst: %.3g\n", worst_appendix_a_error(lac::make_quadrature("gauss-kronrod"), true));
  std::printf("gauss-kronrod tol=1e-8 worst: %.3g\n",
              worst_appendix_a_error(lac::make_quadrature("gauss-kronrod", {std::nullopt, 1e-8}), true));
}

TEST(P002AppendixA, IgfEndpointsMeetTarget) {
  std::printf("igf worst: %.3g\n", worst_appendix_a_error(lac::make_quadrature("igf"), true));
}

TEST(P002Data, RejectsBadInput) {
  EXPECT_THROW(lac::p002::CsvRows::read("/nonexistent/p002.csv"), lac::InputError);
  const auto all = lac::p002::read_reference(reference_csv());
  EXPECT_THROW(lac::p002::find_reference(all, "appendix_b", "7/3", 1.0), lac::InputError);
  EXPECT_DOUBLE_EQ(lac::p002::parse_fraction("4/3"), 4.0 / 3.0);
}

}  // namespace

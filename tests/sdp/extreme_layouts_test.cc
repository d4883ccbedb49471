// Layouts at the edges (issue 22): lengths spread over 1e-150..1e150 (the README's range) and
// vectors that are all within a hair of one line, against 150-digit values
// (tests/support/high_precision_reference.py).

#include <gtest/gtest.h>

#include "vantage/analysis/build_options.h"

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "support/eigen_testing.h"
#include "support/high_precision_reference.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::sdp {
namespace {

namespace reference = testing::reference;

// t of the triad is min |a.n_i| of unit vectors: a few ulps.
constexpr double kTriadT = 1e-15;
// Directions normalised on their own scale are the unit-length layout's to a few ulps, so every
// result agrees with the unit-length layout's to rounding of the search (kSameValue, 1e-14).
constexpr double kSameAsUnitLength = 1e-13;
// p-bar from cross products of unit vectors near a: ~1e-16 absolute, relative to 5e-9 at worst.
constexpr double kPbarRelative = 1e-6;
// Worst-case errors near 90 deg: the absolute rounding of an angle of ~1.57 rad, in degrees,
// plus the relative error of p-bar (the angle is pi/2 - asin p-bar).
constexpr double kNearRightAngleDeg = 1e-9;

LayoutAnalysisOptions with_crosscheck() { return {}; }

TEST(ExtremeLayouts, OrthogonalTriadWithLengthsFrom1e80To1eMinus80) {
  // Issue 22: t = 0.5773270383 was reported certified (t_upper below the true optimum) because a
  // common power of two made the 1e-80 vector's sum of squares subnormal.
  Eigen::Matrix3Xd z = Eigen::Matrix3Xd::Zero(3, 3);
  z(0, 0) = 1e-80;
  z(1, 1) = 1e80;
  z(2, 2) = 1.0;
  const LayoutAnalysis r = analyze_vectors(z, {}, with_crosscheck());
  EXPECT_NEAR(r.t, reference::kTriadT, kTriadT);
  EXPECT_GE(r.certificate.t_upper, reference::kTriadT - kTriadT);
  EXPECT_TRUE(r.certificate.certified);
  EXPECT_TRUE(r.trusted()) << r.message;
  if (built_with_nlopt()) {
    EXPECT_NEAR(r.crosscheck.t, reference::kTriadT, 1e-9);
  }
}

TEST(ExtremeLayouts, LengthsFrom1eMinus150To1e150AreDirections) {
  // A random layout with lengths 10^k, k spread over [-150, 150] (the README's range; 1e-90
  // beside 1e100 was refused as "negligible"): the same answer as the unit-length layout.
  std::mt19937 rng(testing::kSeed + 22);
  Eigen::Matrix3Xd unit = testing::random_points(rng, 9, 1.0);
  for (Eigen::Index i = 0; i < unit.cols(); ++i) unit.col(i).normalize();
  const double exponents[] = {-150, -90, -40, 0, 20, 60, 100, 120, 150};
  Eigen::Matrix3Xd z = unit;
  for (Eigen::Index i = 0; i < z.cols(); ++i) z.col(i) *= std::pow(10.0, exponents[i]);
  const LayoutAnalysis base = analyze_vectors(unit, {}, with_crosscheck());
  const LayoutAnalysis r = analyze_vectors(z, {}, with_crosscheck());
  EXPECT_TRUE(r.trusted()) << r.message;
  EXPECT_NEAR(r.t, base.t, kSameAsUnitLength);
  EXPECT_NEAR(r.pbar_min, base.pbar_min, kSameAsUnitLength);
  EXPECT_EIGEN_NEAR(r.worst_viewpoint, base.worst_viewpoint, 1e-9);
  EXPECT_EIGEN_NEAR(r.worst_case_errors_deg, base.worst_case_errors_deg, 1e-9);
}

TEST(ExtremeLayouts, TwoVectorsAHairApart) {
  // Issue 22: 1e-8 rad apart gave t = 1, p-bar_min = 0, 0 deg, certified, no warning.
  for (const reference::TwoVectorCase& c : reference::kTwoVectors) {
    Eigen::Matrix3Xd z(3, 2);
    z << 1.0, c.x,  //
        0.0, c.y,   //
        0.0, 0.0;
    const LayoutAnalysis r = analyze_vectors(z, {}, with_crosscheck());
    EXPECT_FALSE(r.degenerate) << c.delta;
    EXPECT_NEAR(r.pbar_min, c.pbar_min, kPbarRelative * c.pbar_min) << c.delta;
    EXPECT_NEAR(r.max_worst_case_error_deg, c.max_error_deg, kNearRightAngleDeg) << c.delta;
    // The viewpoint bisects the two: both set p-bar (the second one's Eq. 26 error itself is
    // ill-conditioned at that tie, p / p-bar = 1 - rounding, so it is not compared).
    const Eigen::Vector3d a = r.worst_viewpoint;
    EXPECT_NEAR(a.cross(z.col(0)).norm(), a.cross(z.col(1).normalized()).norm(),
                kPbarRelative * c.pbar_min)
        << c.delta;
    // Near-degenerate exactly when the certificate's width reaches t = 1: p-bar_min^2 / 2 <= 1e-9.
    const bool expected = c.pbar_min * c.pbar_min / (1.0 + r.t) <= 1e-9;
    EXPECT_EQ(r.near_degenerate, expected) << c.delta;
    EXPECT_EQ(r.message.find("near-degenerate") != std::string::npos, expected) << r.message;
  }
  // The criterion splits the cases: 1e-8 and 1e-6 rad are near-degenerate, 1e-4 and 1e-2 not.
  EXPECT_EQ(std::size(reference::kTwoVectors), 4u);
}

TEST(ExtremeLayouts, SixPointsCollinearWithinAHair) {
  for (const reference::CollinearCase& c : reference::kCollinear) {
    Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero(3, 6);
    for (int k = 0; k < 6; ++k) {
      points(0, k) = k;
      points(1, k) = reference::kCollinearOffsets[k] * c.scale;
    }
    Eigen::Matrix3Xd z(3, 15);
    int column = 0;
    for (int i = 0; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) z.col(column++) = points.col(j) - points.col(i);
    }
    const LayoutAnalysis r = analyze_vectors(z, {}, with_crosscheck());
    EXPECT_FALSE(r.degenerate) << c.scale;
    EXPECT_TRUE(r.near_degenerate) << c.scale;  // p-bar_min <= 1.65e-5 < sqrt(2e-9)
    EXPECT_FALSE(r.message.empty());
    EXPECT_NEAR(r.pbar_min, c.pbar_min, kPbarRelative * c.pbar_min) << c.scale;
    EXPECT_NEAR(r.max_worst_case_error_deg, c.max_error_deg, kNearRightAngleDeg) << c.scale;
    EXPECT_GT(r.max_worst_case_error_deg, 89.99);  // never the 0 deg of issue 22
  }
}

TEST(ExtremeLayouts, NearDegenerateCriterionIsTheCertificateWidth) {
  // 1 - t <= tolerance, from p-bar (t itself has rounded to 1 here).
  EXPECT_TRUE(is_near_degenerate(4.4e-5, 1.0, 1e-9));
  EXPECT_FALSE(is_near_degenerate(4.5e-5, 1.0, 1e-9));
  EXPECT_TRUE(is_near_degenerate(4.5e-5, 1.0, 1e-8));  // a looser certificate says less
  EXPECT_FALSE(is_near_degenerate(0.8165, 0.5774, 1e-3));
}

}  // namespace
}  // namespace vantage::sdp

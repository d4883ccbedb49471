// Identification margins of one tool (docs/math.md §24): every number against an independent
// brute force written here (all pairs of pairs; every permutation with an SVD fit, itself
// checked against a numeric fit over rotations).

#include "vantage/tracker/identification.h"
#include "vantage/analysis/common.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "support/message_of.h"

namespace vantage::tracker {
namespace {

using ::testing::HasSubstr;
using testing::kSeed;
using testing::message_of;
using testing::random_points;
using testing::random_rotation;

// The library's fit and the SVD fit below are two exact solutions of one least-squares problem:
// they agree to rounding, amplified by the conditioning of the cross-covariance.
constexpr double kFitTolerance = 1e-9;
// A layout equal to its mirror has mu at rounding level (1e-16 of its size, times a few).
constexpr double kZeroMirror = 1e-12;
// Nelder-Mead over the rotation vector converges to about 1e-10 in the residual here.
constexpr double kNumericFitTolerance = 1e-6;

double distance(const Eigen::Matrix3Xd& p, int i, int j) { return (p.col(i) - p.col(j)).norm(); }

// Brute force of Eq. (24.1): every pair of distinct pairs.
double brute_distance_difference(const Eigen::Matrix3Xd& p, int lost = -1) {
  std::vector<double> d;
  for (int i = 0; i < p.cols(); ++i) {
    for (int j = i + 1; j < p.cols(); ++j) {
      if (i != lost && j != lost) d.push_back(distance(p, i, j));
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < d.size(); ++a) {
    for (std::size_t b = a + 1; b < d.size(); ++b) best = std::min(best, std::abs(d[a] - d[b]));
  }
  return best;
}

// The best improper fit of x onto y by the SVD (Haralick's det guard, flipped): Q = U diag(1, 1,
// s) V^T with det Q = -1.
double svd_improper_rms(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y) {
  const Eigen::Matrix3Xd cx = x.colwise() - x.rowwise().mean();
  const Eigen::Matrix3Xd cy = y.colwise() - y.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cy * cx.transpose(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  const double s = -(svd.matrixU() * svd.matrixV().transpose()).determinant();
  const Eigen::Matrix3d Q =
      svd.matrixU() * Eigen::Vector3d(1.0, 1.0, s).asDiagonal() * svd.matrixV().transpose();
  return std::sqrt((Q * cx - cy).colwise().squaredNorm().sum() / static_cast<double>(x.cols()));
}

// Nelder-Mead over the rotation vector w of Q = R(w) M, translation by the centroids.
double numeric_improper_rms(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y,
                            std::mt19937& rng) {
  Eigen::Matrix3Xd cx = x.colwise() - x.rowwise().mean();
  cx.row(0) = -cx.row(0);
  const Eigen::Matrix3Xd cy = y.colwise() - y.rowwise().mean();
  const auto cost = [&](const Eigen::Vector3d& w) {
    const double angle = w.norm();
    const Eigen::Matrix3d R = angle > 0 ? Eigen::AngleAxisd(angle, w / angle).toRotationMatrix()
                                        : Eigen::Matrix3d::Identity();
    return (R * cx - cy).colwise().squaredNorm().sum();
  };
  double best = std::numeric_limits<double>::infinity();
  std::uniform_real_distribution<double> u(-kPi, kPi);
  for (int start = 0; start < 8; ++start) {
    std::vector<Eigen::Vector3d> simplex(4, Eigen::Vector3d(u(rng), u(rng), u(rng)));
    for (int k = 0; k < 3; ++k) simplex[k + 1](k) += 0.5;
    std::vector<double> f(4);
    for (int k = 0; k < 4; ++k) f[k] = cost(simplex[k]);
    for (int iteration = 0; iteration < 2000; ++iteration) {
      std::vector<int> order(4);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return f[a] < f[b]; });
      const int lo = order[0], hi = order[3], second = order[2];
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) centre += simplex[order[k]] / 3.0;
      const Eigen::Vector3d reflected = centre + (centre - simplex[hi]);
      const double fr = cost(reflected);
      if (fr < f[lo]) {
        const Eigen::Vector3d expanded = centre + 2.0 * (centre - simplex[hi]);
        const double fe = cost(expanded);
        simplex[hi] = fe < fr ? expanded : reflected;
        f[hi] = std::min(fe, fr);
      } else if (fr < f[second]) {
        simplex[hi] = reflected;
        f[hi] = fr;
      } else {
        const Eigen::Vector3d contracted = centre + 0.5 * (simplex[hi] - centre);
        const double fc = cost(contracted);
        if (fc < f[hi]) {
          simplex[hi] = contracted;
          f[hi] = fc;
        } else {
          for (int k = 1; k < 4; ++k) {
            simplex[order[k]] = simplex[lo] + 0.5 * (simplex[order[k]] - simplex[lo]);
            f[order[k]] = cost(simplex[order[k]]);
          }
        }
      }
    }
    best = std::min(best, *std::min_element(f.begin(), f.end()));
  }
  return std::sqrt(best / static_cast<double>(x.cols()));
}

// Brute force of Eq. (24.2): every permutation, each fitted by the SVD.
double brute_mirror_rms(const Eigen::Matrix3Xd& p) {
  std::vector<int> pi(static_cast<std::size_t>(p.cols()));
  std::iota(pi.begin(), pi.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {
    Eigen::Matrix3Xd target(3, p.cols());
    for (int i = 0; i < p.cols(); ++i) target.col(i) = p.col(pi[static_cast<std::size_t>(i)]);
    best = std::min(best, svd_improper_rms(p, target));
  } while (std::next_permutation(pi.begin(), pi.end()));
  return best;
}

TEST(MinDistanceDifference, EqualsEveryPairOfPairs) {
  std::mt19937 rng(kSeed);
  int cases = 0;
  for (int n = 2; n <= 9; ++n) {
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::Matrix3Xd p = random_points(rng, n, 50.0);
      const DistanceDifference got = min_distance_difference(p);
      const double truth = brute_distance_difference(p);
      EXPECT_EQ(got.value, truth) << "n " << n;
      if (std::isinf(truth)) {
        EXPECT_EQ(got.pair_a.first, -1);
        continue;
      }
      ASSERT_LT(got.pair_a.first, got.pair_a.second);
      ASSERT_LT(got.pair_b.first, got.pair_b.second);
      EXPECT_TRUE(got.pair_a < got.pair_b);
      EXPECT_EQ(std::abs(distance(p, got.pair_a.first, got.pair_a.second) -
                         distance(p, got.pair_b.first, got.pair_b.second)),
                truth);
      ++cases;
    }
  }
  EXPECT_EQ(cases, 7 * 5);
}

TEST(MinDistanceDifference, ZeroForEqualDistancesWithThePairsNamed) {
  // A square: four sides of one length (and two equal diagonals).
  Eigen::Matrix3Xd square(3, 4);
  square << 0, 10, 10, 0, 0, 0, 10, 10, 0, 0, 0, 0;
  const DistanceDifference got = min_distance_difference(square);
  EXPECT_EQ(got.value, 0.0);
  EXPECT_EQ(got.pair_a, std::make_pair(0, 1));
  EXPECT_EQ(got.pair_b, std::make_pair(0, 3));
}

TEST(MinMarkerSeparation, EqualsEveryPair) {
  std::mt19937 rng(kSeed + 1);
  const Eigen::Matrix3Xd p = random_points(rng, 8, 30.0);
  double truth = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 8; ++i) {
    for (int j = i + 1; j < 8; ++j) truth = std::min(truth, distance(p, i, j));
  }
  const MarkerSeparation got = min_marker_separation(p);
  EXPECT_EQ(got.value, truth);
  EXPECT_EQ(distance(p, got.pair.first, got.pair.second), truth);
}

TEST(IdentificationMargins, DropoutEqualsTheLayoutWithoutEachMarker) {
  std::mt19937 rng(kSeed + 2);
  for (int n = 3; n <= 8; ++n) {
    const Eigen::Matrix3Xd p = random_points(rng, n, 40.0);
    const IdentificationMargins got = identification_margins(p);
    EXPECT_EQ(got.distance_difference.value, brute_distance_difference(p));
    ASSERT_EQ(got.under_dropout.size(), static_cast<std::size_t>(n));
    double worst = std::numeric_limits<double>::infinity();
    for (int m = 0; m < n; ++m) {
      const DropoutDifference& e = got.under_dropout[static_cast<std::size_t>(m)];
      EXPECT_EQ(e.lost, m);
      const double truth = brute_distance_difference(p, m);
      EXPECT_EQ(e.difference.value, truth) << "n " << n << " lost " << m;
      EXPECT_GE(e.difference.value, got.distance_difference.value);
      if (!std::isinf(truth)) {
        EXPECT_NE(e.difference.pair_a.first, m);
        EXPECT_NE(e.difference.pair_b.second, m);
        EXPECT_EQ(std::abs(distance(p, e.difference.pair_a.first, e.difference.pair_a.second) -
                           distance(p, e.difference.pair_b.first, e.difference.pair_b.second)),
                  truth);
      }
      worst = std::min(worst, truth);
    }
    ASSERT_GE(got.worst_under_dropout, 0);
    EXPECT_EQ(got.under_dropout[static_cast<std::size_t>(got.worst_under_dropout)].difference.value,
              worst);
  }
}

TEST(MirrorFit, SvdFitIsTheNumericOptimumOverRotations) {
  // The brute force's own check: no rotation found numerically beats the SVD fit.
  std::mt19937 rng(kSeed + 3);
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::Matrix3Xd p = random_points(rng, 5, 20.0);
    Eigen::Matrix3Xd y = p;
    std::swap_ranges(y.col(0).data(), y.col(0).data() + 3, y.col(trial + 1).data());
    EXPECT_NEAR(numeric_improper_rms(p, y, rng), svd_improper_rms(p, y), kNumericFitTolerance);
  }
}

TEST(MirrorFit, EqualsEveryPermutationOnRandomTools) {
  std::mt19937 rng(kSeed + 4);
  for (int n = 3; n <= 7; ++n) {
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::Matrix3Xd p = random_points(rng, n, 30.0);
      const MirrorFit got = mirror_fit(p);
      EXPECT_TRUE(got.certified);
      const double truth = brute_mirror_rms(p);
      EXPECT_NEAR(got.rms, truth, kFitTolerance * 30.0) << "n " << n;
      EXPECT_EQ(got.rms_lower, got.rms);
      // The assignment reported gives the rms reported.
      Eigen::Matrix3Xd target(3, n);
      for (int i = 0; i < n; ++i)
        target.col(i) = p.col(got.assignment[static_cast<std::size_t>(i)]);
      EXPECT_NEAR(svd_improper_rms(p, target), got.rms, kFitTolerance * 30.0);
      if (n == 3) {
        EXPECT_LT(got.rms, kZeroMirror * 30.0);  // three points are planar
      }
    }
  }
}

TEST(MirrorFit, ZeroForPlanarAndAchiralToolsPositiveForChiral) {
  std::mt19937 rng(kSeed + 5);
  Eigen::Matrix3Xd planar = random_points(rng, 6, 50.0);
  planar.row(2).setZero();
  const Eigen::Matrix3d R = random_rotation(rng);
  planar = R * planar;
  EXPECT_LT(mirror_fit(planar).rms, kZeroMirror * 50.0);
  EXPECT_TRUE(mirror_fit(planar).own_mirror);
  EXPECT_LT(brute_mirror_rms(planar), kZeroMirror * 50.0);

  // A regular tetrahedron is its own mirror, but not under the identity assignment.
  Eigen::Matrix3Xd tetrahedron(3, 4);
  tetrahedron << 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1, 1;
  tetrahedron = R * (10.0 * tetrahedron);
  const MirrorFit achiral = mirror_fit(tetrahedron);
  EXPECT_LT(achiral.rms, kZeroMirror * 10.0);
  std::vector<int> identity(4);
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_NE(achiral.assignment, identity);
  EXPECT_TRUE(achiral.own_mirror);

  // Four markers at distinct heights off a scalene triangle: chiral.
  Eigen::Matrix3Xd chiral(3, 4);
  chiral << 0, 40, 10, 15, 0, 0, 30, 12, 0, 0, 0, 25;
  const MirrorFit fit = mirror_fit(chiral);
  EXPECT_GT(fit.rms, 1.0);
  EXPECT_FALSE(fit.own_mirror);
  EXPECT_NEAR(fit.rms, brute_mirror_rms(chiral), kFitTolerance * 40.0);
}

TEST(MirrorFit, OutOfBudgetBracketsTheTruth) {
  std::mt19937 rng(kSeed + 6);
  const Eigen::Matrix3Xd p = random_points(rng, 7, 30.0);
  const double truth = brute_mirror_rms(p);
  MirrorFitOptions options;
  options.max_comparisons = 10;
  const MirrorFit got = mirror_fit(p, options);
  EXPECT_FALSE(got.certified);
  EXPECT_GE(got.rms, truth - kFitTolerance * 30.0);
  EXPECT_LE(got.rms_lower, truth + kFitTolerance * 30.0);
  EXPECT_LT(got.rms_lower, got.rms);
}

TEST(IdentificationMargins, RejectsTooFewOrNonFinitePoints) {
  EXPECT_THAT(message_of([] { identification_margins(Eigen::Matrix3Xd::Zero(3, 2)); }),
              HasSubstr("points"));
  Eigen::Matrix3Xd p = Eigen::Matrix3Xd::Identity(3, 3);
  p(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message_of([&] { identification_margins(p); }), HasSubstr("points[2]"));
  IdentificationOptions options;
  options.mirror.max_comparisons = 0;
  EXPECT_THAT(
      message_of([&] { identification_margins(Eigen::Matrix3Xd::Identity(3, 3), options); }),
      HasSubstr("options.mirror.max_comparisons"));
}

}  // namespace
}  // namespace vantage::tracker

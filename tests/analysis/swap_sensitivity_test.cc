#include "vantage/analysis/swap_sensitivity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "support/message_of.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::kSeed;

// Incremental (Eq. 10) and recomputed D give the same rotation up to eigenvector rounding.
constexpr double kDegrees = 1e-6;

TEST(SwapSensitivity, IncrementalEqualsRecomputedForAnyTrueRotation) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 10; ++trial) {
    const int m = 3 + trial;
    const Eigen::Matrix3Xd z = testing::random_points(rng, m);
    Eigen::VectorXd w = Eigen::VectorXd::Random(m).cwiseAbs().array() + 0.5;
    const std::vector<SwapError> worst = swap_sensitivity(z, w, 1000);
    ASSERT_EQ(static_cast<int>(worst.size()), m * (m - 1) / 2);
    for (size_t k = 1; k < worst.size(); ++k) EXPECT_GE(worst[k - 1].error_deg, worst[k].error_deg);
    // Recompute each swap from scratch with a random true rotation and scale.
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    for (const SwapError& s : worst) {
      Eigen::Matrix3Xd v = R * z / 1.7;
      v.col(s.i).swap(v.col(s.j));
      const OrientationResult r = absolute_orientation(z, v, w);
      EXPECT_NEAR(rotation_angle_between(r.R_camera_object, R) * kDegreesPerRadian, s.error_deg,
                  kDegrees)
          << "pair " << s.i << ", " << s.j;
    }
  }
}

TEST(SwapSensitivity, TriadSwapsAreAmbiguous) {
  // Z = I, swapping e1 and e2: D' = diag(-2 u u^T, 0) with u = e2 - e1 has the top eigenvalue 0
  // three times (identity and two half turns are all optimal): worst case 180 degrees.
  const std::vector<SwapError> swaps = swap_sensitivity(Eigen::Matrix3d::Identity(), {}, 3);
  ASSERT_EQ(swaps.size(), 3u);
  for (const SwapError& s : swaps) {
    EXPECT_TRUE(s.ambiguous) << s.i << " " << s.j;
    EXPECT_EQ(s.error_deg, 180.0);
  }
}

TEST(SwapSensitivity, WellDeterminedSwapsLeaveTheRotation) {
  // Many well-spread vectors: swapping two keeps R = I the unique optimum (error exactly 0).
  std::mt19937 rng(kSeed + 3);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 12);
  const std::vector<SwapError> swaps = swap_sensitivity(z, {}, 66);
  int unchanged = 0;
  for (const SwapError& s : swaps) {
    if (!s.ambiguous && s.error_deg < 1e-6) ++unchanged;
    if (!s.ambiguous) {
      Eigen::Matrix3Xd v = z;
      v.col(s.i) = z.col(s.j);
      v.col(s.j) = z.col(s.i);
      const OrientationResult direct = absolute_orientation(z, v);
      EXPECT_NEAR(rotation_angle_between(direct.R_camera_object, Eigen::Matrix3d::Identity()) *
                      kDegreesPerRadian,
                  s.error_deg, kDegrees);
    }
  }
  EXPECT_GT(unchanged, 0);
}

TEST(SwapSensitivity, WorstFiveAndEdgeCases) {
  std::mt19937 rng(kSeed + 1);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 8);
  const std::vector<SwapError> five = swap_sensitivity(z);
  ASSERT_EQ(five.size(), 5u);
  const std::vector<SwapError> all = swap_sensitivity(z, {}, 100);
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(five[k].i, all[k].i);
    EXPECT_EQ(five[k].j, all[k].j);
    EXPECT_LT(five[k].i, five[k].j);
  }
  // Swapping identical vectors changes nothing.
  Eigen::Matrix3Xd twins(3, 3);
  twins << Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 1, 0);
  const std::vector<SwapError> t = swap_sensitivity(twins, {}, 3);
  bool found = false;
  for (const SwapError& s : t) {
    if (s.i == 0 && s.j == 1) {
      found = true;
      EXPECT_NEAR(s.error_deg, 0.0, kDegrees);
    }
    EXPECT_TRUE(std::isfinite(s.error_deg));
  }
  EXPECT_TRUE(found);
}

TEST(SwapSensitivity, BadInputThrowsNamingTheArgument) {
  std::mt19937 rng(kSeed + 2);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 4);
  using ::testing::HasSubstr;
  using testing::message_of;
  EXPECT_THAT(message_of([] { swap_sensitivity(Eigen::Matrix3Xd(3, 1)); }),
              HasSubstr("z: need at least 2 columns, got 1"));
  EXPECT_THAT(message_of([&] { swap_sensitivity(z, Eigen::VectorXd::Ones(3)); }),
              HasSubstr("weights: has 3 entries, expected 4"));
  Eigen::VectorXd negative = Eigen::VectorXd::Ones(4);
  negative(2) = -1.0;
  EXPECT_THAT(message_of([&] { swap_sensitivity(z, negative); }),
              HasSubstr("weights[2]: must be positive and finite"));
  Eigen::Matrix3Xd nan = z;
  nan(0, 3) = std::nan("");
  EXPECT_THAT(message_of([&] { swap_sensitivity(nan); }), HasSubstr("z[3]: not finite"));
  EXPECT_THAT(message_of([&] { swap_sensitivity(z, {}, 0); }), HasSubstr("count: must be >= 1"));
}

// Every pair by the eigensolver, as swap_sensitivity() did before it screened pairs: the
// reference for the screen that proves a swap leaves R = I without one.
std::vector<SwapError> every_pair_by_eigensolver(const Eigen::Matrix3Xd& z,
                                                 const Eigen::VectorXd& w) {
  const Eigen::Matrix4d D = orientation_matrix_d(z, z, w);
  std::vector<SwapError> all;
  for (int i = 0; i < z.cols(); ++i) {
    for (int j = i + 1; j < z.cols(); ++j) {
      const Eigen::Matrix4d swapped =
          D + swap_delta_d(z.col(i), z.col(j), z.col(i), z.col(j), w.size() ? w(i) : 1.0,
                           w.size() ? w(j) : 1.0);
      const TopEigenpair top = top_eigenpair(swapped);
      if (!(top.gap > kSwapAmbiguousGap * swapped.norm())) {
        all.push_back({i, j, 180.0, true});
        continue;
      }
      const double angle =
          rotation_angle_between(rotation_from_quaternion(top.vector), Eigen::Matrix3d::Identity());
      all.push_back({i, j, angle * kDegreesPerRadian, false});
    }
  }
  std::sort(all.begin(), all.end(), [](const SwapError& a, const SwapError& b) {
    if (a.error_deg != b.error_deg) return a.error_deg > b.error_deg;
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  return all;
}

TEST(SwapSensitivity, ScreenedPairsAreBitIdenticalToTheEigensolver) {
  // Unit weights (the screen decides most pairs, or all at once for many directions), random
  // weights (it decides none: the last column of Delta D is then not zero), a triad plus points
  // (ambiguous and large swaps), and free vectors of a point layout (long and short vectors).
  std::mt19937 rng(kSeed + 60);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::Matrix3Xd z = testing::random_points(rng, 40 + 10 * trial);
    if (trial == 4) {
      // Many unit directions: the bound over all pairs decides them at once.
      z.resize(3, 300);
      for (int i = 0; i < 300; ++i) z.col(i) = testing::random_unit_vector(rng);
    }
    Eigen::VectorXd w;
    if (trial == 1) w = Eigen::VectorXd::Random(z.cols()).cwiseAbs().array() + 0.5;
    if (trial == 2) z.leftCols(3) = Eigen::Matrix3d::Identity();
    if (trial == 3) {
      for (int i = 1; i < z.cols(); ++i) z.col(i) -= z.col(0) * (i % 3);
    }
    const int pairs = static_cast<int>(z.cols() * (z.cols() - 1) / 2);
    const std::vector<SwapError> fast = swap_sensitivity(z, w, pairs);
    const std::vector<SwapError> reference = every_pair_by_eigensolver(z, w);
    ASSERT_EQ(fast.size(), reference.size());
    for (std::size_t k = 0; k < fast.size(); ++k) {
      EXPECT_EQ(fast[k].i, reference[k].i) << "trial " << trial << " rank " << k;
      EXPECT_EQ(fast[k].j, reference[k].j) << "trial " << trial << " rank " << k;
      EXPECT_EQ(fast[k].error_deg, reference[k].error_deg) << "trial " << trial << " rank " << k;
      EXPECT_EQ(fast[k].ambiguous, reference[k].ambiguous) << "trial " << trial << " rank " << k;
    }
    // The worst five are the first five of the full ranking.
    const std::vector<SwapError> five = swap_sensitivity(z, w, 5);
    ASSERT_EQ(five.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
      EXPECT_EQ(five[k].i, reference[k].i);
      EXPECT_EQ(five[k].j, reference[k].j);
    }
  }
}

}  // namespace
}  // namespace vantage

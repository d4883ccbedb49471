// With and without NLopt (VANTAGE_WITH_NLOPT): the library knows which it was built with, and
// minimize_affine_residual either runs or says that it did not, after checking its input in
// both builds.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "affine_testing.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

// Noise-free data: the direct minimisation reaches J_2d = 0 up to BOBYQA's step tolerance
// (1e-13 rad), i.e. to rounding of the squared residual.
constexpr double kNoiseFreeResidual = 1e-12;

TEST(NloptBuild, LibraryAgreesWithTheBuildOption) {
  // VANTAGE_WITH_NLOPT comes from CMake (the option), built_with_nlopt() from the compiled
  // library: a test suite linked against a library of the other configuration fails here.
  EXPECT_EQ(built_with_nlopt(), VANTAGE_WITH_NLOPT != 0);
  EXPECT_STREQ(kWithoutNlopt, "built without NLopt");
}

TEST(NloptBuild, AffineCrossCheckRunsOrSaysItDidNot) {
  std::mt19937 rng(testing::kSeed + 40);
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 5);
  const Eigen::Matrix2Xd d = testing::affine_image(R, z, 2.0);
  const AffineCrossCheckResult direct = minimize_affine_residual(z, d, 2.0);
  if (built_with_nlopt()) {
    EXPECT_EQ(direct.skipped, "");
    EXPECT_LT(direct.residual, kNoiseFreeResidual);
    EXPECT_GT(direct.evaluations, 0);
  } else {
    EXPECT_EQ(direct.skipped, kWithoutNlopt);
    EXPECT_TRUE(std::isnan(direct.residual)) << "nothing ran, so there is no residual";
    EXPECT_EQ(direct.evaluations, 0);
  }
}

TEST(NloptBuild, AffineCrossCheckChecksItsInputEitherWay) {
  Eigen::Matrix3Xd z(3, 4);
  z << Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.3, -0.7, 0.2);
  const Eigen::Matrix2Xd d = z.topRows<2>();
  EXPECT_THROW(minimize_affine_residual(z, d, -1.0), InvalidArgument);
  EXPECT_THROW(minimize_affine_residual(z, d.leftCols(3), 1.0), InvalidArgument);
  AffineCrossCheckOptions bad;
  bad.starts = 0;
  EXPECT_THROW(minimize_affine_residual(z, d, 1.0, {}, bad), InvalidArgument);
}

}  // namespace
}  // namespace vantage

// The workspace's own lattice (docs/math.md §20, "Coverage"; issue 36, item 4): the sphere's
// Fibonacci lattice without a workspace, and on a cap equal-area points all inside it, so that a
// small workspace is sampled as densely as it needs.

#include "vantage/visibility/workspace_lattice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/visibility/visibility.h"

namespace vantage::visibility {
namespace {

// A spiral of M equal-area points puts k of them in a concentric sub-cap of area share s with
// |k - s M| below a couple of points (its rows are ordered along the axis).
constexpr double kSpiralPoints = 2.0;

Workspace cap(const Eigen::Vector3d& axis, double half_angle_deg) {
  return Workspace{axis.normalized(), std::cos(half_angle_deg / kDegreesPerRadian)};
}

TEST(WorkspaceLattice, WithoutAWorkspaceItIsTheSpheresLattice) {
  const WorkspaceLattice whole = workspace_lattice(std::nullopt, 2000);
  EXPECT_EQ(whole.directions, fibonacci_directions(2000));
  EXPECT_DOUBLE_EQ(whole.spacing, std::sqrt(4.0 * kPi / 2000));
  const WorkspaceLattice sphere =
      workspace_lattice(Workspace{Eigen::Vector3d::UnitX(), -1.0}, 2000);
  EXPECT_EQ(sphere.directions, fibonacci_directions(2000));
}

TEST(WorkspaceLattice, CapsOfEverySizeAreSampledInsideAndByArea) {
  const Eigen::Vector3d axis(0.3, -0.2, 0.9);
  for (double half_angle : {0.2, 3.0, 30.0, 75.0, 170.0}) {
    SCOPED_TRACE(half_angle);
    const Workspace w = cap(axis, half_angle);
    const WorkspaceLattice lattice = workspace_lattice(w, 20000);
    const double share = (1.0 - w.cos_half_angle) / 2.0;
    const auto m = static_cast<double>(lattice.directions.cols());
    EXPECT_EQ(m, std::max(std::ceil(20000 * share), 100.0));
    // The sub-cap of half the angle holds its share of the cap's area (exact: 1 - cos).
    const double inner_cos = std::cos(half_angle / 2.0 / kDegreesPerRadian);
    const double inner_share = (1.0 - inner_cos) / (1.0 - w.cos_half_angle);
    int inner = 0;
    for (Eigen::Index k = 0; k < lattice.directions.cols(); ++k) {
      const Eigen::Vector3d a = lattice.directions.col(k);
      EXPECT_NEAR(a.norm(), 1.0, 1e-15);
      EXPECT_GE(a.dot(w.axis), w.cos_half_angle) << k;
      inner += a.dot(w.axis) >= inner_cos;
    }
    EXPECT_NEAR(inner, inner_share * m, kSpiralPoints);
  }
}

// Four markers facing +z with 1-degree cones, seen together exactly from the directions within
// 1 degree of +z; the workspace is the 2-degree cap about +z. The trackable share is the area
// ratio (1 - cos 1) / (1 - cos 2), about 1/4. The sphere's 20 000-point lattice has 6 points in
// that workspace (it reported 2/6 or so); a 0.2-degree workspace got none and reported 0.
TEST(VisibilityCoverage, SmallWorkspacesAreSampledOnTheirOwnCap) {
  VisibilityProblem p;
  p.points.resize(3, 4);
  p.points << 0, 1, 0, 1,  //
      0, 0, 1, 1,          //
      0, 0, 0, 0.5;
  p.normals = Eigen::Matrix3Xd::Zero(3, 4);
  p.normals.row(2).setOnes();
  p.cos_cone = Eigen::VectorXd::Constant(4, std::cos(1.0 / kDegreesPerRadian));
  p.workspace = cap(Eigen::Vector3d::UnitZ(), 2.0);
  const VisibilityCoverage c = visibility_coverage(p, 20000);
  EXPECT_EQ(c.samples, 100);
  const double exact =
      (1.0 - std::cos(1.0 / kDegreesPerRadian)) / (1.0 - std::cos(2.0 / kDegreesPerRadian));
  EXPECT_NEAR(c.trackable_fraction, exact, kSpiralPoints / c.samples);

  p.cos_cone.setConstant(0.0);
  p.workspace = cap(Eigen::Vector3d(1.0, 1.0, 1.0), 0.2);
  const VisibilityCoverage tiny = visibility_coverage(p, 20000);
  EXPECT_EQ(tiny.samples, 100);
  EXPECT_EQ(tiny.trackable_fraction, 1.0);
}

}  // namespace
}  // namespace vantage::visibility

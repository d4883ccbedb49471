// Where markers may go (docs/math.md §21, "Sites" and "Where markers may go"): normals turned
// outward one site at a time, keep-out volumes with a clearance, and the sites they drop; the
// truth is the geometry of boxes, written here.

#include "vantage/design/site_filters.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "support/cube_mesh.h"
#include "vantage/analysis/common.h"
#include "vantage/design/placement.h"

namespace vantage::design {
namespace {

// The unit cube mapped onto the box [lo, hi].
Mesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Mesh mesh = testing::unit_cube();
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    mesh.vertices.col(v) = lo + (hi - lo).cwiseProduct(mesh.vertices.col(v));
  }
  return mesh;
}

// Every other triangle wound the other way: no consistent winding, signed volume zero.
Mesh half_flipped(Mesh mesh) {
  for (Eigen::Index t = 1; t < mesh.triangles.cols(); t += 2) {
    std::swap(mesh.triangles(1, t), mesh.triangles(2, t));
  }
  return mesh;
}

TEST(SiteNormals, PointOutOfTheCubeWhateverTheWinding) {
  // On the unit cube, a site's outward normal is its face's: n . (p - centre) = 1/2.
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5);
  for (const Mesh& mesh : {testing::unit_cube(), half_flipped(testing::unit_cube())}) {
    const SurfaceSites sites = sample_surface_sites(mesh, 300, 0.0, 3);
    ASSERT_EQ(sites.points.cols(), 300);
    for (Eigen::Index i = 0; i < sites.points.cols(); ++i) {
      EXPECT_NEAR(sites.normals.col(i).dot(sites.points.col(i) - centre), 0.5, 1e-12) << i;
    }
  }
}

TEST(SiteNormals, TurnedOutwardWhenGivenInward) {
  // outward_normals() on its own: every normal given pointing into the cube comes back out.
  const Mesh cube = testing::unit_cube();
  const SurfaceSites sites = sample_surface_sites(cube, 100, 0.0, 4);
  const Eigen::Matrix3Xd out = outward_normals(cube, sites.points, -sites.normals);
  EXPECT_TRUE(out.isApprox(sites.normals));
  EXPECT_THROW(outward_normals(cube, sites.points, sites.normals.leftCols(3)), InvalidArgument);
}

// A motor pod under its propeller (scripts/make_quadrotor.py's shape): a box open at the bottom,
// [-1, 1]^2 x [0, 2], and a single-sided square sheet 0.2 above its top, three times as wide.
// Every ray up from the pod's top meets the sheet and many rays down from under it leave through
// the open bottom, so the rays alone turn the top's normal in; the pod holds a volume (its patch
// is cup-like), which turns it out.
Mesh pod_under_a_disc() {
  Mesh pod = box(Eigen::Vector3d(-1.0, -1.0, 0.0), Eigen::Vector3d(1.0, 1.0, 2.0));
  // The unit cube's first two triangles are its z = 0 face.
  const Eigen::Matrix3Xi walls = pod.triangles.rightCols(10);
  Mesh mesh;
  mesh.vertices.resize(3, 12);
  mesh.vertices.leftCols(8) = pod.vertices;
  mesh.vertices.rightCols(4) << -3, 3, 3, -3, -3, -3, 3, 3, 2.2, 2.2, 2.2, 2.2;
  mesh.triangles.resize(3, 12);
  mesh.triangles.leftCols(10) = walls;
  mesh.triangles.rightCols(2) << 8, 8, 9, 10, 10, 11;
  return mesh;
}

TEST(SiteNormals, APodUnderADiscFacesOutAllRound) {
  const Mesh mesh = pod_under_a_disc();
  const SurfaceSites sites = sample_surface_sites(mesh, 400, 0.0, 5);
  Eigen::Matrix3Xd top(3, 0);
  int on_pod = 0;
  for (Eigen::Index i = 0; i < sites.points.cols(); ++i) {
    const Eigen::Vector3d p = sites.points.col(i);
    if (p.z() > 2.1) continue;  // the sheet: either side is outside
    ++on_pod;
    // The pod's outward normal: its face's, away from the box's axis or up at the top.
    Eigen::Vector3d expected = Eigen::Vector3d::UnitZ();
    if (p.z() < 2.0 - 1e-12) {
      expected = std::abs(p.x()) > std::abs(p.y()) ? Eigen::Vector3d(p.x() > 0 ? 1 : -1, 0, 0)
                                                   : Eigen::Vector3d(0, p.y() > 0 ? 1 : -1, 0);
    } else {
      top.conservativeResize(3, top.cols() + 1);
      top.col(top.cols() - 1) = p;
    }
    EXPECT_TRUE(sites.normals.col(i).isApprox(expected, 1e-12))
        << i << ": " << sites.normals.col(i).transpose() << " at " << p.transpose();
  }
  ASSERT_GT(on_pod, 100);
  ASSERT_GT(top.cols(), 10);
  // The rays alone get the top wrong (the case this rule is for).
  const Eigen::Matrix3Xd by_rays =
      outward_normals(mesh, top, Eigen::Vector3d::UnitZ().replicate(1, top.cols()));
  EXPECT_LT(by_rays.row(2).minCoeff(), 0.0);
}

TEST(KeepOut, InsideOrWithinTheClearance) {
  constexpr double kClearance = 0.1;
  const KeepOut cube(testing::unit_cube(), kClearance);
  EXPECT_TRUE(cube.excludes({0.5, 0.5, 0.5}));     // inside, at the centre
  EXPECT_TRUE(cube.excludes({0.97, 0.2, 0.6}));    // inside, near a face
  EXPECT_TRUE(cube.excludes({1.05, 0.5, 0.5}));    // outside, within the clearance
  EXPECT_TRUE(cube.excludes({-0.06, 1.06, 0.5}));  // off an edge, 0.085 away
  EXPECT_FALSE(cube.excludes({1.2, 0.5, 0.5}));
  EXPECT_FALSE(cube.excludes({-0.08, 1.08, 0.5}));  // off an edge, 0.113 away
  EXPECT_FALSE(cube.excludes({3.0, 3.0, 3.0}));
  EXPECT_THROW(KeepOut(testing::unit_cube(), -1.0), InvalidArgument);
}

TEST(KeepOut, DropsExactlyTheSitesWithinTheClearance) {
  // Sites on the box [0,2]x[0,1]x[0,1]; the keep-out box covers x <= 1.5 beyond the other
  // faces, so a site's distance to it is x - 1.5 when x > 1.5: dropped iff x <= 1.5 + clearance.
  constexpr double kClearance = 0.05;
  const Mesh body = box({0, 0, 0}, {2, 1, 1});
  const SurfaceSites all = sample_surface_sites(body, 400, 0.0, 5);
  std::vector<KeepOut> volumes;
  volumes.emplace_back(box({-1, -1, -1}, {1.5, 2, 2}), kClearance);
  SurfaceSites kept = all;
  const int dropped = drop_excluded_sites(volumes, &kept);
  int expected = 0;
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < all.points.cols(); ++i) {
    if (all.points(0, i) <= 1.5 + kClearance) {
      ++expected;
      continue;
    }
    ASSERT_LT(k, kept.points.cols());
    EXPECT_EQ(kept.points.col(k), all.points.col(i));
    EXPECT_EQ(kept.normals.col(k), all.normals.col(i));
    EXPECT_EQ(kept.triangles[static_cast<std::size_t>(k)],
              all.triangles[static_cast<std::size_t>(i)]);
    ++k;
  }
  EXPECT_EQ(dropped, expected);
  EXPECT_EQ(kept.points.cols(), k);
  EXPECT_GT(dropped, 0);
  EXPECT_GT(k, 0);
}

}  // namespace
}  // namespace vantage::design

// Markers snapped onto a body (docs/math.md §21, "Snapping a layout to its body"): the truth is
// the geometry of a box (the nearest point of its surface, written here from its faces) and, on a
// tetrahedron, the nearest of many surface points sampled here.

#include "vantage/design/surface_snap.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <random>

#include "support/box_mesh.h"
#include "vantage/analysis/common.h"

namespace vantage::design {
namespace {

// Coordinates of a few units: the closest-point arithmetic rounds at a few ulps.
constexpr double kExact = 1e-12;

const Eigen::Vector3d kLo(-1.0, -0.5, 0.0), kHi(1.0, 0.5, 0.25);

// The nearest point of the box's surface to x, and the outward axis of the face it is on (for x
// in a face's region: inside the box, or outside past exactly one face).
std::pair<Eigen::Vector3d, Eigen::Vector3d> box_truth(const Eigen::Vector3d& x) {
  Eigen::Vector3d q = x.cwiseMax(kLo).cwiseMin(kHi);
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  if (q != x) {
    for (int c = 0; c < 3; ++c) n(c) = x(c) > kHi(c) ? 1.0 : x(c) < kLo(c) ? -1.0 : 0.0;
    return {q, n};
  }
  double best = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c) {
    for (int side = 0; side < 2; ++side) {
      const double face = side ? kHi(c) : kLo(c);
      if (std::abs(x(c) - face) < best) {
        best = std::abs(x(c) - face);
        q = x;
        q(c) = face;
        n = Eigen::Vector3d::Zero();
        n(c) = side ? 1.0 : -1.0;
      }
    }
  }
  return {q, n};
}

// Every other triangle wound the other way.
Mesh half_flipped(Mesh mesh) {
  for (Eigen::Index t = 1; t < mesh.triangles.cols(); t += 2) {
    std::swap(mesh.triangles(1, t), mesh.triangles(2, t));
  }
  return mesh;
}

// Points in the box or outside past one face only, at least 0.02 from being equally near two
// faces, so that the nearest face is unique.
Eigen::Matrix3Xd face_region_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.4, 1.4);
  Eigen::Matrix3Xd out(3, n);
  int k = 0;
  while (k < n) {
    const Eigen::Vector3d x(u(rng), 0.5 * u(rng), 0.125 + 0.3 * u(rng));
    int outside = 0;
    for (int c = 0; c < 3; ++c) outside += x(c) > kHi(c) || x(c) < kLo(c);
    if (outside > 1) continue;
    if (outside == 0) {
      std::vector<double> gaps;
      for (int c = 0; c < 3; ++c) {
        gaps.push_back(x(c) - kLo(c));
        gaps.push_back(kHi(c) - x(c));
      }
      std::sort(gaps.begin(), gaps.end());
      if (gaps[1] - gaps[0] < 0.02) continue;
    } else {
      bool near_edge = false;
      for (int c = 0; c < 3; ++c) {
        const bool inside_c = x(c) <= kHi(c) && x(c) >= kLo(c);
        if (inside_c && std::min(x(c) - kLo(c), kHi(c) - x(c)) < 0.02) near_edge = true;
      }
      if (near_edge) continue;
    }
    out.col(k++) = x;
  }
  return out;
}

TEST(SurfaceSnap, NearestFacePointAndItsOutwardNormalWhateverTheWinding) {
  const Eigen::Matrix3Xd points = face_region_points(200, 5);
  const Mesh box = testing::box_mesh(kLo, kHi);
  for (const Mesh& mesh : {box, half_flipped(box)}) {
    const SurfaceSnap snap = snap_to_surface(mesh, points, 0.0);
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
      const auto [q, n] = box_truth(points.col(i));
      EXPECT_LT((snap.surface.col(i) - q).norm(), kExact) << i;
      EXPECT_LT((snap.normals.col(i) - n).norm(), kExact) << i;
      EXPECT_EQ(snap.centres.col(i), snap.surface.col(i)) << i;
      EXPECT_NEAR(snap.moved(i), (q - points.col(i)).norm(), kExact) << i;
    }
  }
}

TEST(SurfaceSnap, ASphereRestsOnTheFaceItsCentreHalfTheDiameterOut) {
  const Eigen::Matrix3Xd points = face_region_points(50, 6);
  const double d = 0.03;
  const SurfaceSnap snap = snap_to_surface(testing::box_mesh(kLo, kHi), points, d);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const auto [q, n] = box_truth(points.col(i));
    const Eigen::Vector3d centre = q + 0.5 * d * n;
    EXPECT_LT((snap.centres.col(i) - centre).norm(), kExact) << i;
    // Outside the box, half the diameter from its surface: the sphere touches, never enters.
    const Eigen::Vector3d gap = (centre - centre.cwiseMax(kLo).cwiseMin(kHi));
    EXPECT_NEAR(gap.norm(), 0.5 * d, kExact) << i;
  }
}

TEST(SurfaceSnap, OffACornerTheNormalIsOneOfTheFacesThatMeetThere) {
  Eigen::Matrix3Xd points(3, 2);
  points << 1.3, -1.2,  //
      0.9, -0.7,        //
      0.6, 0.1;
  const SurfaceSnap snap = snap_to_surface(testing::box_mesh(kLo, kHi), points, 0.0);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const auto [q, signs] = box_truth(points.col(i));
    EXPECT_LT((snap.surface.col(i) - q).norm(), kExact) << i;
    const Eigen::Vector3d n = snap.normals.col(i);
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, kExact) << i;  // an axis
    Eigen::Index axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    EXPECT_EQ(n(axis), signs(axis)) << i;  // a face of the corner, pointing out
  }
}

TEST(SurfaceSnap, NoSampledSurfacePointIsNearerThanTheSnappedOne) {
  // A tetrahedron, not axis-aligned: 40 000 points drawn on its faces here.
  Mesh tet;
  tet.vertices.resize(3, 4);
  tet.vertices << 0.1, 1.3, -0.4, 0.2,  //
      -0.2, 0.3, 0.9, 0.1,              //
      0.0, 0.1, 0.2, 1.1;
  tet.triangles.resize(3, 4);
  tet.triangles << 0, 0, 0, 1,  //
      1, 1, 2, 2,               //
      2, 3, 3, 3;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::Matrix3Xd samples(3, 40000);
  for (Eigen::Index s = 0; s < samples.cols(); ++s) {
    const Eigen::Index t = s % 4;
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Eigen::Vector3d p0 = tet.vertices.col(tet.triangles(0, t));
    samples.col(s) = p0 + a * (tet.vertices.col(tet.triangles(1, t)) - p0) +
                     b * (tet.vertices.col(tet.triangles(2, t)) - p0);
  }
  std::uniform_real_distribution<double> box(-1.0, 1.5);
  Eigen::Matrix3Xd points(3, 30);
  for (Eigen::Index i = 0; i < points.cols(); ++i) points.col(i) << box(rng), box(rng), box(rng);
  const SurfaceSnap snap = snap_to_surface(tet, points, 0.0);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const double sampled = (samples.colwise() - points.col(i)).colwise().norm().minCoeff();
    const double snapped = (snap.surface.col(i) - points.col(i)).norm();
    EXPECT_LE(snapped, sampled + kExact) << i;
    EXPECT_LT(sampled - snapped, 0.02) << i;  // the samples are about 0.01 apart
  }
}

TEST(SurfaceSnap, SliversHaveNoNormalAndAreSkipped) {
  // A flat sliver right at the point and a real triangle farther away: the real one wins.
  Mesh mesh;
  mesh.vertices.resize(3, 6);
  mesh.vertices << 0, 1, 2, -1, 1, 0,  //
      0, 0, 0, -1, -1, 1,              //
      0, 0, 0, -1, -1, -1;
  mesh.triangles.resize(3, 2);
  mesh.triangles << 0, 3,  //
      1, 4,                //
      2, 5;
  const MeshPoint nearest = nearest_mesh_point(mesh, Eigen::Vector3d(0.5, 0.0, 0.0));
  EXPECT_EQ(nearest.triangle, 1);
  EXPECT_NEAR(nearest.point.z(), -1.0, kExact);
  EXPECT_NEAR(std::abs(nearest.normal.z()), 1.0, kExact);
  mesh.triangles.conservativeResize(3, 1);
  EXPECT_EQ(nearest_mesh_point(mesh, Eigen::Vector3d::Zero()).triangle, -1);
  EXPECT_THROW(snap_to_surface(mesh, Eigen::Matrix3Xd::Zero(3, 1), 0.0), InvalidArgument);
}

TEST(SurfaceSnap, TheLayoutKeepsWhatItSaysAndRefusesVectors) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 3);
  layout.entries << 0.0, 0.5, -0.5,  //
      0.0, 0.1, -0.1,                //
      0.3, 0.3, 0.3;
  layout.weights = Eigen::Vector3d(1.0, 2.0, 3.0);
  layout.names = {"a", "b", "c"};
  layout.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 60.0};
  layout.placement = LayoutPlacement{};
  const Mesh box = testing::box_mesh(kLo, kHi);
  const SurfaceSnap snap = snap_to_surface(box, layout.entries, 0.01);
  const Layout out = snapped_layout(layout, snap, box, "box.obj");
  EXPECT_EQ(out.entries, snap.centres);
  EXPECT_EQ(out.weights, layout.weights);
  EXPECT_EQ(out.names, layout.names);
  ASSERT_TRUE(out.workspace);
  EXPECT_EQ(out.workspace->half_angle_deg, 60.0);
  EXPECT_FALSE(out.placement);
  ASSERT_TRUE(out.visibility);
  EXPECT_EQ(out.visibility->normals, snap.normals);
  EXPECT_EQ(out.visibility->cone_half_angle_deg,
            Eigen::VectorXd::Constant(3, MarkerVisibility::kDefaultConeDeg));
  EXPECT_EQ(out.visibility->body_path, "box.obj");
  for (Eigen::Index i = 0; i < 3; ++i) {
    EXPECT_NEAR(out.entries(2, i), kHi.z() + 0.005, kExact);  // on the top face
  }
  Layout vectors = layout;
  vectors.mode = LayoutMode::kVectors;
  EXPECT_THROW(snapped_layout(vectors, snap, box, "box.obj"), InvalidArgument);
  EXPECT_THROW(snap_to_surface(box, layout.entries, -1.0), InvalidArgument);
}

}  // namespace
}  // namespace vantage::design

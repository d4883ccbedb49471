// The viewer's visibility readout (which markers a viewpoint sees, the error they leave, the lost
// part of the sphere) against an independent test of docs/math.md §20's model: the dot product
// with each marker's normal for its cone, and a brute-force ray-triangle test over the body mesh
// for occlusion, evaluated here with no code of the library.

#include "vantage/viewer/visibility_readout.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"
#include "vantage/viewer/viewer_session.h"

namespace vantage::viewer {
namespace {

const std::string kSatellite = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/satellite.json";

// Rays leave a marker at p + kRayOffset * size(mesh) * normal, as docs/math.md §20 states, so a
// marker on a face does not shadow itself.
constexpr double kRayOffset = 1e-6;
// A marker's cone test is compared only when n.a is this far from cos(theta): the library and
// this test round the same dot product differently at the edge.
constexpr double kConeMargin = 1e-9;
// The occlusion grid answers with the ray of the cell that holds a (cells of at most the
// resolution, 1 degree); a direction is compared only where the brute-force answer is the same
// at a and at 8 directions this far from it (1.5 cells): away from every shadow's edge.
constexpr double kShadowProbeDeg = 1.5;
// Möller-Trumbore's determinant below this counts as a ray parallel to the triangle.
constexpr double kParallel = 1e-14;
// t(a) from the pairs here and in the library: the same products, summed in another order.
constexpr double kRounding = 1e-12;
// The seen-whole and visibility errors at one viewpoint, asin t in degrees: rounding only.
constexpr double kDegRounding = 1e-9;
constexpr int kDirections = 400;

// Does the ray from `origin` along unit `d` meet the triangle (a, b, c) at a positive distance?
bool ray_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a;
  const Eigen::Vector3d e2 = c - a;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < kParallel) return false;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return false;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  return e2.dot(q) / det > 0.0;
}

bool shadowed(const Mesh& mesh, const Eigen::Vector3d& p, const Eigen::Vector3d& normal,
              const Eigen::Vector3d& a) {
  const Eigen::Vector3d origin = p + kRayOffset * mesh.size() * normal;
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    if (ray_hits(origin, a, mesh.vertices.col(mesh.triangles(0, k)),
                 mesh.vertices.col(mesh.triangles(1, k)),
                 mesh.vertices.col(mesh.triangles(2, k)))) {
      return true;
    }
  }
  return false;
}

// Unit directions kShadowProbeDeg from a, around it.
std::vector<Eigen::Vector3d> ring_around(const Eigen::Vector3d& a) {
  const Eigen::Vector3d u = a.unitOrthogonal();
  const Eigen::Vector3d v = a.cross(u);
  const double r = kShadowProbeDeg / kDegreesPerRadian;
  std::vector<Eigen::Vector3d> ring;
  for (int k = 0; k < 8; ++k) {
    const double phi = 2.0 * kPi * k / 8.0;
    ring.push_back(
        (std::cos(r) * a + std::sin(r) * (std::cos(phi) * u + std::sin(phi) * v)).normalized());
  }
  return ring;
}

// Independent truth at one direction: per marker 1 visible, 0 hidden, -1 undecided (at a cone's
// edge or near a shadow's edge).
std::vector<int> brute_force(const Layout& layout, const Eigen::Vector3d& a) {
  const MarkerVisibility& vis = *layout.visibility;
  std::vector<int> out;
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
    const double cos_cone = std::cos(vis.cone_half_angle_deg(i) / kDegreesPerRadian);
    const double margin = vis.normals.col(i).dot(a) - cos_cone;
    if (std::abs(margin) < kConeMargin) {
      out.push_back(-1);
      continue;
    }
    if (margin < 0.0) {
      out.push_back(0);
      continue;
    }
    const Eigen::Vector3d p = layout.entries.col(i);
    const bool here = shadowed(*vis.body, p, vis.normals.col(i), a);
    bool steady = true;
    for (const Eigen::Vector3d& b : ring_around(a)) {
      steady = steady && shadowed(*vis.body, p, vis.normals.col(i), b) == here;
    }
    out.push_back(steady ? (here ? 0 : 1) : -1);
  }
  return out;
}

// Markers visible and not collinear: the centred points have rank >= 2.
bool spread(const Layout& layout, const std::vector<int>& visible) {
  if (visible.size() < 3) return false;
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(visible.size()));
  for (std::size_t k = 0; k < visible.size(); ++k) {
    points.col(static_cast<Eigen::Index>(k)) = layout.entries.col(visible[k]);
  }
  const Eigen::Matrix3Xd centred = points.colwise() - points.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(centred);
  return svd.singularValues()(1) > 1e-9 * svd.singularValues()(0);
}

Eigen::Vector3d random_direction(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

TEST(VisibilityReadout, HiddenMarkersAgreeWithAnIndependentRayAndConeTest) {
  const Layout layout = io::load_layout(kSatellite);
  ASSERT_TRUE(layout.visibility && layout.visibility->body) << "the example has a body";
  ViewerSession session{LayoutDocument(layout, kSatellite)};
  ASSERT_NE(session.visibility(), nullptr);
  std::mt19937 rng(testing::kSeed);
  int compared = 0;
  int hidden_seen = 0;
  int shadowed_in_cone = 0;  // control: the body does hide markers that face the camera
  int fully_decided = 0;
  for (int n = 0; n < kDirections; ++n) {
    const Eigen::Vector3d a = random_direction(rng);
    const VisibilityReadout r = read_visibility(*session.visibility(), a);
    const std::vector<int> truth = brute_force(layout, a);
    std::vector<bool> visible(truth.size(), false);
    for (const int i : r.visible) visible[static_cast<std::size_t>(i)] = true;
    ASSERT_EQ(r.visible.size() + r.hidden.size(), truth.size());
    for (const int i : r.hidden) EXPECT_FALSE(visible[static_cast<std::size_t>(i)]);
    bool decided = true;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      if (truth[i] < 0) {
        decided = false;
        continue;
      }
      EXPECT_EQ(visible[i], truth[i] == 1) << "marker " << i << " from " << a.transpose();
      ++compared;
      hidden_seen += truth[i] == 0;
      const double cos_cone = std::cos(
          layout.visibility->cone_half_angle_deg(static_cast<Eigen::Index>(i)) / kDegreesPerRadian);
      shadowed_in_cone +=
          truth[i] == 0 && layout.visibility->normals.col(static_cast<Eigen::Index>(i)).dot(a) >
                               cos_cone + kConeMargin;
    }
    if (!decided) continue;
    ++fully_decided;
    std::vector<int> seen;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      if (truth[i] == 1) seen.push_back(static_cast<int>(i));
    }
    double t = 1.0;
    for (std::size_t x = 0; x < seen.size(); ++x) {
      for (std::size_t y = x + 1; y < seen.size(); ++y) {
        const Eigen::Vector3d u =
            (layout.entries.col(seen[y]) - layout.entries.col(seen[x])).normalized();
        t = std::min(t, std::abs(a.dot(u)));
      }
    }
    EXPECT_NEAR(r.t, t, kRounding);
    EXPECT_NEAR(r.error_deg, kDegreesPerRadian * std::asin(t), kDegRounding);
    const bool trackable =
        static_cast<int>(seen.size()) >= layout.visibility->min_visible && spread(layout, seen);
    EXPECT_EQ(r.state == ViewpointState::kTrackable, trackable) << a.transpose();
  }
  // The checks ran on most of the markers and directions, and both answers occurred.
  EXPECT_GT(compared, 9 * kDirections * 12 / 10);
  EXPECT_GT(fully_decided, kDirections / 2);
  EXPECT_GT(hidden_seen, compared / 10);
  EXPECT_GT(shadowed_in_cone, 0);
}

TEST(VisibilityReadout, TheHoveredPointIsWhereTheCameraIs) {
  // The panel markers (4..11) face +z with cones of 80 degrees: a camera above the panels sees
  // them, one below does not. The hovered point is the sphere's point nearest the eye.
  ViewerSession session{LayoutDocument(io::load_layout(kSatellite), kSatellite)};
  ASSERT_NE(session.visibility(), nullptr);
  const Viewport viewport = scene_viewport(1400, 900);
  const Eigen::Vector2d centre(viewport.x + 0.5 * viewport.width,
                               viewport.y + 0.5 * viewport.height);
  for (const double side : {1.0, -1.0}) {
    session.camera.look_along(side * Eigen::Vector3d::UnitZ());
    const std::optional<Eigen::Vector3d> hovered = session.camera.pick_sphere(centre, viewport);
    ASSERT_TRUE(hovered);
    EXPECT_GT(hovered->z() * side, 0.99);
    const VisibilityReadout r = read_visibility(*session.visibility(), *hovered);
    for (int i = 4; i < 12; ++i) {
      const bool seen = std::find(r.visible.begin(), r.visible.end(), i) != r.visible.end();
      EXPECT_EQ(seen, side > 0.0) << "panel marker " << i << ", camera on z " << side;
    }
  }
}

TEST(VisibilityReadout, LostVerticesAreThoseTheIndependentTestCannotTrack) {
  const Layout layout = io::load_layout(kSatellite);
  ViewerSession session{LayoutDocument(layout, kSatellite)};
  const VisibilityShading* shading = session.visibility_shading();
  ASSERT_NE(shading, nullptr);
  const Eigen::Matrix3Xd& vertices = session.shading().vertices;
  ASSERT_EQ(static_cast<Eigen::Index>(shading->states.size()), vertices.cols());
  int lost = 0;
  int checked = 0;
  for (Eigen::Index v = 0; v < vertices.cols(); v += 97) {
    const Eigen::Vector3d a = vertices.col(v);
    const std::vector<int> truth = brute_force(layout, a);
    if (std::find(truth.begin(), truth.end(), -1) != truth.end()) continue;
    std::vector<int> seen;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      if (truth[i] == 1) seen.push_back(static_cast<int>(i));
    }
    const bool trackable = static_cast<int>(seen.size()) >= 3 && spread(layout, seen);
    const ViewpointState state = shading->states[static_cast<std::size_t>(v)];
    EXPECT_EQ(state == ViewpointState::kTrackable, trackable) << a.transpose();
    EXPECT_NE(state, ViewpointState::kOutsideWorkspace) << "the satellite has no workspace";
    if (!trackable) {
      ++lost;
      EXPECT_EQ(shading->error_deg(v), 90.0);
    }
    ++checked;
  }
  EXPECT_GT(checked, static_cast<int>(vertices.cols() / 97) / 2);
  EXPECT_GT(lost, 0) << "the satellite loses some directions (the issue's 96 % trackable)";
  EXPECT_LT(lost, checked);
}

TEST(VisibilityReadout, AWorkspaceGreysTheDirectionsOutsideIt) {
  Layout layout = io::load_layout(kSatellite);
  layout.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 30.0};
  ViewerSession session{LayoutDocument(layout, kSatellite)};
  const VisibilityShading* shading = session.visibility_shading();
  ASSERT_NE(shading, nullptr);
  const double cos_cap = std::cos(30.0 / kDegreesPerRadian);
  int inside = 0;
  for (Eigen::Index v = 0; v < session.shading().vertices.cols(); ++v) {
    const double z = session.shading().vertices(2, v);
    if (std::abs(z - cos_cap) < 1e-9) continue;  // on the cap's edge
    const bool out =
        shading->states[static_cast<std::size_t>(v)] == ViewpointState::kOutsideWorkspace;
    EXPECT_EQ(out, z < cos_cap) << session.shading().vertices.col(v).transpose();
    inside += !out;
  }
  EXPECT_GT(inside, 0);
}

TEST(VisibilityReadout, BadViewpointIsRefused) {
  ViewerSession session{LayoutDocument(io::load_layout(kSatellite), kSatellite)};
  ASSERT_NE(session.visibility(), nullptr);
  EXPECT_THROW(read_visibility(*session.visibility(), Eigen::Vector3d::Zero()), InvalidArgument);
  EXPECT_THROW(read_visibility(*session.visibility(), Eigen::Vector3d(std::nan(""), 0.0, 1.0)),
               InvalidArgument);
  ViewerSession whole{LayoutDocument(LayoutDocument::default_layout())};
  EXPECT_EQ(whole.visibility(), nullptr) << "a layout without normals is seen whole";
  EXPECT_EQ(whole.visibility_shading(), nullptr);
}

}  // namespace
}  // namespace vantage::viewer

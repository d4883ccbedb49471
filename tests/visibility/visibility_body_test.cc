// Visibility with a body mesh (docs/math.md §20) against independent truth: a convex body hides
// nothing its markers' cones of at most 90 degrees see, so its answer is the cone model's; a
// panel's shadow, computed here by intersecting rays with its plane, is what the occlusion grid
// reports away from the shadow's edge, and it only ever takes directions away.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "support/box_mesh.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::visibility {
namespace {

using testing::box_mesh;

// Eighteen markers on the faces of the box |x| <= 2, |y| <= 1.5, |z| <= 1, three per face,
// each with its face's normal.
Layout box_layout(double cone_deg) {
  const Eigen::Vector3d half(2.0, 1.5, 1.0);
  const double offsets[3][2] = {{0.6, 0.3}, {-0.5, 0.55}, {-0.2, -0.7}};
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 18);
  MarkerVisibility v;
  v.normals.resize(3, 18);
  int k = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {1.0, -1.0}) {
      for (const auto& o : offsets) {
        Eigen::Vector3d q = Eigen::Vector3d::Zero();
        q(axis) = side * half(axis);
        q((axis + 1) % 3) = o[0] * half((axis + 1) % 3);
        q((axis + 2) % 3) = o[1] * side * half((axis + 2) % 3);
        layout.entries.col(k) = q;
        v.normals.col(k++) = side * Eigen::Vector3d::Unit(axis);
      }
    }
  }
  layout.weights = Eigen::VectorXd::Ones(18);
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(18, cone_deg);
  layout.visibility = v;
  return layout;
}

TEST(VisibilityBody, ConvexBodyGivesTheConeModelsAnswer) {
  for (double cone : {60.0, 85.0, 90.0}) {
    SCOPED_TRACE(cone);
    const Layout cones = box_layout(cone);
    Layout body = cones;
    body.visibility->body = box_mesh(Eigen::Vector3d(-2, -1.5, -1), Eigen::Vector3d(2, 1.5, 1));
    body.visibility->body_path = "box";
    const VisibilityModel without = VisibilityModel::of(cones);
    const VisibilityModel with = VisibilityModel::of(body);
    ASSERT_TRUE(with.has_body());
    const VisibilityWorstViewpoint a = visibility_worst_viewpoint(without.problem());
    const VisibilityWorstViewpoint b = visibility_worst_viewpoint(with.problem());
    ASSERT_TRUE(a.certified()) << a.message << " (" << a.patches << " patches)";
    ASSERT_TRUE(b.certified()) << b.message;
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.viewpoint, b.viewpoint);
    EXPECT_EQ(a.visible_markers, b.visible_markers);
  }
}

// Markers on the top face (z = 0) of a slab, all facing up with 80-degree cones, under a panel
// 0 <= x <= 1, -1 <= y <= 1 at height kPanelHeight (0.02 thick).
constexpr double kPanelHeight = 0.5;

Layout under_panel(bool with_panel) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 7);
  layout.entries << 0.5, 0.2, 0.8, -0.6, -0.3, -0.9, 0.1,  //
      0.3, -0.5, -0.1, 0.4, -0.6, 0.0, 0.7,                //
      0, 0, 0, 0, 0, 0, 0;
  layout.weights = Eigen::VectorXd::Ones(7);
  MarkerVisibility v;
  v.normals = Eigen::Matrix3Xd::Zero(3, 7);
  v.normals.row(2).setOnes();
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(7, 80.0);
  v.min_visible = 5;  // four markers lie under the panel: where it hides two, the body is lost
  if (with_panel) {
    Mesh slab = box_mesh(Eigen::Vector3d(-1.5, -1.5, -0.2), Eigen::Vector3d(1.5, 1.5, 0));
    const Mesh panel =
        box_mesh(Eigen::Vector3d(0, -1, kPanelHeight), Eigen::Vector3d(1, 1, kPanelHeight + 0.02));
    Mesh both;
    both.vertices.resize(3, 16);
    both.vertices << slab.vertices, panel.vertices;
    both.triangles.resize(3, 24);
    both.triangles << slab.triangles, (panel.triangles.array() + 8).matrix();
    v.body = both;
    v.body_path = "slab and panel";
  }
  layout.visibility = v;
  return layout;
}

// Whether the ray p + s a (s > 0) meets the panel's underside, by its plane: the truth.
bool under_the_panel(const Eigen::Vector3d& p, const Eigen::Vector3d& a) {
  if (a.z() <= 0.0) return false;
  const Eigen::Vector3d q = p + (kPanelHeight - p.z()) / a.z() * a;
  return q.x() >= 0.0 && q.x() <= 1.0 && q.y() >= -1.0 && q.y() <= 1.0;
}

TEST(VisibilityBody, PanelShadowIsWhereTheGeometrySaysAndOnlyTakesAway) {
  const Layout layout = under_panel(true);
  const VisibilityModel with = VisibilityModel::of(layout);
  const VisibilityModel without = VisibilityModel::of(under_panel(false));
  const double resolution = *with.resolution_deg() / kDegreesPerRadian;
  const Eigen::Matrix3Xd& p = layout.entries;
  // Directions on a lattice of the upper hemisphere: the grid agrees with the plane test except
  // within two cells of the shadow's edge (where a cell's sample may fall on either side).
  int shadowed = 0, checked = 0;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < 20000; ++k) {
    const double z = 1.0 - (k + 0.5) / 20000.0;  // upper hemisphere
    const double r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d a(r * std::cos(golden * k), r * std::sin(golden * k), z);
    const DirectionVisibility seen = with.at(a);
    const DirectionVisibility cones = without.at(a);
    for (int i : seen.visible) {
      EXPECT_NE(std::find(cones.visible.begin(), cones.visible.end(), i), cones.visible.end())
          << "the body shows a marker its cone hides";
    }
    for (int i : cones.visible) {
      const bool truth = under_the_panel(p.col(i), a);
      // The plane test with the direction tilted by two cells either way must agree.
      bool near_edge = false;
      for (int axis : {0, 1}) {
        const Eigen::Vector3d tilt = Eigen::Vector3d::Unit(axis);
        for (double sign : {-1.0, 1.0}) {
          const Eigen::Vector3d b =
              Eigen::AngleAxisd(sign * 2 * resolution, tilt.cross(a).normalized()) * a;
          near_edge = near_edge || under_the_panel(p.col(i), b) != truth;
        }
      }
      if (near_edge) continue;
      ++checked;
      const bool hidden =
          std::find(seen.visible.begin(), seen.visible.end(), i) == seen.visible.end();
      EXPECT_EQ(hidden, truth) << "marker " << i << " at a = " << a.transpose();
      shadowed += truth;
    }
    if (seen.trackable) {
      EXPECT_TRUE(cones.trackable);
    }
  }
  EXPECT_GT(shadowed, 1000) << "the panel shadows a good part of the sky";
  EXPECT_GT(checked, 50000);
  // From straight above the markers under the panel (x in [0, 1]) are gone.
  const DirectionVisibility up = with.at(Eigen::Vector3d::UnitZ());
  for (int i : up.visible) EXPECT_LT(p(0, i), 0.0) << i;
  EXPECT_EQ(without.at(Eigen::Vector3d::UnitZ()).visible.size(), 7u);
  // Fewer markers seen: less of the sphere is trackable (min_visible 5 of 7).
  EXPECT_LT(visibility_coverage(with.problem()).trackable_fraction,
            visibility_coverage(without.problem()).trackable_fraction);
}

}  // namespace
}  // namespace vantage::visibility

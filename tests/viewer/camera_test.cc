#include "vantage/viewer/camera.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace vantage::viewer {
namespace {

constexpr double kPixelTolerance = 1e-6;  // projections are closed-form
constexpr double kUnitTolerance = 1e-9;
const Viewport kViewport{0.0, 0.0, 950.0, 800.0};

TEST(OrbitCamera, FrameIsRightHandedAndOrthonormal) {
  OrbitCamera camera;
  for (int k = 0; k < 40; ++k) {
    camera.orbit(37.0, -11.0 * ((k % 7) - 3));
    EXPECT_NEAR(camera.right().cross(camera.up()).dot(camera.back()), 1.0, kUnitTolerance);
    EXPECT_NEAR(camera.right().dot(camera.up()), 0.0, kUnitTolerance);
    EXPECT_LE(std::abs(camera.pitch_deg()), 90.0);
  }
}

TEST(OrbitCamera, LookAlongPutsTheAxisAtTheCentre) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  OrbitCamera camera;
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d a = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    camera.look_along(a);
    EXPECT_NEAR((camera.back() - a).norm(), 0.0, kUnitTolerance);
    const std::optional<Eigen::Vector2d> q = camera.project(a, kViewport);
    ASSERT_TRUE(q);
    EXPECT_NEAR(q->x(), 475.0, kPixelTolerance);
    EXPECT_NEAR(q->y(), 400.0, kPixelTolerance);
    EXPECT_FALSE(camera.hidden_by_sphere(a));
    EXPECT_TRUE(camera.hidden_by_sphere(-a));
  }
  camera.look_along(Eigen::Vector3d(0, 0, 3));
  EXPECT_NEAR(camera.pitch_deg(), 90.0, kUnitTolerance);
}

TEST(OrbitCamera, PickingInvertsProjectionOnTheVisibleSphere) {
  OrbitCamera camera;
  camera.orbit(-120.0, 45.0);
  int checked = 0;
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) {
      const Eigen::Vector2d pixel(475.0 + 30.0 * i, 400.0 + 30.0 * j);
      const std::optional<Eigen::Vector3d> hit = camera.pick_sphere(pixel, kViewport);
      ASSERT_TRUE(hit) << i << " " << j;
      EXPECT_NEAR(hit->norm(), 1.0, kUnitTolerance);
      EXPECT_FALSE(camera.hidden_by_sphere(*hit));
      const std::optional<Eigen::Vector2d> back = camera.project(*hit, kViewport);
      ASSERT_TRUE(back);
      EXPECT_NEAR((*back - pixel).norm(), 0.0, kPixelTolerance);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 81);
  EXPECT_FALSE(camera.pick_sphere(Eigen::Vector2d(2.0, 2.0), kViewport));  // corner: misses
}

TEST(OrbitCamera, PickDirectionFollowsAVectorTipOffTheUnitSphere) {
  // Vector tips are drawn at 1.45 times their direction, mostly outside the unit sphere's
  // outline, where pick_sphere() finds nothing: a tip dragged by pick_sphere never moved.
  constexpr double kTipRadius = 1.45;
  OrbitCamera camera;
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  int off_the_sphere = 0;
  int on_the_tip_sphere = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d n = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const Eigen::Vector3d tip = kTipRadius * n;
    const std::optional<Eigen::Vector2d> pixel = camera.project(tip, kViewport);
    ASSERT_TRUE(pixel);
    if (!camera.pick_sphere(*pixel, kViewport)) ++off_the_sphere;
    // The tip's own pixel gives its own direction back.
    EXPECT_NEAR((camera.pick_direction(*pixel, kViewport, kTipRadius, tip) - n).norm(), 0.0,
                kUnitTolerance);
    // A pixel nearby whose ray meets the tip sphere gives a direction whose tip is drawn exactly
    // there.
    const Eigen::Vector2d target = *pixel + Eigen::Vector2d(6.0, -4.0);
    const Eigen::Vector3d ray = camera.ray_direction(target, kViewport);
    if ((camera.eye() - camera.eye().dot(ray) * ray).norm() >= kTipRadius) continue;
    ++on_the_tip_sphere;
    const Eigen::Vector3d moved = camera.pick_direction(target, kViewport, kTipRadius, tip);
    EXPECT_NEAR(moved.norm(), 1.0, kUnitTolerance);
    const std::optional<Eigen::Vector2d> drawn = camera.project(kTipRadius * moved, kViewport);
    ASSERT_TRUE(drawn);
    EXPECT_NEAR((*drawn - target).norm(), 0.0, kPixelTolerance) << n.transpose();
  }
  EXPECT_GT(on_the_tip_sphere, 150);
  EXPECT_GT(off_the_sphere, 100) << "most tips lie outside the unit sphere's outline";
  // A pixel whose ray misses the tip sphere gives the direction of the ray's closest point.
  const Eigen::Vector2d corner(1.0, 1.0);
  const Eigen::Vector3d ray = camera.ray_direction(corner, kViewport);
  const Eigen::Vector3d closest = camera.eye() - camera.eye().dot(ray) * ray;
  EXPECT_NEAR((camera.pick_direction(corner, kViewport, kTipRadius, Eigen::Vector3d::UnitX()) -
               closest.normalized())
                  .norm(),
              0.0, kUnitTolerance);
}

TEST(OrbitCamera, ZoomIsClampedAndResetRestores) {
  OrbitCamera camera;
  camera.zoom(100.0);
  EXPECT_DOUBLE_EQ(camera.distance(), OrbitCamera::kMinDistance);
  camera.zoom(-100.0);
  EXPECT_DOUBLE_EQ(camera.distance(), OrbitCamera::kMaxDistance);
  camera.orbit(50.0, 50.0);
  camera.reset();
  EXPECT_DOUBLE_EQ(camera.yaw_deg(), OrbitCamera::kDefaultYawDeg);
  EXPECT_DOUBLE_EQ(camera.pitch_deg(), OrbitCamera::kDefaultPitchDeg);
  EXPECT_DOUBLE_EQ(camera.distance(), OrbitCamera::kDefaultDistance);
}

TEST(ViewPreset, NamesRoundTrip) {
  for (const ViewPreset p : {ViewPreset::kIso, ViewPreset::kWorst, ViewPreset::kPaper,
                             ViewPreset::kTop, ViewPreset::kFront, ViewPreset::kSide}) {
    EXPECT_EQ(parse_view_preset(to_string(p)), p);
  }
  EXPECT_FALSE(parse_view_preset("bottom"));
  EXPECT_EQ(view_preset_names(), "iso|worst|paper|top|front|side");
}

TEST(SceneViewport, LeavesRoomForThePanels) {
  const Viewport wide = scene_viewport(1400, 900);
  EXPECT_DOUBLE_EQ(wide.width, 1400.0 - kPanelColumnWidth);
  EXPECT_DOUBLE_EQ(wide.height, 900.0);
  EXPECT_DOUBLE_EQ(scene_viewport(600, 400).width, 600.0 * 0.55);
}

}  // namespace
}  // namespace vantage::viewer

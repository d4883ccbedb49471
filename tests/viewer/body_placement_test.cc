#include "vantage/viewer/body_placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "support/cube_mesh.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/mesh.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/viewer/viewer_session.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::viewer {
namespace {

constexpr auto kPlaceWait = std::chrono::seconds(600);  // generous: the machine is shared
constexpr double kConeDeg = 80.0;
// The session and the direct call run the same deterministic code on the same doubles.
constexpr double kExact = 0.0;

// A unit cube centred at the origin, wound outward.
Mesh cube() {
  Mesh mesh;
  mesh.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.col(i) =
        Eigen::Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  mesh.triangles.resize(3, 12);
  for (int q = 0; q < 6; ++q) {
    const int* v = quads[q];
    mesh.triangles.col(2 * q) << v[0], v[1], v[2];
    mesh.triangles.col(2 * q + 1) << v[0], v[2], v[3];
  }
  return mesh;
}

// Four markers on the cube's top face, seen from a 30-degree cap around +z (or, without the
// workspace, from the whole sphere: no four sites with 80-degree cones cover it).
Layout cube_layout(bool cap) {
  Layout layout;
  layout.name = "cube";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 4);
  layout.entries << 0.3, -0.3, 0.2, -0.1, 0.3, 0.1, -0.3, -0.2, 0.5, 0.5, 0.5, 0.5;
  layout.weights = Eigen::VectorXd::Ones(4);
  MarkerVisibility visibility;
  visibility.normals = Eigen::Vector3d::UnitZ().replicate(1, 4);
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(4, kConeDeg);
  visibility.body = cube();
  layout.visibility = visibility;
  if (cap) layout.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 30.0};
  layout.validate();
  return layout;
}

PlaceSettings small_settings() {
  PlaceSettings settings;
  settings.markers = 4;
  settings.candidates = 40;
  settings.random_trials = 50;
  settings.seed = 7;
  return settings;
}

// The truth: the library's own calls on the same inputs, as `vantage place` makes them.
design::PlacementResult direct_placement(const Layout& layout, const PlaceSettings& settings,
                                         Eigen::Matrix3Xd* points, Eigen::Matrix3Xd* normals) {
  const design::SurfaceSites sampled = design::sample_surface_sites(
      *layout.visibility->body, settings.candidates, settings.min_separation, settings.seed);
  Layout sites = layout;
  sites.entries = sampled.points;
  sites.weights = Eigen::VectorXd::Ones(sampled.points.cols());
  sites.visibility->normals = sampled.normals;
  sites.visibility->cone_half_angle_deg =
      Eigen::VectorXd::Constant(sampled.points.cols(), kConeDeg);
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(sites);
  design::PlacementProblem problem;
  problem.sites = model.problem();
  problem.markers = settings.markers;
  design::PlaceOptions options;
  options.random_trials = settings.random_trials;
  options.seed = settings.seed;
  *points = sampled.points;
  *normals = sampled.normals;
  return design::place_markers(problem, options);
}

TEST(BodyPlacement, SessionPlacesTheLibrarysChoiceAndReanalyses) {
  const Layout layout = cube_layout(true);
  const PlaceSettings settings = small_settings();
  Eigen::Matrix3Xd points;
  Eigen::Matrix3Xd normals;
  const design::PlacementResult truth = direct_placement(layout, settings, &points, &normals);
  ASSERT_EQ(truth.status, design::PlacementResult::Status::kComplete);
  ASSERT_EQ(truth.chosen.size(), 4u);

  ViewerSession session{LayoutDocument(layout, "")};
  ASSERT_TRUE(session.wait_until_current(kPlaceWait));
  const std::size_t undo_before = session.document().undo_depth();
  ASSERT_TRUE(session.place_markers(settings));
  EXPECT_TRUE(session.placing());
  EXPECT_FALSE(session.place_markers(settings));  // one placement at a time
  ASSERT_TRUE(session.wait_until_current(kPlaceWait));
  ASSERT_FALSE(session.placing());
  ASSERT_TRUE(session.placement());
  EXPECT_EQ(session.placement()->error, "");
  EXPECT_EQ(session.placement()->result.chosen, truth.chosen);
  EXPECT_EQ(session.placement()->result.value.pbar_min, truth.value.pbar_min);

  const Layout& placed = session.layout();
  ASSERT_EQ(placed.entries.cols(), settings.markers);
  ASSERT_TRUE(placed.visibility && placed.visibility->body && placed.workspace && placed.placement);
  for (int j = 0; j < settings.markers; ++j) {
    const int s = truth.chosen[static_cast<std::size_t>(j)];
    EXPECT_EIGEN_NEAR(placed.entries.col(j), points.col(s), kExact);
    EXPECT_EIGEN_NEAR(placed.visibility->normals.col(j), normals.col(s), kExact);
    EXPECT_EQ(placed.placement->chosen[static_cast<std::size_t>(j)], s);
  }
  EXPECT_EQ(placed.placement->site_points.cols(), settings.candidates);
  EXPECT_EQ(placed.placement->steps.size(), truth.steps.size());
  EXPECT_EQ(session.document().undo_depth(), undo_before + 1);
  // The analysis that follows is of the placed layout, as on loading it.
  ASSERT_TRUE(session.analysis_current());
  ASSERT_TRUE(session.analysis()->visibility);
  EXPECT_EQ(session.analysis()->layout.entries.cols(), settings.markers);
  ASSERT_NE(session.visibility(), nullptr);
}

TEST(BodyPlacement, IncompleteResultLeavesTheLayout) {
  const Layout layout = cube_layout(false);
  const PlaceSettings settings = small_settings();
  Eigen::Matrix3Xd points;
  Eigen::Matrix3Xd normals;
  const design::PlacementResult truth = direct_placement(layout, settings, &points, &normals);
  ASSERT_EQ(truth.status, design::PlacementResult::Status::kIncomplete);

  ViewerSession session{LayoutDocument(layout, "")};
  ASSERT_TRUE(session.wait_until_current(kPlaceWait));
  const std::uint64_t revision = session.document().revision();
  ASSERT_TRUE(session.place_markers(settings));
  ASSERT_TRUE(session.wait_until_current(kPlaceWait));
  ASSERT_TRUE(session.placement());
  EXPECT_EQ(session.placement()->result.status, design::PlacementResult::Status::kIncomplete);
  EXPECT_EQ(session.placement()->result.chosen, truth.chosen);
  EXPECT_TRUE(session.message_is_error());
  EXPECT_NE(session.message().find("incomplete"), std::string::npos);
  EXPECT_EQ(session.document().revision(), revision);
  EXPECT_EIGEN_NEAR(session.layout().entries, layout.entries, kExact);
  EXPECT_FALSE(session.layout().placement);
}

// Issue 35 item 8: the panel's camera objective, diameter and workspace go through `vantage
// place`'s run. Truth: the camera's map of the placed layout by the library (pose_crb_map with
// the settings and the aim the sensor block records), the sphere centres D/2 off the body.
TEST(BodyPlacement, CameraObjectiveDiameterAndWorkspaceAreVantagePlaces) {
  constexpr double kDiameter = 0.04;
  const Layout layout = cube_layout(false);
  PlaceSettings settings = small_settings();
  settings.objective = "camera";
  settings.distance = 6.0;
  settings.focal = 900.0;
  settings.noise_px = 0.3;
  settings.marker_diameter = kDiameter;
  settings.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 30.0};
  const PlaceOutcome outcome = place_on_body(layout, 0, settings);
  ASSERT_EQ(outcome.error, "");
  ASSERT_TRUE(outcome.complete) << outcome.failure;
  const Layout& placed = outcome.placed;
  ASSERT_TRUE(placed.sensor && placed.workspace);
  EXPECT_EQ(placed.workspace->half_angle_deg, 30.0);
  camera::PoseCrbOptions crb;
  crb.distance = 6.0;
  crb.focal_length = 900.0;
  crb.noise_px = 0.3;
  crb.samples = placed.sensor->samples;
  crb.aim = placed.sensor->aim;
  const camera::PoseCrbMap map = camera::pose_crb_map(camera::PoseCrbModel(placed, crb));
  ASSERT_EQ(map.status, camera::PoseCrbMap::Status::kOk);
  EXPECT_EQ(outcome.objective_value, map.worst.rot_rms_deg);
  for (Eigen::Index j = 0; j < placed.entries.cols(); ++j) {
    EXPECT_NEAR(distance_to_mesh(*layout.visibility->body, placed.entries.col(j)), kDiameter / 2,
                1e-12);
    for (Eigen::Index k = 0; k < j; ++k) {
      EXPECT_GE((placed.entries.col(j) - placed.entries.col(k)).norm(), kDiameter);
    }
  }
}

// The panel's approach (issue 35: "the viewer's Place tab lacks --distances"): the value is the
// largest over the distances of the library's map of the placed layout at each, and the sensor
// block records the distances; a typed approach that is not numbers is refused by name.
TEST(BodyPlacement, AnApproachIsTheWorstOfItsDistances) {
  const Layout layout = cube_layout(false);
  PlaceSettings settings = small_settings();
  settings.objective = "camera";
  settings.distances = {4.0, 6.0, 9.0};
  settings.focal = 900.0;
  settings.noise_px = 0.3;
  settings.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 30.0};
  const PlaceOutcome outcome = place_on_body(layout, 0, settings);
  ASSERT_EQ(outcome.error, "");
  ASSERT_TRUE(outcome.complete) << outcome.failure;
  const Layout& placed = outcome.placed;
  ASSERT_TRUE(placed.sensor);
  EXPECT_EQ(placed.sensor->distances, settings.distances);
  camera::PoseCrbOptions crb;
  crb.distance = settings.distances.front();
  crb.focal_length = 900.0;
  crb.noise_px = 0.3;
  crb.samples = placed.sensor->samples;
  crb.aim = placed.sensor->aim;
  const camera::PoseCrbModel model(placed, crb);
  double worst = 0.0;
  for (const double d : settings.distances) {
    const camera::PoseCrbMap map = camera::pose_crb_map(model, d);
    ASSERT_EQ(map.status, camera::PoseCrbMap::Status::kOk) << "at " << d;
    worst = std::max(worst, map.worst.rot_rms_deg);
  }
  EXPECT_EQ(outcome.objective_value, worst);

  settings.distances = {std::numeric_limits<double>::quiet_NaN()};
  const PlaceOutcome refused = place_on_body(layout, 0, settings);
  EXPECT_NE(refused.error.find("--distances"), std::string::npos) << refused.error;
}

// A missing camera setting is refused as `vantage place` refuses it, naming the option.
TEST(BodyPlacement, MissingObjectiveSettingsAreNamed) {
  PlaceSettings settings = small_settings();
  settings.objective = "camera";
  settings.distance = 6.0;
  settings.noise_px = 0.3;
  const PlaceOutcome outcome = place_on_body(cube_layout(true), 0, settings);
  EXPECT_NE(outcome.error.find("--focal"), std::string::npos) << outcome.error;
  settings.objective = "tracker";
  const PlaceOutcome tracker = place_on_body(cube_layout(true), 0, settings);
  EXPECT_NE(tracker.error.find("--fle-rms"), std::string::npos) << tracker.error;
}

// `vantage place`'s --exclude and its checks of the problem, through the viewer's settings.
TEST(BodyPlacement, KeepOutVolumesAndTheProblemsChecksAreVantagePlaces) {
  // A box over the cube's top (z from 0.25 up, wider than the cube) as a keep-out volume.
  Mesh lid = cube();
  for (Eigen::Index v = 0; v < lid.vertices.cols(); ++v) {
    lid.vertices.col(v).x() *= 2.0;
    lid.vertices.col(v).y() *= 2.0;
    lid.vertices(2, v) = lid.vertices(2, v) < 0.0 ? 0.25 : 2.0;
  }
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "vantage_viewer_keep_out_lid.obj";
  std::ofstream(path) << testing::obj_text(lid);
  const Layout layout = cube_layout(false);
  PlaceSettings settings = small_settings();
  const Layout everywhere = body_sites(layout, settings);
  settings.exclude = {path.string()};
  const Layout kept_out = body_sites(layout, settings);
  EXPECT_LT(kept_out.entries.cols(), everywhere.entries.cols());
  EXPECT_GT(kept_out.entries.cols(), 0);
  for (Eigen::Index j = 0; j < kept_out.entries.cols(); ++j) {
    EXPECT_LT(kept_out.entries(2, j), 0.25) << j;
  }
  const PlaceOutcome outcome = place_on_body(layout, 0, settings);
  EXPECT_EQ(outcome.excluded, everywhere.entries.cols() - kept_out.entries.cols());
  std::filesystem::remove(path);
  // Named as `vantage place` names them (the viewer skipped these checks before).
  PlaceSettings robust = small_settings();
  robust.markers = 3;
  robust.robust_dropout = true;
  const PlaceOutcome refused = place_on_body(layout, 0, robust);
  EXPECT_NE(refused.error.find("--robust-dropout"), std::string::npos) << refused.error;
  PlaceSettings wide = small_settings();
  wide.marker_diameter = 10.0;
  const PlaceOutcome too_wide = place_on_body(layout, 0, wide);
  EXPECT_NE(too_wide.error.find("--marker-diameter: a sphere of diameter 10 is wider"),
            std::string::npos)
      << too_wide.error;
}

TEST(BodyPlacement, RefusedWithoutABody) {
  Layout layout = cube_layout(true);
  layout.visibility->body.reset();
  ViewerSession session{LayoutDocument(layout, "")};
  EXPECT_FALSE(session.place_markers(small_settings()));
  EXPECT_TRUE(session.message_is_error());
  EXPECT_FALSE(session.placing());
  const PlaceOutcome outcome = place_on_body(layout, 0, small_settings());
  EXPECT_NE(outcome.error.find("body"), std::string::npos);
}

}  // namespace
}  // namespace vantage::viewer

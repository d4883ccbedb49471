// The tag sweep of the pose CRB (docs/math.md §22, "How many tags, and how big") against boards
// built here by hand: faces and extents, the tiling's corners, and each row's map.

#include "vantage/camera/pose_crb_tags.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"

namespace vantage::camera {
namespace {

// Corners computed two ways (by hand here, through faces and tiling there) agree to rounding.
constexpr double kRounding = 1e-12;

// A k x k board of tags of side `side` at pitch `pitch` in the plane through `origin` spanned by
// the unit vectors x, y (normal x cross y), each tag's corners in the reader's order, named
// tag<first_id + j>_c0..c3, appended to `layout` with the normal and a `cone_deg` cone.
void add_board(Layout* layout, int k, double side, double pitch, const Eigen::Vector3d& origin,
               const Eigen::Vector3d& x, const Eigen::Vector3d& y, double cone_deg) {
  const Eigen::Vector3d n = x.cross(y);
  const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int row = 0; row < k; ++row) {
    for (int col = 0; col < k; ++col) {
      const int id = static_cast<int>(layout->names.size()) / 4;
      const Eigen::Vector3d centre = origin + (col * pitch) * x + (row * pitch) * y;
      for (int c = 0; c < 4; ++c) {
        const long m = layout->entries.cols();
        layout->entries.conservativeResize(3, m + 1);
        layout->entries.col(m) = centre + side / 2 * signs[c][0] * x + side / 2 * signs[c][1] * y;
        layout->names.push_back("tag" + std::to_string(id) + "_c" + std::to_string(c));
        layout->visibility->normals.conservativeResize(3, m + 1);
        layout->visibility->normals.col(m) = n;
        layout->visibility->cone_half_angle_deg.conservativeResize(m + 1);
        layout->visibility->cone_half_angle_deg(m) = cone_deg;
      }
    }
  }
  layout->weights = Eigen::VectorXd::Ones(layout->entries.cols());
}

Layout empty_tag_layout() {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 0);
  layout.visibility = MarkerVisibility{};
  layout.visibility->normals.resize(3, 0);
  layout.visibility->cone_half_angle_deg.resize(0);
  return layout;
}

PoseCrbOptions camera() {
  PoseCrbOptions options;
  options.distance = 2.0;
  options.focal_length = 900.0;
  options.noise_px = 0.3;
  options.samples = 2000;
  options.threads = 1;
  return options;
}

const Eigen::Vector3d kX = Eigen::Vector3d(1, 1, 0).normalized();
const Eigen::Vector3d kY = Eigen::Vector3d(-1, 1, 1).normalized();
const Eigen::Vector3d kZ = kX.cross(kY);

TEST(TagFaces, ABoardIsOneFaceWhoseExtentHoldsItsCorners) {
  Layout layout = empty_tag_layout();
  // 3 x 3 tags of side 0.08 at pitch 0.1: corners span 0.2 + 0.08 along each axis.
  const Eigen::Vector3d origin(0.3, -0.2, 0.5);
  add_board(&layout, 3, 0.08, 0.1, origin, kX, kY, 80.0);
  const std::vector<TagFace> faces = tag_faces(layout);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].tags, 9);
  EXPECT_NEAR(faces[0].extent, 0.28, kRounding);
  EXPECT_LT((faces[0].centre - (origin + 0.1 * kX + 0.1 * kY)).norm(), kRounding);
  EXPECT_LT((faces[0].normal - kZ).norm(), kRounding);
}

TEST(TagFaces, TwoParallelBoardsInDifferentPlanesAreTwoFaces) {
  Layout layout = empty_tag_layout();
  add_board(&layout, 1, 0.1, 0.2, Eigen::Vector3d::Zero(), kX, kY, 80.0);
  add_board(&layout, 1, 0.1, 0.2, 0.3 * kZ, kX, kY, 80.0);
  add_board(&layout, 1, 0.1, 0.2, 0.5 * kX, kX, kY, 80.0);  // same plane as the first
  const std::vector<TagFace> faces = tag_faces(layout);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].tags, 2);
  EXPECT_EQ(faces[1].tags, 1);
  EXPECT_NEAR(faces[0].extent, 0.6, kRounding);
}

TEST(TagGridLayout, TilingSpreadsEqualCellsOverTheFaceExtent) {
  const double pitch = 0.05, fill = 0.7;
  Layout layout = empty_tag_layout();
  add_board(&layout, 4, fill * pitch, pitch, Eigen::Vector3d(0.1, 0.2, 0.3), kX, kY, 75.0);
  // The face's extent runs from the first tag's c0 to the last tag's c2; the tiling's cells
  // split that extent equally: the expected board is rebuilt here with that pitch.
  const std::vector<TagFace> faces = tag_faces(layout);
  const double extent = 3 * pitch + fill * pitch;
  ASSERT_NEAR(faces[0].extent, extent, kRounding);
  const double grid_pitch = extent / 4;
  Layout expected = empty_tag_layout();
  const Eigen::Vector3d first_centre = faces[0].centre - (extent / 2 - grid_pitch / 2) * (kX + kY);
  add_board(&expected, 4, fill * grid_pitch, grid_pitch, first_centre, kX, kY, 75.0);
  const Layout tiled = tag_grid_layout(layout, faces, 4, fill);
  ASSERT_EQ(tiled.entries.cols(), expected.entries.cols());
  EXPECT_LT((tiled.entries - expected.entries).cwiseAbs().maxCoeff(), kRounding);
  EXPECT_EQ(tiled.names, expected.names);
  EXPECT_LT((tiled.visibility->normals - expected.visibility->normals).cwiseAbs().maxCoeff(),
            kRounding);
  EXPECT_EQ(tiled.visibility->cone_half_angle_deg, expected.visibility->cone_half_angle_deg);
}

TEST(TagGridLayout, OneTagPerSideIsTheBoundingSquareScaledByTheFill) {
  Layout layout = empty_tag_layout();
  add_board(&layout, 1, 0.2, 1.0, Eigen::Vector3d::Zero(), kX, kY, 90.0);
  const Layout tiled = tag_grid_layout(layout, tag_faces(layout), 1, 0.5);
  EXPECT_LT((tiled.entries - 0.5 * layout.entries).cwiseAbs().maxCoeff(), kRounding);
}

TEST(TagSweep, EachRowIsTheMapOfItsTiling) {
  Layout layout = empty_tag_layout();
  add_board(&layout, 2, 0.1, 0.15, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
            Eigen::Vector3d::UnitY(), 80.0);
  TagSweepOptions options;
  options.per_side = {1, 3};
  options.fill = {0.6};
  const std::vector<TagSweepRow> rows = pose_crb_tag_sweep(layout, camera(), options);
  ASSERT_EQ(rows.size(), 2u);
  const std::vector<TagFace> faces = tag_faces(layout);
  for (const TagSweepRow& row : rows) {
    SCOPED_TRACE(row.per_side);
    EXPECT_EQ(row.tags, row.per_side * row.per_side);
    EXPECT_NEAR(row.tag_size, 0.6 * 0.25 / row.per_side, kRounding);
    EXPECT_NEAR(row.tag_pixels, row.tag_size * 900.0 / 2.0, kRounding);
    const PoseCrbModel model(tag_grid_layout(layout, faces, row.per_side, 0.6), camera());
    const PoseCrbMap map = pose_crb_map(model);
    ASSERT_EQ(row.status, PoseCrbMap::Status::kOk);
    EXPECT_EQ(row.worst.rot_rms_deg, map.worst.rot_rms_deg);
    EXPECT_EQ(row.percentiles.p50, map.percentiles.p50);
    EXPECT_EQ(row.median.rot_rms_deg, map.percentiles.p50);
    EXPECT_EQ(row.trackable_fraction, map.trackable_fraction);
  }
  // Nine tags of a third the side: more corners, and the outer ones at the board's edge.
  EXPECT_LT(rows[1].median.rot_rms_deg, rows[0].median.rot_rms_deg);
}

TEST(TagSweep, RefusesLayoutsThatAreNotTagCorners) {
  Layout layout = empty_tag_layout();
  add_board(&layout, 1, 0.1, 0.2, Eigen::Vector3d::Zero(), kX, kY, 80.0);
  Layout renamed = layout;
  renamed.names[2] = "tag0_c3";
  Layout skewed = layout;
  skewed.entries(0, 2) += 0.01;
  Layout unnamed = layout;
  unnamed.names.clear();
  const std::pair<const Layout*, const char*> cases[] = {
      {&renamed, "names"}, {&skewed, "points"}, {&unnamed, "names"}};
  for (const auto& [bad, field] : cases) {
    try {
      tag_faces(*bad);
      ADD_FAILURE() << "accepted a layout whose " << field << " are wrong";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  }
  TagSweepOptions bad_fill;
  bad_fill.fill = {1.5};
  TagSweepOptions bad_count;
  bad_count.per_side = {0};
  for (const TagSweepOptions& options : {bad_fill, bad_count}) {
    try {
      pose_crb_tag_sweep(layout, camera(), options);
      ADD_FAILURE() << "accepted bad sweep options";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field().rfind("sweep_tags.", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace vantage::camera

// The pose CRB figures (docs/math.md §22): the map's CSV holds the bound of the library's model
// at every cell, recomputed here from a model built apart; its worst and best rows are the
// report's; the sweep's CSV is the library's distance sweep, recomputed here; the default sweep
// spans max(D / 2, 1.1 r) to 2 D; bad data and options throw one error naming the field, and
// leave nothing written.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "plot_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"
#include "vantage/plot/crb_figures.h"
#include "vantage/plot/sphere_map.h"

namespace vantage::plot {
namespace {

using testing::Csv;
using testing::read_csv;
using testing::TempDir;

// The CSV's numbers are written in the shortest form that reads back to the same double; the
// recomputation is the same arithmetic on the same inputs, so only reading back can differ.
constexpr double kRounding = 1e-12;
constexpr int kPictureSamples = 60;
constexpr int kCsvSamples = 40;

Layout cube_layout() {
  return io::load_layout(std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/apriltag_cube.yaml");
}

camera::PoseCrbOptions cube_camera() {
  camera::PoseCrbOptions camera;
  camera.distance = 2.0;
  camera.focal_length = 900.0;
  camera.noise_px = 0.3;
  camera.samples = 2000;  // fewer than the default 10 000: the test is about the files
  return camera;
}

CrbFiguresOptions small_figures() {
  CrbFiguresOptions options;
  options.samples_per_axis = kPictureSamples;
  options.csv_samples_per_axis = kCsvSamples;
  options.sweep = camera::PoseCrbSweep{1.5, 3.0, 3};
  return options;
}

void expect_row(const Csv& csv, std::size_t row, const camera::PoseCrbAt& at) {
  EXPECT_NEAR(csv.number(row, "x"), at.direction.x(), kRounding);
  EXPECT_NEAR(csv.number(row, "y"), at.direction.y(), kRounding);
  EXPECT_NEAR(csv.number(row, "z"), at.direction.z(), kRounding);
  EXPECT_EQ(csv.number(row, "visible"), static_cast<double>(at.visible_markers.size()));
  EXPECT_EQ(csv.text(row, "trackable"), at.trackable ? "1" : "0");
  if (at.trackable) {
    EXPECT_NEAR(csv.number(row, "rot_rms_deg"), at.rot_rms_deg, kRounding * at.rot_rms_deg);
    EXPECT_NEAR(csv.number(row, "trans_rms"), at.trans_rms, kRounding * at.trans_rms);
  } else {
    EXPECT_EQ(csv.text(row, "rot_rms_deg"), "");
    EXPECT_EQ(csv.text(row, "trans_rms"), "");
  }
}

TEST(CrbFigures, MapCsvHoldsTheBoundOfEveryCellAndTheReportsExtremes) {
  const Layout layout = cube_layout();
  TempDir dir("crbmap");
  CrbFigures figures = crb_figures(layout, cube_camera(), small_figures());
  write_crb_figures(figures, small_figures(), dir.path());
  ASSERT_EQ(figures.files.size(), 2u);
  EXPECT_EQ(figures.files[0].name, "crb_map");
  ASSERT_EQ(figures.report.map.status, camera::PoseCrbMap::Status::kOk);

  const Csv csv = read_csv(figures.files[0].csv);
  ASSERT_GE(csv.rows.size(), 2u);
  EXPECT_EQ(csv.text(0, "kind"), "worst");
  expect_row(csv, 0, figures.report.map.worst);
  EXPECT_EQ(csv.text(1, "kind"), "best");
  expect_row(csv, 1, figures.report.map.best);

  const camera::PoseCrbModel apart(layout, cube_camera());
  std::size_t row = 2;
  int trackable = 0;
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < kCsvSamples; ++r) {
      for (int c = 0; c < kCsvSamples; ++c) {
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, kCsvSamples),
                                 SphereSamples::cell_centre(kCsvSamples - 1 - r, kCsvSamples));
        if (xy.squaredNorm() > 1.0) continue;
        ASSERT_LT(row, csv.rows.size());
        EXPECT_EQ(csv.text(row, "kind"), "cell");
        EXPECT_EQ(csv.number(row, "disc"), d);
        const camera::PoseCrbAt at = apart.at(direction_from_sphere_map(d, xy));
        expect_row(csv, row, at);
        trackable += at.trackable ? 1 : 0;
        ++row;
      }
    }
  }
  EXPECT_EQ(row, csv.rows.size());
  EXPECT_GT(trackable, 0);  // the comparison of the bounds ran

  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(figures.files[0].image.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  stbi_image_free(pixels);
  EXPECT_EQ(width, FigureOptions{}.width);
  EXPECT_EQ(height, FigureOptions{}.height);
}

TEST(CrbFigures, SweepCsvIsTheLibrarysDistanceSweep) {
  const Layout layout = cube_layout();
  TempDir dir("crbsweep");
  CrbFigures figures = crb_figures(layout, cube_camera(), small_figures());
  write_crb_figures(figures, small_figures(), dir.path());
  EXPECT_EQ(figures.files[1].name, "crb_sweep");
  const Csv csv = read_csv(figures.files[1].csv);
  const camera::PoseCrbModel apart(layout, cube_camera());
  const std::vector<camera::PoseCrbSweepRow> rows =
      camera::pose_crb_distance_sweep(apart, 1.5, 3.0, 3);
  ASSERT_EQ(csv.rows.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_NEAR(csv.number(k, "distance"), rows[k].distance, kRounding);
    ASSERT_EQ(csv.text(k, "status"), "ok");
    if (rows[k].worst.unbounded) {
      // No figure past the first-order limit (docs/math.md §22, "Unbounded").
      EXPECT_EQ(csv.text(k, "worst_rot_rms_deg"), "");
      EXPECT_EQ(csv.text(k, "worst_trans_rms"), "");
      continue;
    }
    EXPECT_NEAR(csv.number(k, "worst_rot_rms_deg"), rows[k].worst.rot_rms_deg,
                kRounding * rows[k].worst.rot_rms_deg);
    EXPECT_NEAR(csv.number(k, "worst_trans_rms"), rows[k].worst.trans_rms,
                kRounding * rows[k].worst.trans_rms);
    EXPECT_NEAR(csv.number(k, "median_rot_rms_deg"), rows[k].median.rot_rms_deg,
                kRounding * rows[k].median.rot_rms_deg);
    EXPECT_NEAR(csv.number(k, "median_trans_rms"), rows[k].median.trans_rms,
                kRounding * rows[k].median.trans_rms);
    EXPECT_NEAR(csv.number(k, "worst_x"), rows[k].worst.direction.x(), kRounding);
    EXPECT_LE(csv.number(k, "median_rot_rms_deg"), csv.number(k, "worst_rot_rms_deg"));
  }
}

TEST(CrbFigures, DefaultSweepSpansHalfToTwiceTheDistanceAboveTheRadius) {
  const camera::PoseCrbSweep wide = default_crb_sweep(4.0, 1.0);
  EXPECT_EQ(wide.from, 2.0);
  EXPECT_EQ(wide.to, 8.0);
  EXPECT_EQ(wide.count, kDefaultSweepCount);
  const camera::PoseCrbSweep close = default_crb_sweep(1.2, 1.0);
  EXPECT_NEAR(close.from, 1.1, kRounding);
  EXPECT_LT(close.from, close.to);
}

// The field an InvalidArgument of `call` names, "" when it throws none.
template <typename Call>
std::string field_of(Call&& call) {
  try {
    call();
  } catch (const InvalidArgument& e) {
    return e.field();
  }
  return "";
}

TEST(CrbFigures, BadOptionsNameTheFieldAndWriteNothing) {
  const Layout layout = cube_layout();
  TempDir dir("crbbad");
  CrbFigures figures = crb_figures(layout, cube_camera(), small_figures());
  CrbMapData data;
  data.model = figures.model.get();
  data.report = &figures.report;
  data.samples_per_axis = 5;
  EXPECT_EQ(field_of([&] { write_crb_map(data, dir.path()); }), "samples_per_axis");
  data.samples_per_axis = kPictureSamples;
  data.csv_samples_per_axis = 100000;
  EXPECT_EQ(field_of([&] { write_crb_map(data, dir.path()); }), "csv_samples_per_axis");
  data.model = nullptr;
  EXPECT_EQ(field_of([&] { write_crb_map(data, dir.path()); }), "model");
  camera::PoseCrbReport one_row = figures.report;
  one_row.sweep_distance.resize(1);
  EXPECT_EQ(field_of([&] { write_crb_sweep("cube", one_row, dir.path()); }), "sweep_distance");
  camera::PoseCrbOptions camera = cube_camera();
  camera.distance = 0.0;
  EXPECT_EQ(field_of([&] { crb_figures(layout, camera, small_figures()); }), "distance");
  camera = cube_camera();
  camera.noise_px = -1.0;
  EXPECT_EQ(field_of([&] { crb_figures(layout, camera, small_figures()); }), "noise_px");
  CrbFiguresOptions backwards = small_figures();
  backwards.sweep = camera::PoseCrbSweep{3.0, 1.5, 3};
  EXPECT_EQ(field_of([&] { crb_figures(layout, cube_camera(), backwards); }), "sweep_distance");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace vantage::plot

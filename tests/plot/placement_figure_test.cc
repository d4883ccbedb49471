// The placement figure (plot/placement_figure.h): drawn, its CSV holds the numbers it was given,
// it is selected only for a placed layout, and bad data is refused naming the field.

#include "vantage/plot/placement_figure.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "plot_testing.h"
#include "vantage/plot/layout_figures.h"

namespace vantage::plot {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

// A unit cube (12 triangles), six face-centre sites, three chosen, two greedy steps.
PlacementFigureData cube_data() {
  static Mesh mesh = [] {
    Mesh m;
    m.vertices.resize(3, 8);
    for (int i = 0; i < 8; ++i) {
      m.vertices.col(i) =
          Eigen::Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
    }
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    m.triangles.resize(3, 12);
    for (int q = 0; q < 6; ++q) {
      m.triangles.col(2 * q) << quads[q][0], quads[q][1], quads[q][2];
      m.triangles.col(2 * q + 1) << quads[q][0], quads[q][2], quads[q][3];
    }
    return m;
  }();
  PlacementFigureData data;
  data.layout_name = "cube";
  data.body = &mesh;
  Eigen::Matrix3Xd normals(3, 6);
  normals << 1, -1, 0, 0, 0, 0,  //
      0, 0, 1, -1, 0, 0,         //
      0, 0, 0, 0, 1, -1;
  data.placement.site_points = 0.5 * normals;
  data.placement.site_normals = normals;
  data.placement.chosen = {0, 2, 4};
  data.placement.steps = {{2, 0.0, 0.0}, {3, 0.7, 0.4}};
  data.placement.random_trials = 20;
  data.placement.random_best_pbar_min = 0.6;
  data.placement.random_median_pbar_min = 0.2;
  data.markers = data.placement.site_points(Eigen::all, std::vector<int>{0, 2, 4});
  data.normals = normals(Eigen::all, std::vector<int>{0, 2, 4});
  data.pbar_min = 0.7;
  data.coverage = 0.4;
  return data;
}

TEST(PlacementFigure, WritesTheImageAndTheNumbersItWasGiven) {
  TempDir dir("placement");
  const FigureFiles files = write_placement_figure(cube_data(), dir.path());
  EXPECT_TRUE(std::filesystem::file_size(files.image) > 0);
  const testing::Csv csv = testing::read_csv(files.csv);
  ASSERT_EQ(csv.rows.size(), 5u);  // two steps, the answer, best and median of the baseline
  EXPECT_EQ(csv.text(0, "series"), "step");
  EXPECT_EQ(csv.number(1, "pbar_min"), 0.7);
  EXPECT_EQ(csv.number(1, "coverage"), 0.4);
  EXPECT_EQ(csv.text(2, "series"), "answer");
  EXPECT_EQ(csv.number(2, "k"), 3.0);
  EXPECT_EQ(csv.text(3, "series"), "random_best");
  EXPECT_EQ(csv.number(3, "pbar_min"), 0.6);
  EXPECT_EQ(csv.number(4, "pbar_min"), 0.2);
}

// A camera placement charts its objective: the CSV gains the objective column, empty where a
// step tracks nothing.
TEST(PlacementFigure, ACameraPlacementChartsItsObjective) {
  TempDir dir("placement_camera");
  PlacementFigureData data = cube_data();
  data.sensor = LayoutSensor{};
  data.sensor->statistic = "worst";
  data.placement.steps[0].objective = std::numeric_limits<double>::infinity();
  data.placement.steps[1].objective = 7.5;
  data.placement.objective_value = 6.25;
  data.placement.random_best_objective = 9.0;
  data.placement.random_median_objective = std::numeric_limits<double>::infinity();
  const FigureFiles files = write_placement_figure(data, dir.path());
  EXPECT_TRUE(std::filesystem::file_size(files.image) > 0);
  const testing::Csv csv = testing::read_csv(files.csv);
  ASSERT_EQ(csv.rows.size(), 5u);
  EXPECT_EQ(csv.text(0, "objective"), "");
  EXPECT_EQ(csv.number(1, "objective"), 7.5);
  EXPECT_EQ(csv.number(2, "objective"), 6.25);
  EXPECT_EQ(csv.number(3, "objective"), 9.0);
  EXPECT_EQ(csv.text(4, "objective"), "");
  EXPECT_EQ(csv.number(2, "pbar_min"), data.pbar_min);  // the p-bar_min columns stay
}

TEST(PlacementFigure, RefusesBadData) {
  TempDir dir("placement_bad");
  PlacementFigureData data = cube_data();
  data.placement.chosen = {0, 2, 9};
  EXPECT_THROW(write_placement_figure(data, dir.path()), InvalidArgument);
  data = cube_data();
  data.normals.conservativeResize(3, 2);
  EXPECT_THROW(write_placement_figure(data, dir.path()), InvalidArgument);
  data = cube_data();
  data.pbar_min = 1.5;
  EXPECT_THROW(write_placement_figure(data, dir.path()), InvalidArgument);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(PlacementFigure, IsSelectedOnlyForAPlacedLayout) {
  LayoutFiguresOptions options;
  const auto has = [](const std::vector<std::string>& names) {
    return std::find(names.begin(), names.end(), "placement") != names.end();
  };
  EXPECT_FALSE(has(selected_figures(options, false, true, false)));
  EXPECT_TRUE(has(selected_figures(options, false, true, true)));
  options.only = {"placement"};
  try {
    selected_figures(options, false, true, false);
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("vantage place"));
  }
}

}  // namespace
}  // namespace vantage::plot

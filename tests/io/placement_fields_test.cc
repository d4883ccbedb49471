// The "placement" block of a layout written by `vantage place` (docs/math.md §21): it survives
// a write and a read bit for bit, and a bad block gets one error naming its field.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"

namespace vantage::io {
namespace {

using ::testing::HasSubstr;

// Three markers on a cube's faces, chosen from four sites; one greedy step and a baseline.
constexpr const char* kPlaced = R"({
  "points": [[0.5, 0.1, 0.0], [0.0, 0.5, 0.1], [0.1, 0.0, 0.5]],
  "normals": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  "placement": {
    "sites": "cube.obj",
    "chosen": [0, 2, -1],
    "objective": "coverage, then certified p-bar_min",
    "min_separation": 0.012,
    "marker_diameter": 0.01,
    "steps": [{"k": 3, "pbar_min": 0.5, "coverage": 0.25}],
    "random_baseline": {"trials": 10, "best_pbar_min": 0.4, "median_pbar_min": 0.1},
    "site_points": [[0.5, 0.1, 0.0], [-0.5, 0, 0], [0.0, 0.5, 0.1], [0, -0.5, 0]],
    "site_normals": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]]
  }
})";

std::string error_of(const std::string& text) {
  try {
    parse_layout(text, "placed.json");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no exception";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string with(const std::string& from, const std::string& to) { return with(kPlaced, from, to); }

TEST(PlacementFields, SurviveAWriteAndARead) {
  const Layout layout = parse_layout(kPlaced, "placed.json");
  ASSERT_TRUE(layout.placement.has_value());
  const LayoutPlacement& p = *layout.placement;
  EXPECT_EQ(p.chosen, (std::vector<int>{0, 2, -1}));
  EXPECT_EQ(p.site_points.cols(), 4);
  ASSERT_EQ(p.steps.size(), 1u);
  EXPECT_EQ(p.steps[0].coverage, 0.25);
  EXPECT_EQ(p.random_trials, 10);
  const Layout again = parse_layout(layout_to_json(layout), "again.json");
  ASSERT_TRUE(again.placement.has_value());
  EXPECT_EQ(again.placement->chosen, p.chosen);
  EXPECT_EQ(again.placement->site_points, p.site_points);
  EXPECT_EQ(again.placement->site_normals, p.site_normals);
  EXPECT_EQ(again.placement->steps[0].pbar_min, 0.5);
  EXPECT_EQ(again.placement->random_median_pbar_min, 0.1);
  EXPECT_EQ(again.placement->sites, "cube.obj");
  EXPECT_EQ(again.placement->min_separation, 0.012);
  EXPECT_EQ(again.placement->marker_diameter, 0.01);
}

// A file written before the sizes were recorded: point markers, no separation.
TEST(PlacementFields, SizesDefaultToPointMarkers) {
  const Layout layout = parse_layout(
      with("    \"min_separation\": 0.012,\n    \"marker_diameter\": 0.01,\n", ""), "old.json");
  ASSERT_TRUE(layout.placement.has_value());
  EXPECT_EQ(layout.placement->min_separation, 0.0);
  EXPECT_EQ(layout.placement->marker_diameter, 0.0);
}

// A camera or tracker placement records its objective's values (null: none); an affine one does
// not write them.
TEST(PlacementFields, ObjectiveValuesSurviveWithASensor) {
  std::string text = with("\"coverage\": 0.25}", "\"coverage\": 0.25, \"objective\": null}");
  text = with(text, "\"median_pbar_min\": 0.1}",
              "\"median_pbar_min\": 0.1, \"best_objective\": 3.5, \"median_objective\": null}");
  text =
      with(text, "\"sites\": \"cube.obj\",", "\"sites\": \"cube.obj\", \"objective_value\": 2.5,");
  text = with(text, "  \"placement\": {",
              "  \"sensor\": {\"type\": \"tracker\", \"targets\": [[0, 0, 1]], \"fle_rms\": 0.2},\n"
              "  \"placement\": {");
  const Layout layout = parse_layout(text, "placed.json");
  const LayoutPlacement& p = *layout.placement;
  EXPECT_EQ(p.steps[0].objective, std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.random_best_objective, 3.5);
  EXPECT_EQ(p.random_median_objective, std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.objective_value, 2.5);
  const Layout again = parse_layout(layout_to_json(layout), "again.json");
  EXPECT_EQ(layout_to_json(again), layout_to_json(layout));
  EXPECT_EQ(again.placement->objective_value, 2.5);
  EXPECT_EQ(again.placement->steps[0].objective, std::numeric_limits<double>::infinity());
  // Without a sensor the values are not written.
  Layout affine = layout;
  affine.sensor.reset();
  EXPECT_EQ(layout_to_json(affine).find("objective_value"), std::string::npos);
  EXPECT_THAT(error_of(with(text, ", \"median_objective\": null", "")),
              HasSubstr("give best_objective and median_objective together, or neither"));
  EXPECT_THAT(error_of(with(text, "\"objective_value\": 2.5", "\"objective_value\": -1")),
              HasSubstr("placement.objective_value: expected a finite number >= 0, or null"));
}

TEST(PlacementFields, BadBlocksNameTheirField) {
  EXPECT_THAT(error_of(with("\"chosen\": [0, 2, -1]", "\"chosen\": [0, 2]")),
              HasSubstr("placement.chosen: expected one site per marker"));
  EXPECT_THAT(error_of(with("\"chosen\": [0, 2, -1]", "\"chosen\": [0, 4, -1]")),
              HasSubstr("placement.chosen[1]"));
  EXPECT_THAT(error_of(with("\"coverage\": 0.25", "\"cover\": 0.25")),
              HasSubstr("placement.steps[0]"));
  EXPECT_THAT(error_of(with("\"trials\": 10", "\"trials\": -1")),
              HasSubstr("placement.random_baseline.trials"));
  EXPECT_THAT(error_of(with("\"site_normals\": [[1, 0, 0], ", "\"site_normals\": [")),
              HasSubstr("placement.site_normals"));
  EXPECT_THAT(error_of(with("\"objective\"", "\"purpose\"")), HasSubstr("purpose"));
  EXPECT_THAT(error_of(with("\"marker_diameter\": 0.01", "\"marker_diameter\": -0.01")),
              HasSubstr("placement.marker_diameter: expected a finite length >= 0"));
  EXPECT_THAT(error_of(with("\"min_separation\": 0.012", "\"min_separation\": \"1\"")),
              HasSubstr("placement.min_separation"));
}

}  // namespace
}  // namespace vantage::io

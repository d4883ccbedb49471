// The "sensor" block of a layout placed for a camera or a tracker (docs/math.md §21,
// "Objectives"): it survives a write and a read bit for bit, edits of the entries keep it, and a
// bad block gets one error naming its field.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/message_of.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"

namespace vantage::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kCamera = R"({
  "points": [[0.5, 0.1, 0.0], [0.0, 0.5, 0.1], [0.1, 0.0, 0.5], [-0.5, 0.0, 0.0]],
  "sensor": {"type": "camera", "distance": 3, "focal_px": 1000, "noise_px": 0.2,
             "samples": 2000, "aim": [0.1, 0.30000000000000004, -0.2], "statistic": "p95"}
})";

constexpr const char* kTracker = R"({
  "points": [[0.5, 0.1, 0.0], [0.0, 0.5, 0.1], [0.1, 0.0, 0.5], [-0.5, 0.0, 0.0]],
  "sensor": {"type": "tracker", "targets": [[0, 0, -2], [1, 1, 0]], "fle_rms": 0.25}
})";

std::string error_of(const std::string& text) {
  return testing::message_of([&] { parse_layout(text, "placed.json"); });
}

std::string with(const std::string& text, const std::string& from, const std::string& to) {
  std::string out = text;
  const std::size_t at = out.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return out.replace(at, from.size(), to);
}

TEST(SensorFields, ACameraSurvivesAWriteAndARead) {
  const Layout layout = parse_layout(kCamera, "cam.json");
  ASSERT_TRUE(layout.sensor.has_value());
  const Layout again = parse_layout(layout_to_json(layout), "again.json");
  ASSERT_TRUE(again.sensor.has_value());
  const LayoutSensor& s = *again.sensor;
  EXPECT_EQ(s.kind, LayoutSensor::Kind::kCamera);
  EXPECT_EQ(s.distances, std::vector<double>{3.0});
  EXPECT_EQ(s.focal_px, 1000.0);
  EXPECT_EQ(s.noise_px, 0.2);
  EXPECT_EQ(s.samples, 2000);
  EXPECT_EQ(s.aim, Eigen::Vector3d(0.1, 0.30000000000000004, -0.2));
  EXPECT_EQ(s.statistic, "p95");
  EXPECT_EQ(layout_to_json(again), layout_to_json(layout));
}

// An approach's distances, in their order; one distance is written as "distance".
TEST(SensorFields, AnApproachSurvivesAWriteAndARead) {
  const Layout layout =
      parse_layout(with(kCamera, "\"distance\": 3", "\"distances\": [5, 3, 2.5]"), "cam.json");
  EXPECT_EQ(layout.sensor->distances, (std::vector<double>{5.0, 3.0, 2.5}));
  const std::string text = layout_to_json(layout);
  EXPECT_THAT(text, HasSubstr("\"distances\""));
  EXPECT_EQ(layout_to_json(parse_layout(text, "again.json")), text);
  EXPECT_THAT(layout_to_json(parse_layout(kCamera, "one.json")), Not(HasSubstr("distances")));
}

TEST(SensorFields, ATrackerSurvivesAWriteAndARead) {
  const Layout rms = parse_layout(kTracker, "tool.json");
  const Layout again = parse_layout(layout_to_json(rms), "again.json");
  ASSERT_TRUE(again.sensor.has_value());
  EXPECT_EQ(again.sensor->kind, LayoutSensor::Kind::kTracker);
  ASSERT_EQ(again.sensor->targets.size(), 2u);
  EXPECT_EQ(again.sensor->targets[1], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(again.sensor->fle_rms, 0.25);
  const Layout sigma =
      parse_layout(with(kTracker, "\"fle_rms\": 0.25", "\"fle_sigma\": [0.1, 0.3]"), "s.json");
  const Layout sigma_again = parse_layout(layout_to_json(sigma), "again.json");
  EXPECT_EQ(sigma_again.sensor->fle_rms, 0.0);
  EXPECT_EQ(sigma_again.sensor->fle_sigma_perp, 0.1);
  EXPECT_EQ(sigma_again.sensor->fle_sigma_axial, 0.3);
}

// It describes the sensor, not the markers: removing a marker keeps it (the placement goes).
TEST(SensorFields, EditsOfTheEntriesKeepIt) {
  const Layout layout = without_entry(parse_layout(kTracker, "tool.json"), 3);
  ASSERT_TRUE(layout.sensor.has_value());
  EXPECT_EQ(layout.sensor->fle_rms, 0.25);
}

TEST(SensorFields, BadBlocksNameTheirField) {
  EXPECT_THAT(error_of(with(kCamera, "\"camera\"", "\"lidar\"")),
              HasSubstr("sensor.type: expected \"camera\" or \"tracker\", got \"lidar\""));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distance\": -3")),
              HasSubstr("sensor.distance: expected a finite number > 0"));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distance\": 3, \"distances\": [3, 4]")),
              HasSubstr("sensor.distances: give distance or distances, not both"));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distances\": [3]")),
              HasSubstr("sensor.distances: expected 2 to 64 numbers > 0 (one: distance)"));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distances\": [3, 0]")),
              HasSubstr("sensor.distances: expected 2 to 64"));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distances\": [3, 4, 3]")),
              HasSubstr("sensor.distances[2]: repeats an earlier distance"));
  EXPECT_THAT(error_of(with(kCamera, "\"distance\": 3", "\"distances\": [3, \"x\"]")),
              HasSubstr("sensor.distances"));
  EXPECT_THAT(error_of(with(kCamera, "\"samples\": 2000", "\"samples\": 20.5")),
              HasSubstr("sensor.samples: expected an integer in [100, 10000000]"));
  EXPECT_THAT(error_of(with(kCamera, "\"statistic\": \"p95\"", "\"statistic\": \"p50\"")),
              HasSubstr("sensor.statistic"));
  EXPECT_THAT(error_of(with(kCamera, "[0.1, 0.30000000000000004, -0.2]", "[0.1, 0.3]")),
              HasSubstr("sensor.aim"));
  EXPECT_THAT(error_of(with(kCamera, "\"focal_px\"", "\"focal\"")), HasSubstr("focal"));
  EXPECT_THAT(error_of(with(kTracker, "\"fle_rms\": 0.25", "\"fle_rms\": 0.25, \"distance\": 3")),
              HasSubstr("distance"));
  EXPECT_THAT(
      error_of(with(kTracker, "\"fle_rms\": 0.25", "\"fle_rms\": 0.25, \"fle_sigma\": [1, 1]")),
      HasSubstr("sensor.fle_rms: give fle_rms or fle_sigma, not both or neither"));
  EXPECT_THAT(error_of(with(kTracker, "\"fle_rms\": 0.25", "\"fle_sigma\": [0, 0]")),
              HasSubstr("sensor.fle_sigma"));
  EXPECT_THAT(error_of(with(kTracker, "[[0, 0, -2], [1, 1, 0]]", "[]")),
              HasSubstr("sensor.targets"));
  EXPECT_THAT(error_of(with(kTracker, "{\"type\": \"tracker\", ", "{")),
              HasSubstr("sensor.type: required"));
  EXPECT_THAT(error_of(R"({"vectors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
                          "sensor": {"type": "tracker", "targets": [[0, 0, 1]], "fle_rms": 0.2}})"),
              HasSubstr("sensor: a camera or tracker tracks marker points"));
}

}  // namespace
}  // namespace vantage::io

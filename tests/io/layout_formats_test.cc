#include "vantage/io/layout_formats.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"

namespace vantage::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string kExamples = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";

// The cube's corners are rotations of exact decimal offsets by 7-digit quaternions.
constexpr double kCubeTolerance = 1e-7;

// Decimal numbers are read with correct rounding: the file and this literal give the same double.
constexpr double kExact = 0.0;

TEST(LayoutFormats, ExtensionChoosesTheFormat) {
  EXPECT_EQ(layout_format_of("a/b.json"), LayoutFormat::kJson);
  EXPECT_EQ(layout_format_of("b.CSV"), LayoutFormat::kCsv);
  EXPECT_EQ(layout_format_of("tags.yaml"), LayoutFormat::kAprilTag);
  EXPECT_EQ(layout_format_of("tags.yml"), LayoutFormat::kAprilTag);
  try {
    layout_format_of("markers.txt");
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("markers.txt: cannot tell the layout format"));
    EXPECT_THAT(std::string(e.what()), HasSubstr("--format"));
  }
}

TEST(LayoutFormats, FormatNamesRoundTrip) {
  for (LayoutFormat f :
       {LayoutFormat::kAuto, LayoutFormat::kJson, LayoutFormat::kCsv, LayoutFormat::kAprilTag}) {
    EXPECT_EQ(layout_format_from_string(to_string(f), "--format"), f);
  }
  EXPECT_THROW(layout_format_from_string("xml", "--format"), InvalidArgument);
}

TEST(LayoutFormats, OverrideReadsAnyExtension) {
  LayoutReadOptions options;
  options.format = LayoutFormat::kCsv;
  const Layout layout = parse_layout_as("a,0,0,0\nb,1,0,0\nc,0,1,0\n", "markers.txt", options);
  EXPECT_EQ(layout.entries.cols(), 3);
  EXPECT_THROW(parse_layout_as("a,0,0,0\nb,1,0,0\nc,0,1,0\n", "markers.txt"), InvalidArgument);
}

TEST(LayoutFormats, CsvExampleMatchesTheJsonItStandsFor) {
  const Layout csv = load_layout(kExamples + "mocap_rigid_body.csv");
  EXPECT_EQ(csv.name, "mocap_rigid_body");
  ASSERT_EQ(csv.entries.cols(), 5);
  EXPECT_EIGEN_NEAR(csv.entries.col(4), Eigen::Vector3d(0.010, 0.015, 0.085), kExact);
  EXPECT_EIGEN_NEAR(csv.weights, (Eigen::VectorXd(5) << 1, 1, 0.5, 1, 0.5).finished(), kExact);
  // Written as JSON and read back: the same layout.
  const Layout again = parse_layout(layout_to_json(csv), "again.json");
  EXPECT_EIGEN_NEAR(again.entries, csv.entries, kExact);
  EXPECT_EIGEN_NEAR(again.weights, csv.weights, kExact);
}

TEST(LayoutFormats, AprilTagCubeCornersLieOnTheCubeFaces) {
  const Layout cube = load_layout(kExamples + "apriltag_cube.yaml");
  EXPECT_EQ(cube.name, "cube");
  ASSERT_EQ(cube.entries.cols(), 12);
  for (int tag = 0; tag < 3; ++tag) {
    // Tag 0 on the top face (z = 0.05), tag 1 on +x, tag 2 on +y; corners +-0.04 off centre.
    const int face_axis = tag == 0 ? 2 : tag - 1;
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d x = cube.entries.col(4 * tag + c);
      EXPECT_NEAR(x(face_axis), 0.05, kCubeTolerance) << tag << " " << c;
      for (int i = 0; i < 3; ++i) {
        if (i != face_axis) {
          EXPECT_NEAR(std::abs(x(i)), 0.04, kCubeTolerance) << tag << " " << c;
        }
      }
    }
  }
  LayoutReadOptions centres;
  centres.apriltag.tag_points = TagPoints::kCentres;
  const Layout centred = load_layout(kExamples + "apriltag_cube.yaml", centres);
  Eigen::Matrix3Xd expected(3, 3);
  expected << 0, 0.05, 0, 0, 0, 0.05, 0.05, 0, 0;
  EXPECT_EIGEN_NEAR(centred.entries, expected, kExact);
}

TEST(LayoutFormats, EveryFormatNamesItsMarkers) {
  EXPECT_EQ(load_layout(kExamples + "mocap_rigid_body.csv").names,
            (std::vector<std::string>{"hub", "arm_long", "arm_short", "arm_side", "mast"}));
  const Layout cube = load_layout(kExamples + "apriltag_cube.yaml");
  ASSERT_EQ(cube.names.size(), 12u);
  EXPECT_EQ(cube.names[0], "tag0_c0");
  EXPECT_EQ(cube.names[7], "tag1_c3");
  LayoutReadOptions centres;
  centres.apriltag.tag_points = TagPoints::kCentres;
  EXPECT_EQ(load_layout(kExamples + "apriltag_cube.yaml", centres).names,
            (std::vector<std::string>{"tag0", "tag1", "tag2"}));
}

// A scratch directory removed with the object.
struct Scratch {
  Scratch() {
    path = std::filesystem::temp_directory_path() /
           ("vantage_formats_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path);
  }
  ~Scratch() { std::filesystem::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::filesystem::path path;
};

TEST(LayoutFormats, SaveWritesTheFormatTheExtensionNames) {
  Scratch scratch;
  const Layout csv = load_layout(kExamples + "mocap_rigid_body.csv");
  save_layout(scratch.file("body.csv"), csv);
  save_layout(scratch.file("body.JSON"), csv);
  // The .csv file is CSV (a JSON reader refuses it) and the .JSON file is JSON; both hold the
  // same markers, weights and names.
  EXPECT_THROW(parse_layout(read_text_file(scratch.file("body.csv")), "body.csv"), InvalidArgument);
  const Layout from_csv = load_layout(scratch.file("body.csv"));
  const Layout from_json = load_layout(scratch.file("body.JSON"), {LayoutFormat::kJson, {}});
  for (const Layout* again : {&from_csv, &from_json}) {
    EXPECT_TRUE((again->entries.array() == csv.entries.array()).all());
    EXPECT_TRUE((again->weights.array() == csv.weights.array()).all());
    EXPECT_EQ(again->names, csv.names);
  }
}

TEST(LayoutFormats, SaveRefusesFormatsItCannotWriteAndWritesNothing) {
  Scratch scratch;
  const Layout triad = load_layout(kExamples + "triad.json");
  const Layout cube = load_layout(kExamples + "apriltag_cube.yaml");
  const std::pair<std::string, const Layout*> refused[] = {
      {"tags.yaml", &cube}, {"tags.yml", &cube},   {"layout.txt", &triad},
      {"layout", &triad},   {"triad.csv", &triad},  // directions: CSV holds markers
  };
  for (const auto& [name, layout] : refused) {
    try {
      save_layout(scratch.file(name), *layout);
      ADD_FAILURE() << name << " was written";
    } catch (const InvalidArgument& e) {
      EXPECT_THAT(std::string(e.what()), HasSubstr(scratch.file(name) + ": ")) << name;
      EXPECT_THAT(std::string(e.what()), Not(HasSubstr("\n")));
    }
    EXPECT_FALSE(std::filesystem::exists(scratch.file(name))) << name;
  }
  EXPECT_EQ(layout_write_format("a.json"), LayoutFormat::kJson);
  EXPECT_EQ(layout_write_format("a.Csv"), LayoutFormat::kCsv);
}

// Issue 36, item 8: a 50 MB single-line .ini value was echoed whole to stderr. A value quoted
// from a file is cut to io::kExcerptBytes and its size said, in every reader.
constexpr std::size_t kHugeValue = 5'000'000;
constexpr std::size_t kShortMessage = 400;
TEST(LayoutFormats, AHugeBadValueIsQuotedShort) {
  Scratch scratch;
  const std::string huge(kHugeValue, '7');
  const std::pair<std::string, std::string> files[] = {
      {"tool.ini", "[geometry]\ncount=" + huge + "x\n"},
      {"tool.csv", "name,x,y,z\na,1,2," + huge + "x\nb,1,2,3\nc,3,4,5\n"},
      {"tool.json", "{\"points\": [[0,0,0],[1,0,0],[0,1,0]], \"" + huge + "x\": 1}"},
      {"key.ini", huge + "x=1\n[geometry]\ncount=3\n"},
      {"section.ini", "[geometry]\ncount=3\n[" + huge + "x]\n[" + huge + "x]\n"},
      {"name.csv", "name,x,y,z\n" + huge + "x,1,2,q\nb,1,2,3\nc,3,4,5\n"},
      // JSON: a key on the path to a bad value, an overflowing number, an unterminated string.
      {"path.json", "{\"points\": [[0,0,0],[1,0,0],[0,1,0]], \"" + huge + "x\": {\"a\": [1, q]}}"},
      {"overflow.json", "{\"points\": [[0,0,0],[1,0,0],[0,1,1e" + huge + "]]}"},
      {"string.json", "{\"points\": [[0,0,0],[1,0,0],[0,1,\"" + huge + "\n]]}"},
  };
  for (const auto& [name, text] : files) {
    std::ofstream(scratch.file(name)) << text;
    try {
      load_layout(scratch.file(name));
      ADD_FAILURE() << name << " was read";
    } catch (const InvalidArgument& e) {
      const std::string message = e.what();
      EXPECT_LT(message.size(), kShortMessage) << name;
      // The quoted token is the value and what the lexer read around it: 5 000 00x bytes.
      EXPECT_THAT(message, HasSubstr("... (" + std::to_string(huge.size()).substr(0, 6)))
          << name << ": " << message.substr(0, kShortMessage);
    }
  }
}

TEST(LayoutFormats, JsonStillReadsAsBefore) {
  const Layout json = load_layout(kExamples + "triad.json");
  EXPECT_EIGEN_NEAR(json.entries, read_layout(kExamples + "triad.json").entries, kExact);
}

}  // namespace
}  // namespace vantage::io

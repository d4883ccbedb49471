#include "vantage/io/atracsys_geometry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"

namespace vantage::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Decimal numbers are read with correct rounding and written in digits that read back exactly:
// the file, the literal and the written-and-read value are the same double.
constexpr double kExact = 0.0;

// The geometry of the fusionTrack user manual v4.5.2, Listing 7.2 (fiducials 1 to 3 as the
// manual prints them; its fiducial 0 and id are not in the public excerpt, so they are ours),
// with a ';' comment, blanks, CR-LF line ends and an extra key the SDK ignores.
constexpr const char* kManualGeometry =
    "; geometry of the manual's example\r\n"
    "[geometry]\r\n"
    "count=4\r\n"
    "id = 150\r\n"
    "[fiducial0]\r\n"
    "x=0.0\r\ny=0.0\r\nz=0.0\r\n"
    "[fiducial1]\r\n"
    "x=-11.811\r\ny=500.934\r\nz=0.048\r\n"
    "[fiducial2]\r\n"
    "x=-11.77\r\ny=970.879\r\nz=0.266\r\n"
    "[fiducial3]\r\n"
    "x=-11.759\r\ny=1165.952\r\nz=-0.131\r\ncolour=green\r\n";

TEST(AtracsysGeometry, ReadsTheManualsExample) {
  const AtracsysGeometry g = parse_atracsys_geometry(kManualGeometry, "dir/geometry150.ini");
  EXPECT_EQ(g.id, 150u);
  EXPECT_FALSE(g.pivot.has_value());
  const Layout& layout = g.layout;
  EXPECT_EQ(layout.name, "geometry150");
  EXPECT_EQ(layout.mode, LayoutMode::kPoints);
  EXPECT_THAT(layout.names, ElementsAre("fiducial0", "fiducial1", "fiducial2", "fiducial3"));
  Eigen::Matrix3Xd expected(3, 4);
  expected << 0.0, -11.811, -11.77, -11.759,  //
      0.0, 500.934, 970.879, 1165.952,        //
      0.0, 0.048, 0.266, -0.131;
  EXPECT_EIGEN_NEAR(layout.entries, expected, kExact);
  EXPECT_EIGEN_NEAR(layout.weights, Eigen::VectorXd::Ones(4), kExact);
  EXPECT_FALSE(layout.visibility.has_value());
}

TEST(AtracsysGeometry, ReadsThePivotAndAnySectionOrder) {
  // As sawAtracsysFusionTrack's files have it: [geometry] last, a [pivot] for the tip.
  const AtracsysGeometry g = parse_atracsys_geometry(
      "[fiducial0]\nx=1\ny=0\nz=0\n[fiducial1]\nx=0\ny=1\nz=0\n[fiducial2]\nx=0\ny=0\nz=1\n"
      "[pivot]\nx=0\ny=0\nz=-150\n[geometry]\ncount=3\nid=4294967295\n",
      "tool.ini");
  EXPECT_EQ(g.id, 4294967295u);
  ASSERT_TRUE(g.pivot.has_value());
  EXPECT_EIGEN_NEAR(*g.pivot, Eigen::Vector3d(0, 0, -150), kExact);
  EXPECT_EIGEN_NEAR(g.layout.entries, Eigen::Matrix3d::Identity(), kExact);
}

TEST(AtracsysGeometry, WriteThenReadGivesTheSameBitsIdAndPivot) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
  int checked = 0;
  for (int n = kAtracsysMinFiducials; n <= kAtracsysMaxFiducials; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      Layout layout;
      layout.name = "random tool";
      layout.mode = LayoutMode::kPoints;
      layout.entries = Eigen::Matrix3Xd::NullaryExpr(3, n, [&] { return coordinate(rng); });
      layout.weights = Eigen::VectorXd::Ones(n);
      layout.candidates.resize(3, 0);
      const Eigen::Vector3d pivot(coordinate(rng), coordinate(rng), coordinate(rng));
      const std::uint32_t id = 101u + static_cast<std::uint32_t>(trial);
      const std::string text = layout_to_atracsys_geometry(layout, id, pivot);
      const AtracsysGeometry back = parse_atracsys_geometry(text, "geometry.ini");
      EXPECT_EQ(back.id, id);
      ASSERT_TRUE(back.pivot.has_value());
      EXPECT_TRUE((*back.pivot).cwiseEqual(pivot).all()) << text;
      EXPECT_TRUE(back.layout.entries.cwiseEqual(layout.entries).all()) << text;
      EXPECT_TRUE(atracsys_dropped_fields(layout).empty());
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4 * 20);
}

TEST(AtracsysGeometry, ListsWhatTheFileCannotHold) {
  Layout layout = parse_atracsys_layout(kManualGeometry, "g150.ini");
  EXPECT_TRUE(atracsys_dropped_fields(layout).empty());
  layout.names[2] = "tip side";
  layout.weights(1) = 2.0;
  MarkerVisibility visibility;
  visibility.normals = Eigen::Matrix3Xd::Zero(3, 4);
  visibility.normals.row(2).setOnes();
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(4, 90.0);
  layout.visibility = visibility;
  layout.description = "from the manual";
  EXPECT_THAT(atracsys_dropped_fields(layout),
              ElementsAre("names", "weights", "normals", "visibility", "description"));
  // They are left out; the positions are still written exactly.
  const Layout back = parse_atracsys_layout(layout_to_atracsys_geometry(layout, 150), "g.ini");
  EXPECT_TRUE(back.entries.cwiseEqual(layout.entries).all());
}

TEST(AtracsysGeometry, WriterRefusesWhatIsNoGeometry) {
  Layout layout = parse_atracsys_layout(kManualGeometry, "g150.ini");
  Layout seven = layout;
  seven.entries.conservativeResize(3, 7);
  seven.entries.rightCols(3) << 5, 6, 7, 8, 9, 10, 11, 12, 13;
  seven.weights = Eigen::VectorXd::Ones(7);
  seven.names.clear();
  EXPECT_THAT(
      [&] {
        try {
          layout_to_atracsys_geometry(seven, 150);
        } catch (const InvalidArgument& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      HasSubstr("points: an Atracsys geometry file holds 3 to 6 fiducials, the layout has 7"));
  Layout with_candidates = layout;
  with_candidates.candidates = Eigen::Matrix3Xd::Ones(3, 1);
  EXPECT_THROW(layout_to_atracsys_geometry(with_candidates, 150), InvalidArgument);
  Layout vectors = layout;
  vectors.mode = LayoutMode::kVectors;
  vectors.entries.col(0) << 1, 0, 0;
  vectors.names.clear();
  EXPECT_THROW(layout_to_atracsys_geometry(vectors, 150), InvalidArgument);
}

TEST(AtracsysGeometry, TheIdComesFromTheFileName) {
  EXPECT_EQ(atracsys_geometry_id_of("a/geometry150.ini"), 150u);
  EXPECT_EQ(atracsys_geometry_id_of("probe_7.INI"), 7u);
  EXPECT_EQ(atracsys_geometry_id_of("4294967295.ini"), 4294967295u);
  EXPECT_THROW(atracsys_geometry_id_of("tool.ini"), InvalidArgument);
  EXPECT_THROW(atracsys_geometry_id_of("geometry4294967296.ini"), InvalidArgument);
  EXPECT_EQ(layout_write_format("geometry150.ini"), LayoutFormat::kAtracsys);
  EXPECT_THROW(layout_write_format("tool.ini"), InvalidArgument);
  EXPECT_EQ(layout_write_format("tool.rom"), LayoutFormat::kNdiRom);
  EXPECT_EQ(layout_format_of("tool.ini"), LayoutFormat::kAtracsys);
  EXPECT_EQ(layout_format_from_string("atracsys", "--format"), LayoutFormat::kAtracsys);
  EXPECT_EQ(to_string(LayoutFormat::kAtracsys), std::string("atracsys"));
}

struct BadGeometry {
  const char* name;
  const char* text;
  const char* expected;  // the one error line must name the line, section and key
};

class BadGeometryFile : public ::testing::TestWithParam<BadGeometry> {};

TEST_P(BadGeometryFile, GivesOneLineNamingFileLineAndField) {
  std::string message;
  try {
    parse_atracsys_layout(GetParam().text, "bad.ini");
  } catch (const InvalidArgument& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().text;
  EXPECT_THAT(message, HasSubstr("bad.ini: "));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

#define VANTAGE_FIDUCIALS_012 \
  "[fiducial0]\nx=0\ny=0\nz=0\n[fiducial1]\nx=10\ny=0\nz=0\n[fiducial2]\nx=0\ny=10\nz=0\n"

const BadGeometry kBadGeometries[] = {
    {"Empty", "", "no [geometry] section"},
    {"NoGeometry", VANTAGE_FIDUCIALS_012, "no [geometry] section"},
    {"NoCount", "[geometry]\nid=150\n" VANTAGE_FIDUCIALS_012, "[geometry] (line 1): no count key"},
    {"NoId", "[geometry]\ncount=3\n" VANTAGE_FIDUCIALS_012, "[geometry] (line 1): no id key"},
    {"CountTooSmall", "[geometry]\ncount=2\nid=1\n" VANTAGE_FIDUCIALS_012,
     "line 2, [geometry] count: expected an integer from 3 to 6, got \"2\""},
    {"CountTooLarge", "[geometry]\ncount=7\nid=1\n", "line 2, [geometry] count: expected"},
    {"CountNotInteger", "[geometry]\ncount=3.0\nid=1\n", "got \"3.0\""},
    {"IdNegative", "[geometry]\ncount=3\nid=-1\n" VANTAGE_FIDUCIALS_012,
     "line 3, [geometry] id: expected an integer from 0 to 4294967295, got \"-1\""},
    {"IdTooLarge", "[geometry]\ncount=3\nid=4294967296\n" VANTAGE_FIDUCIALS_012,
     "line 3, [geometry] id"},
    {"MissingFiducial",
     "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=0\ny=0\nz=0\n[fiducial2]\nx=0\ny=1\nz=0\n",
     "no [fiducial1] section (count=3)"},
    {"FiducialBeyondCount", "[geometry]\ncount=3\nid=1\n" VANTAGE_FIDUCIALS_012 "[fiducial3]\n",
     "line 16, [fiducial3]: beyond count=3 of [geometry] (line 2)"},
    {"MissingY", "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=0\nz=0\n[fiducial1]\n",
     "[fiducial0] (line 4): no y key"},
    {"NotANumber",
     "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=0\ny=1.5mm\nz=0\n[fiducial1]\nx=1\ny=0\nz=0\n"
     "[fiducial2]\nx=0\ny=0\nz=1\n",
     "line 6, [fiducial0] y: expected a finite number (mm), got \"1.5mm\""},
    {"Empty value", "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=\ny=0\nz=0\n",
     "line 5, [fiducial0] x: expected a finite number (mm), got \"\""},
    {"Infinite", "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=1e999\ny=0\nz=0\n",
     "line 5, [fiducial0] x"},
    {"NaN", "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=nan\ny=0\nz=0\n", "line 5, [fiducial0] x"},
    {"PivotWithoutZ", "[geometry]\ncount=3\nid=1\n" VANTAGE_FIDUCIALS_012 "[pivot]\nx=0\ny=0\n",
     "[pivot] (line 16): no z key"},
    {"RepeatedSection", "[geometry]\ncount=3\nid=1\n[geometry]\n",
     "line 4: [geometry] repeats the section of line 1"},
    {"RepeatedKey", "[geometry]\ncount=3\ncount=4\n",
     "line 3, [geometry] count: repeats the key of line 2"},
    {"KeyBeforeSection", "count=3\n[geometry]\n",
     "line 1, count: a key before the first [section]"},
    {"Garbage", "[geometry]\ncount=3\nid=1\nhello\n",
     "line 4: expected a [section], a key=value line or a ';' comment, got \"hello\""},
    {"HashComment", "# comment\n[geometry]\n", "line 1: expected a [section]"},
    {"UnclosedSection", "[geometry\n", "line 1: expected ']' at the end"},
    {"EmptySection", "[ ]\n", "line 1: empty section name"},
    {"EmptyKey", "[geometry]\n=3\n", "line 2, [geometry]: empty key"},
    {"Coincident",
     "[geometry]\ncount=3\nid=1\n[fiducial0]\nx=0\ny=0\nz=0\n[fiducial1]\nx=0\ny=0\nz=0\n"
     "[fiducial2]\nx=0\ny=10\nz=0\n",
     "[fiducial1]"},
};

INSTANTIATE_TEST_SUITE_P(AtracsysGeometry, BadGeometryFile, ::testing::ValuesIn(kBadGeometries),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& c : name) {
                             if (c == ' ') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace vantage::io

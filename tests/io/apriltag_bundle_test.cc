#include "vantage/io/apriltag_bundle.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "support/eigen_testing.h"
#include "support/message_of.h"
#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Corners are rotations and shifts of exact decimal offsets: a few ulps of the inputs.
constexpr double kGeometryTolerance = 1e-14;

// Decimal numbers are read with correct rounding: the file and this literal give the same double.
constexpr double kExact = 0.0;
// A corner is the centre (|p| ~ 3, normal draws) plus a rotated offset of at most 0.25: tens of
// ulps of the centre.
constexpr double kRotatedTagTolerance = 1e-13;
// The cosine of two unit vectors is second order in their angle; what is left is the rounding of
// two normalisations and a dot product, far below this.
constexpr double kTurnTolerance = 1e-12;

std::string bundle(const std::string& tags, const std::string& name = "b") {
  return "tag_bundles:\n  - name: " + name + "\n    layout:\n" + tags;
}

std::string tag(int id, double size, const std::string& pose) {
  return "      - {id: " + std::to_string(id) + ", size: " + std::to_string(size) + ", " + pose +
         "}\n";
}

const std::string kIdentity = "x: 0, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0";

std::string error_of(const std::string& text, const AprilTagOptions& options = {}) {
  try {
    parse_apriltag_layout(text, "bad.yaml", options);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

struct BadBundle {
  const char* name;
  std::string text;
  const char* expected;  // the field and index the one error line must name
};

class BadAprilTagFile : public ::testing::TestWithParam<BadBundle> {};

TEST_P(BadAprilTagFile, GivesOneLineNamingFileFieldAndIndex) {
  const std::string message = error_of(GetParam().text);
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().text;
  EXPECT_THAT(message, HasSubstr("bad.yaml: "));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

const std::string kTwoTags =
    tag(0, 0.1, kIdentity) + tag(1, 0.1, "x: 1, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0");

const BadBundle kBadBundles[] = {
    {"NotYaml", "tag_bundles: [ {name: b, layout: [", "not valid YAML: line 1"},
    // Found by the fuzzer: after a NUL byte yaml-cpp quotes the next character (a newline) raw
    // in its message.
    {"NulThenNewline", std::string("a: b\0\nc\"\n", 9), "unknown escape character: \\x0a"},
    {"Scalar", "42", "the top level must be a YAML map"},
    {"NoBundles", "standalone_tags: []\n", "tag_bundles: missing"},
    {"BundlesNotAList", "tag_bundles: 3\n", "tag_bundles: expected a non-empty list"},
    {"EmptyBundles", "tag_bundles: []\n", "tag_bundles: expected a non-empty list"},
    {"BundleNotAMap", "tag_bundles: [3]\n", "tag_bundles[0]: expected a map"},
    {"NoLayout", "tag_bundles: [{name: b}]\n", "tag_bundles[0].layout: expected a list"},
    {"TagNotAMap", bundle("      - 5\n"), "tag_bundles[0].layout[0]: expected a map"},
    {"MissingSize", bundle("      - {id: 0, " + kIdentity + "}\n"),
     "tag_bundles[0].layout[0]: missing field \"size\""},
    {"MissingQz", bundle(tag(0, 0.1, "x: 0, y: 0, z: 0, qw: 1, qx: 0, qy: 0")),
     "tag_bundles[0].layout[0]: missing field \"qz\""},
    {"TextX",
     bundle(tag(0, 0.1, kIdentity) +
            "      - {id: 1, size: 0.1, x: far, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0}\n"),
     "tag_bundles[0].layout[1].x: expected a finite number"},
    {"NanY", bundle(tag(0, 0.1, "x: 0, y: .nan, z: 0, qw: 1, qx: 0, qy: 0, qz: 0")),
     "tag_bundles[0].layout[0].y: expected a finite number"},
    {"ListZ", bundle(tag(0, 0.1, "x: 0, y: 0, z: [1], qw: 1, qx: 0, qy: 0, qz: 0")),
     "tag_bundles[0].layout[0].z: expected a finite number"},
    {"NegativeId", bundle("      - {id: -1, size: 0.1, " + kIdentity + "}\n"),
     "tag_bundles[0].layout[0].id: expected a non-negative integer"},
    {"FractionalId", bundle("      - {id: 1.5, size: 0.1, " + kIdentity + "}\n"),
     "tag_bundles[0].layout[0].id: expected a non-negative integer"},
    {"RepeatedId", bundle(kTwoTags + tag(1, 0.1, kIdentity)),
     "tag_bundles[0].layout[2].id: tag 1 repeats layout[1]"},
    {"ZeroSize", bundle(tag(0, 0.0, kIdentity)), "tag_bundles[0].layout[0].size: must be > 0"},
    {"ZeroQuaternion", bundle(tag(0, 0.1, "x: 0, y: 0, z: 0, qw: 0, qx: 0, qy: 0, qz: 0")),
     "tag_bundles[0].layout[0].qw: zero quaternion"},
    {"CoincidentCorners",
     bundle(kTwoTags + tag(2, 0.1, "x: 1, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0")),
     "layout[2] (tag 2, corner 0): coincides with tag_bundles[0].layout[1] (tag 1, corner 0)"},
    {"TwoBundlesNoChoice", bundle(kTwoTags, "one") + "  - name: two\n    layout:\n" + kTwoTags,
     "2 bundles; choose one with --bundle (one, two)"},
    // Issue 22: a repeated key was accepted with its first value; unknown keys were ignored.
    {"DuplicateX",
     bundle("      - {id: 0, size: 0.05, x: 0.05, y: 0, z: 0, x: 9, qw: 1, qx: 0, qy: 0, qz: 0}\n" +
            kTwoTags.substr(kTwoTags.find('\n') + 1)),
     "tag_bundles[0].layout[0].x: duplicate key (each field may appear once)"},
    {"DuplicateBlockKey", "tag_bundles:\n  - name: b\n    name: c\n    layout:\n" + kTwoTags,
     "tag_bundles[0].name: duplicate key"},
    {"DuplicateTopLevel", bundle(kTwoTags) + "tag_bundles: []\n", "tag_bundles: duplicate key"},
    {"DuplicateInStandaloneTags",
     "standalone_tags: [{id: 1, size: 0.1, id: 2}]\n" + bundle(kTwoTags),
     "standalone_tags[0].id: duplicate key"},
    {"UnknownTagField",
     bundle(kTwoTags + "      - {id: 2, size: 0.1, x: 2, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0, "
                       "colour: red}\n"),
     "tag_bundles[0].layout[2]: unknown field \"colour\" (expected id, size, x, y, z, qw, qx, "
     "qy, qz)"},
    {"MisspelledTagField",
     bundle("      - {id: 0, size: 0.1, X: 0, y: 0, z: 0, qw: 1, qx: 0, "
            "qy: 0, qz: 0}\n"),
     "tag_bundles[0].layout[0]: unknown field \"X\""},
    {"UnknownBundleField", "tag_bundles:\n  - name: b\n    frame: cube\n    layout:\n" + kTwoTags,
     "tag_bundles[0]: unknown field \"frame\" (expected name, layout)"},
    {"UnknownTopLevelField", "tag_bundle: []\n" + bundle(kTwoTags),
     "unknown field \"tag_bundle\" (expected standalone_tags, tag_bundles)"},
};

INSTANTIATE_TEST_SUITE_P(AprilTagBundle, BadAprilTagFile, ::testing::ValuesIn(kBadBundles),
                         [](const auto& info) { return std::string(info.param.name); });

// Issue 36, item 8: a name from the file (or --bundle) is quoted as an excerpt, and the list of
// the file's bundles stops at ten, so that a 100 kB name is not a 100 kB message.
TEST(AprilTagBundle, LongNamesAreQuotedAsExcerptsAndTheListStops) {
  constexpr std::size_t kShortMessage = 1000;
  const std::string long_name(100000, 'n');
  std::string text = bundle(kTwoTags, long_name);
  for (int b = 0; b < 11; ++b) {
    text += "  - name: b" + std::to_string(b) + "\n    layout:\n" + kTwoTags;
  }
  const std::string choose = error_of(text);
  EXPECT_THAT(choose, HasSubstr("12 bundles; choose one with --bundle (" + std::string(60, 'n') +
                                "... (100000 bytes), b0, b1"));
  EXPECT_THAT(choose, HasSubstr(", b8, and 2 more)"));
  EXPECT_LT(choose.size(), kShortMessage);
  AprilTagOptions options;
  options.bundle = long_name + "x";
  const std::string missing = error_of(text, options);
  EXPECT_THAT(missing,
              HasSubstr("no bundle named \"" + std::string(60, 'n') + "... (100001 bytes)"));
  EXPECT_LT(missing.size(), kShortMessage);
  EXPECT_THAT(testing::message_of([&] { tag_points_from_string(long_name, "--tag-points"); }),
              HasSubstr("--tag-points: expected corners or centres, got \"" + std::string(60, 'n') +
                        "... (100000 bytes)\""));
}

TEST(AprilTagBundle, IdentityTagCornersAreHalfSizeOffsetsInApriltagRosOrder) {
  const AprilTagMarkers m = parse_apriltag_markers(
      bundle(tag(7, 0.2, "x: 1, y: 2, z: 3, qw: 1, qx: 0, qy: 0, qz: 0") + tag(8, 0.1, kIdentity)),
      "t.yaml");
  ASSERT_EQ(m.layout.entries.cols(), 8);
  EXPECT_EQ(m.layout.mode, LayoutMode::kPoints);
  EXPECT_EQ(m.layout.name, "b");
  EXPECT_EIGEN_NEAR(m.layout.entries.col(0), Eigen::Vector3d(0.9, 1.9, 3), kGeometryTolerance);
  EXPECT_EIGEN_NEAR(m.layout.entries.col(1), Eigen::Vector3d(1.1, 1.9, 3), kGeometryTolerance);
  EXPECT_EIGEN_NEAR(m.layout.entries.col(2), Eigen::Vector3d(1.1, 2.1, 3), kGeometryTolerance);
  EXPECT_EIGEN_NEAR(m.layout.entries.col(3), Eigen::Vector3d(0.9, 2.1, 3), kGeometryTolerance);
  EXPECT_EQ(m.tag_ids[3], 7);
  EXPECT_EQ(m.tag_ids[4], 8);
  EXPECT_EQ(m.corners[6], 2);
  EXPECT_EIGEN_NEAR(m.layout.weights, Eigen::VectorXd::Ones(8), kExact);
}

TEST(AprilTagBundle, RotatedTagsKeepTheirSizeAndLieInTheirPlane) {
  std::mt19937 rng(vantage::testing::kSeed);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    const double scale = 0.5 + trial;  // the reader normalises q itself
    const Eigen::Vector3d p(normal(rng), normal(rng), normal(rng));
    const double size = 0.05 + 0.01 * trial;
    char pose[256];
    std::snprintf(pose, sizeof pose,
                  "x: %.17g, y: %.17g, z: %.17g, qw: %.17g, qx: %.17g, qy: %.17g, qz: %.17g", p.x(),
                  p.y(), p.z(), scale * q.w(), scale * q.x(), scale * q.y(), scale * q.z());
    const AprilTagMarkers m = parse_apriltag_markers(
        bundle(tag(0, size, pose) + tag(1, 0.01, "x: 9, y: 9, z: 9, qw: 1, qx: 0, qy: 0, qz: 0")),
        "t.yaml");
    const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
    const Eigen::Matrix3Xd corners = m.layout.entries.leftCols(4);
    EXPECT_EIGEN_NEAR(corners.rowwise().mean(), p, kRotatedTagTolerance);
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d edge = corners.col((c + 1) % 4) - corners.col(c);
      EXPECT_NEAR(edge.norm(), size, kRotatedTagTolerance) << trial;
      EXPECT_NEAR(R.col(2).dot(corners.col(c) - p), 0.0, kRotatedTagTolerance)
          << trial;  // in the tag plane
    }
    // Counter-clockwise about the tag normal: (c1 - c0) x (c2 - c1) is along +z_tag.
    const Eigen::Vector3d turn =
        (corners.col(1) - corners.col(0)).cross(corners.col(2) - corners.col(1));
    EXPECT_NEAR(turn.normalized().dot(R.col(2)), 1.0, kTurnTolerance) << trial;
    // Each corner's normal is the side its corners turn counter-clockwise about: the tag's face.
    ASSERT_TRUE(m.layout.visibility.has_value());
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(m.layout.visibility->normals.col(c).dot(turn.normalized()), 1.0, kTurnTolerance);
    }
  }
}

TEST(AprilTagBundle, CentresModeGivesOneMarkerPerTagAtItsPosition) {
  AprilTagOptions options;
  options.tag_points = TagPoints::kCentres;
  const AprilTagMarkers m = parse_apriltag_markers(
      bundle(kTwoTags + tag(5, 0.1, "x: 0, y: 2, z: 0.5, qw: 0, qx: 1, qy: 0, qz: 0")), "t.yaml",
      options);
  Eigen::Matrix3Xd expected(3, 3);
  expected << 0, 1, 0, 0, 0, 2, 0, 0, 0.5;
  EXPECT_EIGEN_NEAR(m.layout.entries, expected, kExact);
  EXPECT_EQ(m.corners[2], -1);
}

TEST(AprilTagBundle, BundleIsChosenByName) {
  const std::string text = bundle(kTwoTags, "one") + "  - name: two\n    layout:\n" + kTwoTags +
                           tag(2, 0.1, "x: 0, y: 3, z: 0, qw: 1, qx: 0, qy: 0, qz: 0");
  AprilTagOptions options;
  options.bundle = "two";
  const Layout layout = parse_apriltag_layout(text, "t.yaml", options);
  EXPECT_EQ(layout.name, "two");
  EXPECT_EQ(layout.entries.cols(), 12);
  options.bundle = "three";
  EXPECT_THAT(error_of(text, options), HasSubstr("no bundle named \"three\" (one, two)"));
}

TEST(AprilTagBundle, AliasesAreCheckedOnceNotOncePerUse) {
  // Each level refers to the one before ten times: 10^8 uses of the first list, but every node
  // is checked once (the walk would take hours otherwise). The unknown key is still found.
  std::string text = "l0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int level = 1; level <= 8; ++level) {
    const std::string previous = "*l" + std::to_string(level - 1);
    text += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", " : "") + previous;
    text += "]\n";
  }
  text += bundle(kTwoTags);
  EXPECT_THAT(error_of(text), HasSubstr("unknown field \"l0\""));
}

TEST(AprilTagBundle, StandaloneTagsAreAllowedAndNotRead) {
  const Layout layout = parse_apriltag_layout(
      "standalone_tags: [{id: 20, size: 0.05, name: loose}]\n" + bundle(kTwoTags), "t.yaml");
  EXPECT_EQ(layout.entries.cols(), 8);
}

TEST(AprilTagBundle, TagPointsNamesParse) {
  EXPECT_EQ(tag_points_from_string("corners", "--tag-points"), TagPoints::kCorners);
  EXPECT_EQ(tag_points_from_string("centres", "--tag-points"), TagPoints::kCentres);
  EXPECT_EQ(tag_points_from_string("centers", "--tag-points"), TagPoints::kCentres);
  EXPECT_THROW(tag_points_from_string("edges", "--tag-points"), InvalidArgument);
}

}  // namespace
}  // namespace vantage::io

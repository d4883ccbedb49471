#include "vantage/io/layout_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

// Decimal numbers are read with correct rounding: the file and this literal give the same double.
constexpr double kExact = 0.0;
// A pair weight is one correctly rounded sqrt or mean of small integers: at most one ulp of 6.5.
constexpr double kPairWeightTolerance = 1e-15;

using ::testing::HasSubstr;
using ::testing::Not;

std::string error_of(const std::string& text) {
  try {
    parse_layout(text, "bad.json");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

struct BadLayout {
  const char* name;
  const char* text;
  const char* expected;  // the field (and index) the one error line must name
};

class BadLayoutFile : public ::testing::TestWithParam<BadLayout> {};

TEST_P(BadLayoutFile, GivesOneLineNamingFileFieldAndIndex) {
  const std::string message = error_of(GetParam().text);
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().text;
  EXPECT_THAT(message, HasSubstr("bad.json: "));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

const BadLayout kBadLayouts[] = {
    {"NotJson", "{\"vectors\": [[1,0,0],", "not valid JSON"},
    {"Empty", "", "not valid JSON"},
    {"RootNotObject", "[[1,0,0],[0,1,0]]", "top level"},
    {"BothVectorsAndPoints", R"({"vectors": [[1,0,0],[0,1,0]], "points": [[1,0,0],[0,1,0]]})",
     "not both"},
    {"NeitherVectorsNorPoints", R"({"name": "x"})", "vectors/points: missing"},
    {"UnknownField", R"({"vectors": [[1,0,0],[0,1,0]], "weight": [1,1]})", "\"weight\""},
    {"VectorsNotAList", R"({"vectors": 3})", "vectors: expected a list"},
    {"WrongArity", R"({"vectors": [[1,0,0],[0,1]]})", "vectors[1]: expected 3 numbers, got 2"},
    {"EntryNotAList", R"({"vectors": [[1,0,0], 5]})", "vectors[1]: expected 3 numbers"},
    {"NotANumber", R"({"vectors": [[1,0,0],[0,"y",0]]})", "vectors[1][1]: expected a number"},
    // JSON has no NaN or Inf literals and 1e999 is beyond double range: the reader names where.
    {"Overflow", R"({"vectors": [[1,0,0],[0,1,1e999]]})", "vectors[1][2]: number out of range"},
    {"NegativeOverflow", R"({"weights": [1, -1e400], "vectors": [[1,0,0],[0,1,0]]})",
     "weights[1]: number out of range"},
    {"NaNLiteral", R"({"vectors": [[1,0,0],[0,1,NaN]]})", "vectors[1][2]: not a finite number"},
    {"InfinityLiteral", R"({"vectors": [[1,0,0],[Infinity,1,0]]})",
     "vectors[1][0]: not a finite number"},
    {"MinusInfinityLiteral", R"({"vectors": [[1,0,0],[0,-Infinity,0]]})",
     "vectors[1][1]: not a finite number"},
    {"LowercaseNan", R"({"points": [[1,0,0],[0,1,0],[0,0,nan]]})",
     "points[2][2]: not a finite number"},
    {"DuplicateKey", R"({"vectors": [[1,0,0],[0,1,0]], "vectors": [[0,0,1],[0,1,0]]})",
     "vectors: duplicate key"},
    {"DuplicateName", R"({"name": "a", "vectors": [[1,0,0],[0,1,0]], "name": "b"})",
     "name: duplicate key"},
    {"ZeroLengthVector", R"({"vectors": [[1,0,0],[0,0,0],[0,0,1]]})",
     "vectors[1]: zero-length vector"},
    {"CoincidentPoints", R"({"points": [[1,0,0],[0,1,0],[1,0,0]]})",
     "points[2]: coincides with points[0]"},
    {"TooFewVectors", R"({"vectors": [[1,0,0]]})", "vectors: need at least 2"},
    {"NoVectors", R"({"vectors": []})", "vectors: need at least 2"},
    {"WeightsWrongLength", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1]})",
     "weights: expected 2 entries"},
    {"WeightZero", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1, 0]})",
     "weights[1]: must be > 0"},
    {"WeightNegative", R"({"points": [[1,0,0],[0,1,0],[0,0,1]], "weights": [-1, 1, 1]})",
     "weights[0]: must be > 0"},
    {"WeightNotNumber", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1, null]})",
     "weights[1]: expected a number"},
    {"CandidateWrongArity", R"({"vectors": [[1,0,0],[0,1,0]], "candidates": [[1,2]]})",
     "candidates[0]: expected 3 numbers"},
    {"CandidateZero", R"({"vectors": [[1,0,0],[0,1,0]], "candidates": [[0,0,0]]})",
     "candidates[0]: zero-length"},
    {"NameNotString", R"({"name": 3, "vectors": [[1,0,0],[0,1,0]]})", "name: expected a string"},
    {"DescriptionNotString", R"({"description": [], "vectors": [[1,0,0],[0,1,0]]})",
     "description: expected a string"},
    {"TwoPoints", R"({"points": [[0,0,0],[1,0,0]]})", "points: need at least 3 points"},
    {"NearlyCoincidentPoints", R"({"points": [[0,0,0],[1,0,0],[1e-200,0,0]]})",
     "points[2]: coincides with points[0]"},
    // Coincidence is relative to the layout's own scale: 1e-13 apart at coordinates ~1.
    {"CoincidentRelativeToScale", R"({"points": [[0,0,0],[1,0,0],[2,2,2],[1,1e-13,0]]})",
     "points[3]: coincides with points[1]"},
    {"FirstCoincidenceReported", R"({"points": [[5,0,0],[0,0,0],[1,1,1],[0,0,0],[5,0,0]]})",
     "points[3]: coincides with points[1]"},
    {"HugePoint", R"({"points": [[1e308,0,0],[-1e308,0,0],[0,1,0]]})",
     "points[0]: coordinates beyond"},
    {"TinyVector", R"({"vectors": [[1,0,0],[1e-320,0,0]]})", "vectors[1]: length outside"},
    {"HugeWeight", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1e200, 1]})",
     "weights[0]: must be <= 1e100"},
    {"NamesNotAList", R"({"vectors": [[1,0,0],[0,1,0]], "names": "xy"})",
     "names: expected a list of strings"},
    {"NameEntryNotString", R"({"vectors": [[1,0,0],[0,1,0]], "names": ["x", 2]})",
     "names[1]: expected a string"},
    {"NamesWrongLength", R"({"points": [[1,0,0],[0,1,0],[0,0,1]], "names": ["a", "b"]})",
     "names: expected 3 entries (one per point), got 2"},
    {"NameEmpty", R"({"vectors": [[1,0,0],[0,1,0]], "names": ["x", ""]})", "names[1]: empty name"},
    {"NameRepeated", R"({"points": [[1,0,0],[0,1,0],[0,0,1]], "names": ["a", "b", "a"]})",
     "names[2]: repeats names[0]"},
    // Found by the fuzzer: a key with an escaped newline, named in the error, kept it raw. Control
    // characters of the user's text are written \xNN.
    {"NewlineInKeyOfBadJson", R"({"po\ntsanem14": [1, )", "not valid JSON: po\\x0atsanem14"},
    {"ControlCharactersInUnknownKey", R"({"vectors": [[1,0,0],[0,1,0]], "we\r\u0001ird": 1})",
     "we\\x0d\\x01ird"},
};

INSTANTIATE_TEST_SUITE_P(LayoutFile, BadLayoutFile, ::testing::ValuesIn(kBadLayouts),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(LayoutFile, ParsesDirectionModeWithDefaults) {
  const Layout layout = parse_layout(R"({"vectors": [[1,0,0],[0,2,0],[0,0,3]]})", "t.json");
  EXPECT_EQ(layout.mode, LayoutMode::kVectors);
  EXPECT_EQ(layout.entries.cols(), 3);
  EXPECT_EIGEN_NEAR(layout.weights, Eigen::VectorXd::Ones(3), kExact);
  EXPECT_EQ(layout.candidates.cols(), 0);
  EXPECT_EQ(layout.name, "");
}

TEST(LayoutFile, PointModeExpandsToWeightedFreeVectors) {
  const Layout layout = parse_layout(
      R"({"name": "p", "points": [[0,0,0],[1,0,0],[0,2,0]], "weights": [1, 4, 9]})", "t.json");
  EXPECT_EQ(layout.mode, LayoutMode::kPoints);
  const DataVectors data = data_vectors(layout);
  ASSERT_EQ(data.vectors.cols(), 3);
  EXPECT_EIGEN_NEAR(data.vectors.col(0), Eigen::Vector3d(1, 0, 0), kExact);         // z1 - z0
  EXPECT_EIGEN_NEAR(data.vectors.col(1), Eigen::Vector3d(0, 2, 0), kExact);         // z2 - z0
  EXPECT_EIGEN_NEAR(data.vectors.col(2), Eigen::Vector3d(-1, 2, 0), kExact);        // z2 - z1
  EXPECT_EIGEN_NEAR(data.weights, Eigen::Vector3d(2, 3, 6), kPairWeightTolerance);  // sqrt(w_i w_j)
  EXPECT_EIGEN_NEAR(data_vectors(layout, PairWeighting::kArithmeticMean).weights,
                    Eigen::Vector3d(2.5, 5, 6.5), kPairWeightTolerance);
  EXPECT_EQ(data.pairs[2], std::make_pair(1, 2));
}

TEST(LayoutFile, RoundTripsThroughWrite) {
  const Layout layout = parse_layout(
      R"({"name": "rt", "description": "round trip", "points": [[0,0,0],[1,0.5,0],[0,2,-1]],
          "weights": [1, 2, 3],
          "candidates": [[0.25, 0.5, 0.75]]})",
      "t.json");
  const Layout again = parse_layout(layout_to_json(layout), "again.json");
  EXPECT_EQ(again.name, "rt");
  EXPECT_EQ(again.description, "round trip");
  EXPECT_EQ(again.mode, LayoutMode::kPoints);
  EXPECT_EIGEN_NEAR(again.entries, layout.entries, kExact);
  EXPECT_EIGEN_NEAR(again.weights, layout.weights, kExact);
  EXPECT_EIGEN_NEAR(again.candidates, layout.candidates, kExact);
}

// Marker names are part of the file: read, written back in entry order, read again.
TEST(LayoutFile, NamesRoundTripAndAreOptional) {
  const Layout layout = parse_layout(
      R"({"points": [[0,0,0],[1,0.5,0],[0,2,-1]], "names": ["hub", "arm 1", "LED3"]})", "t.json");
  EXPECT_EQ(layout.names, (std::vector<std::string>{"hub", "arm 1", "LED3"}));
  EXPECT_EQ(layout.entry_name(1), "arm 1");
  const std::string text = layout_to_json(layout);
  EXPECT_THAT(text, HasSubstr("\"names\""));
  EXPECT_EQ(parse_layout(text, "again.json").names, layout.names);
  // Unnamed layouts stay unnamed in the file; their entries are called by their index.
  const Layout unnamed = parse_layout(R"({"vectors": [[1,0,0],[0,1,0]]})", "t.json");
  EXPECT_TRUE(unnamed.names.empty());
  EXPECT_THAT(layout_to_json(unnamed), Not(HasSubstr("names")));
  EXPECT_EQ(unnamed.entry_name(1), "v1");
  EXPECT_EQ(unused_entry_name(layout, "added"), "added1");
}

// Found by the fuzzer: a name read from a YAML or CSV file need not be UTF-8; writing it as JSON
// threw nlohmann's type_error. The bytes become U+FFFD and the layout round-trips.
TEST(LayoutFile, NonUtf8NameIsWrittenAsReplacementCharacters) {
  Layout layout = parse_layout(R"({"name": "x", "vectors": [[1,0,0],[0,1,0],[0,0,1]]})", "t.json");
  layout.name = "bad \xc3( name";
  std::string text;
  ASSERT_NO_THROW(text = layout_to_json(layout));
  const Layout again = parse_layout(text, "again.json");
  EXPECT_EQ(again.name, "bad \xef\xbf\xbd( name");
  EXPECT_EIGEN_NEAR(again.entries, layout.entries, kExact);
}

TEST(LayoutFile, CoincidenceIsScaleInvariant) {
  // The same layout in units from 1e-140 to 1e140: accepted at every scale (an absolute
  // threshold would call the small ones coincident), and the same near-coincidence (1e-13 of
  // the extent) rejected at every scale.
  for (const double scale : {1e-140, 1e-100, 1.0, 1e100, 1e140}) {
    Layout layout;
    layout.mode = LayoutMode::kPoints;
    layout.entries.resize(3, 4);
    layout.entries << 0, 1, 0, 0,  //
        0, 0, 1, 0,                //
        0, 0, 0, 1;
    layout.entries *= scale;
    layout.weights = Eigen::VectorXd::Ones(4);
    EXPECT_NO_THROW(layout.validate()) << scale;
    layout.entries.col(3) = layout.entries.col(1) + Eigen::Vector3d(0, 1e-13 * scale, 0);
    EXPECT_THROW(layout.validate(), InvalidArgument) << scale;
  }
}

TEST(LayoutFile, ManyPointsValidateWithoutQuadraticWork) {
  // 200 000 points on a 2-D grid (many share a coordinate): the sweep finds no coincidence
  // and finds the one planted duplicate, naming the later index.
  constexpr int kSide = 400, kPoints = kSide * 500;
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, kPoints);
  for (int k = 0; k < kPoints; ++k) layout.entries.col(k) << k % kSide, k / kSide, 0.0;
  layout.weights = Eigen::VectorXd::Ones(kPoints);
  EXPECT_NO_THROW(layout.validate());
  layout.entries.col(kPoints - 1) = layout.entries.col(12345);
  try {
    layout.validate();
    FAIL() << "duplicate not found";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("points[" + std::to_string(kPoints - 1) +
                                                 "]: coincides with points[12345]"));
  }
}

TEST(LayoutFile, FreeVectorCountCannotOverflow) {
  EXPECT_EQ(free_vector_count(0), 0);
  EXPECT_EQ(free_vector_count(3), 3);
  EXPECT_EQ(free_vector_count(50000), Eigen::Index{1249975000});  // > INT_MAX / 2
  EXPECT_EQ(free_vector_count(Eigen::Index{3'000'000'001}),
            Eigen::Index{3'000'000'001} * Eigen::Index{1'500'000'000});
  // 50 000 points would need 1.25e9 free vectors: a clear error, not int overflow or bad_alloc.
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = Eigen::Matrix3Xd::Zero(3, 50000);
  for (int k = 0; k < 50000; ++k) layout.entries(0, k) = k;
  layout.weights = Eigen::VectorXd::Ones(50000);
  try {
    data_vectors(layout);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("50000 points give 1249975000 free vectors"));
  }
}

TEST(LayoutFile, WriteRefusesToOverwriteUnlessTold) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "vantage_layout_file_test.json").string();
  std::filesystem::remove(path);
  const Layout layout = parse_layout(R"({"vectors": [[1,0,0],[0,1,0]]})", "t.json");
  write_layout(path, layout);
  EXPECT_THROW(write_layout(path, layout), InvalidArgument);
  EXPECT_NO_THROW(write_layout(path, layout, /*overwrite=*/true));
  EXPECT_EIGEN_NEAR(read_layout(path).entries, layout.entries, kExact);
  std::filesystem::remove(path);
}

TEST(LayoutFile, MissingFileNamesThePath) {
  try {
    read_layout("/nonexistent/layout.json");
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("/nonexistent/layout.json: cannot open"));
  }
}

TEST(LayoutFile, BundledExamplesParse) {
  for (const char* name : {"triad", "note3_four_vectors", "coplanar_fan", "satellite"}) {
    const Layout layout =
        read_layout(std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json");
    EXPECT_GE(layout.entries.cols(), 2) << name;
    EXPECT_FALSE(layout.name.empty()) << name;
  }
}

}  // namespace
}  // namespace vantage::io

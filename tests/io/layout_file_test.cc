#include "vantage/io/layout_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

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
    // JSON has no NaN or Inf literals; a number beyond double range fails in the JSON reader.
    {"Overflow", R"({"vectors": [[1,0,0],[0,1e999,0]]})", "number overflow parsing '1e999'"},
    {"NaNLiteral", R"({"vectors": [[1,0,0],[0,NaN,0]]})", "not valid JSON"},
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
    {"HugePoint", R"({"points": [[1e308,0,0],[-1e308,0,0],[0,1,0]]})",
     "points[0]: coordinates beyond"},
    {"TinyVector", R"({"vectors": [[1,0,0],[1e-320,0,0]]})", "vectors[1]: length outside"},
    {"HugeWeight", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1e200, 1]})",
     "weights[0]: must be <= 1e100"},
};

INSTANTIATE_TEST_SUITE_P(LayoutFile, BadLayoutFile, ::testing::ValuesIn(kBadLayouts),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(LayoutFile, ParsesDirectionModeWithDefaults) {
  const Layout layout = parse_layout(R"({"vectors": [[1,0,0],[0,2,0],[0,0,3]]})", "t.json");
  EXPECT_EQ(layout.mode, LayoutMode::kVectors);
  EXPECT_EQ(layout.entries.cols(), 3);
  EXPECT_EIGEN_NEAR(layout.weights, Eigen::VectorXd::Ones(3), 0.0);
  EXPECT_EQ(layout.candidates.cols(), 0);
  EXPECT_EQ(layout.name, "");
}

TEST(LayoutFile, PointModeExpandsToWeightedFreeVectors) {
  const Layout layout = parse_layout(
      R"({"name": "p", "points": [[0,0,0],[1,0,0],[0,2,0]], "weights": [1, 4, 9]})", "t.json");
  EXPECT_EQ(layout.mode, LayoutMode::kPoints);
  const DataVectors data = data_vectors(layout);
  ASSERT_EQ(data.vectors.cols(), 3);
  EXPECT_EIGEN_NEAR(data.vectors.col(0), Eigen::Vector3d(1, 0, 0), 0.0);   // z1 - z0
  EXPECT_EIGEN_NEAR(data.vectors.col(1), Eigen::Vector3d(0, 2, 0), 0.0);   // z2 - z0
  EXPECT_EIGEN_NEAR(data.vectors.col(2), Eigen::Vector3d(-1, 2, 0), 0.0);  // z2 - z1
  EXPECT_EIGEN_NEAR(data.weights, Eigen::Vector3d(2, 3, 6), 1e-15);        // sqrt(w_i w_j)
  EXPECT_EIGEN_NEAR(data_vectors(layout, PairWeighting::kArithmeticMean).weights,
                    Eigen::Vector3d(2.5, 5, 6.5), 1e-15);
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
  EXPECT_EIGEN_NEAR(again.entries, layout.entries, 0.0);
  EXPECT_EIGEN_NEAR(again.weights, layout.weights, 0.0);
  EXPECT_EIGEN_NEAR(again.candidates, layout.candidates, 0.0);
}

TEST(LayoutFile, WriteRefusesToOverwriteUnlessTold) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "vantage_layout_file_test.json").string();
  std::filesystem::remove(path);
  const Layout layout = parse_layout(R"({"vectors": [[1,0,0],[0,1,0]]})", "t.json");
  write_layout(path, layout);
  EXPECT_THROW(write_layout(path, layout), InvalidArgument);
  EXPECT_NO_THROW(write_layout(path, layout, /*overwrite=*/true));
  EXPECT_EIGEN_NEAR(read_layout(path).entries, layout.entries, 0.0);
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

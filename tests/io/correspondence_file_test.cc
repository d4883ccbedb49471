#include "vantage/io/correspondence_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::string& text) {
  try {
    parse_correspondences(text, "c.json");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(CorrespondenceFile, ParsesEveryField) {
  const CorrespondenceFile file = parse_correspondences(
      R"({"model": [[0,0,0],[1,0,0]], "measured": [[1,1,1],[2,1,1]], "image": [[0,0],[1,0]],
          "weights": [1, 2]})",
      "c.json");
  EXPECT_TRUE(file.has_model && file.has_measured && file.has_image);
  EXPECT_FALSE(file.has_image1);
  EXPECT_EQ(file.model.cols(), 2);
  EXPECT_EQ(file.weights(1), 2.0);
  EXPECT_NO_THROW(file.require({"model", "measured"}, "orient"));
  EXPECT_THROW(file.require({"image1"}, "two-view"), InvalidArgument);
}

TEST(CorrespondenceFile, BadFilesNameTheField) {
  EXPECT_THAT(error_of(R"({"model": [[0,0,0]], "measured": [[1,1,1],[2,2,2]]})"),
              HasSubstr("c.json: measured: has 2 entries but model has 1"));
  EXPECT_THAT(error_of(R"({"model": [[0,0,0]], "image": [[1,1,1]]})"),
              HasSubstr("image[0]: expected 2 numbers, got 3"));
  EXPECT_THAT(error_of(R"({"measured": [[0,0,0]]})"), HasSubstr("measured: given without"));
  EXPECT_THAT(error_of(R"({"image1": [[0,0]]})"), HasSubstr("image2: missing"));
  EXPECT_THAT(error_of(R"({"model": [[0,0,0]], "weights": [0]})"),
              HasSubstr("weights[0]: must be > 0"));
  EXPECT_THAT(error_of(R"({"model": [[0,0,0]], "weights": [1, 2]})"),
              HasSubstr("weights: has 2 entries but model has 1"));
  EXPECT_THAT(error_of(R"({"model": [[0,0,1e400]]})"),
              HasSubstr("model[0][2]: number out of range"));
  EXPECT_THAT(error_of(R"({"modle": []})"), HasSubstr("unknown field \"modle\""));
  EXPECT_THAT(error_of("nope"), HasSubstr("not valid JSON"));
  const CorrespondenceFile only_model = parse_correspondences(R"({"model": [[0,0,0]]})", "c.json");
  try {
    only_model.require({"model", "measured"}, "vantage orient");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(std::string(e.what()),
                HasSubstr("c.json: measured: missing, required by vantage orient"));
  }
}

}  // namespace
}  // namespace vantage::io

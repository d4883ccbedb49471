// Figures name the markers as the layout does (issue 39, item 7): the dropout chart (seen whole
// and on a body) and the vectors figure, in their CSVs (a name with a comma or a quote in RFC
// 4180 quotes) and on the page (shortened there).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::ScratchDir;

// Six markers, two of whose names need quotes in a CSV.
nlohmann::json named_layout() {
  return {{"name", "named"},
          {"points", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0.2, 0}, {0, -1, 0.3}, {0.2, 0, -1}}},
          {"names", {"tip", "left, rear", "say \"hi\"", "m4", "m5", "a-very-long-marker-name"}}};
}

TEST(PlotNamesCli, DropoutAndVectorsNameTheMarkers) {
  ScratchDir scratch;
  scratch.write("named.json", named_layout().dump());
  const testing::CliRun run =
      testing::run_vantage("plot named.json --out figs --only dropout,vectors", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string dropout = testing::read_file(scratch.path("figs/dropout.csv"));
  EXPECT_THAT(dropout, HasSubstr("\n\"left, rear\",1,"));
  EXPECT_THAT(dropout, HasSubstr("\n\"say \"\"hi\"\"\",2,"));
  EXPECT_THAT(dropout, HasSubstr("\na-very-long-marker-name,5,"));
  EXPECT_THAT(dropout, Not(HasSubstr("\np1,")));
  const std::string vectors = testing::read_file(scratch.path("figs/vectors.csv"));
  EXPECT_THAT(vectors, HasSubstr("series,index,x,y,z,name\n"));
  EXPECT_THAT(vectors, HasSubstr(",tip\n"));
  EXPECT_THAT(vectors, HasSubstr(",\"left, rear\"\n"));
}

TEST(PlotNamesCli, OnABodyTheDropoutNamesTheMarkers) {
  ScratchDir scratch;
  nlohmann::json layout = named_layout();
  layout["normals"] = layout["points"];
  layout["visibility"] = {{"cone_half_angle_deg", 100.0}};
  scratch.write("named.json", layout.dump());
  const testing::CliRun run =
      testing::run_vantage("plot named.json --out figs --only dropout", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string dropout = testing::read_file(scratch.path("figs/dropout.csv"));
  EXPECT_THAT(dropout, HasSubstr("\n\"left, rear\",1,"));
  EXPECT_THAT(dropout, HasSubstr("\ntip,0,"));
}

TEST(PlotNamesCli, UnnamedMarkersKeepTheirIndexNames) {
  ScratchDir scratch;
  nlohmann::json layout = named_layout();
  layout.erase("names");
  scratch.write("plain.json", layout.dump());
  ASSERT_EQ(
      testing::run_vantage("plot plain.json --out figs --only dropout,vectors", scratch).status, 0);
  EXPECT_THAT(testing::read_file(scratch.path("figs/dropout.csv")), HasSubstr("\np1,1,"));
  EXPECT_THAT(testing::read_file(scratch.path("figs/vectors.csv")), HasSubstr(",p0\n"));
}

}  // namespace
}  // namespace vantage

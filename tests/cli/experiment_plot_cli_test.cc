// `vantage plot --experiment NAME --out DIR`: the figures of a directory written by `vantage
// experiment NAME --out DIR --quick`, its JSON contract and its bad-input contract.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::run_vantage;
using testing::ScratchDir;

TEST(ExperimentPlotCli, DrawsTheFiguresOfAQuickExperiment) {
  ScratchDir scratch;
  const testing::CliRun experiment =
      run_vantage("experiment mcinroy-orientation --out run --quick", scratch);
  ASSERT_EQ(experiment.status, 0) << experiment.err;
  const nlohmann::json out =
      testing::run_json("plot --experiment mcinroy-orientation --out run --size 600x400", scratch);
  EXPECT_EQ(out.at("experiment"), "mcinroy-orientation");
  EXPECT_EQ(out.at("size"), nlohmann::json::array({600, 400}));
  ASSERT_EQ(out.at("figures").size(), 1u);
  EXPECT_EQ(out.at("figures")[0].at("name"), "mcinroy_orientation");
  EXPECT_TRUE(std::filesystem::is_regular_file(scratch.path("run/mcinroy_orientation.png")));
  EXPECT_TRUE(std::filesystem::is_regular_file(scratch.path("run/mcinroy_orientation.csv")));
}

TEST(ExperimentPlotCli, BadCallsAreRefusedWithOneLine) {
  ScratchDir scratch;
  std::filesystem::create_directories(scratch.path("empty"));
  testing::expect_bad_input(run_vantage("plot --experiment nope --out empty", scratch),
                            "--experiment");
  testing::expect_bad_input(run_vantage("plot --experiment bound --out missing", scratch), "--out");
  testing::expect_bad_input(run_vantage("plot --experiment bound --out empty", scratch),
                            "bound_trials.csv");
  testing::expect_bad_input(run_vantage("plot --out figs", scratch), "LAYOUT");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("figs")));
  EXPECT_TRUE(std::filesystem::is_empty(scratch.path("empty")));
}

}  // namespace
}  // namespace vantage

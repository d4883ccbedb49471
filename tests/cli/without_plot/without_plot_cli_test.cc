// The `vantage` command built without vantage::plot (VANTAGE_WITH_PLOT=OFF, as `make demo` builds
// it): `vantage plot` and `vantage design --plot` say that the build has no figures, as bad
// usage (exit status 2, one line, nothing written), and everything else still works.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::expect_bad_input;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kTriad = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/triad.json";
constexpr char kWithoutFigures[] = "this vantage was built without figures";

TEST(WithoutPlotCli, PlotSaysTheBuildHasNoFigures) {
  static_assert(VANTAGE_WITH_PLOT == 0, "only built into a suite without vantage::plot");
  ScratchDir scratch;
  expect_bad_input(run_vantage("plot '" + kTriad + "' --out figures", scratch),
                   std::string("plot: ") + kWithoutFigures);
  EXPECT_FALSE(std::filesystem::exists(scratch.path("figures")));
  // Whatever the arguments: the subcommand is known, its options are not checked.
  expect_bad_input(run_vantage("plot --experiment bound --out run --nonsense", scratch),
                   kWithoutFigures);
}

TEST(WithoutPlotCli, DesignPlotSaysSoBeforeAnyWork) {
  ScratchDir scratch;
  expect_bad_input(
      run_vantage("design '" + kTriad + "' --add 1 --plot figures --write out.json", scratch),
      std::string("--plot: ") + kWithoutFigures);
  EXPECT_FALSE(std::filesystem::exists(scratch.path("figures")));
  EXPECT_FALSE(std::filesystem::exists(scratch.path("out.json")));
}

TEST(WithoutPlotCli, DesignWithoutPlotStillRuns) {
  ScratchDir scratch;
  const testing::CliRun run =
      run_vantage("design '" + kTriad + "' --add 1 --no-direct --quiet", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, ::testing::HasSubstr("p-bar_min"));
  EXPECT_EQ(run.err, "");
}

}  // namespace
}  // namespace vantage

// `vantage plot LAYOUT --crb` (issue 21; docs/math.md §22): the two figures and their CSVs are
// written, the map's worst row is `vantage crb`'s worst, and bad input is one line naming the
// option, exit 2, with no directory made.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::BadCall;
using testing::CliRun;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kCube =
    "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/apriltag_cube.yaml'";
const std::string kCamera = " --distance 2 --focal 900 --noise-px 0.3 --samples 2000";
// JSON and CSV numbers are printed to round-trip.
constexpr double kRoundTrip = 1e-12;

// Field `column` of the CSV's first data row.
double first_row_number(const std::string& path, const std::string& column) {
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  std::stringstream h(header), r(row);
  std::string name, value;
  while (std::getline(h, name, ',') && std::getline(r, value, ',')) {
    if (name == column) return std::stod(value);
  }
  ADD_FAILURE() << "no column " << column << " in " << path;
  return 0.0;
}

TEST(CrbPlotCli, WritesTheMapAndTheSweepWithTheWorstOfVantageCrb) {
  ScratchDir scratch;
  const nlohmann::json plot = testing::run_json(
      "plot " + kCube + " --crb" + kCamera + " --sweep-distance 1.5:3:3 --out figs", scratch);
  ASSERT_EQ(plot["figures"].size(), 2u);
  for (const char* file :
       {"figs/crb_map.png", "figs/crb_map.csv", "figs/crb_sweep.png", "figs/crb_sweep.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(scratch.path(file))) << file;
  }
  const nlohmann::json crb = testing::run_json("crb " + kCube + kCamera, scratch);
  const double worst = crb["worst"]["rot_rms_deg"].get<double>();
  EXPECT_NEAR(first_row_number(scratch.path("figs/crb_map.csv"), "rot_rms_deg"), worst,
              kRoundTrip * worst);
  EXPECT_NEAR(plot["worst_rot_rms_deg"].get<double>(), worst, kRoundTrip * worst);
}

// At 4 m the cube's worst first-order rot_rms passes 45 degrees: `plot --crb` printed
// "worst rot_rms inf deg" (docs/math.md §22, "Unbounded": a word, not a number).
TEST(CrbPlotCli, AnUnboundedWorstIsSaidNotPrinted) {
  ScratchDir scratch;
  const std::string args = "plot " + kCube +
                           " --crb --distance 4 --focal 900 --noise-px 0.3 "
                           "--samples 2000 --sweep-distance 3:4:2 --out ";
  const nlohmann::json json = testing::run_json(args + "a", scratch);
  EXPECT_TRUE(json["worst_rot_rms_deg"].is_null());
  EXPECT_TRUE(json["worst_unbounded"].get<bool>());
  const nlohmann::json crb = testing::run_json(
      "crb " + kCube + " --distance 4 --focal 900 --noise-px 0.3 --samples 2000", scratch);
  EXPECT_EQ(json["unbounded_fraction"], crb["unbounded_fraction"]);
  EXPECT_TRUE(crb["worst"]["unbounded"].get<bool>());
  const CliRun text = testing::run_vantage(args + "b", scratch);
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("worst rot_rms unbounded (first-order rot_rms past 45 deg)"));
  EXPECT_THAT(text.out, ::testing::Not(HasSubstr("inf")));
}

TEST(CrbPlotCli, BadInputIsOneLineAndMakesNoDirectory) {
  ScratchDir scratch;
  const BadCall calls[] = {
      {"no distance", nullptr, "--crb --focal 900 --noise-px 0.3 --out figs", "--distance"},
      {"no focal", nullptr, "--crb --distance 2 --noise-px 0.3 --out figs", "--focal"},
      {"no noise", nullptr, "--crb --distance 2 --focal 900 --out figs", "--noise-px"},
      {"camera without --crb", nullptr, "--distance 2 --out figs", "--distance"},
      {"zero noise", nullptr, "--crb --distance 2 --focal 900 --noise-px 0 --out figs",
       "--noise-px"},
      {"inside the markers", nullptr, "--crb --distance 0.01 --focal 900 --noise-px 1 --out figs",
       "--distance"},
      {"bad sweep", nullptr,
       "--crb --distance 2 --focal 900 --noise-px 1 --sweep-distance 3:1:4 --out figs",
       "--sweep-distance"},
      {"with --only", nullptr,
       "--crb --distance 2 --focal 900 --noise-px 1 --only vectors --out figs", "--only"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    testing::run_bad_call("plot " + kCube + " ", call, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("figs")));
  }
}

}  // namespace
}  // namespace vantage

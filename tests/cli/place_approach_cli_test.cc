// `vantage place --objective camera --distances D1,D2,...` (docs/math.md §21, "An approach"): the
// value is the largest over the distances of what `vantage crb --distance Dk` reports on the
// written file, the file records the approach, `vantage analyze` reports the same, and bad
// distances get one line naming --distances.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/cube_sites.h"
#include "support/sanitized.h"

namespace vantage {
namespace {

using testing::BadCall;
using ::testing::HasSubstr;
using testing::ScratchDir;

const std::vector<double> kDistances = {6.0, 2.0, 12.0};
constexpr const char* kCamera = " --focal 900 --noise-px 0.3";

std::string aim_option(const nlohmann::json& aim) {
  std::ostringstream out;
  out.precision(17);
  out << aim[0].get<double>() << "," << aim[1].get<double>() << "," << aim[2].get<double>();
  return out.str();
}

TEST(PlaceApproachCli, TheValueIsTheLargestOfWhatCrbReportsAtEachDistance) {
  ScratchDir scratch;
  scratch.write("sites.json", testing::cube_sites());
  // Under the sanitizers a coarser lattice: the same code, less of the work.
  const std::string samples = testing::kUnderSanitizer ? "300" : "600";
  const nlohmann::json json = testing::run_json(
      "place --sites sites.json --markers 5 --out cam.json --objective camera --distances 6,2,12" +
          std::string(kCamera) + " --crb-samples " + samples,
      scratch);
  ASSERT_EQ(json["status"], "complete");
  const nlohmann::json& objective = json["objective"];
  EXPECT_EQ(objective["camera"]["distances"], nlohmann::json(kDistances));
  ASSERT_EQ(objective["approach"].size(), kDistances.size());
  // Each distance against `vantage crb` on the written file, with the camera the report names.
  double largest = -1.0, deciding = 0.0;
  for (std::size_t k = 0; k < kDistances.size(); ++k) {
    std::ostringstream crb;
    crb << "crb cam.json --distance " << kDistances[k] << kCamera << " --samples " << samples
        << " --aim " << aim_option(objective["camera"]["aim"]);
    const nlohmann::json of_crb = testing::run_json(crb.str(), scratch);
    const nlohmann::json& step = objective["approach"][k];
    EXPECT_EQ(step["distance"].get<double>(), kDistances[k]);
    ASSERT_EQ(of_crb["status"], "ok");
    EXPECT_EQ(step["value_deg"], of_crb["worst"]["rot_rms_deg"]);
    const double value = of_crb["worst"]["rot_rms_deg"].get<double>();
    if (value > largest) {
      largest = value;
      deciding = kDistances[k];
    }
  }
  EXPECT_EQ(objective["value_deg"].get<double>(), largest);
  EXPECT_EQ(objective["deciding_distance"].get<double>(), deciding);
  // The file records the approach, and `vantage analyze` evaluates it to the same value.
  const nlohmann::json file = nlohmann::json::parse(testing::read_file(scratch.path("cam.json")));
  EXPECT_EQ(file["sensor"]["distances"], nlohmann::json(kDistances));
  EXPECT_FALSE(file["sensor"].contains("distance"));
  const nlohmann::json analyzed = testing::run_json("analyze cam.json --no-crosscheck", scratch);
  EXPECT_EQ(analyzed["sensor"]["value_deg"], objective["value_deg"]);
  EXPECT_EQ(analyzed["sensor"]["approach"], objective["approach"]);
  const testing::CliRun text = testing::run_vantage("analyze cam.json --no-crosscheck", scratch);
  EXPECT_THAT(text.out, HasSubstr("the approach's distances D = 6, 2, 12"));
  EXPECT_THAT(text.out, HasSubstr("(decides)"));
}

// The distance that decides is the worst whatever the order: one that tracks nothing before one
// whose worst is unbounded, before the largest figure; each is named for what it is.
TEST(PlaceApproachCli, TheWorstDistanceDecidesWhateverTheOrder) {
  ScratchDir scratch;
  nlohmann::json sites = nlohmann::json::parse(testing::cube_sites());
  sites["visibility"]["cone_half_angle_deg"] = 60.0;
  scratch.write("cube60.json", sites.dump());
  scratch.write("sites.json", testing::cube_sites());
  const std::string place =
      "place --sites cube60.json --markers 8 --objective camera --focal 900 --noise-px 0.3 "
      "--crb-samples 300 --allow-partial --out ";
  for (const char* order : {"6,0.6", "0.6,6"}) {
    SCOPED_TRACE(order);
    const testing::CliRun run =
        testing::run_vantage(place + "o.json --overwrite --distances " + order, scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    // At 0.6 (just above the sites' radius) no direction sees enough markers; at 6 the worst
    // passes the first-order limit.
    EXPECT_THAT(run.out, HasSubstr("D 0.6: not trackable: no sampled direction"));
    EXPECT_THAT(run.out, HasSubstr("(300 sampled)  (decides)"));
    EXPECT_THAT(run.out, HasSubstr("D 6: worst rot_rms unbounded"));
  }
  const testing::CliRun far = testing::run_vantage(
      "place --sites sites.json --markers 5 --objective camera --focal 900 --noise-px 0.3 "
      "--crb-samples 300 --allow-partial --out far.json --distances 6,1000",
      scratch);
  ASSERT_EQ(far.status, 0) << far.err;
  EXPECT_THAT(far.out, HasSubstr("D 1000: worst rot_rms unbounded (first-order rot_rms past the "
                                 "45 deg limit)  (decides)"));
}

TEST(PlaceApproachCli, BadDistancesGetOneLineAndWriteNothing) {
  ScratchDir scratch;
  scratch.write("sites.json", testing::cube_sites());
  std::string many = "1";
  for (int k = 0; k < 64; ++k) many += ",1";
  const std::string too_many =
      "--sites sites.json --markers 4 --out o.json --objective camera --focal 800 --noise-px 1 "
      "--distances " +
      many;
  const BadCall calls[] = {
      {"not a number", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distances 6,x --focal "
       "800 --noise-px 1",
       "--distances: expected comma-separated numbers"},
      {"with --distance", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distance 6 --distances "
       "6,8 --focal 800 --noise-px 1",
       "--distances: goes without --distance"},
      {"a negative distance", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distances 6,-8 --focal "
       "800 --noise-px 1",
       "--distances: must be a finite number > 0"},
      {"a distance inside the sites", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distances 6,0.3 --focal "
       "800 --noise-px 1",
       "--distances"},
      {"with affine", nullptr, "--sites sites.json --markers 4 --out o.json --distances 6,8",
       "--distances: goes with --objective camera"},
      {"65 distances", nullptr, too_many.c_str(), "--distances: at most 64 distances, got 65"},
      {"a repeated distance", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distances 6,8,6 --focal "
       "800 --noise-px 1",
       "--distances: distance 3 repeats an earlier one"},
      {"given empty", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distance 6 --distances "
       "'' --focal 800 --noise-px 1",
       "--distances: expected comma-separated numbers"},
      {"too many samples", nullptr,
       "--sites sites.json --markers 4 --out o.json --objective camera --distances 6,8,10,12,14 "
       "--crb-samples 300000 --focal 800 --noise-px 1",
       "--distances: 5 distances of --crb-samples 300000 exceed 1000000 samples"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    testing::run_bad_call("place", call, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("o.json")));
  }
}

}  // namespace
}  // namespace vantage

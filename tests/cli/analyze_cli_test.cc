#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "support/cli_runner.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

// The CLI prints what the library computes; the library's own suites check the mathematics to
// 1e-9. Here: the paper's printed values (three decimals) and exact closed forms.
constexpr double kClosedForm = 1e-9;
constexpr double kPrinted = 5e-4;
// The default certificate tolerance: certified means t_upper - t_lower <= it.
constexpr double kCertificateTolerance = 1e-9;

// The paper's single LMI is solved by CSDP, accurate to ~1e-8 relative.
constexpr double kSdpAccuracy = 1e-6;
// sqrt(2 pi / N) evaluated twice: an ulp or two.
constexpr double kRounding = 1e-12;
const double kTriadPbar = std::sqrt(2.0 / 3.0);

std::string layout(const char* name) {
  return "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json'";
}

nlohmann::json analyze_json(const std::string& args, ScratchDir& scratch) {
  return testing::run_json("analyze " + args, scratch);
}

TEST(AnalyzeCli, TriadHasFourWorstViewpointsAndTheContractFields) {
  ScratchDir scratch;
  const auto json = analyze_json(layout("triad"), scratch);
  for (const char* field : {"name", "mode", "n_vectors", "worst_viewpoint", "worst_viewpoints", "t",
                            "pbar_min", "worst_case_errors_deg", "max_worst_case_error_deg",
                            "certificate", "paper_lmi", "crosscheck", "swaps", "solver"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  EXPECT_EQ(json["mode"], "vectors");
  EXPECT_EQ(json["n_vectors"], 3);
  EXPECT_NEAR(json["pbar_min"].get<double>(), kTriadPbar, kClosedForm);
  EXPECT_NEAR(json["t"].get<double>(), 1.0 / std::sqrt(3.0), kClosedForm);
  EXPECT_EQ(json["worst_viewpoints"].size(), 4u);
  EXPECT_EQ(json["worst_case_errors_deg"].size(), 3u);
  EXPECT_LE(
      json["certificate"]["t_upper"].get<double>() - json["certificate"]["t_lower"].get<double>(),
      kCertificateTolerance);
  EXPECT_TRUE(json["crosscheck"]["agrees"].get<bool>());
  EXPECT_EQ(json["solver"]["backend"], "csdp");
  EXPECT_EQ(json["solver"]["status"], "certified");
  EXPECT_EQ(json["swaps"].size(), 3u);  // all pairs of three vectors
  EXPECT_NEAR(json["paper_lmi"]["pbar"].get<double>(), kTriadPbar, kSdpAccuracy);
}

TEST(AnalyzeCli, CrossCheckSaysWhetherItsSamplesCoverTheCells) {
  // The triad's optimal cell (inradius asin(1/sqrt 3) = 0.62 rad) is far wider than 20 000
  // samples' spacing; 3000 random directions (t* ~ 0.006) get 4e7 / 3000 = 13 333 samples,
  // 0.022 rad apart: other cells are only spot-checked, and the report says so.
  ScratchDir scratch;
  const auto triad = analyze_json(layout("triad"), scratch)["crosscheck"];
  EXPECT_TRUE(triad["samples_cover_cells"].get<bool>());
  EXPECT_EQ(triad["samples"], 20000);
  EXPECT_NEAR(triad["sample_spacing_rad"].get<double>(), std::sqrt(2.0 * kPi / 20000), kRounding);
  std::mt19937 rng(20261126);
  std::normal_distribution<double> gauss;
  nlohmann::json many;
  for (int k = 0; k < 3000; ++k) many["vectors"].push_back({gauss(rng), gauss(rng), gauss(rng)});
  scratch.write("many.json", many.dump());
  const auto json = analyze_json("many.json --swaps 1", scratch);
  const auto check = json["crosscheck"];
  EXPECT_TRUE(check["agrees"].get<bool>());
  EXPECT_FALSE(check["samples_cover_cells"].get<bool>());
  EXPECT_EQ(check["samples"], 13333);
  EXPECT_GT(check["sample_spacing_rad"].get<double>(), std::asin(json["t"].get<double>()));
  const auto text = run_vantage("analyze many.json", scratch);
  EXPECT_THAT(text.out, HasSubstr("other cells only spot-checked"));
}

TEST(AnalyzeCli, NoteThreeLayoutGlobalVersusPaper) {
  ScratchDir scratch;
  const auto json = analyze_json(layout("note3_four_vectors"), scratch);
  EXPECT_NEAR(json["pbar_min"].get<double>(), 0.8165, kPrinted);
  EXPECT_NEAR(json["paper_lmi"]["pbar"].get<double>(), 0.953, kPrinted);
}

TEST(AnalyzeCli, PointModeUsesFreeVectors) {
  ScratchDir scratch;
  const auto json = analyze_json(layout("satellite") + " --swaps 3", scratch);
  EXPECT_EQ(json["mode"], "points");
  EXPECT_EQ(json["n_vectors"], 66);  // 12 markers -> 12 * 11 / 2 free vectors
  EXPECT_EQ(json["swaps"].size(), 3u);
  EXPECT_TRUE(json["swaps"][0].contains("pair_i"));
  EXPECT_LE(json["pbar_min"].get<double>(), json["ceiling"].get<double>());
  EXPECT_GE(json["paper_lmi"]["pbar"].get<double>(), json["pbar_min"].get<double>() - kSdpAccuracy);
}

TEST(AnalyzeCli, CoplanarFanReachesItsCeiling) {
  ScratchDir scratch;
  const auto json = analyze_json(layout("coplanar_fan"), scratch);
  EXPECT_NEAR(json["pbar_min"].get<double>(), std::cos(kPi / 6.0), kClosedForm);
  EXPECT_NEAR(json["ceiling"].get<double>(), std::cos(kPi / 6.0), kClosedForm);
}

TEST(AnalyzeCli, ReadableReport) {
  ScratchDir scratch;
  const auto run = run_vantage("analyze " + layout("triad") + " --no-crosscheck", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("worst viewpoint a"));
  EXPECT_THAT(run.out, HasSubstr("0.816496581"));
}

struct BadLayoutCall {
  const char* name;
  const char* text;
  const char* expected;
};

class AnalyzeCliBadLayout : public ::testing::TestWithParam<BadLayoutCall> {};

TEST_P(AnalyzeCliBadLayout, OneLineNamingFileFieldIndexExitTwo) {
  ScratchDir scratch;
  scratch.write("layout.json", GetParam().text);
  const auto run = run_vantage("analyze layout.json --json", scratch);
  testing::expect_bad_input(run, GetParam().expected);
  EXPECT_THAT(run.err, HasSubstr("vantage: error: layout.json: "));
}

const BadLayoutCall kBadLayouts[] = {
    {"NotJson", "vectors: 1 0 0", "not valid JSON"},
    {"BothModes", R"({"vectors": [[1,0,0],[0,1,0]], "points": [[1,0,0],[0,1,0]]})", "not both"},
    {"NeitherMode", R"({"weights": [1, 2]})", "vectors/points: missing"},
    {"WrongArity", R"({"vectors": [[1,0,0],[0,1,0,4]]})", "vectors[1]: expected 3 numbers"},
    {"HugeNumber", R"({"vectors": [[1,0,0],[0,1,-1e500]]})", "vectors[1][2]: number out of range"},
    {"ZeroLength", R"({"vectors": [[1,0,0],[0,1,0],[0,0,0]]})", "vectors[2]: zero-length"},
    {"Coincident", R"({"points": [[1,2,3],[0,0,0],[1,2,3]]})",
     "points[2]: coincides with points[0]"},
    {"TwoPoints", R"({"points": [[1,2,3],[0,0,0]]})", "points: need at least 3 points"},
    {"OverflowingPoints", R"({"points": [[1e308,0,0],[-1e308,0,0],[0,1,0]]})",
     "points[0]: coordinates beyond"},
    {"WeightsLength", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1,1,1]})",
     "weights: expected 2 entries"},
    {"WeightNotPositive", R"({"vectors": [[1,0,0],[0,1,0]], "weights": [1,-0.5]})",
     "weights[1]: must be > 0"},
    {"OneVector", R"({"vectors": [[1,0,0]]})", "vectors: need at least 2"},
};

INSTANTIATE_TEST_SUITE_P(AnalyzeCli, AnalyzeCliBadLayout, ::testing::ValuesIn(kBadLayouts),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(AnalyzeCli, MissingFileAndBadOptions) {
  ScratchDir scratch;
  auto run = run_vantage("analyze missing.json", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_THAT(run.err, HasSubstr("missing.json: cannot open file"));
  run = run_vantage("analyze " + layout("triad") + " --swaps 0", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_THAT(run.err, HasSubstr("--swaps"));
  EXPECT_EQ(run.out, "");
  run = run_vantage("analyze " + layout("triad") + " --pair-weighting median", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(testing::line_count(run.err), 1);
}

TEST(AnalyzeCli, AgreesWithDesignOnTheWrittenLayout) {
  // Issue 4: every p-bar_min that `design` reports agrees with `analyze` on the written layout.
  ScratchDir scratch;
  for (const char* name : {"coplanar_fan", "note3_four_vectors"}) {
    const auto design = run_vantage(
        "design " + layout(name) + " --add 2 --no-direct --write out.json --overwrite --json",
        scratch);
    ASSERT_EQ(design.status, 0) << design.err;
    const auto designed = nlohmann::json::parse(design.out);
    const auto analyzed = analyze_json("out.json --no-crosscheck", scratch);
    EXPECT_NEAR(analyzed["pbar_min"].get<double>(), designed["final_pbar_min"].get<double>(),
                kClosedForm)
        << name;
    EXPECT_EQ(analyzed["n_vectors"].get<int>(), designed["steps"].back()["n_vectors"].get<int>());
  }
}

}  // namespace
}  // namespace vantage

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "support/cli_runner.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

// The paper prints the triad's bound to four decimals (35.2644 degrees).
constexpr double kPaperDigits = 1e-4;
// At the certified worst viewpoint the largest error is asin(t_lower), the bound asin(t_upper):
// the certificate tolerance (1e-9) apart.
constexpr double kAtWorstViewpoint = 1e-6;
// The bound is asin of the certified upper t: the measured ratio exceeds 1 by rounding only.
constexpr double kRatioRounding = 1e-9;

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

std::string layout(const char* name) {
  return "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json'";
}

nlohmann::json example(const char* name) {
  std::ifstream in(std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json");
  return nlohmann::json::parse(in);
}

/// The satellite seen whole: its file without normals, cones and body.
std::string bare_satellite(const ScratchDir& scratch) {
  nlohmann::json file = example("satellite");
  for (const char* key : {"normals", "visibility", "workspace"}) file.erase(key);
  scratch.write("bare.json", file.dump());
  return "bare.json";
}

/// The satellite's normals and cones without its body (the cone model alone).
std::string satellite_cones(const ScratchDir& scratch) {
  nlohmann::json file = example("satellite");
  file["visibility"].erase("body");
  scratch.write("cones.json", file.dump());
  return "cones.json";
}

/// The cone test, written out: marker i is in its cone from a iff n_i.a >= |n_i| cos(theta).
std::vector<int> in_cones(const nlohmann::json& file, const std::vector<double>& a) {
  const double cos_cone =
      std::cos(file["visibility"]["cone_half_angle_deg"].get<double>() * kPi / 180.0);
  std::vector<int> out;
  for (std::size_t i = 0; i < file["normals"].size(); ++i) {
    const auto n = file["normals"][i].get<std::vector<double>>();
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (n[0] * a[0] + n[1] * a[1] + n[2] * a[2] >= length * cos_cone) {
      out.push_back(static_cast<int>(i));
    }
  }
  return out;
}

/// min |a.u_ij| over the pairs of `visible`, by brute force.
double brute_t(const nlohmann::json& file, const std::vector<int>& visible,
               const std::vector<double>& a) {
  double t = 1.0;
  for (std::size_t x = 0; x < visible.size(); ++x) {
    for (std::size_t y = x + 1; y < visible.size(); ++y) {
      const auto p = file["points"][visible[x]].get<std::vector<double>>();
      const auto q = file["points"][visible[y]].get<std::vector<double>>();
      const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
      const double length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      t = std::min(t, std::abs(u[0] * a[0] + u[1] * a[1] + u[2] * a[2]) / length);
    }
  }
  return t;
}

TEST(SimulateCli, JsonContractAndBoundCheck) {
  ScratchDir scratch;
  const auto json = testing::run_json("simulate " + layout("triad") + " --trials 50", scratch);
  for (const char* field : {"layout", "mode", "trials", "total_trials", "seed", "shard",
                            "estimators", "bound_check", "config"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  for (const char* name : {"affine", "standard"}) {
    const auto& e = json["estimators"][name];
    for (const char* field : {"rot_err_deg", "trans_err_rel", "time_us"}) {
      for (const char* stat : {"median", "mean", "p95", "max"}) {
        EXPECT_TRUE(e[field].contains(stat)) << name << " " << field << " " << stat;
      }
    }
    EXPECT_TRUE(e.contains("failures"));
    EXPECT_TRUE(e.contains("wrong_but_ok"));
  }
  const auto& b = json["bound_check"];
  EXPECT_EQ(b["trials"], 50);
  EXPECT_EQ(b["vectors"], 3);
  EXPECT_LE(b["max_ratio"].get<double>(), 1.0 + kRatioRounding);
  EXPECT_NEAR(b["bound_deg"].get<double>(), 35.2644, kPaperDigits);
  EXPECT_TRUE(b["passed"].get<bool>());
  EXPECT_FALSE(json.contains("per_trial"));
}

TEST(SimulateCli, WorstViewpointReachesTheBound) {
  ScratchDir scratch;
  const auto json = testing::run_json(
      "simulate " + bare_satellite(scratch) + " --trials 20 --viewpoint worst --methods affine",
      scratch);
  EXPECT_NEAR(json["bound_check"]["max_ratio"].get<double>(), 1.0, kAtWorstViewpoint);
  EXPECT_EQ(json["bound_check"]["vectors"], 66);
  EXPECT_EQ(json["bound_check"]["affine_relation"][0]["free_vectors"], "auto");
  EXPECT_FALSE(json.contains("visibility"));
  // On its body the worst viewpoint is the one under visibility, and its bound is reached.
  const auto body = testing::run_json(
      "simulate " + layout("satellite") + " --trials 20 --viewpoint worst --methods affine",
      scratch);
  EXPECT_NEAR(body["visibility"]["max_ratio"].get<double>(), 1.0, kAtWorstViewpoint);
  EXPECT_EQ(body["visibility"]["draws"], 0);
  EXPECT_LT(body["bound_check"]["max_ratio"].get<double>(), 1.0);
}

TEST(SimulateCli, ALayoutWithoutNormalsGivesTheOutputOfBeforeVisibility) {
  // Golden values: `vantage simulate bare.json --trials 40 --seed 11 --noise-px 0.5 --methods
  // affine,standard --json` built before simulate knew visibility (commit 490fc4d), printed in
  // full (nlohmann's shortest round-trip form): equal bit for bit.
  ScratchDir scratch;
  const auto json = testing::run_json("simulate " + bare_satellite(scratch) +
                                          " --trials 40 --seed 11 --noise-px 0.5 --methods "
                                          "affine,standard",
                                      scratch);
  EXPECT_EQ(json["bound_check"]["max_error_deg"].get<double>(), 6.564419303710888);
  EXPECT_EQ(json["estimators"]["affine"]["rot_err_deg"]["median"].get<double>(),
            1.5209087699731845);
  EXPECT_EQ(json["estimators"]["standard"]["rot_err_deg"]["mean"].get<double>(), 32.90980720213958);
  EXPECT_FALSE(json.contains("visibility"));
  EXPECT_FALSE(json["config"]["layout"].contains("normals"));
}

TEST(SimulateCli, OnItsBodyEveryViewIsTrackableAndWithinItsBound) {
  // A measured angle may exceed asin t(a) where t(a) is tiny by the rounding Eq. (26) allows
  // there: up to ~1e-8 rad for a vector in the image plane (simulate/bound_check.h).
  constexpr double kNearImagePlaneRad = 1e-7;
  // t(a) evaluated here and by vantage, in different orders.
  constexpr double kRounding = 1e-12;
  ScratchDir scratch;
  const nlohmann::json file = example("satellite");
  for (const bool with_body : {true, false}) {
    const std::string input = with_body ? layout("satellite") : satellite_cones(scratch);
    const auto json = testing::run_json("simulate " + input +
                                            " --trials 400 --per-trial --methods affine "
                                            "--noise-px 0.3 --seed 9",
                                        scratch);
    const auto& v = json["visibility"];
    EXPECT_EQ(v["model"], with_body ? "cone+mesh" : "cone");
    EXPECT_TRUE(v["passed"].get<bool>()) << v["message"];
    EXPECT_TRUE(json["bound_check"]["passed"].get<bool>());
    EXPECT_EQ(v["trials"], 400);
    EXPECT_LE(v["max_ratio"].get<double>(), 1.0 + kRatioRounding);
    EXPECT_LE(v["max_view_t"].get<double>(), v["t_upper"].get<double>() + kRounding);
    const auto& trials = json["per_trial"]["visibility"];
    ASSERT_EQ(trials["visible"].size(), 400u);
    for (std::size_t k = 0; k < 400; ++k) {
      const auto a = trials["direction"][k].get<std::vector<double>>();
      const auto visible = trials["visible"][k].get<std::vector<int>>();
      const std::vector<int> cones = in_cones(file, a);
      if (with_body) {  // the body can only hide markers of their cones
        EXPECT_TRUE(std::includes(cones.begin(), cones.end(), visible.begin(), visible.end()))
            << "trial " << k;
      } else {
        EXPECT_EQ(visible, cones) << "trial " << k;
      }
      EXPECT_GE(visible.size(), 3u) << "trial " << k;
      const double t = brute_t(file, visible, a);
      EXPECT_NEAR(trials["t"][k].get<double>(), t, kRounding) << "trial " << k;
      EXPECT_LE(trials["max_error_rad"][k].get<double>(), std::asin(t) + kNearImagePlaneRad)
          << "trial " << k;
    }
  }
}

TEST(SimulateCli, ShardsOnTheBodyMergeToTheUnshardedRun) {
  ScratchDir scratch;
  const std::string base =
      "simulate " + layout("satellite") + " --trials 30 --noise-px 0.5 --methods affine --seed 2";
  auto whole = testing::run_json(base + " --threads 1", scratch);
  for (int k = 1; k <= 2; ++k) {
    const testing::CliRun run =
        run_vantage(base + " --shard " + std::to_string(k) + "/2 --json", scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    scratch.write("v" + std::to_string(k) + ".json", run.out);
  }
  auto merged = testing::run_json("simulate --merge v2.json v1.json", scratch);
  EXPECT_EQ(merged["visibility"], whole["visibility"]);
  EXPECT_EQ(merged["bound_check"], whole["bound_check"]);
}

TEST(SimulateCli, ShardsMergeToTheUnshardedRun) {
  ScratchDir scratch;
  const std::string base = "simulate " + layout("satellite") +
                           " --trials 24 --noise-px 0.5 --methods standard,full3d --seed 4";
  auto whole = testing::run_json(base + " --threads 1", scratch);
  for (int k = 1; k <= 3; ++k) {
    const testing::CliRun run =
        run_vantage(base + " --threads 2 --shard " + std::to_string(k) + "/3 --json", scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    scratch.write("s" + std::to_string(k) + ".json", run.out);
  }
  auto merged = testing::run_json("simulate --merge s3.json s1.json s2.json", scratch);
  EXPECT_EQ(merged["trials"], 24);
  for (const char* name : {"standard", "full3d"}) {
    for (const char* field : {"rot_err_deg", "trans_err_rel"}) {
      EXPECT_EQ(merged["estimators"][name][field], whole["estimators"][name][field]) << name;
    }
  }
  EXPECT_EQ(merged["bound_check"]["max_error_deg"], whole["bound_check"]["max_error_deg"]);
  testing::expect_bad_input(run_vantage("simulate --merge s1.json s1.json", scratch),
                            "overlapping");
}

TEST(SimulateCli, CsvHasOneRowPerTrialAndEstimator) {
  ScratchDir scratch;
  const testing::CliRun run =
      run_vantage("simulate " + layout("satellite") +
                      " --trials 7 --camera pinhole --methods oi-foam,oi-svd --csv out.csv --quiet",
                  scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("oi-foam"));
  EXPECT_EQ(testing::line_count(testing::read_file(scratch.path("out.csv"))), 1 + 7 * 2);
}

TEST(SimulateCli, BadInputIsOneLineAndWritesNothing) {
  ScratchDir scratch;
  const std::string triad = layout("triad");
  const testing::BadCall calls[] = {
      {"zero trials", nullptr, "--trials 0", "--trials"},
      {"both noises", nullptr, "--noise-px 1 --snr-db 40", "--snr-db"},
      {"negative noise", nullptr, "--noise-px -1", "--noise-px"},
      {"bad range", nullptr, "--range 0", "--range"},
      {"bad focal", nullptr, "--focal -3", "--focal"},
      {"pinhole vectors", nullptr, "--camera pinhole", "--camera"},
      {"unknown method", nullptr, "--methods nope", "--methods"},
      {"inapplicable method", nullptr, "--methods oi-foam", "oi-foam"},
      {"bad shard", nullptr, "--shard 4/3", "--shard"},
      {"bad camera", nullptr, "--camera fisheye", "--camera"},
  };
  for (const testing::BadCall& call : calls) {
    const std::string args = triad + " " + call.args + " --csv never.csv";
    testing::expect_bad_input(run_vantage("simulate " + args, scratch), call.expected);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("never.csv"))) << call.name;
  }
  // Markers whose cones of 1 degree share one normal: 7.6e-5 of the sphere is trackable.
  scratch.write("narrow.json",
                R"({"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                    "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1]],
                    "visibility": {"cone_half_angle_deg": 1}})");
  const testing::CliRun narrow = run_vantage("simulate narrow.json --csv never.csv", scratch);
  testing::expect_bad_input(narrow, "narrow.json: visibility: only");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("never.csv")));
  testing::expect_bad_input(run_vantage("simulate", scratch), "LAYOUT");
  testing::expect_bad_input(run_vantage("simulate missing.json", scratch), "missing.json");
  scratch.write("junk.json", "{}");
  testing::expect_bad_input(run_vantage("simulate --merge junk.json", scratch), "per_trial");
}

TEST(ExperimentCli, EveryExperimentRunsQuick) {
  ScratchDir scratch;
  for (const char* name : {"mcinroy-orientation", "mcinroy-pose", "bound", "haralick-2d2d",
                           "haralick-3d3d", "haralick-two-view", "wu-points", "wu-snr"}) {
    const auto json = testing::run_json(
        std::string("experiment ") + name + " --quick --out out_" + name, scratch);
    EXPECT_EQ(json["experiment"], name);
    EXPECT_TRUE(std::filesystem::exists(scratch.path(std::string("out_") + name + "/summary.md")));
  }
}

TEST(ExperimentCli, BadInput) {
  ScratchDir scratch;
  testing::expect_bad_input(run_vantage("experiment nope --out x", scratch), "nope");
  testing::expect_bad_input(run_vantage("experiment bound --out x --trials -2", scratch),
                            "--trials");
  testing::expect_bad_input(run_vantage("experiment wu-snr --out x --layouts a.json", scratch),
                            "--layouts");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("x")));
}

}  // namespace
}  // namespace vantage

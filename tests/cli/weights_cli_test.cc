#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";

// The null-space condition of Prop. 3 (Eq. 11) to the issue's accuracy.
constexpr double kNullSpace = 1e-9;
// The weights are normalised to sum n; CSDP solves the LP to relative accuracy ~1e-8.
constexpr double kSumTolerance = 1e-6;

// The printed residual against the norm recomputed from the printed weights: both near 1e-15.
constexpr double kResidualRecomputed = 1e-12;

using testing::run_json;

Eigen::Matrix3Xd columns(const nlohmann::json& rows) {
  Eigen::Matrix3Xd out(3, rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    for (int r = 0; r < 3; ++r) out(r, static_cast<Eigen::Index>(i)) = rows[i][r].get<double>();
  }
  return out;
}

// Checks Eq. (11) on the reported weights independently of the library: w >= 0, sum w = n,
// ||sum w_i z_i|| small, and the reported residual and min_weight are those of w.
void expect_null_space_weights(const nlohmann::json& json, const Eigen::Matrix3Xd& z) {
  ASSERT_TRUE(json["feasible"].get<bool>()) << json.dump();
  ASSERT_EQ(json["weights"].size(), static_cast<size_t>(z.cols()));
  Eigen::VectorXd w(z.cols());
  for (Eigen::Index i = 0; i < z.cols(); ++i) w(i) = json["weights"][i].get<double>();
  EXPECT_GE(w.minCoeff(), 0.0);
  EXPECT_NEAR(w.sum(), static_cast<double>(z.cols()), kSumTolerance);
  EXPECT_LE((z * w).norm(), kNullSpace);
  EXPECT_LE(json["residual"].get<double>(), kNullSpace);
  EXPECT_NEAR(json["residual"].get<double>(), (z * w).norm(), kResidualRecomputed);
  EXPECT_DOUBLE_EQ(json["min_weight"].get<double>(), w.minCoeff());
}

TEST(WeightsCli, SymmetricLayoutHasPositiveNullSpaceWeights) {
  ScratchDir scratch;
  // Symmetric pairs (the paper's remark after Prop. 3) with unequal arms and an extra point at
  // the origin side: the max-min weights are strictly positive.
  const std::string text =
      R"({"points": [[1,0,0],[-1,0,0],[0,2,0],[0,-2,0],[0,0,3],[0,0,-3],[0.5,0.5,0.5]]})";
  scratch.write("sym.json", text);
  const auto json = run_json("weights sym.json", scratch);
  for (const char* field : {"feasible", "weights", "residual", "min_weight", "status"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  EXPECT_EQ(json["status"], "positive");
  EXPECT_GT(json["min_weight"].get<double>(), 0.0);
  EXPECT_FALSE(json.contains("suggestion"));
  expect_null_space_weights(json, columns(nlohmann::json::parse(text)["points"]));
}

TEST(WeightsCli, SatelliteExampleIsBalanced) {
  ScratchDir scratch;
  const std::string path = kLayouts + "satellite.json";
  const auto json = run_json("weights '" + path + "'", scratch);
  EXPECT_EQ(json["status"], "positive");
  expect_null_space_weights(json,
                            columns(nlohmann::json::parse(testing::read_file(path))["points"]));
}

TEST(WeightsCli, OneSidedPointsAreInfeasibleWithAFixThatWorks) {
  ScratchDir scratch;
  const std::string text = R"({"points": [[1,0,0],[2,1,0],[1.5,0,1],[1,1,1]]})";
  scratch.write("side.json", text);
  const auto run = run_vantage("weights side.json --json", scratch);
  ASSERT_EQ(run.status, 0) << "infeasible is an answer, not an error: " << run.err;
  EXPECT_EQ(run.err, "");
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_FALSE(json["feasible"].get<bool>());
  EXPECT_EQ(json["status"], "infeasible");
  EXPECT_TRUE(json["weights"].empty());
  ASSERT_TRUE(json.contains("suggestion"));
  const auto& suggestion = json["suggestion"];
  EXPECT_FALSE(suggestion["text"].get<std::string>().empty());
  ASSERT_TRUE(json.contains("suggestions"));
  EXPECT_EQ(json["suggestions"][0], suggestion);

  // Apply every suggested fix to the file and ask again: weights exist.
  const Eigen::Matrix3Xd z = columns(nlohmann::json::parse(text)["points"]);
  for (const auto& fix : json["suggestions"]) {
    Eigen::Matrix3Xd fixed = z;
    if (fix["kind"] == "shift_origin") {
      fixed = z.colwise() - columns(nlohmann::json::array({fix["shift"]})).col(0);
    } else {
      ASSERT_TRUE(fix["kind"] == "symmetric_partner" || fix["kind"] == "balancing_entry");
      fixed.conservativeResize(3, z.cols() + 1);
      fixed.col(z.cols()) = columns(nlohmann::json::array({fix["added"]})).col(0);
    }
    nlohmann::json layout;
    layout["points"] = nlohmann::json::array();
    for (Eigen::Index i = 0; i < fixed.cols(); ++i) {
      layout["points"].push_back({fixed(0, i), fixed(1, i), fixed(2, i)});
    }
    scratch.write("fixed.json", layout.dump());
    const auto again = run_json("weights fixed.json", scratch);
    expect_null_space_weights(again, fixed);
    EXPECT_NEAR(again["min_weight"].get<double>(), fix["min_weight"].get<double>(), kSumTolerance);
  }
}

TEST(WeightsCli, TriadDirectionsAreInfeasible) {
  ScratchDir scratch;
  const auto json = run_json("weights '" + kLayouts + "triad.json'", scratch);
  EXPECT_FALSE(json["feasible"].get<bool>());
  EXPECT_EQ(json["mode"], "vectors");
  EXPECT_TRUE(json.contains("suggestion"));
}

TEST(WeightsCli, ReadableReport) {
  ScratchDir scratch;
  scratch.write("side.json", R"({"points": [[1,0,0],[2,1,0],[1.5,0,1]]})");
  auto run = run_vantage("weights side.json", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("status      infeasible"));
  EXPECT_THAT(run.out, HasSubstr("suggestion: "));
  run = run_vantage("weights '" + kLayouts + "satellite.json'", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("status      positive"));
  EXPECT_THAT(run.out, HasSubstr("residual"));
}

using testing::BadCall;

class WeightsCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(WeightsCliBadInput, OneErrorLineExitTwo) {
  ScratchDir scratch;
  testing::run_bad_call("weights", GetParam(), scratch);
}

const BadCall kBadCalls[] = {
    {"NoLayout", nullptr, "", "LAYOUT is required"},
    {"MissingFile", nullptr, "in.json", "in.json: cannot open file"},
    {"NotJson", "[1,", "in.json --json", "in.json: not valid JSON"},
    {"CoincidentPoints", R"({"points": [[0,0,0],[1,0,0],[1,0,0]]})", "in.json", "points[2]"},
    {"BadWeights", R"({"points": [[0,0,0],[1,0,0],[0,1,0]], "weights": [1, -1, 1]})", "in.json",
     "weights[1]"},
};

INSTANTIATE_TEST_SUITE_P(WeightsCli, WeightsCliBadInput, ::testing::ValuesIn(kBadCalls),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vantage

// `vantage design --objective camera|tracker` (docs/math.md §21, "In design"): K of the layout's
// candidates added for the camera's pose CRB or the tracker's TRE. Truth: every K-subset of the
// candidates scored independently of the search (the camera's lattice of the library's CRB map,
// the tracker's certified bound as `vantage analyze` evaluates a file), and `vantage analyze` on
// the written file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "vantage/analysis/layout.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/commands/sensor_json.h"

namespace vantage {
namespace {

using testing::BadCall;
using ::testing::HasSubstr;
using testing::ScratchDir;

// Four markers packed in a 6 cm patch, and six candidates around them, nearer and farther: the
// camera's and the tracker's objectives both reward spread, the paper's bound does not.
const Eigen::Matrix3Xd kMarkers =
    (Eigen::Matrix3Xd(3, 4) << 0, 0.06, 0, 0.05, 0, 0, 0.06, 0.05, 0, 0, 0, 0.02).finished();
const Eigen::Matrix3Xd kCandidates =
    (Eigen::Matrix3Xd(3, 6) << 0.3, -0.25, 0.1, 0.02, -0.1, 0.5,  //
     0.05, 0.2, -0.3, 0.1, -0.05, 0.4,                            //
     0.01, 0.05, 0.03, 0.2, 0.1, -0.05)
        .finished();
constexpr int kAdd = 2;

std::string rows(const Eigen::Matrix3Xd& m) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index j = 0; j < m.cols(); ++j) out.push_back({m(0, j), m(1, j), m(2, j)});
  return out.dump();
}

std::string layout_text() {
  return R"({"name": "patch", "points": )" + rows(kMarkers) +
         R"(, "names": ["m1", "m2", "m3", "m4"], "candidates": )" + rows(kCandidates) + "}";
}

// The markers and candidates a and b.
Layout with_pair(int a, int b) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, kMarkers.cols() + 2);
  layout.entries << kMarkers, kCandidates.col(a), kCandidates.col(b);
  layout.weights = Eigen::VectorXd::Ones(layout.entries.cols());
  return layout;
}

constexpr double kDistance = 2.0;
constexpr int kSamples = 400;

// The camera objective's search value of a choice: the largest first-order rot_rms over the
// lattice of the library's CRB map (docs/math.md §21: the search ranks by the samples, not by the
// refined worst).
double lattice_worst(const Layout& layout, const Eigen::Vector3d& aim) {
  camera::PoseCrbOptions crb;
  crb.distance = kDistance;
  crb.focal_length = 1000.0;
  crb.noise_px = 0.3;
  crb.samples = kSamples;
  crb.aim = aim;
  const camera::PoseCrbMap map = camera::pose_crb_map(camera::PoseCrbModel(layout, crb));
  double worst = 0.0;
  for (const camera::PoseCrbAt& at : map.samples) {
    worst = std::max(worst, at.first_order_rot_rms_deg);
  }
  return worst;
}

TEST(DesignObjectiveCli, CameraChoosesTheBestPairOfCandidates) {
  ScratchDir scratch;
  scratch.write("in.json", layout_text());
  const nlohmann::json json = testing::run_json(
      "design in.json --add 2 --objective camera --distance 2 --focal 1000 --noise-px 0.3 "
      "--crb-samples " +
          std::to_string(kSamples) + " --write out.json",
      scratch);
  ASSERT_EQ(json["status"], "complete");
  EXPECT_EQ(json["search"], "exhaustive");
  EXPECT_EQ(json["written"], "out.json");
  // The aim is the centre of the bounding box of the markers and the candidates.
  Eigen::Matrix3Xd all(3, kMarkers.cols() + kCandidates.cols());
  all << kMarkers, kCandidates;
  const Eigen::Vector3d aim = 0.5 * (all.rowwise().minCoeff() + all.rowwise().maxCoeff()).eval();
  double best = std::numeric_limits<double>::infinity();
  std::vector<int> best_pair;
  for (int a = 0; a < kCandidates.cols(); ++a) {
    for (int b = a + 1; b < kCandidates.cols(); ++b) {
      const double value = lattice_worst(with_pair(a, b), aim);
      if (value < best) best = value, best_pair = {a, b};
    }
  }
  EXPECT_EQ(json["added"], nlohmann::json(best_pair));
  EXPECT_NEAR(json["search_value_deg"].get<double>(), best, 1e-12 * best);
  // The written file: the markers, the two added (named), the other four candidates, the sensor;
  // `vantage analyze` reports the value the design reported.
  const nlohmann::json written =
      nlohmann::json::parse(testing::read_file(scratch.path("out.json")));
  EXPECT_EQ(written["points"].size(), 6u);
  EXPECT_EQ(written["candidates"].size(), 4u);
  EXPECT_EQ(written["names"][4], "added1");
  EXPECT_EQ(written["sensor"]["type"], "camera");
  const nlohmann::json analyzed = testing::run_json("analyze out.json", scratch);
  EXPECT_EQ(analyzed["sensor"]["value_deg"], json["sensor"]["value_deg"]);
  // Better than the markers alone.
  ASSERT_TRUE(json["initial"].is_object());
  EXPECT_LT(json["sensor"]["value_deg"].get<double>(), json["initial"]["value_deg"].get<double>());
}

TEST(DesignObjectiveCli, TrackerChoosesTheBestPairByTheCertifiedBound) {
  ScratchDir scratch;
  scratch.write("in.json", layout_text());
  const std::string tracker = " --objective tracker --target 0,0,-0.3 --fle-rms 0.001";
  const nlohmann::json json =
      testing::run_json("design in.json --add 2 --write out.json" + tracker, scratch);
  ASSERT_EQ(json["status"], "complete");
  // Every pair's certified worst RMS TRE, as `vantage analyze` evaluates a file with the sensor.
  const LayoutSensor sensor = [&] {
    LayoutSensor s;
    s.kind = LayoutSensor::Kind::kTracker;
    s.targets = {Eigen::Vector3d(0, 0, -0.3)};
    s.fle_rms = 0.001;
    return s;
  }();
  double best = std::numeric_limits<double>::infinity();
  std::vector<int> best_pair;
  for (int a = 0; a < kCandidates.cols(); ++a) {
    for (int b = a + 1; b < kCandidates.cols(); ++b) {
      Layout layout = with_pair(a, b);
      layout.sensor = sensor;
      const double value = sensor_json::evaluate(layout, 0).value;
      if (value < best) best = value, best_pair = {a, b};
    }
  }
  EXPECT_EQ(json["added"], nlohmann::json(best_pair));
  EXPECT_EQ(json["sensor"]["value"].get<double>(), best);
  const nlohmann::json analyzed = testing::run_json("analyze out.json", scratch);
  EXPECT_EQ(analyzed["sensor"]["value"], json["sensor"]["value"]);
}

TEST(DesignObjectiveCli, TheTextReportNamesTheSensorAndTheAddedCandidates) {
  ScratchDir scratch;
  scratch.write("in.json", layout_text());
  const testing::CliRun run = testing::run_vantage(
      "design in.json --add 1 --objective camera --distance 2 --focal 1000 --noise-px 0.3 "
      "--crb-samples 400",
      scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("adding 1 of them for the camera objective"));
  EXPECT_THAT(run.out, HasSubstr(" as given -> "));
  EXPECT_THAT(run.out, HasSubstr(" with candidates c"));
}

TEST(DesignObjectiveCli, BadInputIsOneLineExitTwoNothingWritten) {
  ScratchDir scratch;
  const std::string camera = " --objective camera --distance 2 --focal 1000 --noise-px 0.3";
  const std::string with_candidates = layout_text();
  const std::string no_candidates = R"({"points": )" + rows(kMarkers) + "}";
  const std::string on_a_body =
      R"({"points": )" + rows(kMarkers) + R"(, "normals": [[0,0,1],[0,0,1],[0,0,1],[0,0,1]],)" +
      R"( "visibility": {"cone_half_angle_deg": 80}, "candidates": )" + rows(kCandidates) + "}";
  const std::string vectors = R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})";
  // Markers whose distances differ by at least 0.13, and candidates at the midpoints of marker
  // pairs: each is as far from two markers, so none keeps a distance difference of 0.1.
  const std::string midpoints = R"({"points": [[0,0,0],[1,0,0],[0,2.2,0],[0,0,3.7]],)"
                                R"( "candidates": [[0.5,0,0],[0,1.1,0],[0,0,1.85]]})";
  const std::string far_camera = " --objective camera --distance 10 --focal 1000 --noise-px 0.3";
  const std::string add1 = "in.json --add 1 --write out.json";
  const std::string add7 = "in.json --add 7 --write out.json";
  struct Call {
    std::string name, file, args, expected;
  };
  const std::vector<Call> calls = {
      {"NoCandidates", no_candidates, add1 + camera, "in.json: candidates"},
      {"AVisibilityModel", on_a_body, add1 + camera, "in.json: visibility"},
      {"Vectors", vectors, add1 + camera, "in.json: vectors"},
      {"MoreThanTheCandidates", with_candidates, add7 + camera,
       "--add: 7 exceeds the 6 candidates"},
      {"NoFocal", with_candidates, add1 + " --objective camera --distance 2 --noise-px 0.3",
       "--focal"},
      {"MarginIsTheAugmenters", with_candidates, add1 + camera + " --margin 1", "--margin"},
      {"NoPlot", with_candidates, add1 + camera + " --plot figs", "--plot"},
      {"CsvLosesTheSensor", with_candidates, "in.json --add 1 --write out.csv" + camera, "--write"},
      {"FocalWithoutTheCamera", with_candidates, add1 + " --focal 1000",
       "--focal: goes with --objective camera"},
      {"NoFle", with_candidates, add1 + " --objective tracker --target 0,0,1", "--fle-rms"},
      // Found by a review: the search's own refusals and the checks' order named no flag.
      {"CameraInsideTheSites", with_candidates,
       add1 + " --objective camera --distance 0.01 --focal 1000 --noise-px 0.3", "--distance"},
      {"NoCandidateKeepsTheGap", midpoints, add1 + far_camera + " --min-distance-difference 0.1",
       "--min-distance-difference: no 5 sites"},
      {"NegativeGap", with_candidates, add1 + camera + " --min-distance-difference -0.1",
       "--min-distance-difference: must be a finite number >= 0"},
      {"EmptyWrite", with_candidates, "in.json --add 1 --write ''" + camera,
       "--write: empty file name"},
      {"UnknownWriteFormat", with_candidates, "in.json --add 1 --write out.txt" + camera,
       "--write"},
  };
  for (const Call& call : calls) {
    SCOPED_TRACE(call.name);
    const BadCall bad{call.name.c_str(), call.file.c_str(), call.args.c_str(),
                      call.expected.c_str()};
    testing::run_bad_call("design", bad, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("out.json")));
    EXPECT_FALSE(std::filesystem::exists(scratch.path("out.csv")));
  }
}

}  // namespace
}  // namespace vantage

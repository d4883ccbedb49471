#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;
using Matrix = std::array<std::array<double, 3>, 3>;
using Vector = std::array<double, 3>;

const std::string kExamples = std::string(VANTAGE_SOURCE_DIR) + "/examples/correspondences/";
const std::string kAffine = kExamples + "affine_pose.json";
const std::string kPerspective = kExamples + "perspective_pose.json";
const std::string kTwoView = kExamples + "two_view.json";

// Noise-free examples, written with 12-15 decimals: recovered poses agree far below these.
constexpr double kExactTolerance = 1e-9;
// Orthogonal iteration stops on a relative change of E of 1e-12 (its default), E ~ 1e-20:
// the pose is then known to ~1e-10.
constexpr double kIterativeTolerance = 1e-8;

/// Rotation by `degrees` about `axis` (Rodrigues), independent of the library.
Matrix rotation(double degrees, Vector axis) {
  const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (double& a : axis) a /= norm;
  const double t = degrees * kPi / 180.0;
  const double c = std::cos(t), s = std::sin(t), v = 1.0 - c;
  const auto [x, y, z] = axis;
  return {{{c + x * x * v, x * y * v - z * s, x * z * v + y * s},
           {y * x * v + z * s, c + y * y * v, y * z * v - x * s},
           {z * x * v - y * s, z * y * v + x * s, c + z * z * v}}};
}

/// The truths the example files were generated from (their "description" fields).
const Matrix kAffineR = rotation(35.0, {1.0, -2.0, 2.0});
const Vector kAffineP = {0.3, -0.2, 10.0};
constexpr double kAffineAlpha = 0.01;
constexpr double kAffineFocal = 1000.0;  // p_z = alpha * f (Eq. 37)
const Matrix kPerspectiveR = rotation(-50.0, {2.0, 1.0, -1.0});
const Vector kPerspectiveP = {0.15, -0.1, 4.0};
const Matrix kTwoViewR = rotation(12.0, {0.0, 1.0, 0.2});
const Vector kTwoViewT = {-0.5, 0.05, 0.1};  // recovered as a unit vector

Vector unit(Vector v) {
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& a : v) a /= norm;
  return v;
}

/// Largest entry-wise difference between a JSON 3x3 row list and a matrix.
double max_difference(const nlohmann::json& rows, const Matrix& expected) {
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      worst = std::max(worst, std::abs(rows.at(i).at(j).get<double>() - expected[i][j]));
  return worst;
}

/// Angle between the rotation in `rows` and `expected`, degrees.
double angle_between_deg(const nlohmann::json& rows, const Matrix& expected) {
  double trace = 0.0;  // tr(R^T R_expected)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) trace += rows.at(i).at(j).get<double>() * expected[i][j];
  return std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * kDegreesPerRadian;
}

void expect_vector_near(const nlohmann::json& list, const Vector& expected, double tolerance) {
  ASSERT_EQ(list.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(list.at(i).get<double>(), expected[i], tolerance) << i;
}

/// A numerical failure (exit 1) says why: one line on stderr, "vantage: pose: <status>: ...".
void expect_reason_on_stderr(const testing::CliRun& run, const std::string& what) {
  EXPECT_EQ(run.status, 1) << what;
  EXPECT_EQ(testing::line_count(run.err), 1) << what << "\n" << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage: pose: ")) << what;
  for (const char* internal : {"degenerate_gap", "sign pattern", "3-D problem", "start is"}) {
    EXPECT_THAT(run.err, ::testing::Not(HasSubstr(internal))) << what;
  }
}

nlohmann::json run_json(const std::string& args, int expected_status = 0) {
  ScratchDir scratch;
  const auto run = run_vantage("pose " + args + " --json", scratch);
  EXPECT_EQ(run.status, expected_status) << args << "\n" << run.err;
  if (expected_status == 1) {
    expect_reason_on_stderr(run, args);
  } else {
    EXPECT_EQ(run.err, "") << args;
  }
  // JSON has no NaN or Infinity: the command prints null instead.
  EXPECT_THAT(run.out, ::testing::Not(HasSubstr("NaN"))) << args;
  EXPECT_THAT(run.out, ::testing::Not(HasSubstr("Infinity"))) << args;
  return nlohmann::json::parse(run.out);
}

void expect_contract_fields(const nlohmann::json& json, const std::string& method) {
  // The fixed contract of every method (scripts depend on it).
  for (const char* field : {"method", "R", "p", "status", "ambiguous", "reprojection_rms_px"}) {
    EXPECT_TRUE(json.contains(field)) << method << ": " << field;
  }
  EXPECT_EQ(json["method"], method);
  ASSERT_EQ(json["R"].size(), 3u);
  for (const auto& row : json["R"]) EXPECT_EQ(row.size(), 3u);
  EXPECT_EQ(json["p"].size(), 3u);
  EXPECT_TRUE(json["ambiguous"].is_boolean()) << method;
  EXPECT_TRUE(json["reprojection_rms_px"].is_number() || json["reprojection_rms_px"].is_null());
  if (json["status"] == "ok" && !json["ambiguous"].get<bool>()) {
    EXPECT_FALSE(json.contains("message")) << method;
  } else {
    EXPECT_TRUE(json.contains("message")) << method;
  }
  if (json.contains("alternative")) {
    const auto& alternative = json["alternative"];
    EXPECT_EQ(alternative["R"].size(), 3u) << method;
    EXPECT_EQ(alternative["p"].size(), 3u) << method;
    EXPECT_TRUE(alternative.contains("reprojection_rms_px")) << method;
  }
}

TEST(PoseCli, AffineRecoversTheExamplePose) {
  for (const char* free_vectors : {"all", "spanning"}) {
    const auto json =
        run_json("'" + kAffine + "' --method affine --focal 1000 --free-vectors " + free_vectors);
    expect_contract_fields(json, "affine");
    for (const char* field : {"sign_patterns", "ambiguity_margin", "clamped"}) {
      EXPECT_TRUE(json.contains(field)) << field;
    }
    EXPECT_EQ(json["status"], "ok") << free_vectors;
    EXPECT_LT(max_difference(json["R"], kAffineR), kExactTolerance) << free_vectors;
    expect_vector_near(json["p"], kAffineP, kExactTolerance);
    EXPECT_NEAR(json["alpha"].get<double>(), kAffineAlpha, kExactTolerance * kAffineAlpha);
    EXPECT_EQ(json["depth_known"], true);
    EXPECT_EQ(json["clamped"], 0);
    EXPECT_EQ(json["in_plane"], 1);  // model[5] - model[1], in both free-vector sets
    EXPECT_GT(json["ambiguity_margin"].get<double>(), 0.0);
  }
  const auto all = run_json("'" + kAffine + "' --method affine --free-vectors all");
  EXPECT_EQ(all["free_vector_count"], 15);    // 6 points, all pairs
  EXPECT_EQ(all["sign_patterns"], 1u << 14);  // one of the 15 lies in the image plane
  const auto tree = run_json("'" + kAffine + "' --method affine --free-vectors spanning");
  EXPECT_EQ(tree["free_vector_count"], 5);
  EXPECT_EQ(tree["sign_patterns"], 1u << 4);
}

TEST(PoseCli, AffineWithoutFocalLeavesTheDepthUnknown) {
  const auto json = run_json("'" + kAffine + "' --method affine");
  EXPECT_EQ(json["depth_known"], false);
  EXPECT_TRUE(json["camera"]["focal"].is_null());
  EXPECT_TRUE(json["p"][2].is_null());
  EXPECT_NEAR(json["p"][0].get<double>(), kAffineP[0], kExactTolerance);
  EXPECT_NEAR(json["p"][1].get<double>(), kAffineP[1], kExactTolerance);
}

TEST(PoseCli, StandardApproachIsTheBiasedBaseline) {
  const auto standard = run_json("'" + kAffine + "' --method standard --focal 1000");
  expect_contract_fields(standard, "standard");
  EXPECT_EQ(standard["status"], "ok");
  EXPECT_EQ(standard["sign_patterns"], 1);
  EXPECT_TRUE(standard["ambiguity_margin"].is_null());  // +infinity: a single pattern
  EXPECT_TRUE(standard["runner_up_angle_deg"].is_null());
  EXPECT_EQ(standard["clamped"], 0);
  // Setting v_z = 0 treats every free vector as if it lay in the image plane; on this model
  // (depths spanning 0.9 across a body 1.95 long) that costs several degrees even without noise,
  // while Prop. 8 is exact. The bounds bracket the measured 7.7 deg loosely: the baseline must be
  // biased (it is not Prop. 8) but still a pose of the right body.
  const double error_deg = angle_between_deg(standard["R"], kAffineR);
  EXPECT_GT(error_deg, 1.0);
  EXPECT_LT(error_deg, 15.0);
  EXPECT_NEAR(standard["alpha"].get<double>(), kAffineAlpha, 0.05 * kAffineAlpha);
  expect_vector_near(standard["p"], kAffineP, 0.05);
  const auto affine = run_json("'" + kAffine + "' --method affine --focal 1000");
  EXPECT_GT(standard["objective"].get<double>(), affine["objective"].get<double>());
  EXPECT_GT(standard["reprojection_rms_px"].get<double>(),
            affine["reprojection_rms_px"].get<double>());
}

TEST(PoseCli, Full3dRecoversTheExamplePose) {
  for (const char* free_vectors : {"all", "spanning"}) {
    const auto json =
        run_json("'" + kAffine + "' --method full3d --free-vectors " + std::string(free_vectors));
    expect_contract_fields(json, "full3d");
    EXPECT_EQ(json["status"], "ok");
    EXPECT_LT(max_difference(json["R"], kAffineR), kExactTolerance);
    expect_vector_near(json["p"], kAffineP, kExactTolerance);
    EXPECT_NEAR(json["alpha"].get<double>(), kAffineAlpha, kExactTolerance * kAffineAlpha);
  }
}

TEST(PoseCli, Full3dReportsTheFreeVectorsItBuilt) {
  // full3d solves one Theorem-1 problem: auto means all pairs there, spanning n - 1.
  for (const std::string free_vectors : {"", " --free-vectors all", " --free-vectors spanning"}) {
    const auto json = run_json("'" + kAffine + "' --method full3d" + free_vectors);
    const int n = json["n"].get<int>();
    const int expected =
        free_vectors.find("spanning") == std::string::npos ? n * (n - 1) / 2 : n - 1;
    EXPECT_EQ(json["free_vector_count"], expected) << free_vectors;
  }
}

TEST(PoseCli, OrthogonalIterationRecoversTheExamplePose) {
  for (const char* method : {"oi-foam", "oi-svd"}) {
    const auto json = run_json("'" + kPerspective + "' --method " + std::string(method));
    expect_contract_fields(json, method);
    EXPECT_EQ(json["status"], "ok");
    EXPECT_TRUE(json["alpha"].is_null());
    EXPECT_GT(json["iterations"].get<int>(), 0);
    EXPECT_EQ(json["points_behind_camera"], 0);
    EXPECT_LT(max_difference(json["R"], kPerspectiveR), kIterativeTolerance) << method;
    expect_vector_near(json["p"], kPerspectiveP, kIterativeTolerance);
  }
}

TEST(PoseCli, OrthogonalIterationDividesPixelsByTheFocalLength) {
  constexpr double kFocal = 800.0;
  auto file = nlohmann::json::parse(testing::read_file(kPerspective));
  for (auto& point : file["image"])
    for (auto& coordinate : point) coordinate = coordinate.get<double>() * kFocal;
  ScratchDir scratch;
  const std::string path = scratch.write("pixels.json", file.dump());
  const auto json = run_json("'" + path + "' --method oi-foam --focal 800");
  EXPECT_EQ(json["status"], "ok");
  EXPECT_EQ(json["camera"]["focal"], kFocal);
  EXPECT_LT(max_difference(json["R"], kPerspectiveR), kIterativeTolerance);
  expect_vector_near(json["p"], kPerspectiveP, kIterativeTolerance);
}

/// The perspective example in pixels of a camera with focal length f and principal point c,
/// written with a "camera" field when `with_camera`.
std::string pixel_file(ScratchDir& scratch, double f, double cx, double cy, bool with_camera) {
  auto file = nlohmann::json::parse(testing::read_file(kPerspective));
  for (auto& point : file["image"]) {
    point[0] = cx + f * point[0].get<double>();
    point[1] = cy + f * point[1].get<double>();
  }
  if (with_camera) file["camera"] = {{"focal", f}, {"principal_point", {cx, cy}}};
  return scratch.write(with_camera ? "camera.json" : "bare.json", file.dump());
}

TEST(PoseCli, PerspectiveMethodsReadTheCameraFromTheFileOrTheOptions) {
  ScratchDir scratch;
  const std::string with_camera = pixel_file(scratch, 800.0, 320.0, 240.0, true);
  const std::string bare = pixel_file(scratch, 800.0, 320.0, 240.0, false);
  auto wrong_focal = nlohmann::json::parse(testing::read_file(with_camera));
  wrong_focal["camera"]["focal"] = 500.0;
  const std::string wrong = scratch.write("wrong.json", wrong_focal.dump());
  // The perspective example is noise-free: the pinhole refinement is exact; OI stops on the
  // pose-change rule.
  for (const char* method : {"perspective", "oi-foam"}) {
    for (const std::string& args :
         {"'" + with_camera + "'", "'" + bare + "' --focal 800 --principal-point 320 240",
          // options override the file: a wrong file focal length corrected on the command line
          "'" + wrong + "' --focal 800"}) {
      const auto json = run_json(args + " --method " + method);
      expect_contract_fields(json, method);
      EXPECT_EQ(json["status"], "ok") << args;
      EXPECT_EQ(json["camera"]["focal"], 800.0);
      EXPECT_LT(max_difference(json["R"], kPerspectiveR), kIterativeTolerance) << method << args;
      expect_vector_near(json["p"], kPerspectiveP, kIterativeTolerance);
      EXPECT_LT(json["reprojection_rms_px"].get<double>(), 1e-6);
    }
  }
  // Today's files (normalised coordinates, no camera) keep working: f = 1.
  const auto normalised = run_json("'" + kPerspective + "' --method perspective");
  EXPECT_EQ(normalised["camera"]["focal"], 1.0);
  EXPECT_LT(max_difference(normalised["R"], kPerspectiveR), kExactTolerance);
  // A wrong principal point is a different camera: the fit is no longer exact.
  const auto shifted = run_json("'" + with_camera + "' --method perspective --principal-point 0 0");
  EXPECT_GT(shifted["reprojection_rms_px"].get<double>(), 1.0);
}

TEST(PoseCli, AffineRefinedIsExactOnTheAffineExample) {
  const auto json = run_json("'" + kAffine + "' --method affine-refined --focal 1000");
  expect_contract_fields(json, "affine-refined");
  EXPECT_EQ(json["status"], "ok");
  EXPECT_EQ(json["ambiguous"], false);
  EXPECT_LT(max_difference(json["R"], kAffineR), kExactTolerance);
  expect_vector_near(json["p"], kAffineP, kExactTolerance);
  EXPECT_NEAR(json["alpha"].get<double>(), kAffineAlpha, kExactTolerance * kAffineAlpha);
  EXPECT_LT(json["reprojection_rms_px"].get<double>(), 1e-9);
}

TEST(PoseCli, TwoViewRecoversTheExampleMotion) {
  const auto json = run_json("'" + kTwoView + "' --method two-view");
  expect_contract_fields(json, "two-view");
  EXPECT_EQ(json["status"], "ok");
  EXPECT_TRUE(json["alpha"].is_null());
  EXPECT_EQ(json["T"], json["p"]);
  EXPECT_EQ(json["points_in_front"], 10);
  EXPECT_LT(max_difference(json["R"], kTwoViewR), kExactTolerance);
  expect_vector_near(json["T"], unit(kTwoViewT), kExactTolerance);
}

TEST(PoseCli, ReadableReportByDefault) {
  ScratchDir scratch;
  const struct {
    std::string args;
    const char* expected;
  } cases[] = {
      {"'" + kAffine + "' --method affine", "p_z unknown"},
      {"'" + kAffine + "' --method standard --focal 1000", "runner-up    none"},
      {"'" + kAffine + "' --method full3d", "alpha        0.01"},
      {"'" + kPerspective + "' --method oi-svd", "iterations   "},
      {"'" + kPerspective + "' --method perspective", "branches     1"},
      {"'" + kAffine + "' --method affine-refined", "reprojection "},
      {"'" + kTwoView + "' --method two-view", "10 of 10 points"},
  };
  for (const auto& c : cases) {
    const auto run = run_vantage("pose " + c.args, scratch);
    ASSERT_EQ(run.status, 0) << c.args << "\n" << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_THAT(run.out, HasSubstr("status       ")) << c.args;
    EXPECT_THAT(run.out, HasSubstr(c.expected)) << c.args;
    EXPECT_THAT(run.out, ::testing::Not(HasSubstr("nan"))) << c.args;
    EXPECT_THAT(run.out, ::testing::Not(HasSubstr("inf"))) << c.args;
  }
}

TEST(PoseCli, CoplanarModelIsAmbiguousButAnswered) {
  // Four coplanar points (z = 0) seen tilted by an affine camera with alpha = 1: the two-fold
  // reversal fits exactly as well, so the status is "ambiguous"; that is an answer (exit 0) and
  // one of the two reported rotations is the truth. model[3] lies on the tilt axis, so its free
  // vector stays in the image plane and Lemma 7's scale is exact.
  const Matrix R = rotation(30.0, {1.0, 0.5, 0.0});
  const std::vector<Vector> model = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 1, 0}};
  nlohmann::json file;
  for (const Vector& z : model) {
    file["model"].push_back(z);
    file["image"].push_back({R[0][0] * z[0] + R[0][1] * z[1] + R[0][2] * z[2],
                             R[1][0] * z[0] + R[1][1] * z[1] + R[1][2] * z[2]});
  }
  ScratchDir scratch;
  const std::string path = scratch.write("coplanar.json", file.dump());
  const auto json = run_json("'" + path + "' --method affine");
  expect_contract_fields(json, "affine");
  EXPECT_EQ(json["status"], "ok");
  EXPECT_EQ(json["ambiguous"], true);
  ASSERT_TRUE(json.contains("alternative"));
  const double best =
      std::min(max_difference(json["R"], R), max_difference(json["alternative"]["R"], R));
  EXPECT_LT(best, kExactTolerance);
  EXPECT_GT(json["runner_up_angle_deg"].get<double>(), 1.0);
}

TEST(PoseCli, EstimatorFailureExitsOneAndStillPrintsTheResult) {
  ScratchDir scratch;
  const std::string collinear = scratch.write(
      "collinear.json",
      R"({"model": [[0,0,0],[1,0,0],[2,0,0],[3,0,0]], "image": [[0,0],[0.5,0.1],[1,0.2],[1.5,0.3]]})");
  for (const char* method :
       {"affine", "standard", "oi-foam", "oi-svd", "affine-refined", "perspective"}) {
    const auto json = run_json("'" + collinear + "' --method " + std::string(method), 1);
    expect_contract_fields(json, method);
    EXPECT_EQ(json["status"], "degenerate") << method;
  }
  // The same image twice: a pure rotation (T = 0), so E is not unique.
  auto views = nlohmann::json::parse(testing::read_file(kTwoView));
  views["image2"] = views["image1"];
  const std::string still = scratch.write("still.json", views.dump());
  const auto json = run_json("'" + still + "' --method two-view", 1);
  EXPECT_EQ(json["status"], "degenerate");
  const auto run = run_vantage("pose '" + still + "' --method two-view", scratch);
  EXPECT_EQ(run.status, 1);
  EXPECT_THAT(run.out, HasSubstr("status       degenerate"));
}

TEST(PoseCli, EveryNumericalFailureSaysWhyOnStderr) {
  // The cases that used to exit 1 with an empty stderr (issue "Hardening II").
  ScratchDir scratch;
  const std::string collinear = scratch.write(
      "line.json",
      R"({"model": [[0,0,0],[1,1,1],[2,2,2],[3,3,3]], "image": [[0,0],[10,12],[20,24],[30,36]],
          "measured": [[0,0,5],[1,1,6],[2,2,7],[3,3,8]]})");
  for (const char* method : {"affine", "full3d", "standard", "perspective", "oi-foam"}) {
    expect_reason_on_stderr(
        run_vantage("pose '" + collinear + "' --method " + std::string(method), scratch), method);
  }
  auto views = nlohmann::json::parse(testing::read_file(kTwoView));
  views["image2"] = views["image1"];
  const std::string same = scratch.write("same.json", views.dump());
  expect_reason_on_stderr(run_vantage("pose '" + same + "' --method two-view", scratch),
                          "identical views");
  for (auto& point : views["image1"]) point = {0.0, 0.0};
  views["image2"] = views["image1"];
  const std::string zeros = scratch.write("zeros.json", views.dump());
  expect_reason_on_stderr(run_vantage("pose '" + zeros + "' --method two-view", scratch),
                          "all zeros");
  const std::string still = scratch.write(
      "still.json",
      R"({"model": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "image": [[5,5],[5,5],[5,5],[5,5]]})");
  expect_reason_on_stderr(run_vantage("pose '" + still + "' --method oi-svd", scratch),
                          "identical image points");
}

TEST(PoseCli, HelpExitsZero) {
  ScratchDir scratch;
  const auto run = run_vantage("pose --help", scratch);
  EXPECT_EQ(run.status, 0);
  EXPECT_THAT(run.out, HasSubstr("--method"));
  EXPECT_THAT(run.out, HasSubstr("--free-vectors"));
}

// In args, AFFINE stands for the affine example's path.
using testing::BadCall;

class PoseCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(PoseCliBadInput, OneErrorLineExitTwoNothingOnStdout) {
  ScratchDir scratch;
  if (GetParam().file_text) scratch.write("in.json", GetParam().file_text);
  std::string args = GetParam().args;
  if (const auto at = args.find("AFFINE"); at != std::string::npos) {
    args.replace(at, 6, "'" + kAffine + "'");
  }
  for (const char* json : {"", " --json"}) {
    testing::expect_bad_input(run_vantage("pose " + args + json, scratch), GetParam().expected);
  }
}

const BadCall kBadCalls[] = {
    {"NoFile", nullptr, "--method affine", "CORRESPONDENCES is required"},
    {"NoMethod", nullptr, "AFFINE", "--method is required"},
    {"UnknownMethod", nullptr, "AFFINE --method epnp", "--method"},
    {"FocalZero", nullptr, "AFFINE --method affine --focal 0", "--focal: must be"},
    {"FocalNegative", nullptr, "AFFINE --method oi-foam --focal -2", "--focal: must be"},
    {"FocalNaN", nullptr, "AFFINE --method two-view --focal nan", "--focal"},
    {"FocalNotANumber", nullptr, "AFFINE --method affine --focal wide", "--focal"},
    {"FocalForFull3d", nullptr, "AFFINE --method full3d --focal 1000", "--focal: not used"},
    {"UnknownFreeVectors", nullptr, "AFFINE --method affine --free-vectors some", "--free-vectors"},
    {"FreeVectorsForOi", nullptr, "AFFINE --method oi-foam --free-vectors all", "--free-vectors"},
    {"MissingFile", nullptr, "in.json --method affine", "in.json: cannot open file"},
    {"NaNInFile", R"({"model": [[0,0,NaN]], "image": [[0,0]]})", "in.json --method affine",
     "in.json: model[0][2]: not a finite number"},
    {"OverflowInFile", R"({"model": [[0,0,1e999]], "image": [[0,0]]})", "in.json --method affine",
     "in.json"},
    {"AffineWithoutImage", R"({"model": [[0,0,0],[1,0,0],[0,1,0]]})", "in.json --method affine",
     "in.json: image: missing, required by the affine method"},
    {"OiWithoutModel", R"({"image1": [[0,0]], "image2": [[0,0]]})", "in.json --method oi-svd",
     "in.json: model: missing, required by the oi-svd method"},
    {"Full3dWithoutMeasured",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0]], "image": [[0,0],[1,0],[0,1]]})",
     "in.json --method full3d", "in.json: measured: missing, required by the full3d method"},
    {"TwoViewWithoutImages", nullptr, "AFFINE --method two-view",
     "image1: missing, required by the two-view method"},
    {"ImageCountMismatch", R"({"model": [[0,0,0],[1,0,0],[0,1,0]], "image": [[0,0],[1,0]]})",
     "in.json --method affine", "image: has 2 entries but model has 3"},
    {"ViewCountMismatch", R"({"image1": [[0,0],[1,0]], "image2": [[0,0]]})",
     "in.json --method two-view", "image2: has 1 entries but image1 has 2"},
    {"AffineTwoPoints", R"({"model": [[0,0,0],[1,0,0]], "image": [[0,0],[1,0]]})",
     "in.json --method affine", "in.json: model: has 2 points, the affine method needs at least 3"},
    {"OiTwoPoints", R"({"model": [[0,0,0],[1,0,0]], "image": [[0,0],[1,0]]})",
     "in.json --method oi-foam",
     "in.json: model: has 2 points, the oi-foam method needs at least 3"},
    {"TwoViewFivePoints",
     R"({"image1": [[0,0],[1,0],[0,1],[1,1],[2,1]], "image2": [[0,0],[1,0],[0,1],[1,1],[2,1]]})",
     "in.json --method two-view",
     "in.json: image1: has 5 points, the two-view method needs at least 8"},
    {"WeightsForTwoView",
     R"({"image1": [[0,0],[1,0],[0,1],[1,1],[2,1],[3,1],[1,3],[2,2]],
         "image2": [[0,0],[1,0],[0,1],[1,1],[2,1],[3,1],[1,3],[2,2]],
         "weights": [1,1,1,1,1,1,1,2]})",
     "in.json --method two-view", "in.json: weights: not used"},
    {"CoincidentModelPoints",
     R"({"model": [[0,0,0],[1,0,0],[1,0,0]], "image": [[0,0],[1,0],[1,1]]})",
     "in.json --method affine", "in.json: model[2]: coincides with model[1]"},
    {"TooManyFreeVectors",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,0],[1,0,1],[0,1,1],[1,1,1]],
         "image": [[0,0],[1,0],[0,1],[0,0],[1,1],[1,0],[0,1],[1,1]]})",
     "in.json --method affine --free-vectors all",
     "in.json: model: 8 points give 28 free vectors, more than the limit 24"},
    {"CameraFocalNegative",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0]], "image": [[0,0],[1,0],[0,1]],
         "camera": {"focal": -5}})",
     "in.json --method perspective", "in.json: camera.focal: must be a finite number > 0"},
    {"CameraPrincipalPointArity",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0]], "image": [[0,0],[1,0],[0,1]],
         "camera": {"principal_point": [1, 2, 3]}})",
     "in.json --method affine", "in.json: camera.principal_point: must be [cx, cy]"},
    {"CameraUnknownKey",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0]], "image": [[0,0],[1,0],[0,1]],
         "camera": {"fx": 5}})",
     "in.json --method affine", "unknown field \"fx\""},
    {"PrincipalPointOneNumber", nullptr, "AFFINE --method perspective --principal-point 3",
     "--principal-point"},
    {"PrincipalPointForFull3d", nullptr, "AFFINE --method full3d --principal-point 3 4",
     "--principal-point: not used"},
    {"FocalBeyondRange", nullptr, "AFFINE --method oi-svd --focal 1e308",
     "--focal: must be a finite number in (0, 1e150]"},
    {"HugeModelOi",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0],[0,0,1e308]], "image": [[0,0],[1,0],[0,1],[1,1]]})",
     "in.json --method oi-foam", "in.json: model[3]: a coordinate beyond 1e150"},
    {"HugeModelFull3d",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0],[1e308,0,0]],
         "measured": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]})",
     "in.json --method full3d", "in.json: model[3]: a coordinate beyond 1e150"},
    {"HugeModelAffine",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0],[1e308,0,0]], "image": [[0,0],[1,0],[0,1],[1,1]]})",
     "in.json --method affine", "in.json: model[3]: a coordinate beyond 1e150"},
    {"HugeImageStandard",
     R"({"model": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "image": [[0,0],[1,0],[0,1],[1e308,1]]})",
     "in.json --method standard", "in.json: image[3]: a coordinate beyond 1e150"},
    {"HugeTwoView",
     R"({"image1": [[0,0],[1,0],[0,1],[1,1],[2,1],[3,1],[1,3],[1e308,2]],
         "image2": [[0,0],[1,0],[0,1],[1,1],[2,1],[3,1],[1,3],[2,2]]})",
     "in.json --method two-view", "in.json: image1[7]: a coordinate beyond 1e150"},
};

INSTANTIATE_TEST_SUITE_P(PoseCli, PoseCliBadInput, ::testing::ValuesIn(kBadCalls),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vantage

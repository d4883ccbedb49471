// `vantage ident` and the identification block of `vantage analyze` (issue 20; docs/math.md §24):
// the JSON names, every number against a brute force over the tools' own points, mirror images,
// the text reports, and bad input (one line, exit 2, nothing written).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>
#include <vector>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::BadCall;
using ::testing::HasSubstr;
using testing::run_json;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kToolDir = std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/";
// JSON numbers round-trip; distances recomputed here from the file's coordinates agree with the
// library's to rounding of millimetre-sized numbers.
constexpr double kDistanceRounding = 1e-12;
// The library's q-method fit and the SVD fit here solve one least-squares problem exactly.
constexpr double kFitRounding = 1e-9;

Eigen::Matrix3Xd points_of(const std::string& path) {
  const nlohmann::json j = nlohmann::json::parse(testing::read_file(path));
  Eigen::Matrix3Xd p(3, static_cast<Eigen::Index>(j["points"].size()));
  for (std::size_t i = 0; i < j["points"].size(); ++i) {
    for (int r = 0; r < 3; ++r)
      p(r, static_cast<Eigen::Index>(i)) = j["points"][i][r].get<double>();
  }
  return p;
}

double ident_distance(const Eigen::Matrix3Xd& p, int i, int j) {
  return (p.col(i) - p.col(j)).norm();
}

// Eq. (24.1) by every pair of pairs, optionally without one marker.
double brute_difference(const Eigen::Matrix3Xd& p, int lost) {
  std::vector<double> d;
  for (int i = 0; i < p.cols(); ++i) {
    for (int j = i + 1; j < p.cols(); ++j) {
      if (i != lost && j != lost) d.push_back(ident_distance(p, i, j));
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < d.size(); ++a) {
    for (std::size_t b = a + 1; b < d.size(); ++b) best = std::min(best, std::abs(d[a] - d[b]));
  }
  return best;
}

// Eq. (24.2) by every permutation, each fitted by the SVD with det = -1.
double brute_mirror(const Eigen::Matrix3Xd& p) {
  const Eigen::Matrix3Xd c = p.colwise() - p.rowwise().mean();
  std::vector<int> pi(static_cast<std::size_t>(p.cols()));
  std::iota(pi.begin(), pi.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {
    Eigen::Matrix3Xd y(3, p.cols());
    for (int i = 0; i < p.cols(); ++i) y.col(i) = c.col(pi[static_cast<std::size_t>(i)]);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(y * c.transpose(),
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    const double s = -(svd.matrixU() * svd.matrixV().transpose()).determinant();
    const Eigen::Matrix3d Q =
        svd.matrixU() * Eigen::Vector3d(1.0, 1.0, s).asDiagonal() * svd.matrixV().transpose();
    best = std::min(best, std::sqrt((Q * c - y).colwise().squaredNorm().sum() / p.cols()));
  } while (std::next_permutation(pi.begin(), pi.end()));
  return best;
}

// Eq. (24.4) by every k-subset of A and every ordered k-tuple of distinct markers of B.
double brute_mismatch(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, int k, bool self) {
  double best = std::numeric_limits<double>::infinity();
  const int na = static_cast<int>(a.cols());
  const int nb = static_cast<int>(b.cols());
  std::vector<int> tuple(static_cast<std::size_t>(k));
  for (int sa = 0; sa < (1 << na); ++sa) {
    if (__builtin_popcount(static_cast<unsigned>(sa)) != k) continue;
    std::vector<int> s;
    for (int i = 0; i < na; ++i) {
      if (sa & (1 << i)) s.push_back(i);
    }
    for (int sb = 0; sb < (1 << nb); ++sb) {
      if (__builtin_popcount(static_cast<unsigned>(sb)) != k) continue;
      std::vector<int> sigma;
      for (int j = 0; j < nb; ++j) {
        if (sb & (1 << j)) sigma.push_back(j);
      }
      do {
        if (self && sigma == s) continue;
        double worst = 0.0;
        for (int x = 0; x < k; ++x) {
          for (int y = x + 1; y < k; ++y) {
            worst = std::max(worst, std::abs(ident_distance(a, s[x], s[y]) -
                                             ident_distance(b, sigma[x], sigma[y])));
          }
        }
        best = std::min(best, worst);
      } while (std::next_permutation(sigma.begin(), sigma.end()));
    }
  }
  return best;
}

std::pair<int, int> pair_of(const nlohmann::json& j) { return {j[0].get<int>(), j[1].get<int>()}; }

TEST(AnalyzeIdentificationCli, JsonBlockEqualsBruteForce) {
  ScratchDir scratch;
  for (const char* name : {"west_planar.json", "ndi_like.json", "five_marker.json"}) {
    SCOPED_TRACE(name);
    const std::string path = kToolDir + name;
    const nlohmann::json j = testing::run_json("analyze '" + path + "' --quiet", scratch);
    ASSERT_TRUE(j.contains("identification"));
    const nlohmann::json& id = j["identification"];
    for (const char* field :
         {"min_distance_difference", "pair_a", "pair_b", "min_marker_separation", "mirror_rms",
          "under_dropout", "worst_under_dropout", "mirror_certified", "own_mirror"}) {
      EXPECT_TRUE(id.contains(field)) << field;
    }
    const Eigen::Matrix3Xd p = points_of(path);
    const int n = static_cast<int>(p.cols());
    const double truth = brute_difference(p, -1);
    EXPECT_NEAR(id["min_distance_difference"].get<double>(), truth, kDistanceRounding * 100);
    const auto a = pair_of(id["pair_a"]);
    const auto b = pair_of(id["pair_b"]);
    EXPECT_NEAR(
        std::abs(ident_distance(p, a.first, a.second) - ident_distance(p, b.first, b.second)),
        truth, kDistanceRounding * 100);
    double separation = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      for (int k = i + 1; k < n; ++k) separation = std::min(separation, ident_distance(p, i, k));
    }
    EXPECT_NEAR(id["min_marker_separation"].get<double>(), separation, kDistanceRounding * 100);
    ASSERT_EQ(id["under_dropout"].size(), static_cast<std::size_t>(n));
    double worst = std::numeric_limits<double>::infinity();
    for (int m = 0; m < n; ++m) {
      const nlohmann::json& e = id["under_dropout"][static_cast<std::size_t>(m)];
      EXPECT_EQ(e["lost"].get<int>(), m);
      EXPECT_NEAR(e["min_distance_difference"].get<double>(), brute_difference(p, m),
                  kDistanceRounding * 100);
      worst = std::min(worst, brute_difference(p, m));
    }
    EXPECT_NEAR(id["worst_under_dropout"]["min_distance_difference"].get<double>(), worst,
                kDistanceRounding * 100);
    EXPECT_TRUE(id["mirror_certified"].get<bool>());
    EXPECT_NEAR(id["mirror_rms"].get<double>(), brute_mirror(p), kFitRounding * 100);
  }
}

TEST(AnalyzeIdentificationCli, PlanarToolIsItsOwnMirrorAndTheTextSaysSo) {
  ScratchDir scratch;
  const testing::CliRun run =
      run_vantage("analyze '" + kToolDir + "west_planar.json' --quiet", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out,
              HasSubstr("identification         distances differ by 6.09 (m0-m1 vs m2-m3)"));
  EXPECT_THAT(run.out, HasSubstr("mirror RMS 0 (its own mirror)"));
  EXPECT_THAT(run.out, HasSubstr("one lost: 8.795 (m0-m1 vs m1-m3) without m2"));
}

TEST(AnalyzeIdentificationCli, DirectionLayoutsHaveNoBlock) {
  ScratchDir scratch;
  scratch.write("triad.json", R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})");
  const nlohmann::json j = testing::run_json("analyze triad.json --quiet", scratch);
  EXPECT_FALSE(j.contains("identification"));
}

TEST(IdentCli, JsonNamesAndEveryPairEqualsBruteForce) {
  ScratchDir scratch;
  const std::vector<std::string> names = {"west_planar.json", "ndi_like.json", "five_marker.json"};
  std::string args = "ident";
  for (const std::string& name : names) args += " '" + kToolDir + name + "'";
  const nlohmann::json j = testing::run_json(args, scratch);
  for (const char* field : {"min_visible", "tools", "pairs", "closest", "certified"}) {
    EXPECT_TRUE(j.contains(field)) << field;
  }
  EXPECT_EQ(j["min_visible"].get<int>(), 3);
  ASSERT_EQ(j["tools"].size(), 3u);
  ASSERT_EQ(j["pairs"].size(), 6u);
  EXPECT_TRUE(j["certified"].get<bool>());
  double smallest = std::numeric_limits<double>::infinity();
  for (const nlohmann::json& p : j["pairs"]) {
    for (const char* field : {"a", "b", "self", "mismatch", "subset", "assignment", "transform",
                              "proper_rms", "improper_rms", "certified"}) {
      EXPECT_TRUE(p.contains(field)) << field;
    }
    const int a = p["a"].get<int>();
    const int b = p["b"].get<int>();
    EXPECT_LE(a, b);
    EXPECT_EQ(p["self"].get<bool>(), a == b);
    const Eigen::Matrix3Xd pa = points_of(kToolDir + names[static_cast<std::size_t>(a)]);
    const Eigen::Matrix3Xd pb = points_of(kToolDir + names[static_cast<std::size_t>(b)]);
    const double truth = brute_mismatch(pa, pb, 3, a == b);
    EXPECT_NEAR(p["mismatch"].get<double>(), truth, kDistanceRounding * 100) << a << " " << b;
    EXPECT_EQ(p["subset"].size(), 3u);
    EXPECT_EQ(p["transform"].get<std::string>(), "either");  // three markers are coplanar
    smallest = std::min(smallest, truth);
  }
  EXPECT_NEAR(j["closest"]["mismatch"].get<double>(), smallest, kDistanceRounding * 100);
}

TEST(IdentCli, MirrorImageOfAToolMatchesAsAReflection) {
  ScratchDir scratch;
  const Eigen::Matrix3Xd p = points_of(kToolDir + "five_marker.json");
  std::string text = R"({"name": "mirror", "points": [)";
  // Mirrored in x and relabelled (reversed).
  for (Eigen::Index i = p.cols() - 1; i >= 0; --i) {
    text += "[" + std::to_string(-p(0, i)) + "," + std::to_string(p(1, i)) + "," +
            std::to_string(p(2, i)) + "]" + (i > 0 ? "," : "");
  }
  scratch.write("mirror.json", text + "]}");
  const nlohmann::json j = testing::run_json(
      "ident '" + kToolDir + "five_marker.json' mirror.json --min-visible 5", scratch);
  ASSERT_EQ(j["pairs"].size(), 3u);
  const nlohmann::json& between = j["pairs"][1];
  EXPECT_EQ(between["a"].get<int>(), 0);
  EXPECT_EQ(between["b"].get<int>(), 1);
  EXPECT_LT(between["mismatch"].get<double>(), kFitRounding);
  EXPECT_EQ(between["transform"].get<std::string>(), "reflection");
  EXPECT_GT(between["proper_rms"].get<double>(), 1.0);
  for (std::size_t s = 0; s < 5; ++s) {
    EXPECT_EQ(between["assignment"][s].get<int>(), 4 - between["subset"][s].get<int>());
  }
  EXPECT_EQ(j["closest"]["b"].get<int>(), 1);
}

TEST(IdentCli, SymmetricMarkersOfOneToolAreASelfAmbiguity) {
  // five_marker's f0..f3 are symmetric about y = 0 (f1 and f2 mirror each other): a view of
  // those four passes for itself with f1 and f2 swapped, by a reflection only.
  ScratchDir scratch;
  const nlohmann::json j =
      testing::run_json("ident '" + kToolDir + "five_marker.json' --min-visible 4", scratch);
  ASSERT_EQ(j["pairs"].size(), 1u);
  const nlohmann::json& self = j["pairs"][0];
  EXPECT_TRUE(self["self"].get<bool>());
  EXPECT_LT(self["mismatch"].get<double>(), kFitRounding);
  EXPECT_EQ(self["subset"], nlohmann::json::parse("[0, 1, 2, 3]"));
  EXPECT_EQ(self["assignment"], nlohmann::json::parse("[0, 2, 1, 3]"));
  EXPECT_EQ(self["transform"].get<std::string>(), "reflection");
}

TEST(IdentCli, TextReportNamesThePairsAndTheClosest) {
  ScratchDir scratch;
  const testing::CliRun run = run_vantage(
      "ident '" + kToolDir + "west_planar.json' '" + kToolDir + "passive4_150.ini'", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("vantage ident: 2 tools, views of k markers (each tool's own "
                                 "minimum; a pair: the smaller of its two)"));
  EXPECT_THAT(run.out, HasSubstr("0 vs 0  self  k 3"));
  EXPECT_THAT(run.out, HasSubstr("0 vs 1  distinct  k 3"));
  EXPECT_THAT(run.out, HasSubstr("matrix of mismatches"));
  EXPECT_THAT(run.out, HasSubstr("closest distinct  0 vs 1"));
  EXPECT_EQ(run.err, "");
}

// The points of `p` as layout JSON (17 significant digits), optionally with `extra` fields.
std::string tool_json(const Eigen::Matrix3Xd& p, const std::string& extra = "") {
  std::ostringstream out;
  out.precision(17);
  out << R"({"points": [)";
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    out << (i ? ", [" : "[") << p(0, i) << ", " << p(1, i) << ", " << p(2, i) << "]";
  }
  out << "]" << extra << "}";
  return out.str();
}

// A folder of tools (issue 37, item 2): its tool files by name, each tool's own minimum (a
// .rom's byte 32), a pair's k the smaller of its two, the verdicts of a moved copy and a mirror
// image, the matrix of every pair's mismatch, and --min-visible for every tool.
TEST(IdentCli, AFolderEachToolsOwnMinimumVerdictsAndTheMatrix) {
  ScratchDir scratch;
  const Eigen::Matrix3Xd tool = points_of(kToolDir + "five_marker.json");
  Eigen::Matrix3d turn;
  turn << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // 90 degrees about z
  Eigen::Matrix3Xd moved = (turn * tool).colwise() + Eigen::Vector3d(5, -7, 100);
  moved.col(0).swap(moved.col(4));
  Eigen::Matrix3Xd mirror = tool;
  mirror.row(2) *= -1.0;
  std::filesystem::create_directory(scratch.dir() / "fleet");
  scratch.write("fleet/a_tool.json", tool_json(tool));
  scratch.write("fleet/b_moved.json", tool_json(moved));
  scratch.write("fleet/c_mirror.json", tool_json(mirror));
  scratch.write("fleet/notes.txt", "not a tool");
  scratch.write("probe.json",
                tool_json(tool, R"(, "normals": [[0,0,1],[0,0,1],[0,0,1],[0,0,1],[0,0,1]],
    "visibility": {"cone_half_angle_deg": 80, "min_visible": 4})"));
  run_json("layout convert probe.json --out fleet/d_probe.rom", scratch);
  const nlohmann::json j = run_json("ident fleet", scratch);
  ASSERT_EQ(j["tools"].size(), 4u);
  EXPECT_THAT(j["tools"][3]["file"].get<std::string>(), HasSubstr("d_probe.rom"));
  const std::vector<int> own = {3, 3, 3, 4};
  for (std::size_t t = 0; t < 4; ++t) EXPECT_EQ(j["tools"][t]["min_visible"], own[t]) << t;
  EXPECT_TRUE(j["min_visible"].is_null());  // the tools' own minima differ
  ASSERT_EQ(j["pairs"].size(), 10u);
  ASSERT_EQ(j["matrix"].size(), 4u);
  for (const nlohmann::json& p : j["pairs"]) {
    const int a = p["a"].get<int>();
    const int b = p["b"].get<int>();
    EXPECT_EQ(p["min_visible"],
              std::min(own[static_cast<std::size_t>(a)], own[static_cast<std::size_t>(b)]));
    EXPECT_EQ(j["matrix"][a][b], p["mismatch"]);
    EXPECT_EQ(j["matrix"][b][a], p["mismatch"]);
    const std::string verdict = p["verdict"].get<std::string>();
    const std::string expected = a == b ? "self" : (a == 2) != (b == 2) ? "mirror" : "same_tool";
    EXPECT_EQ(verdict, expected) << a << " vs " << b;
  }
  EXPECT_TRUE(j["closest_distinct"].is_null());  // every two files hold one tool or its mirror
  // --min-visible sets every tool's k.
  const nlohmann::json four = run_json("ident fleet --min-visible 4", scratch);
  EXPECT_EQ(four["min_visible"], 4);
  for (const nlohmann::json& t : four["tools"]) EXPECT_EQ(t["min_visible"], 4);
  // Bad folders and tolerances: one line, exit 2.
  std::filesystem::create_directory(scratch.dir() / "empty");
  testing::expect_bad_input(run_vantage("ident empty", scratch),
                            "empty: holds no tool files (.json, .csv, .ini, .rom)");
  testing::expect_bad_input(run_vantage("ident fleet --same-tolerance -1", scratch),
                            "--same-tolerance: must be finite and >= 0");
}

TEST(IdentCli, BadInputIsOneLineExitTwoNothingWritten) {
  ScratchDir scratch;
  const std::string west = "'" + kToolDir + "west_planar.json' ";
  const BadCall calls[] = {
      {"no tool", nullptr, "", "TOOL"},
      {"view too small", nullptr, "--min-visible 2", "--min-visible"},
      {"view too large", nullptr, "--min-visible 5", "--min-visible: 5 exceeds the 4 markers"},
      {"not a number", nullptr, "--min-visible x", "--min-visible"},
      {"bad format", nullptr, "--format yaml", "--format"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    BadCall with_tool = call;
    const std::string args = std::string(call.name) == "no tool" ? "" : west + call.args;
    with_tool.args = args.c_str();
    testing::run_bad_call("ident", with_tool, scratch);
  }
  scratch.write("vectors.json", R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})");
  testing::expect_bad_input(run_vantage("ident " + west + "vectors.json", scratch),
                            "vectors.json: vectors");
  scratch.write("broken.json", "{\"points\": [[0,0,0]]");
  testing::expect_bad_input(run_vantage("ident " + west + "broken.json", scratch), "broken.json");
  testing::expect_bad_input(run_vantage("ident " + west + "missing.json", scratch), "missing.json");
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scratch.dir())) {
    static_cast<void>(entry);
    ++files;
  }
  EXPECT_EQ(files, 2u);  // vectors.json and broken.json: ident wrote nothing
}

}  // namespace
}  // namespace vantage

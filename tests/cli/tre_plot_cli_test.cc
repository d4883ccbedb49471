// `vantage plot LAYOUT --tre` (issue 20; docs/math.md §23, "Sweeps and figures"): the three
// figures and their CSVs are written; their numbers are the library's first-order TRE
// (tre_covariance, tre_rms_isotropic) at targets and lines of sight rebuilt here from the CSV's
// distances, angles and directions; the worst is `vantage tre`'s; bad input is one line naming
// the option, exit 2, with no directory made.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"
#include "vantage/analysis/common.h"
#include "vantage/tracker/target_registration.h"

namespace vantage {
namespace {

using testing::BadCall;
using testing::ScratchDir;

const std::string kTrePlotNdiPath =
    std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/ndi_like.json";
const std::string kTrePlotNdi = "'" + kTrePlotNdiPath + "'";
const std::string kTrePlotNdiFle = " --target 0,0,-150 --fle-sigma 0.0995,0.2985";
// CSV numbers are printed to round-trip; the test's arithmetic differs from the command's in the
// order of a few operations: a few roundings of the RMS.
constexpr double kTrePlotRecompute = 1e-11;
// Every k-th row of a CSV is recomputed (the others are the same formula).
constexpr std::size_t kTrePlotStride = 7;

// A CSV as rows of named text fields.
using TreCsvRow = std::map<std::string, std::string>;

std::vector<TreCsvRow> read_tre_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  std::vector<TreCsvRow> rows;
  auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::stringstream s(text);
    std::string field;
    while (std::getline(s, field, ',')) fields.push_back(field);
    if (!text.empty() && text.back() == ',') fields.emplace_back();
    return fields;
  };
  if (!std::getline(in, line)) return rows;
  header = split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    TreCsvRow row;
    for (std::size_t k = 0; k < header.size() && k < fields.size(); ++k) row[header[k]] = fields[k];
    rows.push_back(row);
  }
  return rows;
}

double tre_csv_number(const TreCsvRow& row, const std::string& column) {
  const auto it = row.find(column);
  EXPECT_NE(it, row.end()) << column;
  return it == row.end() ? std::nan("") : std::stod(it->second);
}

Eigen::Vector3d tre_csv_vector(const TreCsvRow& row, const std::string& prefix) {
  return {tre_csv_number(row, prefix + "x"), tre_csv_number(row, prefix + "y"),
          tre_csv_number(row, prefix + "z")};
}

Eigen::Matrix3Xd tre_plot_ndi_points() {
  const nlohmann::json tool = nlohmann::json::parse(testing::read_file(kTrePlotNdiPath));
  Eigen::Matrix3Xd points(3, tool["points"].size());
  for (std::size_t i = 0; i < tool["points"].size(); ++i) {
    for (int k = 0; k < 3; ++k) points(k, static_cast<Eigen::Index>(i)) = tool["points"][i][k];
  }
  return points;
}

// The NDI-like plate: every marker faces +z with a 90-degree cone, so a line of sight sees all
// four markers when a_z > 0 and none when a_z < 0.
double tre_plot_ndi_rms(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& target,
                        const tracker::FleModel& fle, const Eigen::Vector3d& a) {
  return std::sqrt(tracker::tre_covariance(points, {0, 1, 2, 3}, target, fle, a).trace());
}

TEST(TrePlotCli, WritesThreeFiguresWhoseNumbersAreTheLibrarysTre) {
  ScratchDir scratch;
  const nlohmann::json plot = testing::run_json(
      "plot " + kTrePlotNdi + " --tre" + kTrePlotNdiFle + " --direction 0.3,0,1 --out figs",
      scratch);
  ASSERT_EQ(plot["figures"].size(), 3u);
  for (const char* name : {"tre_tip_axis", "tre_polar", "tre_map"}) {
    for (const char* ext : {".png", ".csv"}) {
      EXPECT_TRUE(std::filesystem::exists(scratch.path(std::string("figs/") + name + ext)))
          << name << ext;
    }
  }
  const nlohmann::json tre = testing::run_json("tre " + kTrePlotNdi + kTrePlotNdiFle, scratch);
  const double worst = tre["targets"][0]["worst"]["rms"].get<double>();
  EXPECT_NEAR(plot["worst"]["rms"].get<double>(), worst, kTrePlotRecompute * worst);
  EXPECT_EQ(plot["radius"].get<double>(), 150.0);

  const Eigen::Matrix3Xd points = tre_plot_ndi_points();
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const Eigen::Vector3d axis = (Eigen::Vector3d(0, 0, -150) - centroid).normalized();
  const tracker::FleModel fle{0.0995, 0.2985};
  int checked = 0;
  std::map<std::string, int> series;
  const std::vector<TreCsvRow> tip = read_tre_csv(scratch.path("figs/tre_tip_axis.csv"));
  for (std::size_t k = 0; k < tip.size(); ++k) {
    ++series[tip[k].at("series")];
    if (k % kTrePlotStride != 0) continue;
    const Eigen::Vector3d r = centroid + tre_csv_number(tip[k], "distance") * axis;
    const double truth = tre_plot_ndi_rms(points, r, fle, tre_csv_vector(tip[k], "direction_"));
    EXPECT_NEAR(tre_csv_number(tip[k], "rms"), truth, kTrePlotRecompute * truth) << k;
    ++checked;
  }
  EXPECT_EQ(series, (std::map<std::string, int>{{"worst", 61}, {"best", 61}, {"direction", 61}}));
  const double worst_at_tip = tre_plot_ndi_rms(points, Eigen::Vector3d(0, 0, -150), fle,
                                               tre_csv_vector(tip.front(), "direction_"));
  EXPECT_NEAR(worst_at_tip, worst, kTrePlotRecompute * worst);

  const std::vector<TreCsvRow> polar = read_tre_csv(scratch.path("figs/tre_polar.csv"));
  EXPECT_EQ(polar.size(), 3u * 361u);
  for (std::size_t k = 0; k < polar.size(); k += kTrePlotStride) {
    const int about = polar[k].at("axis")[0] - 'x';
    const double t = tre_csv_number(polar[k], "angle_deg") * kPi / 180.0;
    Eigen::Vector3d r = centroid;
    r[(about + 1) % 3] += 150.0 * std::cos(t);
    r[(about + 2) % 3] += 150.0 * std::sin(t);
    const double truth = tre_plot_ndi_rms(points, r, fle, tre_csv_vector(polar[k], "direction_"));
    EXPECT_NEAR(tre_csv_number(polar[k], "rms"), truth, kTrePlotRecompute * truth) << k;
    ++checked;
  }

  const std::vector<TreCsvRow> map = read_tre_csv(scratch.path("figs/tre_map.csv"));
  int tracked = 0, untracked = 0;
  for (std::size_t k = 0; k < map.size(); k += kTrePlotStride) {
    const Eigen::Vector3d a = tre_csv_vector(map[k], "");
    if (map[k].at("kind") != "cell") continue;
    if (a.z() > 0.0) {
      ASSERT_EQ(map[k].at("tracked"), "1") << k;
      const double truth = tre_plot_ndi_rms(points, Eigen::Vector3d(0, 0, -150), fle, a);
      EXPECT_NEAR(tre_csv_number(map[k], "rms"), truth, kTrePlotRecompute * truth) << k;
      ++tracked;
    } else {
      EXPECT_EQ(map[k].at("tracked"), "0") << k;
      EXPECT_EQ(map[k].at("rms"), "") << k;
      ++untracked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(tracked, 100);
  EXPECT_GT(untracked, 100);
}

TEST(TrePlotCli, IsotropicFleAddsFitzpatricksCurvesAndSvgWorks) {
  ScratchDir scratch;
  const nlohmann::json plot =
      testing::run_json("plot " + kTrePlotNdi +
                            " --tre --target 0,0,-150 --fle-rms 0.33 --radius 100 --format svg "
                            "--out figs",
                        scratch);
  for (const char* name : {"tre_tip_axis.svg", "tre_polar.svg", "tre_map.svg"}) {
    EXPECT_TRUE(std::filesystem::exists(scratch.path(std::string("figs/") + name))) << name;
  }
  EXPECT_EQ(plot["radius"].get<double>(), 100.0);
  const Eigen::Matrix3Xd points = tre_plot_ndi_points();
  int isotropic = 0;
  for (const TreCsvRow& row : read_tre_csv(scratch.path("figs/tre_polar.csv"))) {
    if (row.at("series") != "isotropic") continue;
    const Eigen::Vector3d r = tre_csv_vector(row, "target_");
    EXPECT_NEAR((r - points.rowwise().mean()).norm(), 100.0, 1e-12 * 100.0);
    const double truth = tracker::tre_rms_isotropic(points, r, 0.33);
    EXPECT_NEAR(tre_csv_number(row, "rms"), truth, kTrePlotRecompute * truth);
    EXPECT_EQ(row.at("visible"), "4");
    ++isotropic;
  }
  EXPECT_EQ(isotropic, 3 * 361);
}

TEST(TrePlotCli, BadInputIsOneLineAndMakesNoDirectory) {
  ScratchDir scratch;
  const BadCall calls[] = {
      {"no target", nullptr, "--tre --fle-rms 0.3 --out figs", "--target"},
      {"bad target", nullptr, "--tre --target 0,0 --fle-rms 0.3 --out figs", "--target"},
      {"target at the centroid", nullptr, "--tre --target 0,0,0 --fle-rms 0.3 --out figs",
       "--target"},
      {"no FLE", nullptr, "--tre --target 0,0,-150 --out figs", "--fle-rms"},
      {"both FLEs", nullptr, "--tre --target 0,0,-150 --fle-rms 0.3 --fle-sigma 0.1,0.3 --out figs",
       "--fle-rms"},
      {"bad sigma", nullptr, "--tre --target 0,0,-150 --fle-sigma 0.1 --out figs", "--fle-sigma"},
      {"zero direction", nullptr,
       "--tre --target 0,0,-150 --fle-rms 0.3 --direction 0,0,0 --out figs", "--direction"},
      {"zero radius", nullptr, "--tre --target 0,0,-150 --fle-rms 0.3 --radius 0 --out figs",
       "--radius"},
      // Issue 36, item 2: wrote nan, -nan and inf rows into the three CSVs.
      {"radius 1e300", nullptr, "--tre --target 0,0,-150 --fle-rms 0.3 --radius 1e300 --out figs",
       "--radius: exceeds 1e50"},
      {"target 1e200", nullptr, "--tre --target 1e200,0,0 --fle-rms 0.3 --out figs", "--target"},
      {"target without --tre", nullptr, "--target 0,0,-150 --out figs", "--target"},
      {"radius without --tre", nullptr, "--radius 10 --out figs", "--radius"},
      {"with --crb", nullptr,
       "--tre --crb --distance 2 --focal 900 --noise-px 1 --target 0,0,-150 --fle-rms 0.3 "
       "--out figs",
       "--tre"},
      {"with --only", nullptr, "--tre --target 0,0,-150 --fle-rms 0.3 --only vectors --out figs",
       "--only"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    testing::run_bad_call("plot " + kTrePlotNdi + " ", call, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("figs")));
  }
  const std::string triad = "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/triad.json'";
  testing::run_bad_call(
      "plot " + triad + " ",
      {"vectors", nullptr, "--tre --target 0,0,1 --fle-rms 0.3 --out figs", "points"}, scratch);
  EXPECT_FALSE(std::filesystem::exists(scratch.path("figs")));
}

}  // namespace
}  // namespace vantage

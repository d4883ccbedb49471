// The CSV beside each figure carries the numbers it draws, and they are right: checked against
// the global analysis and against the formulas written out independently here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>

#include "plot_testing.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/layout_figures.h"
#include "vantage/plot/viewpoint_map.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::plot {
namespace {

using testing::Csv;
using testing::example_layout;
using testing::read_csv;
using testing::report_of;
using testing::TempDir;

// The bounds: samples never beat the certified optimum by more than rounding ...
constexpr double kRounding = 1e-12;
// ... and max_error_deg = arccos(pbar) to rounding of the degrees.
constexpr double kDegreesRounding = 1e-9;
// On the diagonal p = p-bar, Eq. (26) has sqrt(1 - p^2/p-bar^2) with an infinite slope: a rounding
// of 1e-16 in p/p-bar moves theta by up to sqrt(2e-16) rad, about 1e-6 degrees.
constexpr double kDiagonalDegrees = 2e-6;
// How close to the diagonal (p-bar - p) that loss of digits matters.
constexpr double kNearDiagonal = 1e-6;
// The vector that sets p-bar lies on that diagonal: its error is arccos p-bar_min up to the same
// loss of digits.
constexpr double kLargestErrorDegrees = 1e-6;
// The global search certifies t to 1e-9; the CSV holds the viewpoints to every digit.
constexpr double kCertified = 1e-9;
// The cap z >= 1/2 has its rim across about 900 of the 125 600 cells of a 400 grid (0.7 %): even
// miscounting all of them stays inside this.
constexpr double kCapResolution = 0.01;
// The CSV's sample grid (ViewpointMapData::csv_samples_per_axis default; the picture's is 400).
constexpr int kSamples = 100;
// The CSV stays proportionate: 7 860 rows of about 92 bytes (satellite: 0.72 MB).
constexpr std::uintmax_t kMaxMapCsvBytes = 1'000'000;
// A grid cell centre lies within sqrt(2)/N of any disc point (cell side 2/N), the inverse
// Lambert map stretches distances by at most 2 (radially at the rim) and p_bar is 1-Lipschitz
// in the angle; doubled for cells at the rim, whose nearest inside centre can be farther.
const double kSampleSpacing = 2.0 * 2.0 * std::sqrt(2.0) / kSamples;

// Eq. (26), written out here independently of vantage::lub_scale_error_angle.
double eq26_deg(double p, double pbar) {
  const double c = p * p / pbar + std::sqrt((1.0 - p * p) * (1.0 - p * p / (pbar * pbar)));
  return kDegreesPerRadian * std::acos(std::clamp(c, -1.0, 1.0));
}

class CsvTruth : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    layout_ = example_layout(GetParam());
    // The figures of the layout seen whole (those of a layout on its body:
    // visibility_figures_test.cc).
    layout_.visibility.reset();
    layout_.workspace.reset();
    data_ = data_vectors(layout_);
    sdp::LayoutAnalysisOptions options;
    options.run_crosscheck = false;
    analysis_ = sdp::analyze_vectors(data_.vectors, data_.weights, options);
    design_ = testing::example_design_curve();
    report_ = report_of(layout_);
  }
  // Writes only the named figure and reads its CSV.
  Csv csv(const std::string& name) {
    LayoutFiguresOptions options;
    options.only = {name};
    figures_ = write_layout_figures(report_, dir_.path(), options, &design_);
    EXPECT_EQ(figures_.status, LayoutFigures::Status::kCertified);
    return read_csv(dir_.path() / (name + ".csv"));
  }

  TempDir dir_{"csv"};
  Layout layout_;
  DataVectors data_;
  sdp::LayoutAnalysis analysis_;
  report::LayoutReport report_;
  DesignCurve design_;
  LayoutFigures figures_;
};

TEST_P(CsvTruth, ViewpointMapSamplesBoundThePbarMinFromAbove) {
  const Csv map = csv("viewpoint_map");
  EXPECT_LT(std::filesystem::file_size(dir_.path() / "viewpoint_map.csv"), kMaxMapCsvBytes);
  ASSERT_EQ(map.header, (std::vector<std::string>{"x", "y", "z", "pbar", "max_error_deg"}));
  // Cells inside the disc: about pi/4 of the N^2 grid.
  EXPECT_NEAR(static_cast<double>(map.rows.size()), kPi / 4 * kSamples * kSamples,
              0.01 * kSamples * kSamples);
  const Eigen::Matrix3Xd unit = data_.vectors.colwise().normalized();
  double min_pbar = 2.0, max_error = -1.0;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const Eigen::Vector3d a(map.number(r, "x"), map.number(r, "y"), map.number(r, "z"));
    const double pbar = map.number(r, "pbar");
    const double error = map.number(r, "max_error_deg");
    min_pbar = std::min(min_pbar, pbar);
    max_error = std::max(max_error, error);
    ASSERT_NEAR(error, kDegreesPerRadian * std::acos(pbar), kDegreesRounding) << "row " << r;
    ASSERT_NEAR(a.norm(), 1.0, kRounding);
    ASSERT_GE(a.z(), 0.0) << "upper hemisphere";
    const double t = (unit.transpose() * a).cwiseAbs().minCoeff();
    ASSERT_NEAR(pbar, std::sqrt(1.0 - t * t), kRounding) << "row " << r;
  }
  EXPECT_GE(min_pbar, analysis_.pbar_min - kRounding);
  EXPECT_LE(min_pbar, analysis_.pbar_min + kSampleSpacing);
  EXPECT_LE(max_error, kDegreesPerRadian * std::acos(analysis_.pbar_min) + kDegreesRounding);
  EXPECT_NEAR(figures_.pbar_min, analysis_.pbar_min, kRounding);
  EXPECT_NEAR(figures_.max_worst_case_error_deg, analysis_.max_worst_case_error_deg, kRounding);
}

TEST_P(CsvTruth, DropoutRowsEqualTheAnalysisOfTheReducedLayout) {
  const Csv dropout = csv("dropout");
  const long n = layout_.entries.cols();
  ASSERT_EQ(dropout.rows.size(), static_cast<std::size_t>(n + 1));
  sdp::LayoutAnalysisOptions options;
  options.run_crosscheck = false;
  double previous = -1.0;
  for (long r = 0; r < n; ++r) {
    const int k = static_cast<int>(dropout.number(r, "index"));
    EXPECT_EQ(dropout.number(r, "rank"), r + 1.0);
    const double pbar = dropout.number(r, "pbar_min");
    EXPECT_LE(pbar, analysis_.pbar_min + kRounding) << "losing a marker never helps";
    EXPECT_GE(pbar, previous - kRounding) << "sorted by harm";
    previous = pbar;
    Layout reduced = layout_;
    reduced.visibility.reset();  // the rows are the layout seen whole
    reduced.entries.resize(3, n - 1);
    reduced.weights.resize(n - 1);
    for (long i = 0, j = 0; i < n; ++i) {
      if (i == k) continue;
      reduced.entries.col(j) = layout_.entries.col(i);
      reduced.weights(j++) = layout_.weights(i);
    }
    const DataVectors data = data_vectors(reduced);
    const sdp::LayoutAnalysis direct = sdp::analyze_vectors(data.vectors, data.weights, options);
    EXPECT_NEAR(pbar, direct.pbar_min, kRounding) << "entry " << k;
    EXPECT_NEAR(dropout.number(r, "max_worst_case_error_deg"), direct.max_worst_case_error_deg,
                kDegreesRounding);
    EXPECT_EQ(dropout.number(r, "n_vectors"), static_cast<double>(data.vectors.cols()));
    EXPECT_EQ(dropout.text(r, "certified"), "1");
  }
  EXPECT_EQ(dropout.text(n, "entry"), "intact");
  EXPECT_NEAR(dropout.number(n, "pbar_min"), analysis_.pbar_min, kRounding);
}

TEST_P(CsvTruth, ErrorSurfaceIsEquation26) {
  const Csv surface = csv("error_surface");
  std::vector<std::size_t> grid_rows, layout_rows;
  for (std::size_t r = 0; r < surface.rows.size(); ++r) {
    (surface.text(r, "series") == "grid" ? grid_rows : layout_rows).push_back(r);
  }
  ASSERT_GT(grid_rows.size(), 1000u);
  std::mt19937 rng(vantage::testing::kSeed);
  std::uniform_int_distribution<std::size_t> pick(0, grid_rows.size() - 1);
  for (int trial = 0; trial < 500; ++trial) {
    const std::size_t r = grid_rows[pick(rng)];
    const double p = surface.number(r, "p"), pbar = surface.number(r, "pbar");
    ASSERT_LE(p, pbar);
    ASSERT_NEAR(surface.number(r, "theta_deg"), eq26_deg(p, pbar), kDegreesRounding)
        << "p " << p << " pbar " << pbar;
  }
  ASSERT_EQ(layout_rows.size(), static_cast<std::size_t>(data_.vectors.cols()));
  double largest = 0.0;
  for (std::size_t r : layout_rows) {
    const double p = surface.number(r, "p"), pbar = surface.number(r, "pbar");
    EXPECT_NEAR(pbar, analysis_.pbar_min, kRounding);
    EXPECT_LE(p, pbar);
    EXPECT_NEAR(surface.number(r, "theta_deg"), eq26_deg(p, pbar),
                pbar - p < kNearDiagonal ? kDiagonalDegrees : kDegreesRounding);
    largest = std::max(largest, surface.number(r, "theta_deg"));
  }
  // The vector that sets p-bar has the whole error arccos p-bar_min (docs/math.md §11).
  EXPECT_NEAR(largest, kDegreesPerRadian * std::acos(analysis_.pbar_min), kLargestErrorDegrees);
}

TEST_P(CsvTruth, VectorsAndDesignCsvHoldTheirInputs) {
  const Csv vectors = csv("vectors");
  const long n = layout_.entries.cols();
  for (long k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(vectors.number(k, std::string(1, "xyz"[c])), layout_.entries(c, k));
    }
  }
  const Eigen::Matrix3Xd unit = data_.vectors.colwise().normalized();
  std::size_t worst_rows = 0;
  for (std::size_t r = n; r < vectors.rows.size(); ++r) {
    if (vectors.text(r, "series") != "worst_viewpoint") continue;
    ++worst_rows;
    const Eigen::Vector3d a(vectors.number(r, "x"), vectors.number(r, "y"), vectors.number(r, "z"));
    EXPECT_NEAR((unit.transpose() * a).cwiseAbs().minCoeff(), analysis_.t, kCertified);
  }
  EXPECT_EQ(worst_rows, analysis_.worst_viewpoints.size());

  const Csv design = csv("design");
  std::size_t ceiling_rows = 0;
  for (std::size_t r = 0; r < design.rows.size(); ++r) {
    if (design.text(r, "series") != "ceiling") continue;
    ++ceiling_rows;
    EXPECT_NEAR(design.number(r, "pbar_min"), std::cos(kPi / (2.0 * design.number(r, "n_vectors"))),
                kRounding);
  }
  EXPECT_GT(ceiling_rows, 0u);
  EXPECT_EQ(design.text(0, "series"), "greedy");
  EXPECT_EQ(design.number(0, "pbar_min"), design_.pbar_min[0]);
}

INSTANTIATE_TEST_SUITE_P(ExampleLayouts, CsvTruth,
                         ::testing::Values("satellite.json", "note3_four_vectors.json"));

TEST(ViewpointSampling, IndependentOfTheThreadCountAndEqualArea) {
  const Eigen::Matrix3Xd vectors = example_layout("note3_four_vectors.json").entries;
  const ViewpointSamples one = sample_viewpoints(vectors, 64, 1);
  const ViewpointSamples three = sample_viewpoints(vectors, 64, 3);
  EXPECT_EQ(one.pbar, three.pbar);
  EXPECT_EQ(one.viewpoints, three.viewpoints);
  // Equal-area: the fraction of samples with z >= 1/2 (a spherical cap of half the hemisphere's
  // area, 2 pi (1 - 1/2) of 2 pi) is 1/2 up to the grid's resolution.
  const ViewpointSamples fine = sample_viewpoints(vectors, 400, 0);
  const double cap = (fine.viewpoints.row(2).array() >= 0.5).cast<double>().mean();
  EXPECT_NEAR(cap, 0.5, kCapResolution);
  EXPECT_THROW(sample_viewpoints(vectors, 8, 0), InvalidArgument);
}

TEST(ViewpointSampling, LambertProjectionRoundTrips) {
  std::mt19937 rng(vantage::testing::kSeed);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Vector3d a(gauss(rng), gauss(rng), std::abs(gauss(rng)));
    a.normalize();
    const Eigen::Vector2d p = lambert_from_viewpoint(a);
    EXPECT_NEAR(p.squaredNorm(), 1.0 - a.z(), kRounding) << "disc radius sqrt(1 - z)";
    EXPECT_TRUE(viewpoint_from_lambert(p).isApprox(a, kRounding));
    EXPECT_TRUE(lambert_from_viewpoint(-a).isApprox(p, kRounding)) << "a and -a are one viewpoint";
  }
}

}  // namespace
}  // namespace vantage::plot

// The TRE figures (docs/math.md §23, "Sweeps and figures"): the map's CSV holds the RMS TRE of a
// model built apart at every cell, no cell beats the certified worst bound, its worst and best
// rows are the report's; the tip-axis and polar CSVs are the library's sweeps; the images have
// the asked size; bad data names its field and writes nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "plot_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"
#include "vantage/plot/sphere_map.h"
#include "vantage/plot/tre_figures.h"

namespace vantage::plot {
namespace {

using testing::Csv;
using testing::read_csv;
using testing::TempDir;

// CSV numbers read back to the same double; the recomputation is the same arithmetic.
constexpr double kTreFigureRounding = 1e-12;
// The search's relative certificate tolerance (TreSearchOptions), plus rounding.
constexpr double kTreFigureCertificate = 1e-6 + 1e-12;
constexpr int kTreFigurePicture = 60;
constexpr int kTreFigureCsv = 40;

Layout tre_fig_ndi_like() {
  return io::load_layout(std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/ndi_like.json");
}

tracker::TreOptions tre_fig_ndi_fle() {
  tracker::TreOptions options;
  options.fle = tracker::FleModel{0.0995, 0.2985};
  return options;
}

TreFiguresOptions small_tre_figures() {
  TreFiguresOptions options;
  options.samples_per_axis = kTreFigurePicture;
  options.csv_samples_per_axis = kTreFigureCsv;
  return options;
}

const Eigen::Vector3d kTreFigureTip(0.0, 0.0, -150.0);

TEST(TreFigures, MapCsvHoldsTheRmsOfEveryCellUnderTheCertifiedWorst) {
  const Layout layout = tre_fig_ndi_like();
  TempDir dir("tremap");
  TreFigures figures = tre_figures(layout, {kTreFigureTip}, tre_fig_ndi_fle(), small_tre_figures());
  write_tre_figures(figures, small_tre_figures(), dir.path());
  ASSERT_EQ(figures.files.size(), 3u);
  EXPECT_EQ(figures.files[0].name, "tre_tip_axis");
  EXPECT_EQ(figures.files[1].name, "tre_polar");
  EXPECT_EQ(figures.files[2].name, "tre_map");
  const tracker::TreExtremes& x = figures.sweeps.report.targets.front().extremes;
  ASSERT_TRUE(x.worst.certified());

  const Csv csv = read_csv(figures.files[2].csv);
  ASSERT_GE(csv.rows.size(), 2u);
  EXPECT_EQ(csv.text(0, "kind"), "worst");
  EXPECT_NEAR(csv.number(0, "rms"), x.worst.rms, kTreFigureRounding * x.worst.rms);
  EXPECT_EQ(csv.text(1, "kind"), "best");
  EXPECT_NEAR(csv.number(1, "rms"), x.best.rms, kTreFigureRounding * x.best.rms);

  const tracker::TreModel apart(layout, tre_fig_ndi_fle().fle);
  std::size_t row = 2;
  int tracked = 0;
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < kTreFigureCsv; ++r) {
      for (int c = 0; c < kTreFigureCsv; ++c) {
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, kTreFigureCsv),
                                 SphereSamples::cell_centre(kTreFigureCsv - 1 - r, kTreFigureCsv));
        if (xy.squaredNorm() > 1.0) continue;
        ASSERT_LT(row, csv.rows.size());
        EXPECT_EQ(csv.text(row, "kind"), "cell");
        EXPECT_EQ(csv.number(row, "disc"), d);
        const tracker::TreAtDirection at =
            apart.at(kTreFigureTip, direction_from_sphere_map(d, xy));
        EXPECT_EQ(csv.number(row, "visible"), static_cast<double>(at.visible_markers.size()));
        EXPECT_EQ(csv.text(row, "tracked"), at.tracked ? "1" : "0");
        if (at.tracked) {
          ++tracked;
          EXPECT_NEAR(csv.number(row, "rms"), at.rms, kTreFigureRounding * at.rms);
          EXPECT_LE(at.rms, x.worst.rms_bound * (1.0 + kTreFigureCertificate));
          EXPECT_GE(at.rms, x.best.rms_bound * (1.0 - kTreFigureCertificate));
        } else {
          EXPECT_EQ(csv.text(row, "rms"), "");
        }
        ++row;
      }
    }
  }
  EXPECT_EQ(row, csv.rows.size());
  // The plate's 90-degree cones track the upper half of the sphere: disc 0 only.
  EXPECT_GT(tracked, 0);

  for (const FigureFiles& f : figures.files) {
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(f.image.c_str(), &width, &height, &channels, 3);
    ASSERT_NE(pixels, nullptr) << f.image;
    stbi_image_free(pixels);
    EXPECT_EQ(width, FigureOptions{}.width);
    EXPECT_EQ(height, FigureOptions{}.height);
  }
}

TEST(TreFigures, TipAxisAndPolarCsvAreTheLibrarysSweeps) {
  const Layout layout = tre_fig_ndi_like();
  TempDir dir("tresweeps");
  tracker::TreOptions options = tre_fig_ndi_fle();
  options.direction = Eigen::Vector3d(0.3, 0.0, 1.0);
  TreFigures figures = tre_figures(layout, {kTreFigureTip}, options, small_tre_figures());
  write_tre_figures(figures, small_tre_figures(), dir.path());
  const tracker::TreModel apart(layout, options.fle);
  const tracker::TreSweeps sweeps = tracker::tre_sweeps(apart, {kTreFigureTip}, options);

  const Csv tip = read_csv(figures.files[0].csv);
  std::size_t row = 0;
  for (const tracker::TreCurve& curve : sweeps.tip_axis.curves) {
    ASSERT_TRUE(curve.tracked);
    for (std::size_t k = 0; k < curve.rms.size(); ++k, ++row) {
      ASSERT_LT(row, tip.rows.size());
      EXPECT_EQ(tip.text(row, "series"), curve.label);
      EXPECT_NEAR(tip.number(row, "distance"), sweeps.tip_axis.distance[k], kTreFigureRounding);
      EXPECT_NEAR(tip.number(row, "direction_x"), curve.direction.x(), kTreFigureRounding);
      EXPECT_NEAR(tip.number(row, "target_z"), sweeps.tip_axis.target(k).z(), kTreFigureRounding);
      EXPECT_NEAR(tip.number(row, "rms"), curve.rms[k], kTreFigureRounding * curve.rms[k]);
    }
  }
  EXPECT_EQ(row, tip.rows.size());  // anisotropic FLE: no isotropic rows

  const Csv polar = read_csv(figures.files[1].csv);
  row = 0;
  const char* axes[] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    const tracker::TreCurve& curve = sweeps.polar.curves[static_cast<std::size_t>(axis)];
    for (std::size_t k = 0; k < curve.rms.size(); ++k, ++row) {
      ASSERT_LT(row, polar.rows.size());
      EXPECT_EQ(polar.text(row, "axis"), axes[axis]);
      EXPECT_EQ(polar.number(row, "angle_deg"), sweeps.polar.angle_deg[k]);
      EXPECT_NEAR(polar.number(row, "rms"), curve.rms[k], kTreFigureRounding * curve.rms[k]);
    }
  }
  EXPECT_EQ(row, polar.rows.size());
  EXPECT_EQ(row, 3u * 361u);
}

// The message of the InvalidArgument of `call`, "" when it throws none.
template <typename Call>
std::string tre_message_of(Call&& call) {
  try {
    call();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

// The message starts with "<field>: " or "<field>[".
bool tre_names(const std::string& message, const std::string& field) {
  return message.rfind(field + ": ", 0) == 0 || message.rfind(field + "[", 0) == 0;
}

TEST(TreFigures, BadDataNamesTheFieldAndWritesNothing) {
  const Layout layout = tre_fig_ndi_like();
  TempDir dir("trebad");
  TreFigures figures = tre_figures(layout, {kTreFigureTip}, tre_fig_ndi_fle(), small_tre_figures());
  TreMapData data;
  data.model = figures.model.get();
  data.sweeps = &figures.sweeps;
  data.samples_per_axis = 5;
  EXPECT_TRUE(
      tre_names(tre_message_of([&] { write_tre_map(data, dir.path()); }), "samples_per_axis"));
  data.samples_per_axis = kTreFigurePicture;
  data.model = nullptr;
  EXPECT_TRUE(tre_names(tre_message_of([&] { write_tre_map(data, dir.path()); }), "model"));
  TreFiguresOptions options = small_tre_figures();
  options.sweep.radius = 0.0;
  EXPECT_TRUE(tre_names(
      tre_message_of([&] { tre_figures(layout, {kTreFigureTip}, tre_fig_ndi_fle(), options); }),
      "radius"));
  // The tool's centroid is the origin: no tip axis.
  EXPECT_TRUE(tre_names(tre_message_of([&] {
                          tre_figures(layout, {Eigen::Vector3d::Zero()}, tre_fig_ndi_fle(),
                                      small_tre_figures());
                        }),
                        "target"));
  tracker::TreOptions zero = tre_fig_ndi_fle();
  zero.fle = tracker::FleModel{0.0, 0.0};
  EXPECT_TRUE(tre_names(
      tre_message_of([&] { tre_figures(layout, {kTreFigureTip}, zero, small_tre_figures()); }),
      "fle.sigma_perp"));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace vantage::plot

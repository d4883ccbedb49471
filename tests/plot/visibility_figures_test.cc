// The figures of a layout on its body (docs/math.md §20): the whole-sphere projection is
// equal-area and inverts; the viewpoint map's grey pixels are the untrackable part of the sphere
// the report measures on its own directions; the CSVs beside the maps agree with the cone model
// written out here; the dropout chart's rows are the analyses of the layout without each marker;
// the vectors figure carries the normals and the worst viewpoint on the body; and layouts without
// normals keep the figures they had.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "plot_testing.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"
#include "vantage/plot/layout_figures.h"
#include "vantage/plot/sphere_map.h"
#include "vantage/plot/viewpoint_map.h"
#include "vantage/plot/visibility_maps.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::plot {
namespace {

using testing::Csv;
using testing::read_csv;
using testing::TempDir;

// Projections and unit vectors agree to rounding.
constexpr double kRounding = 1e-12;
// asin t in degrees from the CSV's shortest round-trip digits: rounding of the degrees.
constexpr double kDegreesRounding = 1e-9;
// The report's coverage is a Fibonacci estimate on 20 000 directions (standard error at most
// 0.0035) and the map's a 2 x 400^2 grid whose cells on a boundary (about 1 % of them for the
// satellite's boundaries) may fall either way: 0.01 holds both with room.
constexpr double kCoverageTolerance = 0.01;
// Pixels of a disc that are neither the grey nor a value colour (count numbers on their boxes,
// boundary lines, antialiased edges) are left out of both counts; they sit on either side, so the
// grey share of the rest moves by at most this (measured 0.7 % on the satellite at 1000 x 800:
// 0.5624 against 0.5698).
constexpr double kPixelTolerance = 0.02;
// A value colour of viridis has max - min channel above 70; the grey has none.
constexpr int kSaturated = 50;
constexpr int kGreyTolerance = 6;
// The CSV grid's samples lie within 2 sqrt(2) / N (cell diagonal, stretched at most 2 by the
// inverse projection) of every direction; t is 1-Lipschitz in the angle away from visibility
// boundaries, and the best sample must come this close to the certified value on the box, whose
// worst viewpoint lies inside a region of constant visibility.
constexpr int kCsvSamples = 100;
const double kSampleSpacing = 2.0 * 2.0 * std::sqrt(2.0) / kCsvSamples;
// The certificate's bracket (VisibilitySearchOptions::certificate_tolerance default).
constexpr double kCertified = 1e-9;

std::string data_file(const std::string& name) {
  return std::string(VANTAGE_SOURCE_DIR) + "/tests/plot/data/" + name;
}

Layout satellite() { return testing::example_layout("satellite.json"); }
Layout box() { return io::read_layout(data_file("box_face_markers.json")); }

// The box without its mesh: the cone model, which this test writes out independently.
Layout box_cones_only() {
  Layout layout = box();
  layout.visibility->body.reset();
  layout.visibility->body_path.clear();
  return layout;
}

Eigen::Vector3d row_direction(const Csv& csv, std::size_t r) {
  return {csv.number(r, "x"), csv.number(r, "y"), csv.number(r, "z")};
}

// The cone model of docs/math.md §20 (V) without a mesh, written out here: the visible markers
// and t(a) = min |a.u_ij| over their pairs.
struct ConeTruth {
  std::vector<int> visible;
  double t = 1.0;
};

ConeTruth cone_truth(const Layout& layout, const Eigen::Vector3d& a) {
  ConeTruth out;
  const MarkerVisibility& v = *layout.visibility;
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
    const double cone = v.cone_half_angle_deg(i) / kDegreesPerRadian;
    if (v.normals.col(i).dot(a) >= std::cos(cone)) out.visible.push_back(static_cast<int>(i));
  }
  for (std::size_t x = 0; x < out.visible.size(); ++x) {
    for (std::size_t y = x + 1; y < out.visible.size(); ++y) {
      const Eigen::Vector3d u =
          (layout.entries.col(out.visible[y]) - layout.entries.col(out.visible[x])).normalized();
      out.t = std::min(out.t, std::abs(a.dot(u)));
    }
  }
  return out;
}

TEST(SphereMap, EveryDirectionRoundTripsOnItsDiscAndTheDiscsAreEqualArea) {
  std::mt19937 rng(vantage::testing::kSeed);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector3d a = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const SphereMapPoint p = sphere_map_from_direction(a);
    EXPECT_EQ(p.disc, a.z() >= 0.0 ? 0 : 1);
    EXPECT_NEAR(p.xy.squaredNorm(), 1.0 - std::abs(a.z()), kRounding) << "radius sqrt(1 - |z|)";
    EXPECT_TRUE(direction_from_sphere_map(p.disc, p.xy).isApprox(a, kRounding));
  }
  // Seen from outside: +y up on both discs, +x right above and left below, so they touch at +x.
  EXPECT_GT(sphere_map_from_direction(Eigen::Vector3d(0.6, 0.0, 0.8)).xy.x(), 0.0);
  EXPECT_LT(sphere_map_from_direction(Eigen::Vector3d(0.6, 0.0, -0.8)).xy.x(), 0.0);
  EXPECT_GT(sphere_map_from_direction(Eigen::Vector3d(0.0, 0.6, -0.8)).xy.y(), 0.0);
  // Equal area: the cells whose direction has |z| >= 1/2 (two caps, half the sphere) are half the
  // cells inside the discs.
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(box_cones_only());
  const SphereSamples s = sample_sphere(model, 400, 0);
  long cap = 0;
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < 400; ++r) {
      for (int c = 0; c < 400; ++c) {
        cap += s.inside[d](r, c) && std::abs(s.direction(d, r, c).z()) >= 0.5;
      }
    }
  }
  EXPECT_NEAR(static_cast<double>(cap) / s.inside_count(), 0.5, 0.01);
  EXPECT_THROW(sample_sphere(model, 8, 0), InvalidArgument);
}

TEST(SphereMap, SamplesDoNotDependOnTheThreadCount) {
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(satellite());
  const SphereSamples one = sample_sphere(model, 64, 1), three = sample_sphere(model, 64, 3);
  for (int d = 0; d < 2; ++d) {
    EXPECT_EQ(one.visible[d], three.visible[d]);
    EXPECT_EQ(one.t[d], three.t[d]);
    EXPECT_EQ(one.trackable[d], three.trackable[d]);
  }
}

struct Decoded {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Decoded decode(const std::filesystem::path& path) {
  Decoded png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (!data) {
    ADD_FAILURE() << "cannot decode " << path;
    return png;
  }
  png.rgb.assign(data, data + static_cast<std::size_t>(png.width) * png.height * 3);
  stbi_image_free(data);
  return png;
}

// Of the disc pixels that are the untrackable grey or a value colour, the grey share.
double grey_share(const Decoded& png) {
  long grey = 0, value = 0;
  for (int d = 0; d < 2; ++d) {
    const DiscPlacement disc = sphere_map_disc_placement(d, png.width, png.height);
    // Inside the rim's line.
    const double r = disc.radius_px - 2.0;
    for (int y = 0; y < png.height; ++y) {
      for (int x = 0; x < png.width; ++x) {
        if ((Eigen::Vector2d(x + 0.5, y + 0.5) - disc.centre_px).norm() > r) continue;
        const unsigned char* p = &png.rgb[(static_cast<std::size_t>(y) * png.width + x) * 3];
        const int hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
        if (hi - lo > kSaturated) {
          ++value;
        } else if (std::abs(p[0] - kUntrackableColour.r) <= kGreyTolerance &&
                   std::abs(p[1] - kUntrackableColour.g) <= kGreyTolerance &&
                   std::abs(p[2] - kUntrackableColour.b) <= kGreyTolerance) {
          ++grey;
        }
      }
    }
  }
  return grey + value == 0 ? 0.0 : static_cast<double>(grey) / (grey + value);
}

class BodyFigures : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    layout_ = std::string(GetParam()) == "satellite" ? satellite() : box();
    report_ = testing::report_of(layout_);
    ASSERT_TRUE(report_.visibility.has_value());
  }
  LayoutFigures write(const std::vector<std::string>& only) {
    LayoutFiguresOptions options;
    options.only = only;
    return write_layout_figures(report_, dir_.path(), options);
  }
  TempDir dir_{"body"};
  Layout layout_;
  report::LayoutReport report_;
};

TEST_P(BodyFigures, EveryFigureIsWrittenAndTheVisibilityFigureIsIncluded) {
  LayoutFiguresOptions options;
  const std::vector<std::string> names = selected_figures(options, false, true);
  EXPECT_EQ(names, (std::vector<std::string>{"viewpoint_map", "visibility", "dropout",
                                             "error_surface", "vectors"}));
  const LayoutFigures figures = write({});
  EXPECT_EQ(figures.status, LayoutFigures::Status::kCertified) << figures.message;
  ASSERT_EQ(figures.files.size(), names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ(figures.files[k].name, names[k]);
    const Decoded png = decode(figures.files[k].image);
    EXPECT_EQ(png.width, 1000) << names[k];
    EXPECT_EQ(png.height, 800) << names[k];
    EXPECT_GT(read_csv(figures.files[k].csv).rows.size(), 0u) << names[k];
  }
  ASSERT_TRUE(figures.visibility_max_worst_case_error_deg.has_value());
  EXPECT_EQ(*figures.visibility_max_worst_case_error_deg,
            report_.visibility->max_worst_case_error_deg);
  EXPECT_EQ(*figures.trackable_fraction, report_.visibility->coverage.trackable_fraction);
}

TEST_P(BodyFigures, TheMapsGreyIsTheUntrackablePartOfTheSphere) {
  const LayoutFigures figures = write({"viewpoint_map"});
  const double lost = 1.0 - report_.visibility->coverage.trackable_fraction;
  const double share = grey_share(decode(figures.files[0].image));
  RecordProperty("grey_share", std::to_string(share));
  RecordProperty("untrackable_fraction", std::to_string(lost));
  EXPECT_NEAR(share, lost, kPixelTolerance);
  // The map's own cells, equal-area, give the same fraction.
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(layout_);
  EXPECT_NEAR(sample_sphere(model, 400, 0).trackable_fraction(), 1.0 - lost, kCoverageTolerance);
  // The CSV's rows (equal-area cells) too, and each row's trackable flag has its error.
  const Csv csv = read_csv(figures.files[0].csv);
  ASSERT_EQ(csv.header, (std::vector<std::string>{"disc", "x", "y", "z", "visible", "trackable",
                                                  "pbar", "max_error_deg"}));
  long untrackable = 0;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const bool trackable = csv.text(r, "trackable") == "1";
    untrackable += !trackable;
    EXPECT_EQ(csv.text(r, "max_error_deg").empty(), !trackable) << "row " << r;
  }
  EXPECT_NEAR(static_cast<double>(untrackable) / csv.rows.size(), lost, kCoverageTolerance);
}

TEST_P(BodyFigures, VectorsCsvCarriesTheNormalsAndTheWorstViewpointOnTheBody) {
  const Csv csv = read_csv(write({"vectors"}).files.front().csv);
  long normals = 0, body_worst = 0;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const Eigen::Vector3d v = row_direction(csv, r);
    if (csv.text(r, "series") == "normal") {
      const int k = static_cast<int>(csv.number(r, "index"));
      EXPECT_EQ(k, normals++);
      EXPECT_EQ(v, Eigen::Vector3d(layout_.visibility->normals.col(k)));
    } else if (csv.text(r, "series") == "body_worst_viewpoint") {
      ++body_worst;
      EXPECT_EQ(v, report_.visibility->worst.viewpoint);
    }
  }
  EXPECT_EQ(normals, layout_.entries.cols());
  EXPECT_EQ(body_worst, 1);
}

INSTANTIATE_TEST_SUITE_P(Bodies, BodyFigures, ::testing::Values("satellite", "box"));

class ConeModelFigures : public ::testing::Test {
 protected:
  void SetUp() override {
    layout_ = box_cones_only();
    report_ = testing::report_of(layout_);
  }
  Csv csv(const std::string& name) {
    LayoutFiguresOptions options;
    options.only = {name};
    write_layout_figures(report_, dir_.path(), options);
    return read_csv(dir_.path() / (name + ".csv"));
  }
  TempDir dir_{"cones"};
  Layout layout_;
  report::LayoutReport report_;
};

TEST_F(ConeModelFigures, MapRowsAreTheConeModelAndNeverBeatTheCertificate) {
  const Csv map = csv("viewpoint_map");
  const visibility::VisibilityWorstViewpoint& worst = report_.visibility->worst;
  ASSERT_TRUE(worst.certified());
  double largest = 0.0;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const Eigen::Vector3d a = row_direction(map, r);
    ASSERT_NEAR(a.norm(), 1.0, kRounding);
    EXPECT_EQ(map.number(r, "disc"), a.z() >= 0.0 ? 0.0 : 1.0);
    const ConeTruth truth = cone_truth(layout_, a);
    ASSERT_EQ(map.number(r, "visible"), static_cast<double>(truth.visible.size())) << "row " << r;
    if (map.text(r, "trackable") != "1") continue;
    const double error = map.number(r, "max_error_deg");
    ASSERT_NEAR(error, kDegreesPerRadian * std::asin(truth.t), kDegreesRounding) << "row " << r;
    ASSERT_NEAR(map.number(r, "pbar"), std::sqrt(1.0 - truth.t * truth.t), kRounding);
    largest = std::max(largest, error);
  }
  const double certified = kDegreesPerRadian * std::asin(worst.t_upper);
  EXPECT_LE(largest, certified + kDegreesRounding);
  EXPECT_GE(largest, certified - kDegreesPerRadian * kSampleSpacing);
}

TEST_F(ConeModelFigures, VisibilityRowsListTheMarkersTheConesAdmit) {
  const Csv count = csv("visibility");
  for (std::size_t r = 0; r < count.rows.size(); ++r) {
    const ConeTruth truth = cone_truth(layout_, row_direction(count, r));
    std::string markers;
    for (int i : truth.visible) markers += (markers.empty() ? "" : " ") + std::to_string(i);
    ASSERT_EQ(count.text(r, "markers"), markers) << "row " << r;
    EXPECT_EQ(count.text(r, "in_workspace"), "1") << "no workspace: the whole sphere";
  }
}

TEST_F(ConeModelFigures, DropoutRowsAreTheLayoutWithoutEachMarkerOnItsBody) {
  const Csv dropout = csv("dropout");
  const long n = layout_.entries.cols();
  ASSERT_EQ(dropout.rows.size(), static_cast<std::size_t>(n + 1));
  double previous = 90.0;
  for (long r = 0; r < n; ++r) {
    const int k = static_cast<int>(dropout.number(r, "index"));
    EXPECT_EQ(dropout.number(r, "rank"), r + 1.0);
    const double error = dropout.number(r, "max_worst_case_error_deg");
    EXPECT_LE(error, previous + kDegreesRounding) << "most harmful (largest error) first";
    previous = error;
    // The layout without marker k, analysed on its own.
    Layout reduced = layout_;
    reduced.entries.resize(3, n - 1);
    reduced.weights.resize(n - 1);
    reduced.visibility->normals.resize(3, n - 1);
    reduced.visibility->cone_half_angle_deg.resize(n - 1);
    for (long i = 0, j = 0; i < n; ++i) {
      if (i == k) continue;
      reduced.entries.col(j) = layout_.entries.col(i);
      reduced.weights(j) = layout_.weights(i);
      reduced.visibility->normals.col(j) = layout_.visibility->normals.col(i);
      reduced.visibility->cone_half_angle_deg(j++) = layout_.visibility->cone_half_angle_deg(i);
    }
    if (r < 3) {  // three of them: each is a certified search of its own
      const visibility::VisibilityReport direct = visibility::analyze_visibility(reduced);
      EXPECT_NEAR(error, direct.max_worst_case_error_deg, kDegreesPerRadian * kCertified)
          << "marker " << k;
      EXPECT_EQ(dropout.number(r, "trackable_fraction"), direct.coverage.trackable_fraction);
    }
    const DataVectors data = data_vectors(reduced);
    sdp::LayoutAnalysisOptions whole;
    whole.run_crosscheck = false;
    EXPECT_NEAR(dropout.number(r, "seen_whole_error_deg"),
                sdp::analyze_vectors(data.vectors, data.weights, whole).max_worst_case_error_deg,
                kDegreesPerRadian * kCertified)
        << "marker " << k;
  }
  EXPECT_EQ(dropout.text(n, "entry"), "intact");
  EXPECT_EQ(dropout.number(n, "max_worst_case_error_deg"),
            report_.visibility->max_worst_case_error_deg);
}

TEST(LayoutWithoutNormals, KeepsTheHemisphereMapAndHasNoVisibilityFigure) {
  const Layout layout = testing::example_layout("triad.json");
  ASSERT_FALSE(layout.visibility.has_value());
  LayoutFiguresOptions options;
  EXPECT_EQ(selected_figures(options, false, false),
            (std::vector<std::string>{"viewpoint_map", "dropout", "error_surface", "vectors"}));
  options.only = {"visibility"};
  EXPECT_THROW(selected_figures(options, false, false), InvalidArgument);
  TempDir dir("plain");
  const report::LayoutReport report = testing::report_of(layout);
  EXPECT_THROW(write_layout_figures(report, dir.path(), options), InvalidArgument);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  options.only = {"viewpoint_map", "vectors"};
  write_layout_figures(report, dir.path(), options);
  EXPECT_EQ(read_csv(dir.path() / "viewpoint_map.csv").header,
            (std::vector<std::string>{"x", "y", "z", "pbar", "max_error_deg"}));
  for (std::size_t r = 0; r < read_csv(dir.path() / "vectors.csv").rows.size(); ++r) {
    EXPECT_NE(read_csv(dir.path() / "vectors.csv").text(r, "series"), "normal");
  }
}

TEST(BodyMaps, MissingModelOrReportThrowsAndWritesNothing) {
  TempDir dir("badmap");
  VisibilityMapData data;
  EXPECT_THROW(write_visibility_viewpoint_map(data, dir.path()), InvalidArgument);
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(box_cones_only());
  data.model = &model;
  EXPECT_THROW(write_visibility_figure(data, dir.path()), InvalidArgument);
  const visibility::VisibilityReport report = visibility::analyze_visibility(box_cones_only());
  data.report = &report;
  data.samples_per_axis = kMaxMapSamples + 1;
  EXPECT_THROW(write_visibility_figure(data, dir.path()), InvalidArgument);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace vantage::plot

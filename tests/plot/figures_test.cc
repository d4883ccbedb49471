// Every figure renders in every format on two example layouts; PNGs decode with the requested
// size, are not one colour and show the worst-viewpoint colour; the library stays silent and
// reports bad input and unwritable targets without leaving files behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include "plot_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/colormap.h"
#include "vantage/plot/layout_figures.h"
#include "vantage/plot/viewpoint_map.h"

namespace vantage::plot {
namespace {

using testing::example_design_curve;
using testing::example_layout;
using testing::report_of;
using testing::TempDir;

struct Png {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
};

Png decode_png(const std::filesystem::path& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (!data) {
    ADD_FAILURE() << "stb_image cannot decode " << path << ": " << stbi_failure_reason();
    return png;
  }
  png.rgb.assign(data, data + static_cast<std::size_t>(png.width) * png.height * 3);
  stbi_image_free(data);
  return png;
}

std::size_t distinct_colours(const Png& png) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
    colours.insert(png.rgb[i] << 16 | png.rgb[i + 1] << 8 | png.rgb[i + 2]);
  }
  return colours.size();
}

std::size_t pixels_of(const Png& png, Rgb c) {
  std::size_t count = 0;
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
    count += png.rgb[i] == c.r && png.rgb[i + 1] == c.g && png.rgb[i + 2] == c.b;
  }
  return count;
}

std::string head(const std::filesystem::path& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string text(bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// A figure has many colours (antialiased text, value map), never a handful.
constexpr std::size_t kMinColours = 50;
// Filled worst-viewpoint markers cover at least this many exact pixels.
constexpr std::size_t kMinMarkerPixels = 20;

class EveryFigure : public ::testing::TestWithParam<std::tuple<const char*, Format>> {};

TEST_P(EveryFigure, RendersWithItsCsv) {
  const auto [layout_file, format] = GetParam();
  const Layout layout = example_layout(layout_file);
  const DesignCurve design = example_design_curve();
  LayoutFiguresOptions options;
  options.figure.format = format;
  options.figure.width = 900;
  options.figure.height = 700;
  TempDir dir("render");
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const LayoutFigures figures =
      write_layout_figures(report_of(layout), dir.path(), options, &design);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "") << "the library must stay silent";
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "the library must stay silent";
  EXPECT_EQ(figures.status, LayoutFigures::Status::kCertified);

  const std::vector<std::string> names =
      selected_figures(options, true, layout.visibility.has_value());
  ASSERT_EQ(figures.files.size(), names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    const FigureFiles& f = figures.files[k];
    EXPECT_EQ(f.name, names[k]);
    EXPECT_EQ(f.image, dir.path() / (f.name + "." + to_string(format)));
    EXPECT_EQ(f.csv, dir.path() / (f.name + ".csv"));
    ASSERT_TRUE(std::filesystem::exists(f.image)) << f.image;
    ASSERT_TRUE(std::filesystem::exists(f.csv)) << f.csv;
    EXPECT_GT(testing::read_csv(f.csv).rows.size(), 0u) << f.csv;
    switch (format) {
      case Format::kPng: {
        const Png png = decode_png(f.image);
        EXPECT_EQ(png.width, 900) << f.name;
        EXPECT_EQ(png.height, 700) << f.name;
        EXPECT_GE(distinct_colours(png), kMinColours) << f.name;
        EXPECT_GE(pixels_of(png, kWorstViewpointColour), kMinMarkerPixels) << f.name;
        break;
      }
      case Format::kSvg:
        EXPECT_NE(head(f.image, 400).find("<svg"), std::string::npos) << f.name;
        break;
      case Format::kPdf:
        EXPECT_EQ(head(f.image, 5), "%PDF-") << f.name;
        break;
    }
  }
  std::size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    ++entries;
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left behind";
  }
  EXPECT_EQ(entries, 2 * names.size());
}

INSTANTIATE_TEST_SUITE_P(
    ExampleLayouts, EveryFigure,
    ::testing::Combine(::testing::Values("satellite.json", "note3_four_vectors.json"),
                       ::testing::Values(Format::kPng, Format::kSvg, Format::kPdf)));

TEST(Figures, DefaultPageIs1000By800) {
  TempDir dir("default");
  LayoutFiguresOptions options;
  options.only = {"vectors"};
  const LayoutFigures figures =
      write_layout_figures(report_of(example_layout("triad.json")), dir.path(), options);
  ASSERT_EQ(figures.files.size(), 1u);
  const Png png = decode_png(figures.files[0].image);
  EXPECT_EQ(png.width, 1000);
  EXPECT_EQ(png.height, 800);
}

TEST(Figures, SelectionFollowsOnlyAndNeedsADesignForTheDesignFigure) {
  LayoutFiguresOptions options;
  EXPECT_EQ(selected_figures(options, false),
            (std::vector<std::string>{"viewpoint_map", "dropout", "error_surface", "vectors"}));
  EXPECT_EQ(selected_figures(options, true).size(), 5u);
  EXPECT_EQ(selected_figures(options, true, true).size(), 6u) << "with normals: visibility";
  options.only = {"vectors", "dropout"};
  EXPECT_EQ(selected_figures(options, false), (std::vector<std::string>{"dropout", "vectors"}));
  options.only = {"histogram"};
  EXPECT_THROW(selected_figures(options, true), InvalidArgument);
  options.only = {"design"};
  EXPECT_THROW(selected_figures(options, false), InvalidArgument);
  options.only = {"vectors", "vectors"};
  EXPECT_THROW(selected_figures(options, false), InvalidArgument);
}

TEST(Figures, BadInputThrowsAndWritesNothing) {
  TempDir dir("bad");
  const Layout layout = example_layout("triad.json");
  LayoutFiguresOptions options;
  options.figure.width = 10;
  EXPECT_THROW(write_layout_figures(report_of(layout), dir.path(), options), InvalidArgument);
  options = {};
  options.threshold_deg = 95.0;
  EXPECT_THROW(write_layout_figures(report_of(layout), dir.path(), options), InvalidArgument);
  options = {};
  options.map_samples = 100;
  EXPECT_THROW(write_layout_figures(report_of(layout), dir.path(), options), InvalidArgument);
  options = {};
  EXPECT_THROW(write_layout_figures(report_of(layout), dir.path() / "missing", options),
               InvalidArgument);
  Layout broken = layout;
  broken.entries.col(1).setZero();
  EXPECT_THROW(write_layout_figures(report_of(broken), dir.path(), options), InvalidArgument);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(Figures, UnwritableTargetIsARenderErrorAndLeavesNoFile) {
  TempDir dir("unwritable");
  ViewpointMapData data;
  data.vectors = Eigen::Matrix3d::Identity();
  data.worst_viewpoints = {Eigen::Vector3d::Ones().normalized()};
  data.pbar_min = std::sqrt(2.0 / 3.0);
  // A directory where the image should go: the file cannot be opened for writing.
  std::filesystem::create_directories(dir.path() / "sub" / "viewpoint_map.png");
  ::testing::internal::CaptureStderr();
  EXPECT_THROW(write_viewpoint_map(data, dir.path() / "sub"), RenderError);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "sub" / "viewpoint_map.csv"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry :
       std::filesystem::directory_iterator(dir.path() / "sub")) {
    ++entries;
  }
  EXPECT_EQ(entries, 1u) << "only the blocking directory";
}

TEST(Figures, ViewpointMapCsvGridIsCheckedAndCappedByThePicture) {
  TempDir dir("csvgrid");
  ViewpointMapData data;
  data.vectors = Eigen::Matrix3d::Identity();
  data.worst_viewpoints = {Eigen::Vector3d::Ones().normalized()};
  data.pbar_min = std::sqrt(2.0 / 3.0);
  for (int bad : {kMinMapSamples - 1, kMaxMapSamples + 1}) {
    data.csv_samples_per_axis = bad;
    EXPECT_THROW(write_viewpoint_map(data, dir.path()), InvalidArgument) << bad;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "nothing written on bad data";
  // A CSV grid finer than the picture's is capped at the picture's: one row per picture cell
  // inside the disc.
  data.samples_per_axis = 64;
  data.csv_samples_per_axis = 100;
  const FigureFiles files = write_viewpoint_map(data, dir.path());
  const ViewpointSamples picture = sample_viewpoints(data.vectors, 64);
  EXPECT_EQ(testing::read_csv(files.csv).rows.size(),
            static_cast<std::size_t>(picture.viewpoints.cols()));
}

TEST(Figures, FormatNamesRoundTrip) {
  for (Format f : {Format::kPng, Format::kSvg, Format::kPdf}) {
    EXPECT_EQ(parse_format(to_string(f)), f);
  }
  EXPECT_THROW(parse_format("gif"), InvalidArgument);
}

}  // namespace
}  // namespace vantage::plot

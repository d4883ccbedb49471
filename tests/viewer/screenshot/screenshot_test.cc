// Runs vantage-viewer under `xvfb-run -a` (Xvfb + Mesa's software OpenGL) on example layouts and
// checks the PNG it writes: its size, that it is not one colour, and that the worst-viewpoint red
// is drawn where the projection of each visible global worst viewpoint falls. The worst
// viewpoints come from sdp::analyze_vectors run here, independently of the viewer. Skipped, with
// the reason printed, only when no X server can be started.

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdlib>
#include <memory>
#include <set>
#include <string>

#include "vantage/io/layout_file.h"
#include "vantage/plot/colormap.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/viewer/camera.h"
#include "viewer/viewer_runner.h"

namespace vantage::testing {
namespace {

constexpr int kWidth = 1200;
constexpr int kHeight = 800;
constexpr double kMarkerRadius = 6.0;  // pixels around a projected worst viewpoint searched
constexpr int kMinRedPixels = 12;      // the drawn marker has radius 7.5 px: ~170 pixels
constexpr int kColourSlack = 24;       // per channel: antialiased edges and the depth shade
constexpr int kMinDistinctColours = 200;

bool x_server_starts(std::string* why) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) {
    *why = "xvfb-run is not installed (Debian package xvfb)";
    return false;
  }
  if (std::system("xvfb-run -a true > /dev/null 2>&1") != 0) {
    *why = "xvfb-run -a could not start an X server";
    return false;
  }
  return true;
}

bool is_red(const unsigned char* px) {
  const plot::Rgb red = plot::kWorstViewpointColour;
  return std::abs(px[0] - red.r) <= kColourSlack && std::abs(px[1] - red.g) <= kColourSlack &&
         std::abs(px[2] - red.b) <= kColourSlack;
}

void check_screenshot(const std::string& file) {
  std::string why;
  if (!x_server_starts(&why)) GTEST_SKIP() << "no X server: " << why;
  ViewerScratch scratch;
  const std::string png = scratch.path("shot.png");
  const std::string layout = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + file;
  const ViewerRun run =
      run_viewer("xvfb-run -a -s '-screen 0 1600x1200x24'",
                 "'" + layout + "' --screenshot '" + png + "' --size " + std::to_string(kWidth) +
                     "x" + std::to_string(kHeight) + " --view iso --frames 3",
                 scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  std::cout << run.out;

  int width = 0;
  int height = 0;
  int channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels(
      stbi_load(png.c_str(), &width, &height, &channels, 3), stbi_image_free);
  ASSERT_TRUE(pixels) << png << ": not a readable image";
  ASSERT_EQ(width, kWidth);
  ASSERT_EQ(height, kHeight);
  auto at = [&](int x, int y) { return pixels.get() + 3 * (static_cast<long>(y) * width + x); };

  std::set<long> colours;
  long red_pixels = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const unsigned char* px = at(x, y);
      colours.insert((long{px[0]} << 16) | (long{px[1]} << 8) | px[2]);
      red_pixels += is_red(px);
    }
  }
  EXPECT_GE(static_cast<int>(colours.size()), kMinDistinctColours);
  EXPECT_LT(red_pixels, width * height / 20) << "red must mark the worst viewpoints only";
  for (int y = 4; y < 30; ++y) {  // control: the background corner has no red
    for (int x = 4; x < 30; ++x) ASSERT_FALSE(is_red(at(x, y))) << x << "," << y;
  }

  const DataVectors data = data_vectors(io::read_layout(layout));
  const sdp::LayoutAnalysis report = sdp::analyze_vectors(data.vectors, data.weights);
  const viewer::OrbitCamera camera;  // --view iso is the default camera
  const viewer::Viewport viewport = viewer::scene_viewport(width, height);
  int checked = 0;
  for (const Eigen::Vector3d& a : report.worst_viewpoints) {
    for (const double sign : {1.0, -1.0}) {
      if (camera.hidden_by_sphere(sign * a)) continue;
      const std::optional<Eigen::Vector2d> q = camera.project(sign * a, viewport);
      ASSERT_TRUE(q);
      int red = 0;
      for (int dy = -6; dy <= 6; ++dy) {
        for (int dx = -6; dx <= 6; ++dx) {
          const int x = static_cast<int>(std::lround(q->x())) + dx;
          const int y = static_cast<int>(std::lround(q->y())) + dy;
          if (dx * dx + dy * dy > kMarkerRadius * kMarkerRadius) continue;
          if (x >= 0 && y >= 0 && x < width && y < height) red += is_red(at(x, y));
        }
      }
      EXPECT_GE(red, kMinRedPixels)
          << "worst viewpoint " << (sign * a).transpose() << " at pixel " << q->transpose();
      ++checked;
    }
  }
  EXPECT_GE(checked, 1) << "no worst viewpoint faces the iso camera";
}

TEST(ViewerScreenshot, Satellite) { check_screenshot("satellite.json"); }

TEST(ViewerScreenshot, OrthogonalTriad) { check_screenshot("triad.json"); }

}  // namespace
}  // namespace vantage::testing

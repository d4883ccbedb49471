// Runs vantage-viewer under `xvfb-run -a` (Xvfb + Mesa's software OpenGL) on example layouts and
// checks the PNG it writes: its size, that it is not one colour, and that the worst-viewpoint red
// is drawn where the projection of each visible global worst viewpoint falls. The worst
// viewpoints come from sdp::analyze_vectors run here, independently of the viewer; for markers on
// a body (docs/math.md §20) they are the signed worst viewpoints of visibility::analyze_visibility,
// and a lost direction facing the camera must be drawn grey. Skipped, with the reason printed, only
// when no X server can be started.

#include <gtest/gtest.h>
#include <stb_image.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/plot/colormap.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/viewer/camera.h"
#include "vantage/visibility/visibility_model.h"
#include "vantage/visibility/visibility_report.h"
#include "viewer/viewer_runner.h"

namespace vantage::testing {
namespace {

constexpr int kWidth = 1200;
constexpr int kHeight = 800;
constexpr double kMarkerRadius = 6.0;  // pixels around a projected worst viewpoint searched
constexpr int kMinRedPixels = 12;      // the drawn marker has radius 7.5 px: ~170 pixels
constexpr int kColourSlack = 24;       // per channel: antialiased edges and the depth shade
constexpr int kMinDistinctColours = 200;
// The lost grey (viewer/app/draw_style.h: 150, 150, 150) under the sphere's depth shade (light
// 0.82 ... 1): a pixel counts as grey when its channels agree and lie in that range.
constexpr int kGreyLow = 118;
constexpr int kGreyHigh = 156;
constexpr int kGreySpread = 6;
constexpr double kLostProbeDeg = 3.0;   // a lost direction is tested only if lost this far around
constexpr double kDotClearance = 14.0;  // pixels from every drawn data-vector dot
constexpr double kGreyShare = 0.8;      // of the pixels within 4 px of the lost direction

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

bool is_grey(const unsigned char* px) {
  const int lo = std::min({px[0], px[1], px[2]});
  const int hi = std::max({px[0], px[1], px[2]});
  return hi - lo <= kGreySpread && lo >= kGreyLow && hi <= kGreyHigh;
}

// A direction facing the camera, lost with every direction kLostProbeDeg around it, away from
// the data-vector dots and the body inset (top right), is drawn grey.
template <typename PixelAt>
void check_lost_is_grey(const Layout& layout, const DataVectors& data,
                        const viewer::OrbitCamera& camera, const viewer::Viewport& viewport,
                        PixelAt at) {
  const visibility::VisibilityModel model = visibility::VisibilityModel::of(layout);
  auto lost_around = [&](const Eigen::Vector3d& a) {
    if (model.at(a).trackable) return false;
    const Eigen::Vector3d u = a.unitOrthogonal();
    const Eigen::Vector3d v = a.cross(u);
    const double r = kLostProbeDeg / kDegreesPerRadian;
    for (int k = 0; k < 8; ++k) {
      const double phi = 2.0 * kPi * k / 8.0;
      const Eigen::Vector3d b =
          std::cos(r) * a + std::sin(r) * (std::cos(phi) * u + std::sin(phi) * v);
      if (model.at(b.normalized()).trackable) return false;
    }
    return true;
  };
  constexpr int kCandidates = 2000;
  for (int n = 0; n < kCandidates; ++n) {
    const double z = 1.0 - 2.0 * (n + 0.5) / kCandidates;  // a Fibonacci lattice of directions
    const double phi = n * kPi * (3.0 - std::sqrt(5.0));
    const Eigen::Vector3d a(std::sqrt(1.0 - z * z) * std::cos(phi),
                            std::sqrt(1.0 - z * z) * std::sin(phi), z);
    if (a.dot(camera.back()) < 0.5 || !lost_around(a)) continue;
    const Eigen::Vector2d q = *camera.project(a, viewport);
    if (q.x() > viewport.x + 0.55 * viewport.width) continue;
    bool clear = true;
    for (Eigen::Index i = 0; i < data.vectors.cols() && clear; ++i) {
      for (const double s : {1.0, -1.0}) {
        const Eigen::Vector3d d = s * data.vectors.col(i).normalized();
        if (camera.hidden_by_sphere(d)) continue;
        clear = clear && (*camera.project(d, viewport) - q).norm() > kDotClearance;
      }
    }
    if (!clear) continue;
    int grey = 0;
    int total = 0;
    for (int dy = -4; dy <= 4; ++dy) {
      for (int dx = -4; dx <= 4; ++dx) {
        if (dx * dx + dy * dy > 16) continue;
        ++total;
        grey += is_grey(at(static_cast<int>(std::lround(q.x())) + dx,
                           static_cast<int>(std::lround(q.y())) + dy));
      }
    }
    EXPECT_GE(grey, kGreyShare * total)
        << "lost direction " << a.transpose() << " at pixel " << q.transpose();
    return;
  }
  ADD_FAILURE() << "no lost direction faces the iso camera clear of the dots";
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

  const Layout read = io::load_layout(layout);
  const DataVectors data = data_vectors(read);
  std::vector<Eigen::Vector3d> worst =
      sdp::analyze_vectors(data.vectors, data.weights).worst_viewpoints;
  std::vector<double> signs = {1.0, -1.0};
  if (read.visibility) {
    worst = visibility::analyze_visibility(read).worst.viewpoints;
    signs = {1.0};  // a camera on that side of the body
  }
  const viewer::OrbitCamera camera;  // --view iso is the default camera
  const viewer::Viewport viewport = viewer::scene_viewport(width, height);
  if (read.visibility) check_lost_is_grey(read, data, camera, viewport, at);
  int checked = 0;
  for (const Eigen::Vector3d& a : worst) {
    for (const double sign : signs) {
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

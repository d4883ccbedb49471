// vantage-viewer [LAYOUT] [--screenshot FILE.png [--frames N]] [--size WxH] [--view NAME]
//                [--pin AX,AY,AZ] [--place K [--candidates N]]
//
// The interactive viewer (GLFW + Dear ImGui). Exit status: 0 done, 2 bad input or usage (one
// line on stderr naming the file, field or option), 1 failure (no display or OpenGL context,
// screenshot not written, analysis not finished in time).

#include <CLI/CLI.hpp>

#include <Eigen/Core>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"
#include "vantage/viewer/viewer_session.h"
#include "viewer_window.h"

namespace {

using vantage::viewer::app::WindowOptions;

// "WxH" with 320 <= W, H <= 8192.
bool parse_size(const std::string& text, int* width, int* height) {
  int w = 0;
  int h = 0;
  char x = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X')) {
    return false;
  }
  if (w < 320 || h < 320 || w > 8192 || h > 8192) return false;
  *width = w;
  *height = h;
  return true;
}

// "AX,AY,AZ", a finite non-zero direction; normalised.
bool parse_direction(const std::string& text, Eigen::Vector3d* direction) {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &extra) != 3) return false;
  const Eigen::Vector3d d(x, y, z);
  if (!d.allFinite() || !(d.norm() > 0.0)) return false;
  *direction = d / d.norm();
  return true;
}

// The command line's values.
struct ViewerArgs {
  std::string layout_path;
  std::string size = "1400x900";
  std::string view = "iso";
  std::string pin;
  int place = 0;
  vantage::viewer::PlaceSettings place_settings;
  std::vector<double> target{0.0, 0.0, 0.0};  // --target, into place_settings.target
  WindowOptions window;
};

void add_viewer_options(CLI::App& cli, ViewerArgs* args) {
  cli.add_option("LAYOUT", args->layout_path,
                 "layout file (.json, .csv markers, .yaml AprilTag bundle); default: the "
                 "orthogonal triad");
  cli.add_option("--screenshot", args->window.screenshot_path,
                 "render, save the window to this PNG and exit (headless use, e.g. xvfb-run -a)");
  cli.add_option("--frames", args->window.frames,
                 "with --screenshot: frames drawn after the analysis is ready (>= 1)")
      ->check(CLI::Range(1, 1000));
  cli.add_option("--size", args->size, "window size WxH in pixels (320..8192 each)");
  cli.add_option("--view", args->view, "starting view: " + vantage::viewer::view_preset_names());
  cli.add_option("--pin", args->pin,
                 "pin the viewpoint AX,AY,AZ (object frame, body -> camera; normalised): the "
                 "readout and the inset show it");
  cli.add_option("--timeout", args->window.timeout_seconds,
                 "with --screenshot: seconds to wait for the analysis (>= 1)")
      ->check(CLI::Range(1, 86400));
  cli.add_option("--place", args->place,
                 "at start-up, place K markers on the layout's body (as the design panel's "
                 "button; the layout needs normals and a body mesh); with --screenshot the PNG "
                 "shows the placed layout")
      ->check(CLI::Range(3, 200));
  cli.add_option("--candidates", args->place_settings.candidates,
                 "with --place: sites sampled on the body")
      ->check(CLI::Range(1, 20000))
      ->capture_default_str();
  vantage::viewer::PlaceSettings& s = args->place_settings;
  cli.add_option("--objective", s.objective, "with --place: affine, camera or tracker")
      ->check(CLI::IsMember({"affine", "camera", "tracker"}))
      ->capture_default_str();
  cli.add_option("--distance", s.distance, "with --place --objective camera: layout units");
  cli.add_option("--distances", s.distances,
                 "with --place --objective camera: D1,D2,... an approach instead of --distance")
      ->delimiter(',');
  cli.add_option("--focal", s.focal, "with --place --objective camera: pixels");
  cli.add_option("--noise-px", s.noise_px, "with --place --objective camera: pixels");
  cli.add_option("--target", args->target,
                 "with --place --objective tracker: the target X,Y,Z (layout frame)")
      ->delimiter(',')
      ->expected(3);
  cli.add_option("--fle-rms", s.fle_rms,
                 "with --place --objective tracker: the isotropic FLE's RMS (layout units)");
  cli.add_option("--marker-diameter", s.marker_diameter,
                 "with --place: spheres of this diameter on the surface");
  cli.add_option("--min-separation", s.min_separation, "with --place: layout units");
  cli.add_option("--exclude", s.exclude,
                 "with --place: keep-out volume (mesh in the body's frame; repeatable)");
  cli.add_option("--region", s.region, "with --place: the part of the body to sample (a mesh)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{
      "vantage-viewer: orbit a fiducial layout's sphere of viewpoints, see its worst "
      "viewpoints and error surface, and improve it with the augmenter"};
  ViewerArgs args;
  add_viewer_options(cli, &args);
  WindowOptions& options = args.window;
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "vantage-viewer: " << e.what() << "\n";
    return 2;
  }
  if (!parse_size(args.size, &options.width, &options.height)) {
    std::cerr << "vantage-viewer: --size: expected WxH with 320..8192 pixels each, got '"
              << args.size << "'\n";
    return 2;
  }
  const std::optional<vantage::viewer::ViewPreset> preset =
      vantage::viewer::parse_view_preset(args.view);
  if (!preset) {
    std::cerr << "vantage-viewer: --view: expected one of " << vantage::viewer::view_preset_names()
              << ", got '" << args.view << "'\n";
    return 2;
  }
  options.view = *preset;
  Eigen::Vector3d pinned = Eigen::Vector3d::UnitZ();
  if (!args.pin.empty() && !parse_direction(args.pin, &pinned)) {
    std::cerr << "vantage-viewer: --pin: expected AX,AY,AZ, a non-zero direction, got '" << args.pin
              << "'\n";
    return 2;
  }

  std::optional<vantage::viewer::LayoutDocument> document;
  try {
    document.emplace(args.layout_path.empty() ? vantage::viewer::LayoutDocument::default_layout()
                                              : vantage::io::load_layout(args.layout_path),
                     args.layout_path);
  } catch (const std::exception& e) {
    std::cerr << "vantage-viewer: " << e.what() << "\n";
    return 2;
  }
  vantage::viewer::ViewerSession session(std::move(*document));
  if (!args.pin.empty()) session.pinned_viewpoint = pinned;
  if (args.place > 0) {
    args.place_settings.markers = args.place;
    args.place_settings.target = Eigen::Vector3d(args.target[0], args.target[1], args.target[2]);
    if (!session.place_markers(args.place_settings)) {
      std::cerr << "vantage-viewer: --place: " << session.message() << "\n";
      return 2;
    }
  }
  return vantage::viewer::app::run_window(session, options);
}

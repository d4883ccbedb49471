// `vantage crb LAYOUT --distance D --focal F --noise-px S`: the Cramér–Rao bound of the pose from
// one pinhole image over every viewpoint (issue 21; docs/math.md §22), the worst and best
// directions, percentiles, the sliver flag and the affine bound of the same layout beside it.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "command.h"
#include "crb_json.h"
#include "layout_input.h"
#include "limits.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/pose_crb.h"

namespace vantage::cli {

namespace {

struct CrbArgs {
  std::string file;
  LayoutInput input;
  double distance = 0.0;
  double focal = 0.0;
  double noise_px = 0.0;
  std::vector<double> principal_point;
  std::string direction;
  std::string sweep_distance;
  int samples = 10000;
  int threads = 0;
  bool json = false;
  bool allow_large = false;
};

/// "AX,AY,AZ" as typed to a vector; InvalidArgument naming --direction otherwise.
Eigen::Vector3d parse_direction(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d a;
  char comma1 = 0, comma2 = 0;
  if (!(in >> a.x() >> comma1 >> a.y() >> comma2 >> a.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !a.allFinite() || a.norm() == 0.0) {
    throw InvalidArgument(
        "--direction", "expected AX,AY,AZ, three finite numbers not all 0, got \"" + text + "\"");
  }
  return a.normalized();
}

/// "D1:D2:N" as typed; InvalidArgument naming --sweep-distance otherwise.
sdp::PoseCrbSweep parse_sweep(const std::string& text) {
  std::istringstream in(text);
  sdp::PoseCrbSweep sweep;
  char colon1 = 0, colon2 = 0;
  if (!(in >> sweep.from >> colon1 >> sweep.to >> colon2 >> sweep.count) || colon1 != ':' ||
      colon2 != ':' || !(in >> std::ws).eof()) {
    throw InvalidArgument("--sweep-distance", "expected D1:D2:N, got \"" + text + "\"");
  }
  return sweep;
}

/// The library's option names as the command's options; any other error is the file's.
InvalidArgument as_option(const InvalidArgument& e, const std::string& file) {
  static const std::pair<const char*, const char*> kOptions[] = {
      {"distance", "--distance"},   {"focal_length", "--focal"},
      {"noise_px", "--noise-px"},   {"principal_point", "--principal-point"},
      {"samples", "--samples"},     {"threads", "--threads"},
      {"direction", "--direction"}, {"sweep_distance", "--sweep-distance"}};
  for (const auto& [field, option] : kOptions) {
    if (e.field() == field) return e.renamed(option, std::nullopt);
  }
  return e.against(file);
}

std::string bound_line(const sdp::PoseCrbAt& at) {
  if (!at.trackable) {
    return format_vector(at.direction, 4) + "  not trackable (" +
           std::to_string(at.visible_markers.size()) + " visible markers)";
  }
  return format_vector(at.direction, 4) + "  rot_rms " + format_number(at.rot_rms_deg, 4) +
         " deg  trans_rms " + format_number(at.trans_rms, 4) + "  (" +
         std::to_string(at.visible_markers.size()) + " visible markers)";
}

void print_report(const std::string& name, const sdp::PoseCrbReport& r) {
  const sdp::PoseCrbMap& map = r.map;
  std::cout << "vantage crb: " << name << "\n"
            << "  pinhole camera at distance " << format_number(r.camera.distance) << " from the "
            << "markers' centroid, f = " << format_number(r.camera.focal_length) << " px, noise "
            << format_number(r.camera.noise_px) << " px per coordinate\n"
            << "  " << r.markers << " markers, visibility " << (r.with_body ? "cone+mesh" : "cone")
            << "; " << map.samples.size() << " directions sampled, trackable fraction "
            << format_number(map.trackable_fraction, 4) << "\n\n";
  if (r.at_direction) std::cout << "at direction     " << bound_line(*r.at_direction) << "\n";
  if (map.status != sdp::PoseCrbMap::Status::kOk) {
    std::cout << "no sampled direction is trackable\n";
  } else {
    std::cout << "worst direction  " << bound_line(map.worst) << "\n"
              << "best direction   " << bound_line(map.best) << "\n"
              << "rot_rms over the trackable area (deg): p50 "
              << format_number(map.percentiles.p50, 4) << ", p95 "
              << format_number(map.percentiles.p95, 4) << ", p99 "
              << format_number(map.percentiles.p99, 4) << "\n"
              << "sliver           " << (map.sliver ? "yes" : "no") << " (the region within 2x "
              << "of the worst is " << format_number(map.worst_region_width_deg, 3)
              << " deg across)\n";
  }
  std::cout << "affine bound     " << format_number(r.affine_bound_deg, 4)
            << " deg (arccos pbar_min, the worst-case error of the affine camera)\n";
  for (const sdp::PoseCrbSweepRow& row : r.sweep_distance) {
    std::cout << "  D " << format_number(row.distance, 4);
    if (row.status != sdp::PoseCrbMap::Status::kOk) {
      std::cout << "  not trackable\n";
      continue;
    }
    std::cout << "  worst rot_rms " << format_number(row.worst.rot_rms_deg, 4) << " deg, trans_rms "
              << format_number(row.worst.trans_rms, 4) << "  median rot_rms "
              << format_number(row.median.rot_rms_deg, 4) << " deg, trans_rms "
              << format_number(row.median.trans_rms, 4) << "\n";
  }
}

int run_crb(const CrbArgs& args) {
  const Layout layout = args.input.read(args.file, args.allow_large);
  sdp::PoseCrbOptions options;
  options.distance = args.distance;
  options.focal_length = args.focal;
  options.noise_px = args.noise_px;
  if (!args.principal_point.empty()) {
    options.principal_point = {args.principal_point[0], args.principal_point[1]};
  }
  options.samples = args.samples;
  options.threads = args.threads;
  std::optional<Eigen::Vector3d> direction;
  if (!args.direction.empty()) direction = parse_direction(args.direction);
  std::optional<sdp::PoseCrbSweep> sweep;
  if (!args.sweep_distance.empty()) sweep = parse_sweep(args.sweep_distance);
  sdp::PoseCrbReport report;
  try {
    report = sdp::pose_crb_report(layout, options, direction, sweep);
  } catch (const InvalidArgument& e) {
    throw as_option(e, args.file);
  }
  if (args.json) {
    print_json(crb_json::report(report));
  } else {
    print_report(layout.name.empty() ? args.file : layout.name, report);
  }
  return kExitOk;
}

}  // namespace

Command add_crb_command(CLI::App& root) {
  auto args = std::make_shared<CrbArgs>();
  CLI::App* sub = root.add_subcommand(
      "crb",
      "Cramér-Rao bound of the pose from one pinhole image over every viewpoint (docs/math.md "
      "§22): worst and best direction, percentiles, sliver flag, the affine bound beside it");
  sub->add_option("LAYOUT", args->file, "layout file (points)")->required();
  args->input.add_options(sub);
  sub->add_option("--distance", args->distance,
                  "camera distance from the markers' centroid, layout units")
      ->required();
  sub->add_option("--focal", args->focal, "focal length, pixels, > 0")->required();
  sub->add_option("--noise-px", args->noise_px, "pixel noise per coordinate, pixels, > 0")
      ->required();
  sub->add_option("--principal-point", args->principal_point, "principal point CX CY, pixels")
      ->expected(2);
  sub->add_option("--direction", args->direction,
                  "also the bound at this viewing direction AX,AY,AZ (body toward camera)");
  sub->add_option("--sweep-distance", args->sweep_distance,
                  "D1:D2:N: the worst and median bound at N distances from D1 to D2");
  sub->add_option("--samples", args->samples, "Fibonacci directions of the map")
      ->capture_default_str();
  sub->add_option("--threads", args->threads, "threads, 0 = all cores")->capture_default_str();
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_crb(*args); }};
}

}  // namespace vantage::cli

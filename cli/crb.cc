// `vantage crb LAYOUT --distance D --focal F --noise-px S`: the Cramér–Rao bound of the pose from
// one pinhole image over every viewpoint (issue 21; docs/math.md §22), the worst and best
// directions, percentiles, the sliver flag and the affine bound of the same layout beside it.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "command.h"
#include "crb_input.h"
#include "layout_input.h"
#include "limits.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/camera/pose_crb_tags.h"
#include "vantage/commands/crb_json.h"
#include "vantage/commands/point_text.h"

namespace vantage::cli {

namespace {

struct CrbArgs {
  std::string file;
  LayoutInput input;
  CrbCameraArgs camera;
  std::string direction;
  bool sweep_tags = false;
  camera::TagSweepOptions tags;
  CLI::Option* tags_per_side_option = nullptr;
  CLI::Option* tag_fill_option = nullptr;
  bool json = false;
  bool quiet = false;
  bool allow_large = false;
};

// rot_rms of a direction in degrees, or "unbounded" (no figure past the first-order limit).
std::string rot_text(const camera::PoseCrbAt& at) {
  return at.unbounded ? std::string("unbounded") : format_number(at.rot_rms_deg, 4) + " deg";
}

// trans_rms of a direction, or "-" where rot_rms is unbounded.
std::string trans_text(const camera::PoseCrbAt& at) {
  return at.unbounded ? std::string("-") : format_number(at.trans_rms, 4);
}

std::string bound_line(const camera::PoseCrbAt& at) {
  if (at.unbounded) {
    return format_vector(at.direction, 4) + "  unbounded (" +
           (at.ill_conditioned ? std::string("the Fisher information is singular")
                               : "first-order rot_rms above " +
                                     format_number(camera::PoseCrbAt::kMaxRotRmsDeg) + " deg") +
           "; " + std::to_string(at.visible_markers.size()) + " visible markers)";
  }
  if (!at.trackable) {
    return format_vector(at.direction, 4) + "  not trackable (" +
           std::to_string(at.visible_markers.size()) + " visible markers)";
  }
  return format_vector(at.direction, 4) + "  rot_rms " + format_number(at.rot_rms_deg, 4) +
         " deg  trans_rms " + format_number(at.trans_rms, 4) + "  (" +
         std::to_string(at.visible_markers.size()) + " visible markers)";
}

void print_report(const std::string& name, const camera::PoseCrbReport& r) {
  const camera::PoseCrbMap& map = r.map;
  std::cout << "vantage crb: " << name << "\n"
            << "  pinhole camera at distance " << format_number(r.camera.distance) << " from the "
            << (r.camera.aim ? "aim point " + format_vector(*r.camera.aim) : "markers' centroid")
            << ", f = " << format_number(r.camera.focal_length) << " px, noise "
            << format_number(r.camera.noise_px) << " px per coordinate\n"
            << "  " << r.markers << " markers, visibility " << (r.with_body ? "cone+mesh" : "cone")
            << "; " << map.samples.size() << " directions sampled, trackable fraction "
            << format_number(map.trackable_fraction, 4) << ", unbounded "
            << format_number(map.unbounded_fraction, 4) << "\n\n";
  if (r.at_direction) std::cout << "at direction     " << bound_line(*r.at_direction) << "\n";
  if (map.status != camera::PoseCrbMap::Status::kOk) {
    std::cout << "not trackable    " << camera::to_string(map.status) << ": "
              << camera::untrackable_reason(map, r.camera.distance) << "\n";
  } else {
    std::cout << "worst direction  " << bound_line(map.worst) << "\n"
              << "best direction   " << bound_line(map.best) << "\n"
              << "rot_rms over the trackable area (deg): p50 "
              << format_number(map.percentiles.p50, 4) << ", p95 "
              << format_number(map.percentiles.p95, 4) << ", p99 "
              << format_number(map.percentiles.p99, 4) << "\n"
              << "sliver           " << (map.sliver ? "yes" : "no")
              << (map.worst.unbounded ? " (the region above 22.5 deg about the worst "
                                      : " (the region within 2x of the worst ")
              << (map.worst_region_fills_workspace
                      ? std::string("reaches the workspace's edge along every cut")
                      : "is " + format_number(map.worst_region_width_deg, 3) + " deg across")
              << ")\n";
  }
  std::cout << "affine bound     " << format_number(r.affine_bound_deg, 4)
            << " deg (arccos pbar_min, the worst-case error of the affine camera)\n";
  for (const camera::PoseCrbSweepRow& row : r.sweep_distance) {
    std::cout << "  D " << format_number(row.distance, 4);
    if (row.status != camera::PoseCrbMap::Status::kOk) {
      std::cout << "  not trackable\n";
      continue;
    }
    std::cout << "  worst rot_rms " << rot_text(row.worst) << ", trans_rms "
              << trans_text(row.worst) << "  median rot_rms " << rot_text(row.median)
              << ", trans_rms " << trans_text(row.median) << "\n";
  }
}

// One cell of the tag table: `text` right-aligned in `width` characters.
std::string cell(const std::string& text, int width) {
  return std::string(std::max(0, width - static_cast<int>(text.size())), ' ') + text;
}

void print_tag_sweep(const std::vector<camera::TagFace>& faces,
                     const std::vector<camera::TagSweepRow>& rows) {
  double largest = 0.0;
  for (const camera::TagFace& face : faces) largest = std::max(largest, face.extent);
  std::cout << "\nhow many tags, and how big: " << faces.size() << " face(s) of fixed extent "
            << "(largest " << format_number(largest, 4) << "), k x k tags on each, of side fill x "
            << "extent / k\n"
            << "   k  tags  fill  tag size  tag px   median rot_rms  median trans   p95 rot_rms  "
               "worst rot_rms\n";
  bool small = false;
  for (const camera::TagSweepRow& row : rows) {
    const bool too_small = row.tag_pixels < camera::TagSweepRow::kMinDetectablePixels;
    small = small || too_small;
    std::cout << cell(std::to_string(row.per_side), 4) << cell(std::to_string(row.tags), 6)
              << cell(format_number(row.fill, 3), 6) << cell(format_number(row.tag_size, 4), 10)
              << cell(format_number(row.tag_pixels, 3) + (too_small ? "*" : " "), 8);
    if (row.status != camera::PoseCrbMap::Status::kOk) {
      std::cout << "   not trackable\n";
      continue;
    }
    std::cout << cell(format_number(row.median.rot_rms_deg, 4) + " deg", 17)
              << cell(format_number(row.median.trans_rms, 4), 14)
              << cell(format_number(row.percentiles.p95, 4) + " deg", 14)
              << cell(rot_text(row.worst), 15) << "\n";
  }
  if (small) {
    std::cout << "   * under " << format_number(camera::TagSweepRow::kMinDetectablePixels)
              << " px across head-on: such a tag may not be decoded at this distance (the "
                 "bound assumes it is)\n";
  }
}

// The --sweep-tags rows (and the faces they tile), errors named by the flags.
std::vector<camera::TagSweepRow> tag_sweep(const CrbArgs& args, const Layout& layout,
                                           const camera::CrbProgress& progress,
                                           std::vector<camera::TagFace>* faces) {
  camera::TagSweepOptions options = args.tags;
  options.progress = progress;
  try {
    *faces = camera::tag_faces(layout);
    return camera::pose_crb_tag_sweep(layout, args.camera.options(), options);
  } catch (const InvalidArgument& e) {
    if (e.field() == "names" || e.field() == "points") throw e.against(args.file);
    if (e.field() == "sweep_tags.per_side") throw e.renamed("--tags-per-side", std::nullopt);
    if (e.field() == "sweep_tags.fill") throw e.renamed("--tag-fill", std::nullopt);
    throw crb_option_error(e, args.file);
  }
}

int run_crb(const CrbArgs& args) {
  if (!args.sweep_tags) {
    // Issue 36: --tags-per-side without --sweep-tags was silently ignored.
    for (const CLI::Option* option : {args.tags_per_side_option, args.tag_fill_option}) {
      if (option->count() > 0) {
        throw InvalidArgument(option->get_name(), "takes effect only with --sweep-tags");
      }
    }
  }
  const std::optional<camera::PoseCrbSweep> sweep = args.camera.sweep();
  if (sweep) {
    check_limit("--sweep-distance", sweep->count, kMaxCrbSweepDistances, "crb", args.allow_large);
  }
  if (args.sweep_tags) {
    check_limit("--sweep-tags (--tags-per-side values x --tag-fill values)",
                static_cast<long>(args.tags.per_side.size() * args.tags.fill.size()),
                kMaxTagSweepRows, "crb", args.allow_large);
  }
  const Layout layout = args.input.read(args.file, args.allow_large);
  std::optional<Eigen::Vector3d> direction;
  if (!args.direction.empty()) direction = commands::parse_direction(args.direction, "--direction");
  camera::PoseCrbReport report;
  std::vector<camera::TagFace> faces;
  std::vector<camera::TagSweepRow> tag_rows;
  {
    Progress progress("crb", !args.json && !args.quiet);  // cleared before the report
    try {
      report = camera::pose_crb_report(layout, args.camera.options(), direction, sweep,
                                       progress.callback());
    } catch (const InvalidArgument& e) {
      throw crb_option_error(e, args.file);
    }
    if (args.sweep_tags) tag_rows = tag_sweep(args, layout, progress.callback(), &faces);
  }
  if (args.json) {
    Json out = crb_json::report(report);
    if (args.sweep_tags) out["sweep_tags"] = crb_json::tag_sweep(faces, tag_rows);
    print_json(out);
  } else {
    print_report(layout.name.empty() ? args.file : layout.name, report);
    if (args.sweep_tags) print_tag_sweep(faces, tag_rows);
  }
  // Issue 36: nothing trackable exited 0, and ill-conditioning was called untrackable; as
  // analyze and tre do, the report is printed and the reason given, exit 1.
  if (report.map.status != camera::PoseCrbMap::Status::kOk) {
    std::cerr << "vantage: crb: " << camera::untrackable_reason(report.map, report.camera.distance)
              << std::endl;
    return kExitFailure;
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
  args->camera.add_options(sub, true);
  sub->add_option("--direction", args->direction,
                  "also the bound at this viewing direction AX,AY,AZ (body toward camera)");
  sub->add_flag("--sweep-tags", args->sweep_tags,
                "AprilTag corners: the bound with every face tiled by k x k tags of the same "
                "extent (docs/math.md §22, \"How many tags, and how big\")");
  args->tags_per_side_option =
      sub->add_option("--tags-per-side", args->tags.per_side,
                      "k of --sweep-tags, each in [1, " +
                          std::to_string(camera::TagSweepOptions::kMaxPerSide) + "]; at most " +
                          std::to_string(kMaxTagSweepRows) +
                          " tilings (values x --tag-fill values) without --allow-large")
          ->delimiter(',')
          ->capture_default_str();
  args->tag_fill_option =
      sub->add_option("--tag-fill", args->tags.fill,
                      "tag side over its cell's side for --sweep-tags, each in (0, 1]")
          ->delimiter(',')
          ->capture_default_str();
  sub->add_option("--threads", args->camera.threads, "threads, 0 = all cores")
      ->capture_default_str();
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--quiet", args->quiet,
                "no progress line on stderr (shown only on a terminal, during the sweeps)");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_crb(*args); }};
}

}  // namespace vantage::cli

// `vantage tre LAYOUT --target X,Y,Z (--fle-rms F | --fle-sigma SP,SD)`: the target registration
// error of a tool tracked by a 3-D tracker (issue 20; docs/math.md §23): Fitzpatrick's isotropic
// RMS, the TRE at a line of sight, the certified worst and best over the tracked directions and a
// Monte Carlo check.

#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "command.h"
#include "layout_input.h"
#include "limits.h"
#include "progress.h"
#include "tre_input.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/tre_json.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::cli {

namespace {

struct TreArgs {
  std::string file;
  LayoutInput input;
  TreTargetArgs target;
  long monte_carlo = 0;
  std::uint64_t seed = 1;
  int threads = 0;
  bool json = false;
  bool quiet = false;
  bool allow_large = false;
};

std::string markers_text(const std::vector<int>& visible) {
  std::string out;
  for (int i : visible) out += (out.empty() ? "" : " ") + std::to_string(i);
  return out;
}

std::string extreme_line(const tracker::TreExtreme& e) {
  if (e.status == tracker::TreExtreme::Status::kUntracked) return "no tracked direction";
  std::string line = format_number(e.rms, 5) + "  at " + format_vector(e.direction, 4) + "  (" +
                     std::to_string(e.visible_markers.size()) +
                     " markers: " + markers_text(e.visible_markers) + ")  ";
  if (e.closed_form) return line + "exact (eigenvector of M)";
  return line + tracker::to_string(e.status) + ", bound " + format_number(e.rms_bound, 7);
}

void print_target(const tracker::TreTargetReport& t) {
  std::cout << "target " << format_vector(t.target, 6) << "\n";
  if (t.rms_isotropic) {
    std::cout << "  RMS TRE, every marker (Fitzpatrick 1998)  "
              << format_number(*t.rms_isotropic, 5) << "\n";
  }
  if (t.at_direction) {
    const tracker::TreAtDirection& at = *t.at_direction;
    std::cout << "  at line of sight " << format_vector(at.direction, 4) << "  ";
    if (!at.tracked) {
      std::cout << "not tracked (" << at.visible_markers.size() << " visible markers)\n";
    } else {
      std::cout << "RMS " << format_number(at.rms, 5) << "  (" << at.visible_markers.size()
                << " markers: " << markers_text(at.visible_markers)
                << ")\n  covariance (tool frame):\n"
                << format_matrix(at.covariance, 4, 5);
    }
  }
  std::cout << "  worst over tracked directions  " << extreme_line(t.extremes.worst) << "\n"
            << "  best over tracked directions   " << extreme_line(t.extremes.best) << "\n";
  if (t.monte_carlo) {
    std::cout << "  Monte Carlo at " << format_vector(t.monte_carlo_direction, 4) << ": "
              << t.monte_carlo->trials << " trials, RMS " << format_number(t.monte_carlo->rms, 5)
              << " vs formula " << format_number(t.monte_carlo->formula_rms, 5) << " ("
              << format_number(100.0 * t.monte_carlo->rel_diff, 3) << " %)\n";
  }
}

void print_report(const std::string& name, const tracker::TreReport& r) {
  std::cout << "vantage tre: " << name << "\n  " << r.markers << " markers, tracked with at least "
            << r.min_visible << " visible; visibility "
            << (r.with_body ? "cone+mesh" : (r.with_normals ? "cone" : "none (all seen)")) << "\n";
  if (r.five_dof) {
    std::cout << "  5-DoF tool: its markers are collinear, along " << format_vector(r.axis, 4)
              << " through " << format_vector(r.axis_point, 4)
              << "; the rotation about that axis is not measured, so only targets on it are "
                 "tracked\n";
  }
  std::cout << "  FLE ";
  if (r.fle.from_rms) {
    std::cout << "isotropic, RMS " << format_number(r.fle.rms(), 5);
  } else {
    std::cout << "sd " << format_number(r.fle.sigma_perp, 5) << " across, "
              << format_number(r.fle.sigma_axial, 5) << " along the line of sight (RMS "
              << format_number(r.fle.rms(), 5) << ")";
  }
  std::cout << "; registration: least squares, no scale (q-method); first order (docs/math.md "
               "§23)\n  RMS TRE in the layout's units; directions are lines of sight from the "
               "tool toward the tracker, tool frame\n\n";
  for (const tracker::TreTargetReport& t : r.targets) print_target(t);
}

int run_tre(const TreArgs& args) {
  const std::vector<Eigen::Vector3d> targets = args.target.parsed_targets();
  tracker::TreOptions options;
  options.fle = args.target.parsed_fle();
  options.direction = args.target.parsed_direction();
  check_limit("--monte-carlo", args.monte_carlo, kMaxTreTrials, "tre", args.allow_large);
  options.monte_carlo_trials = args.monte_carlo;
  options.seed = args.seed;
  options.threads = args.threads;
  const Layout layout = args.input.read(args.file, args.allow_large);
  tracker::TreReport report;
  try {
    Progress progress("tre", !args.json && !args.quiet);  // cleared before the report
    options.progress = progress.callback();
    report = tracker::tre_report(layout, targets, options);
  } catch (const InvalidArgument& e) {
    throw tre_option_error(e, args.file);  // the library's fields as the options that set them
  }
  if (args.json) {
    print_json(tre_json::report(report));
  } else {
    print_report(layout.name.empty() ? args.file : layout.name, report);
  }
  // Issue 36: nothing tracked exited 0 with nothing on stderr; as analyze does, the report is
  // printed and the reason given, exit 1.
  const std::string untracked = tre_json::untracked_reason(report);
  if (!untracked.empty()) {
    std::cerr << "vantage: tre: " << untracked << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_tre_command(CLI::App& root) {
  auto args = std::make_shared<TreArgs>();
  CLI::App* sub = root.add_subcommand(
      "tre",
      "target registration error of a tool on a 3-D tracker (docs/math.md §23): Fitzpatrick's "
      "RMS, the TRE at a line of sight, the certified worst and best over tracked directions");
  sub->add_option("LAYOUT", args->file, "layout file (points, in the tool frame)")->required();
  args->input.add_options(sub);
  args->target.add_options(sub);
  sub->add_option("--monte-carlo", args->monte_carlo,
                  "trials of the Monte Carlo check (>= 1000, at most " +
                      std::to_string(kMaxTreTrials) +
                      " without --allow-large; at --direction, else the worst)");
  sub->add_option("--seed", args->seed, "Monte Carlo seed")->capture_default_str();
  sub->add_option("--threads", args->threads, "Monte Carlo threads, 0 = all cores")
      ->capture_default_str();
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  sub->add_flag("--quiet", args->quiet,
                "no progress line on stderr (shown only on a terminal, during --monte-carlo)");
  return {sub, [args] { return run_tre(*args); }};
}

}  // namespace vantage::cli

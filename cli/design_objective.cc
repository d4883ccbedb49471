// `vantage design LAYOUT --add K --objective camera|tracker ...`: the K of the layout's
// candidates that, added to its markers, make the camera's pose CRB or the tracker's TRE best,
// by `vantage place`'s search on the layout seen whole (docs/math.md §21, "In design").

#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <utility>

#include "command.h"
#include "design_args.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/commands/design_sensor.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {
namespace {

// The augmenter's options have no meaning for place's search: refused, not ignored.
void check_unused_options(const DesignArgs& args) {
  const std::pair<const CLI::Option*, const char*> augmenter_only[] = {
      {args.margin_option, "--margin"},
      {args.search_budget_option, "--search-budget"},
      {args.direct_option, "--direct/--no-direct"}};
  for (const auto& [option, name] : augmenter_only) {
    if (option != nullptr && option->count() > 0) {
      throw InvalidArgument(name, "is the augmenter's (--objective affine); the " +
                                      args.sensor.objective +
                                      " objective chooses among the candidates");
    }
  }
  if (!args.plot.empty()) {
    throw InvalidArgument("--plot", "the design figure charts p-bar_min (--objective affine)");
  }
  if (args.write_given && io::layout_write_format(args.write) != io::LayoutFormat::kJson) {
    throw InvalidArgument("--write", args.write +
                                         ": write the layout as .json (it keeps the "
                                         "sensor block that `vantage analyze` reports)");
  }
}

// A value of the sensor's objective in words: degrees (camera) or layout units (tracker).
std::string value_text(double value, bool camera) {
  if (!std::isfinite(value)) return "none (not tracked)";
  if (camera && value > camera::PoseCrbAt::kMaxRotRmsDeg) return "unbounded";
  return format_number(value, 4) + (camera ? " deg" : "");
}

void print_report(const DesignArgs& args, const Layout& layout, const design_sensor::Sites& sites,
                  const design_sensor::Outcome& out) {
  const bool camera = args.sensor.objective == "camera";
  const design::PlacementResult& r = out.result;
  const long candidates = static_cast<long>(sites.layout.entries.cols()) - sites.markers;
  std::cout << "vantage design: " << args.file
            << (layout.name.empty() ? "" : " (" + layout.name + ")") << ", " << sites.markers
            << " markers, " << candidates << " candidates; adding " << args.add << " of them for "
            << "the " << args.sensor.objective
            << " objective (docs/math.md §21, \"In design\"; the layout seen whole)\n"
            << "sensor  " << sensor_json::words(out.final.sensor) << "\n"
            << "status  " << (out.complete ? "complete" : "incomplete") << "\n"
            << "search  " << r.search << ", "
            << (r.search == "exhaustive" ? std::to_string(r.subsets) + " subsets"
                                         : std::to_string(r.swaps) + " improving swaps")
            << "; search value " << value_text(r.value.objective, camera)
            << (camera && args.sensor.statistic == "worst"
                    ? " (the lattice's worst, before the refinement below)"
                    : "")
            << "\n"
            << "value   " << (out.initial ? value_text(out.initial->value, camera) : "-")
            << " as given -> " << value_text(out.final.value, camera) << " with candidates";
  for (const int c : out.added) std::cout << " c" << c;
  std::cout << "\n";
  if (!r.steps.empty()) {
    std::cout << "\ngreedy step  candidate  search value\n";
    for (const design::PlacementStep& s : r.steps) {
      if (s.added < sites.markers) continue;  // the kept markers' row
      std::cout << pad(std::to_string(s.k - sites.markers), 13)
                << pad("c" + std::to_string(s.added - sites.markers), 11)
                << value_text(s.value.objective, camera) << "\n";
    }
  }
  std::cout << "\n" << sensor_json::to_text(out.final);
  const design::RandomBaseline& b = r.random_baseline;
  if (b.trials > 0) {
    std::cout << "random baseline: best " << value_text(b.best_objective, camera) << ", median "
              << value_text(b.median_objective, camera) << " over " << b.trials
              << " trials (search values)\n";
  }
}

}  // namespace

int run_sensor_design(const DesignArgs& args) {
  check_write_target(args);
  check_unused_options(args);
  const Layout layout = args.input.read(args.file, args.allow_large);
  const design_sensor::Sites sites =
      against_source(args.file, [&] { return design_sensor::sites_of(layout); });
  place_json::Request request = args.sensor;
  request.sites = args.file;
  request.min_distance_difference = args.min_distance_difference;
  try {
    design_sensor::check(request, sites, args.add, layout);
  } catch (const InvalidArgument& e) {
    // The flags' errors as they are; the layout's (candidates, points) against the file.
    if (e.field().rfind("--", 0) == 0) throw;
    throw e.against(args.file);
  }
  std::optional<io::WriteLock> lock;
  if (args.write_given) lock.emplace(args.write);
  design_sensor::Outcome out;
  {
    Progress progress("design", !args.json && !args.quiet);  // cleared before the report
    out = design_sensor::design_for_sensor(request, layout, sites, args.add, progress.callback());
  }
  if (out.complete && args.write_given) io::save_layout(args.write, out.augmented, args.overwrite);
  if (args.json) {
    Json report = design_sensor::report(args.file, request, sites, out);
    if (out.complete && args.write_given) report["written"] = args.write;
    print_json(report);
  } else {
    print_report(args, layout, sites, out);
    if (out.complete && args.write_given) std::cout << "written: " << args.write << "\n";
  }
  if (!out.complete) {
    std::cerr << "vantage: design: " << design_sensor::failure_message(out)
              << (args.write_given ? "; nothing written" : "") << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace vantage::cli

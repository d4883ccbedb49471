// `vantage analyze LAYOUT [--json]`: the worst viewpoint of a layout (Theorem 6, global and
// certified), p-bar_min, the worst-case errors of Eq. (30), the paper's single LMI beside it, the
// NLopt cross-check and the swap sensitivity of Prop. 2.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>

#include "command.h"
#include "layout_input.h"
#include "limits.h"
#include "progress.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/layout.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/io/layout_file.h"
#include "vantage/report/layout_report.h"
#include "vantage/tracker/identification.h"

namespace vantage::cli {

namespace {

// The default report shows this many worst vectors (all of them with --verbose or when there
// are at most kShownVectors + 2).
constexpr long kShownVectors = 5;
// Swap errors at or below this (degrees) are "0": noise-free, a swap either leaves the rotation
// exactly unchanged or moves it far (swap_sensitivity.h), so rounding is the only scale here.
constexpr double kZeroSwapDeg = 1e-6;

struct AnalyzeArgs {
  std::string file;
  LayoutInput input;
  std::string pair_weighting = "geometric";
  int swaps = 5;
  bool crosscheck = true;
  bool dropout = false;
  bool json = false;
  bool verbose = false;
  bool quiet = false;
  bool allow_large = false;
};

/// Indices of the data vectors by decreasing worst-case error (ties by index).
std::vector<long> by_decreasing_error(const Eigen::VectorXd& errors) {
  std::vector<long> order(static_cast<std::size_t>(errors.size()));
  std::iota(order.begin(), order.end(), 0L);
  std::stable_sort(order.begin(), order.end(),
                   [&](long a, long b) { return errors(a) > errors(b); });
  return order;
}

void print_vectors(const report::LayoutReport& report, bool verbose) {
  const sdp::LayoutAnalysis& r = report.analysis;
  const long m = report.data.vectors.cols();
  const bool all = verbose || m <= kShownVectors + 2;
  const long shown = all ? m : kShownVectors;
  std::cout << "\nworst-case error per vector at a (deg, Eq. 30), worst first";
  if (all) {
    std::cout << ":\n";
  } else {
    std::cout << ": " << shown << " of " << m << " (--verbose or --json for all)\n";
  }
  const std::vector<long> order = by_decreasing_error(r.worst_case_errors_deg);
  for (long k = 0; k < shown; ++k) {
    const long v = order[static_cast<std::size_t>(k)];
    std::cout << "  " << report.vector_label(v) << "  "
              << format_number(r.worst_case_errors_deg(v), 6) << "\n";
  }
}

void print_swaps(const report::LayoutReport& report) {
  const sdp::LayoutAnalysis& r = report.analysis;
  const long m = report.data.vectors.cols();
  const bool all_zero = std::all_of(r.swaps.begin(), r.swaps.end(), [](const SwapError& s) {
    return !s.ambiguous && s.error_deg <= kZeroSwapDeg;
  });
  if (all_zero) {
    std::cout << "\nswap sensitivity (Prop. 2): 0 deg for every one of the " << m * (m - 1) / 2
              << " pairs:\n  swapping the measurements of any two data vectors leaves Theorem "
                 "1's noise-free rotation unchanged\n";
    return;
  }
  std::cout << "\nswap sensitivity (Prop. 2), worst pairs (rotation error when two measurements "
               "are swapped):\n";
  for (const SwapError& s : r.swaps) {
    std::cout << "  " << report.vector_label(s.i) << " <-> " << report.vector_label(s.j) << "  "
              << format_number(s.error_deg, 6) << " deg"
              << (s.ambiguous ? "  (ambiguous: the swapped optimum is not unique)" : "") << "\n";
  }
}

std::string paper_lmi_line(const sdp::LayoutAnalysis& r) {
  using Status = sdp::CellViewpoint::Status;
  switch (r.paper_lmi.status) {
    case Status::kOk:
      return "pbar " + format_number(r.paper_lmi.pbar_at, 6) + " at " +
             format_vector(r.paper_lmi.viewpoint) + "  (one sign cell only; >= the global value)";
    case Status::kEmptyCell:
      return "empty_cell: its sign cell holds no viewpoint with every a.n_i > 0, so it gives no "
             "answer";
    case Status::kSolverFailed:
      break;
  }
  return std::string(sdp::to_string(r.paper_lmi.status)) + ": the SDP gave no solution";
}

std::string pair_label(const report::LayoutReport& report, const std::pair<int, int>& p) {
  return report.entry_label(p.first) + "-" + report.entry_label(p.second);
}

std::string difference_text(const report::LayoutReport& report,
                            const tracker::DistanceDifference& d) {
  if (!std::isfinite(d.value)) return "none (one pair)";
  return format_number(d.value, 4) + " (" + pair_label(report, d.pair_a) + " vs " +
         pair_label(report, d.pair_b) + ")";
}

// One line: docs/math.md §24 (ART's distance rule, the closest markers, NDI's mirror rule, the
// worst single loss).
std::string identification_line(const report::LayoutReport& report) {
  const tracker::IdentificationMargins& m = *report.identification;
  const tracker::DropoutDifference& worst =
      m.under_dropout[static_cast<std::size_t>(m.worst_under_dropout)];
  std::string mirror = m.mirror.own_mirror ? "0 (its own mirror)" : format_number(m.mirror.rms, 4);
  if (!m.mirror.certified && !m.mirror.own_mirror) {
    mirror = "in [" + format_number(m.mirror.rms_lower, 4) + ", " + format_number(m.mirror.rms, 4) +
             "] (search budget spent)";
  }
  return "distances differ by " + difference_text(report, m.distance_difference) + ", markers " +
         format_number(m.separation.value, 4) + " apart, mirror RMS " + mirror +
         ", one lost: " + difference_text(report, worst.difference) + " without " +
         report.entry_label(worst.lost);
}

void print_report(const AnalyzeArgs& args, const report::LayoutReport& report) {
  const Layout& layout = report.layout;
  const sdp::LayoutAnalysis& r = report.analysis;
  std::cout << "vantage analyze: " << (layout.name.empty() ? args.file : layout.name) << "\n"
            << "  " << to_string(layout.mode) << " mode, " << layout.entries.cols() << " "
            << to_string(layout.mode) << " -> " << report.data.vectors.cols() << " data vectors\n\n"
            << report.brief_report();
  print_vectors(report, args.verbose);
  print_swaps(report);
  std::cout << "\nt = min_i |a.n_i|      " << format_number(r.t, 9) << "\n"
            << "paper's single LMI     " << paper_lmi_line(r) << "\n"
            << "cross-check            ";
  if (r.crosscheck.ran) {
    std::cout << r.crosscheck.method << " t " << format_number(r.crosscheck.t, 9)
              << (r.crosscheck.agrees ? "  agrees" : "  DISAGREES") << "\n";
    if (!r.crosscheck.samples_cover_cells) {
      std::cout << "                       (" << r.crosscheck.samples << " samples "
                << format_number(r.crosscheck.sample_spacing, 3)
                << " rad apart, wider than the optimal cell: other cells only spot-checked)\n";
    }
  } else {
    std::cout << "skipped ("
              << (args.crosscheck ? r.crosscheck.skipped : std::string("--no-crosscheck")) << ")\n";
  }
  if (report.identification) {
    std::cout << "identification         " << identification_line(report) << "\n";
  }
}

void print_dropout(const report::LayoutReport& report) {
  const report::DropoutAnalysis& dropout = *report.dropout;
  std::cout << "\ndropout: the layout without one "
            << (report.layout.mode == LayoutMode::kPoints ? "marker" : "vector")
            << ", most harmful first (pbar_min, max worst-case error):\n";
  for (int k : dropout.by_harm) {
    const report::DropoutEntry& e = dropout.entries[k];
    std::cout << "  without " << report.entry_label(e.index) << "  pbar_min "
              << format_number(e.worst.pbar_min, 6) << "  "
              << format_number(e.worst.max_worst_case_error_deg, 6) << " deg"
              << (e.worst.certified ? "" : "  (NOT certified)") << "\n";
  }
  if (!report.visibility || report.visibility->dropout.empty()) return;
  const visibility::VisibilityReport& v = *report.visibility;
  std::cout << "\ndropout on its body, most harmful first (max worst-case error, trackable):\n";
  for (int k : v.dropout_by_harm) {
    const visibility::VisibilityDropoutEntry& e = v.dropout[static_cast<std::size_t>(k)];
    std::cout << "  without " << report.entry_label(e.lost) << "  ";
    if (e.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
      std::cout << "untrackable";
    } else {
      std::cout << format_number(e.max_worst_case_error_deg, 6) << " deg";
    }
    std::cout << "  trackable " << format_number(100.0 * e.trackable_fraction, 4) << " %"
              << (e.status == visibility::VisibilityWorstViewpoint::Status::kNotCertified
                      ? "  (NOT certified)"
                      : "")
              << "\n";
  }
}

// Markers far from the body's surface: the mesh may not be their body (or not in their units).
std::string off_body_warning(const report::LayoutReport& report) {
  const visibility::VisibilityReport& v = *report.visibility;
  std::string names;
  double farthest = 0.0;
  for (int i : v.off_body) {
    names += (names.empty() ? "" : ", ") + report.entry_label(i);
    farthest = std::max(farthest, v.distance_to_body[static_cast<std::size_t>(i)]);
  }
  return "visibility.body: " + std::to_string(v.off_body.size()) +
         " marker(s) lie off the "
         "body's surface (" +
         names + "; the farthest " + format_number(farthest, 4) + " away, more than " +
         format_number(100 * visibility::VisibilityReport::kOffSurface, 2) +
         " % of the body's size): is the mesh the markers' body, in their units and frame?";
}

// Markers whose cones face the workspace but which the body hides from every lattice direction
// there (docs/math.md §20, "Markers the body hides").
std::string hidden_warning(const report::LayoutReport& report) {
  const visibility::VisibilityReport& v = *report.visibility;
  std::string names;
  for (int i : v.hidden_by_body) names += (names.empty() ? "" : ", ") + report.entry_label(i);
  return "visibility.body: " + std::to_string(v.hidden_by_body.size()) +
         " marker(s) face the workspace but the body hides them from all " +
         std::to_string(v.coverage.samples) + " lattice directions of the workspace (" + names +
         "): inside the body, or just under its surface?";
}

// The report's JSON, with "sensor" last when the layout names one.
std::string analyze_json(const report::LayoutReport& report,
                         const std::optional<sensor_json::Evaluation>& sensor) {
  if (!sensor) return report::to_json(report);
  sensor_json::Json out = sensor_json::Json::parse(report::to_json(report));
  out["sensor"] = sensor_json::to_json(*sensor);
  return out.dump(2, ' ', false, sensor_json::Json::error_handler_t::replace);
}

int run_analyze(const AnalyzeArgs& args) {
  if (args.swaps < 1) throw InvalidArgument("--swaps", "must be >= 1");
  const Layout layout = args.input.read(args.file, args.allow_large);
  check_limit(args.file + ": data vectors", data_vector_count(layout), kMaxAnalyzeVectors,
              "analyze", args.allow_large);
  if (args.dropout) {
    check_limit(args.file + ": data vectors with --dropout", data_vector_count(layout),
                kMaxDropoutVectors, "analyze --dropout", args.allow_large);
  }
  report::LayoutReportOptions options;
  // CLI11 has checked the name (IsMember).
  options.pair_weighting =
      parse_pair_weighting(args.pair_weighting).value_or(PairWeighting::kGeometricMean);
  options.analysis.swap_count = args.swaps;
  options.analysis.run_crosscheck = args.crosscheck;
  options.dropout = args.dropout;
  report::LayoutReport report;
  std::optional<sensor_json::Evaluation> sensor;
  {
    Progress progress("analyze", !args.json && !args.quiet);  // cleared before the report
    options.analysis.progress = progress.callback();
    report = against_source(args.file, [&] { return report::analyze_layout(layout, options); });
    if (layout.sensor) {
      if (const auto stage = progress.callback()) stage("sensor");
      sensor = against_source(args.file, [&] { return sensor_json::evaluate(layout, 0); });
    }
  }
  if (report.mesh) {
    const std::string name = std::filesystem::path(layout.visibility->body->source).filename();
    const std::string warning = report.mesh->warning(name);
    if (!warning.empty()) std::cerr << "vantage: warning: " << warning << std::endl;
  }
  if (report.visibility && !report.visibility->off_body.empty()) {
    std::cerr << "vantage: warning: " << off_body_warning(report) << std::endl;
  }
  if (report.visibility && !report.visibility->hidden_by_body.empty()) {
    std::cerr << "vantage: warning: " << hidden_warning(report) << std::endl;
  }
  if (args.json) {
    std::cout << analyze_json(report, sensor) << std::endl;
  } else {
    print_report(args, report);
    if (sensor) std::cout << sensor_json::to_text(*sensor);
    if (report.dropout) print_dropout(report);
  }
  if (!report.is_usable()) {
    std::cerr << "vantage: warning: " << report.message() << std::endl;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command add_analyze_command(CLI::App& root) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* sub = root.add_subcommand(
      "analyze",
      "Worst viewpoint of a layout (Theorem 6, global over all sign cells, certified), p-bar_min, "
      "worst-case errors (Eq. 30), the paper's single LMI, NLopt cross-check, swap sensitivity");
  sub->add_option("LAYOUT", args->file, "layout JSON file (vectors or points)")->required();
  args->input.add_options(sub);
  sub->add_option("--swaps", args->swaps, "number of worst swap pairs to report (Prop. 2)")
      ->capture_default_str();
  sub->add_option("--pair-weighting", args->pair_weighting,
                  "point mode: weight of the free vector z_j - z_i, geometric = sqrt(w_i w_j) or "
                  "arithmetic = (w_i + w_j)/2")
      ->check(CLI::IsMember({"geometric", "arithmetic"}))
      ->capture_default_str();
  sub->add_flag("!--no-crosscheck", args->crosscheck, "skip the NLopt cross-check");
  sub->add_flag("--verbose", args->verbose,
                "list the worst-case error of every data vector (default: the worst 5)");
  add_allow_large_flag(sub, args->allow_large);
  sub->add_flag("--quiet", args->quiet, "no progress line on stderr (shown only on a terminal)");
  sub->add_flag("--dropout", args->dropout,
                "also analyse the layout without each marker (point mode) or vector: "
                "which one can it least afford to lose");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_analyze(*args); }};
}

}  // namespace vantage::cli

// `vantage analyze LAYOUT [--json]`: the worst viewpoint of a layout (Theorem 6, global and
// certified), p-bar_min, the worst-case errors of Eq. (30), the paper's single LMI beside it, the
// NLopt cross-check and the swap sensitivity of Prop. 2.

#include <cmath>
#include <iostream>
#include <memory>

#include "command.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/design/augment.h"
#include "vantage/io/layout_file.h"
#include "vantage/sdp/dropout.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::cli {

namespace {

struct AnalyzeArgs {
  std::string file;
  std::string pair_weighting = "geometric";
  int swaps = 5;
  bool crosscheck = true;
  bool dropout = false;
  bool json = false;
};

Json viewpoints_json(const std::vector<Eigen::Vector3d>& viewpoints) {
  Json list = Json::array();
  for (const Eigen::Vector3d& a : viewpoints) list.push_back(json_list(a));
  return list;
}

/// "v3" for a vector, "p2-p7" for the free vector from marker 2 to marker 7.
std::string vector_label(const DataVectors& data, int k) {
  if (data.pairs.empty()) return "v" + std::to_string(k);
  return "p" + std::to_string(data.pairs[k].first) + "-p" + std::to_string(data.pairs[k].second);
}

/// "p3" for marker 3 (point mode), "v3" for vector 3.
std::string entry_label(const Layout& layout, int k) {
  return (layout.mode == LayoutMode::kPoints ? "p" : "v") + std::to_string(k);
}

Json dropout_json(const sdp::DropoutAnalysis& dropout) {
  Json list = Json::array();
  for (const sdp::DropoutEntry& e : dropout.entries) {
    list.push_back({{"index", e.index},
                    {"pbar_min", e.pbar_min},
                    {"max_worst_case_error_deg", e.max_worst_case_error_deg},
                    {"worst_viewpoint", json_list(e.worst_viewpoint)},
                    {"n_vectors", e.n_vectors},
                    {"certified", e.certified}});
  }
  return list;
}

void print_dropout(const Layout& layout, const sdp::DropoutAnalysis& dropout) {
  std::cout << "\ndropout: the layout without one "
            << (layout.mode == LayoutMode::kPoints ? "marker" : "vector")
            << ", most harmful first (pbar_min, max worst-case error):\n";
  for (int k : dropout.by_harm) {
    const sdp::DropoutEntry& e = dropout.entries[k];
    std::cout << "  without " << entry_label(layout, e.index) << "  pbar_min "
              << format_number(e.pbar_min, 6) << "  "
              << format_number(e.max_worst_case_error_deg, 6) << " deg"
              << (e.certified ? "" : "  (NOT certified)") << "\n";
  }
}

int run_analyze(const AnalyzeArgs& args) {
  if (args.swaps < 1) throw InvalidArgument("--swaps: must be >= 1");
  const Layout layout = io::read_layout(args.file);
  const DataVectors data =
      data_vectors(layout, args.pair_weighting == "arithmetic" ? PairWeighting::kArithmeticMean
                                                               : PairWeighting::kGeometricMean);
  sdp::LayoutAnalysisOptions options;
  options.swap_count = args.swaps;
  options.run_crosscheck = args.crosscheck;
  const sdp::LayoutAnalysis report = against_source(
      args.file, [&] { return sdp::analyze_vectors(data.vectors, data.weights, options); });
  const long m = data.vectors.cols();
  const double ceiling = design::pbar_ceiling(static_cast<int>(m));
  sdp::DropoutAnalysis dropout;
  if (args.dropout) dropout = sdp::dropout_analysis(layout);
  const bool trusted =
      report.solver.status == "certified" && (!args.crosscheck || report.crosscheck.agrees) &&
      (!args.dropout || dropout.status == sdp::DropoutAnalysis::Status::kCertified);

  if (args.json) {
    Json out;
    out["name"] = layout.name;
    out["mode"] = to_string(layout.mode);
    out["n_vectors"] = m;
    out["worst_viewpoint"] = json_list(report.worst_viewpoint);
    out["worst_viewpoints"] = viewpoints_json(report.worst_viewpoints);
    out["t"] = report.t;
    out["pbar_min"] = report.pbar_min;
    out["ceiling"] = ceiling;
    out["worst_case_errors_deg"] = json_list(report.worst_case_errors_deg);
    out["max_worst_case_error_deg"] = report.max_worst_case_error_deg;
    out["certificate"] = {{"t_upper", report.certificate.t_upper},
                          {"t_lower", report.certificate.t_lower},
                          {"certified", report.certificate.certified}};
    out["paper_lmi"] = {{"viewpoint", json_list(report.paper_lmi.viewpoint)},
                        {"t", report.paper_lmi.t},
                        {"pbar", report.paper_lmi.pbar},
                        {"status", report.paper_lmi.status}};
    out["crosscheck"] = {{"method", report.crosscheck.method},
                         {"t", report.crosscheck.t},
                         {"agrees", report.crosscheck.agrees}};
    Json swaps = Json::array();
    for (const SwapError& s : report.swaps) {
      Json swap = {{"i", s.i}, {"j", s.j}, {"error_deg", s.error_deg}, {"ambiguous", s.ambiguous}};
      if (!data.pairs.empty()) {
        swap["pair_i"] = {data.pairs[s.i].first, data.pairs[s.i].second};
        swap["pair_j"] = {data.pairs[s.j].first, data.pairs[s.j].second};
      }
      swaps.push_back(swap);
    }
    out["swaps"] = swaps;
    out["solver"] = {{"backend", report.solver.backend},
                     {"status", report.solver.status},
                     {"cells_solved", report.solver.cells_solved},
                     {"patches", report.solver.patches},
                     {"sdp_status", report.solver.sdp_status}};
    if (args.dropout) out["dropout"] = dropout_json(dropout);
    if (!report.message.empty()) out["message"] = report.message;
    print_json(out);
  } else {
    std::cout << "vantage analyze: " << (layout.name.empty() ? args.file : layout.name) << "\n"
              << "  " << to_string(layout.mode) << " mode, " << layout.entries.cols() << " "
              << to_string(layout.mode) << " -> " << m << " data vectors\n\n"
              << "worst viewpoint a      " << format_vector(report.worst_viewpoint) << "\n";
    for (std::size_t k = 1; k < report.worst_viewpoints.size(); ++k) {
      std::cout << "  also (tie)           " << format_vector(report.worst_viewpoints[k]) << "\n";
    }
    std::cout << "t = min_i |a.n_i|      " << format_number(report.t, 9) << "\n"
              << "pbar_min = sqrt(1-t^2) " << format_number(report.pbar_min, 9)
              << "   (ceiling for " << m << " vectors: " << format_number(ceiling, 6) << ")\n"
              << "max worst-case error   " << format_number(report.max_worst_case_error_deg, 6)
              << " deg (Eq. 30)\n"
              << "certificate            t in [" << format_number(report.certificate.t_lower, 12)
              << ", " << format_number(report.certificate.t_upper, 12) << "], "
              << report.solver.status << ", " << report.solver.cells_solved << " cells solved, "
              << "confirmed on " << report.solver.backend << " (" << report.solver.sdp_status
              << ")\n"
              << "paper's single LMI     pbar " << format_number(report.paper_lmi.pbar, 6) << " at "
              << format_vector(report.paper_lmi.viewpoint)
              << "  (one sign cell only; >= the global value)\n"
              << "cross-check            " << report.crosscheck.method << " t "
              << format_number(report.crosscheck.t, 9)
              << (report.crosscheck.agrees ? "  agrees" : "  DISAGREES") << "\n\n"
              << "worst-case error per vector at a (deg, Eq. 30):\n";
    for (long k = 0; k < m; ++k) {
      std::cout << "  " << vector_label(data, static_cast<int>(k)) << "  "
                << format_number(report.worst_case_errors_deg(k), 6) << "\n";
    }
    std::cout << "\nswap sensitivity (Prop. 2), worst pairs:\n";
    for (const SwapError& s : report.swaps) {
      std::cout << "  " << vector_label(data, s.i) << " <-> " << vector_label(data, s.j) << "  "
                << format_number(s.error_deg, 6) << " deg"
                << (s.ambiguous ? "  (ambiguous: the swapped optimum is not unique)" : "") << "\n";
    }
    if (args.dropout) print_dropout(layout, dropout);
  }
  if (!trusted) {
    std::string message = report.message.empty() ? "result not certified" : report.message;
    if (args.dropout && !dropout.message.empty()) message += "; dropout: " + dropout.message;
    std::cerr << "vantage: warning: " << message << std::endl;
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
  sub->add_option("--swaps", args->swaps, "number of worst swap pairs to report (Prop. 2)")
      ->capture_default_str();
  sub->add_option("--pair-weighting", args->pair_weighting,
                  "point mode: weight of the free vector z_j - z_i, geometric = sqrt(w_i w_j) or "
                  "arithmetic = (w_i + w_j)/2")
      ->check(CLI::IsMember({"geometric", "arithmetic"}))
      ->capture_default_str();
  sub->add_flag("!--no-crosscheck", args->crosscheck, "skip the NLopt cross-check");
  sub->add_flag("--dropout", args->dropout,
                "also analyse the layout without each marker (point mode) or vector: "
                "which one can it least afford to lose");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_analyze(*args); }};
}

}  // namespace vantage::cli

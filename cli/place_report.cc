// The placed layout and the reports of `vantage place` (docs/math.md §21).

#include "place_report.h"

#include <cmath>
#include <iostream>

namespace vantage::cli {
namespace {

double error_deg(double pbar_min) {
  return std::asin(std::sqrt(std::max(0.0, 1.0 - pbar_min * pbar_min))) * kDegreesPerRadian;
}

std::string percent(double fraction) { return format_number(100.0 * fraction, 4) + " %"; }

// Site s as the JSON names it: its index among the candidates, or -1 for a kept marker.
int candidate_index(int s, int n_candidates) { return s < n_candidates ? s : -1; }

Json steps_json(const design::PlacementResult& r) {
  Json steps = Json::array();
  for (const design::PlacementStep& s : r.steps) {
    steps.push_back({{"k", s.k},
                     {"added", s.added},
                     {"coverage", s.value.coverage},
                     {"pbar_min", s.value.pbar_min}});
  }
  return steps;
}

}  // namespace

PlacedLayout placed_layout(const PlaceArgs& args, const Layout& sites, int n_candidates,
                           const design::PlacementResult& result) {
  PlacedLayout out;
  for (Eigen::Index i = 0; i < sites.entries.cols(); ++i) {
    out.site_names.push_back(design::site_name(sites, static_cast<int>(i)));
  }
  design::PlacedLayoutRecord record;
  record.sites = args.sites.empty() ? args.body : args.sites;
  record.n_candidates = n_candidates;
  record.robust_dropout = args.robust_dropout;
  out.layout = design::placed_layout(sites, result, record);
  sdp::LayoutReportOptions options;
  options.visibility.search.certificate_tolerance = args.certificate_tolerance;
  options.visibility.threads = args.threads;
  out.report = sdp::analyze_layout(out.layout, options);
  return out;
}

std::string failure_message(const design::PlacementResult& result, const PlacedLayout& placed) {
  if (result.status == design::PlacementResult::Status::kIncomplete) {
    std::string message = result.message + ": the best covers " + percent(result.value.coverage) +
                          " of the workspace";
    if (result.covering_markers) {
      message += "; greedy by coverage covers it with " + std::to_string(*result.covering_markers) +
                 " markers";
    } else {
      message += "; all sites together cover " + percent(result.all_sites_coverage);
    }
    return message;
  }
  const sdp::VisibilityReport& v = *placed.report.visibility;
  return "the placed layout's analysis is not certified: " + v.message();
}

Json place_json(const PlaceArgs& args, int n_candidates, int drawn,
                const design::PlacementResult& r, const PlacedLayout& placed, bool written) {
  Json out;
  out["sites"] = args.sites.empty() ? args.body : args.sites;
  out["status"] = design::to_string(r.status);
  Json chosen = Json::array();
  Json kept = Json::array();
  for (int s : r.chosen) {
    if (s < n_candidates) {
      chosen.push_back(s);
    } else {
      kept.push_back(placed.site_names[static_cast<std::size_t>(s)]);
    }
  }
  out["chosen"] = chosen;
  out["kept"] = kept;
  out["n_candidates"] = n_candidates;
  if (args.sites.empty()) out["drawn"] = drawn;
  out["markers"] = args.markers;
  out["search"] = r.search;
  const Json analysis = Json::parse(sdp::to_json(placed.report));
  out["visibility"] = analysis.contains("visibility") ? analysis["visibility"] : Json();
  out["coverage"] = placed.report.visibility->coverage.trackable_fraction;
  out["pbar_min"] = placed.report.visibility->worst.pbar_min;
  out["random_baseline"] = {{"trials", r.random_baseline.trials},
                            {"complete", r.random_baseline.complete},
                            {"best_coverage", r.random_baseline.best_coverage},
                            {"best_pbar_min", r.random_baseline.best_pbar_min},
                            {"median_pbar_min", r.random_baseline.median_pbar_min}};
  out["steps"] = steps_json(r);
  if (r.robust) {
    out["robust"] = {
        {"pbar_min", r.robust->pbar_min},
        {"worst_lost_marker", candidate_index(r.robust->worst_lost_marker, n_candidates)},
        {"worst_lost_name",
         placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]},
        {"coverage", r.robust->coverage}};
  }
  out["swaps"] = r.swaps;
  out["evaluations"] = r.evaluations;
  if (r.search == "exhaustive") out["subsets"] = r.subsets;
  if (r.status == design::PlacementResult::Status::kIncomplete) {
    out["covering_markers"] = r.covering_markers ? Json(*r.covering_markers) : Json();
    out["all_sites_coverage"] = r.all_sites_coverage;
  }
  out["written"] = written ? Json(args.out) : Json();
  return out;
}

void print_place_report(const PlaceArgs& args, int n_candidates, int drawn,
                        const design::PlacementResult& r, const PlacedLayout& placed,
                        bool written) {
  const sdp::VisibilityReport& v = *placed.report.visibility;
  std::cout << "vantage place: " << args.markers << " markers on "
            << (args.sites.empty() ? args.body : args.sites) << "\n  " << n_candidates
            << " candidate sites";
  if (args.sites.empty())
    std::cout << " (" << drawn << " drawn area-uniformly, seed " << args.seed << ")";
  std::cout << ", min_visible " << v.min_visible << ", " << (v.with_body ? "cone+mesh" : "cone")
            << " visibility, search " << r.search << "\n\n";
  if (!r.steps.empty()) {
    std::cout << "greedy construction (k markers: coverage, certified p-bar_min, worst error):\n";
    for (const design::PlacementStep& s : r.steps) {
      std::cout << "  k " << s.k << "  "
                << (s.added >= 0 ? placed.site_names[static_cast<std::size_t>(s.added)]
                                 : std::string("(kept)"))
                << "  " << percent(s.value.coverage) << "  ";
      if (s.value.status == sdp::VisibilityWorstViewpoint::Status::kUntrackable) {
        std::cout << "untrackable\n";
      } else {
        std::cout << format_number(s.value.pbar_min, 6) << "  "
                  << format_number(error_deg(s.value.pbar_min), 4) << " deg\n";
      }
    }
    std::cout << "swaps after the greedy: " << r.swaps << "\n\n";
  } else {
    std::cout << "exhaustive over " << r.subsets << " feasible subsets\n\n";
  }
  const design::RandomBaseline& b = r.random_baseline;
  std::cout << "random baseline: " << b.trials << " feasible subsets, " << b.complete
            << " trackable everywhere; best p-bar_min " << format_number(b.best_pbar_min, 6)
            << " (coverage " << percent(b.best_coverage) << "), median "
            << format_number(b.median_pbar_min, 6) << "\n";
  std::cout << "chosen:";
  for (int s : r.chosen) std::cout << " " << placed.site_names[static_cast<std::size_t>(s)];
  std::cout << "\n\non its body (the placed layout's analysis, as vantage analyze):\n"
            << "  coverage        " << percent(v.coverage.trackable_fraction) << "\n"
            << "  p-bar_min       " << format_number(v.worst.pbar_min, 6) << "\n"
            << "  worst error     " << format_number(v.max_worst_case_error_deg, 6) << " deg at "
            << format_vector(v.worst.viewpoint) << "\n"
            << "  certificate     " << sdp::to_string(v.worst.status) << " (t in ["
            << format_number(v.worst.t_lower, 9) << ", " << format_number(v.worst.t_upper, 9)
            << "])\n";
  if (r.robust) {
    std::cout << "  one marker lost: p-bar_min " << format_number(r.robust->pbar_min, 6) << " ("
              << format_number(error_deg(r.robust->pbar_min), 4) << " deg) without "
              << placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]
              << ", coverage at least " << percent(r.robust->coverage) << "\n";
  }
  if (written) std::cout << "written: " << args.out << "\n";
}

}  // namespace vantage::cli

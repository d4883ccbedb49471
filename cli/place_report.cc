// The placed layout and the reports of `vantage place` (docs/math.md §21).

#include "place_report.h"

#include <cmath>
#include <iostream>
#include <sstream>

namespace vantage::cli {
namespace {

double error_deg(double pbar_min) {
  return std::asin(std::sqrt(std::max(0.0, 1.0 - pbar_min * pbar_min))) * kDegreesPerRadian;
}

std::string percent(double fraction) { return format_number(100.0 * fraction, 4) + " %"; }

// X,Y,Z with every digit, as --aim reads it back.
std::string aim_option(const Eigen::Vector3d& aim) {
  std::ostringstream out;
  out.precision(17);
  out << aim.x() << "," << aim.y() << "," << aim.z();
  return out.str();
}

// A step's or a baseline's objective value with its unit.
std::string objective_text(const place_json::PlacedLayout& placed, double value) {
  // +inf: no complete choice (below --min-coverage; for the median, most of the trials).
  if (!std::isfinite(value)) return "incomplete";
  if (placed.crb && value > camera::PoseCrbAt::kMaxRotRmsDeg) {
    return "unbounded (first-order rot_rms past the 45 deg limit)";
  }
  return format_number(value, 6) + (placed.tre ? "" : " deg");
}

// The camera objective's lines: what `vantage crb` reports of the placed layout.
void print_camera_objective(const PlaceArgs& args, const place_json::Outcome& outcome) {
  const camera::PoseCrbMap& map = *outcome.placed.crb;
  const camera::PoseCrbOptions& c = *outcome.placed.camera;
  const std::vector<sensor_json::ApproachStep>& approach = outcome.placed.sensor->approach;
  std::cout << "\nthe camera objective (the placed layout's vantage crb --distance "
            << (approach.empty() ? format_number(c.distance, 9) : std::string("D")) << " --focal "
            << format_number(c.focal_length, 9) << " --noise-px " << format_number(c.noise_px, 9)
            << " --samples " << c.samples << " --aim " << aim_option(*c.aim) << "):\n";
  if (!approach.empty()) {
    // The approach: each distance's statistic; the worst decides and is detailed below.
    for (const sensor_json::ApproachStep& step : approach) {
      std::cout << "  D " << format_number(step.distance, 9) << ": ";
      if (step.map.status != camera::PoseCrbMap::Status::kOk) {
        std::cout << "not trackable: " << camera::untrackable_reason(step.map, step.distance);
      } else {
        std::cout << args.statistic << " rot_rms "
                  << (std::isfinite(step.value)
                          ? objective_text(outcome.placed, step.value)
                          : std::string("unbounded (first-order rot_rms past the 45 deg limit)"));
      }
      std::cout << (step.distance == c.distance ? "  (decides)" : "") << "\n";
    }
    std::cout << "  at D " << format_number(c.distance, 9) << ":\n";
  }
  if (map.status != camera::PoseCrbMap::Status::kOk) {
    std::cout << "  not trackable: " << camera::untrackable_reason(map, c.distance) << "\n";
    return;
  }
  const std::string unbounded = "unbounded (first-order rot_rms past the 45 deg limit)";
  std::cout << "  " << args.statistic << " rot_rms   "
            << (std::isfinite(outcome.objective_value)
                    ? format_number(outcome.objective_value, 6) + " deg"
                    : unbounded)
            << " (the search's lattice value "
            << objective_text(outcome.placed, outcome.result.value.objective) << ")\n"
            << "  worst           "
            << (map.worst.unbounded ? unbounded
                                    : format_number(map.worst.rot_rms_deg, 6) + " deg, trans_rms " +
                                          format_number(map.worst.trans_rms, 6))
            << " at " << format_vector(map.worst.direction) << "\n"
            << "  p50 / p95 / p99 " << format_number(map.percentiles.p50, 6) << " / "
            << format_number(map.percentiles.p95, 6) << " / "
            << format_number(map.percentiles.p99, 6) << " deg\n"
            << "  trackable       " << percent(map.trackable_fraction) << " of the workspace"
            << (map.unbounded_fraction > 0.0 ? ", unbounded " + percent(map.unbounded_fraction) +
                                                   " (first-order rot_rms "
                                                   "above 45 deg or F singular: no figure)"
                                             : std::string())
            << "\n";
}

// The tracker objective's lines: what `vantage tre` reports of the placed layout.
void print_tracker_objective(const place_json::Outcome& outcome) {
  const tracker::TreReport& tre = *outcome.placed.tre;
  std::cout << "\nthe tracker objective (the placed layout's vantage tre, FLE ";
  if (tre.fle.from_rms) {
    std::cout << "rms " << format_number(tre.fle.rms(), 9);
  } else {
    std::cout << "sigma " << format_number(tre.fle.sigma_perp, 9) << ","
              << format_number(tre.fle.sigma_axial, 9);
  }
  std::cout << "):\n  worst RMS TRE bound "
            << objective_text(outcome.placed, outcome.objective_value) << " (the search's value "
            << objective_text(outcome.placed, outcome.result.value.objective) << ")\n";
  for (const tracker::TreTargetReport& t : tre.targets) {
    const tracker::TreExtreme& w = t.extremes.worst;
    std::cout << "  target " << format_vector(t.target) << ": ";
    if (w.status == tracker::TreExtreme::Status::kUntracked) {
      std::cout << "untracked\n";
      continue;
    }
    std::cout << "worst " << format_number(w.rms, 6) << " (bound " << format_number(w.rms_bound, 6)
              << ", " << tracker::to_string(w.status) << ") at " << format_vector(w.direction)
              << "\n";
  }
}

// The request: K, the sites and how they were drawn, the markers' shape.
void print_request(const PlaceArgs& args, int n_candidates, int drawn, int excluded,
                   const design::PlacementResult& r, const visibility::VisibilityReport& v) {
  std::cout << "vantage place: " << args.markers << " markers on "
            << (args.sites.empty() ? args.body : args.sites) << "\n  " << n_candidates
            << " candidate sites";
  if (args.sites.empty()) {
    std::cout << " (" << drawn << " drawn area-uniformly";
    if (!args.region.empty()) std::cout << " on " << args.region;
    std::cout << ", seed " << args.seed;
    if (excluded > 0) std::cout << "; " << excluded << " in keep-out volumes dropped";
    std::cout << ")";
  }
  std::cout << ", min_visible " << v.min_visible << ", " << (v.with_body ? "cone+mesh" : "cone")
            << " visibility, search " << r.search << "\n";
  if (args.marker_diameter > 0.0) {
    std::cout << "  spheres of diameter " << format_number(args.marker_diameter, 6)
              << ", centres half of it off the surface; ";
  } else {
    std::cout << "  point markers; ";
  }
  std::cout << "min separation " << format_number(args.separation(), 6) << "\n\n";
}

// The search: the greedy steps, swaps and perturbations (or the exhaustive count), and the random
// baseline.
void print_search(const PlaceArgs& args, const design::PlacementResult& r,
                  const PlacedLayout& placed) {
  if (!r.steps.empty()) {
    std::cout << (placed.crb   ? "greedy construction (k markers: coverage, the objective on the "
                                 "search's lattice):\n"
                  : placed.tre ? "greedy construction (k markers: coverage, worst RMS TRE bound):\n"
                               : "greedy construction (k markers: coverage, certified p-bar_min, "
                                 "worst error):\n");
    for (const design::PlacementStep& s : r.steps) {
      std::cout << "  k " << s.k << "  "
                << (s.added >= 0 ? placed.site_names[static_cast<std::size_t>(s.added)]
                                 : std::string("(kept)"))
                << "  " << percent(s.value.coverage) << "  ";
      if (s.value.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
        std::cout << "untrackable\n";
      } else if (placed.crb || placed.tre) {
        std::cout << objective_text(placed, s.value.objective) << "\n";
      } else {
        std::cout << format_number(s.value.pbar_min, 6) << "  "
                  << format_number(error_deg(s.value.pbar_min), 4) << " deg\n";
      }
    }
    std::cout << "swaps after the greedy: " << r.swaps << "\n";
    if (args.perturbations > 0) {
      std::cout << "perturbation rounds: " << args.perturbations << ", "
                << r.improving_perturbations << " of them improving\n";
    }
    std::cout << "\n";
  } else {
    std::cout << "exhaustive over " << r.subsets << " feasible subsets\n\n";
  }
  const design::RandomBaseline& b = r.random_baseline;
  if (b.trials == 0) {
    std::cout << "random baseline: none (no feasible random subset drawn)\n";
  } else if (placed.crb || placed.tre) {
    std::cout << "random baseline: " << b.trials << " feasible subsets, " << b.complete
              << " complete; best objective " << objective_text(placed, b.best_objective)
              << " (coverage " << percent(b.best_coverage) << "), median "
              << objective_text(placed, b.median_objective) << "\n";
  } else {
    std::cout << "random baseline: " << b.trials << " feasible subsets, " << b.complete
              << " trackable everywhere; best p-bar_min " << format_number(b.best_pbar_min, 6)
              << " (coverage " << percent(b.best_coverage) << "), median "
              << format_number(b.median_pbar_min, 6) << "\n";
  }
}

// The chosen sites and the placed layout's analysis (and its value after a lost marker).
void print_on_its_body(const design::PlacementResult& r, const PlacedLayout& placed,
                       const visibility::VisibilityReport& v) {
  std::cout << "chosen:";
  for (int s : r.chosen) std::cout << " " << placed.site_names[static_cast<std::size_t>(s)];
  std::cout << "\n\non its body (the placed layout's analysis, as vantage analyze):\n"
            << "  coverage        " << percent(v.coverage.trackable_fraction) << "\n"
            << "  p-bar_min       " << format_number(v.worst.pbar_min, 6) << "\n"
            << "  worst error     " << format_number(v.max_worst_case_error_deg, 6) << " deg at "
            << format_vector(v.worst.viewpoint) << "\n"
            << "  certificate     " << v.certificate_status() << " (t in ["
            << format_number(v.worst.t_lower, 9) << ", " << format_number(v.worst.t_upper, 9)
            << "])\n";
  if (r.robust && (placed.crb || placed.tre)) {
    std::cout << "  one marker lost: the objective " << objective_text(placed, r.robust->objective)
              << " on the search's terms without "
              << placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]
              << ", coverage at least " << percent(r.robust->coverage) << "\n";
  } else if (r.robust) {
    std::cout << "  one marker lost: p-bar_min " << format_number(r.robust->pbar_min, 6) << " ("
              << format_number(error_deg(r.robust->pbar_min), 4) << " deg) without "
              << placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]
              << ", coverage at least " << percent(r.robust->coverage) << "\n";
  }
}

}  // namespace

void print_place_report(const PlaceArgs& args, int n_candidates, int drawn, int excluded,
                        const place_json::Outcome& outcome, bool written) {
  const design::PlacementResult& r = outcome.result;
  const PlacedLayout& placed = outcome.placed;
  const visibility::VisibilityReport& v = *placed.report.visibility;
  print_request(args, n_candidates, drawn, excluded, r, v);
  print_search(args, r, placed);
  print_on_its_body(r, placed, v);
  if (placed.crb) print_camera_objective(args, outcome);
  if (placed.tre) print_tracker_objective(outcome);
  if (written) std::cout << "written: " << args.out << "\n";
}

}  // namespace vantage::cli

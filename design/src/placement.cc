// place_markers(): K of N sites on a body (docs/math.md §21).

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "placement_search.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/design/placement.h"

namespace vantage::design {
namespace {

PlacementValue value_of(const internal::Scored& s, int directions, bool affine) {
  PlacementValue out;
  out.coverage = directions == 0 ? 0.0 : static_cast<double>(s.covered) / directions;
  out.objective = s.t;
  if (affine) {
    out.t_upper = s.t;
    out.pbar_min = std::sqrt(std::max(0.0, 1.0 - s.t * s.t));
  }
  out.status = s.status;
  return out;
}

// The worst single loss of `chosen`: its objective and p-bar_min are those of the family of
// single losses that the robust search scores (each S without one marker, every member searched
// to the certificate), so that they are what `vantage analyze --dropout` reports of the placed
// layout; the coverage is the least over the losses.
RobustValue robust_value(internal::PlacementSearch& search, const std::vector<int>& chosen) {
  const internal::Scored s = search.score(chosen);
  RobustValue out;
  out.objective = s.t;
  out.pbar_min = search.affine() ? std::sqrt(std::max(0.0, 1.0 - s.t * s.t)) : 0.0;
  out.worst_lost_marker = s.worst_lost;
  out.coverage = 1.0;
  const int directions = search.coverage().directions();
  for (std::size_t m = 0; m < chosen.size(); ++m) {
    const int covered = search.coverage().key(internal::without_position(chosen, m)).covered;
    out.coverage =
        std::min(out.coverage, directions == 0 ? 0.0 : static_cast<double>(covered) / directions);
  }
  return out;
}

// The iterated local search after the swaps (docs/math.md §21, "Search"): `options.perturbations`
// rounds, each from the best answer so far, of a random perturbation and swaps from it.
internal::Scored perturbed_search(internal::PlacementSearch& search, internal::Scored best,
                                  const PlaceOptions& options, PlacementResult* out) {
  std::seed_seq seeds{options.seed, std::uint64_t{2}};
  std::mt19937_64 engine(seeds);
  for (int round = 0; round < options.perturbations; ++round) {
    const std::optional<internal::Scored> start = search.perturbed(best, &engine);
    if (!start) continue;
    const internal::Scored next = search.swaps(*start, &out->swaps);
    if (search.better(next, best)) {
      best = next;
      ++out->improving_perturbations;
    }
  }
  return best;
}

}  // namespace

double PlacementProblem::least_separation() const {
  return std::max(min_separation, Layout::coincidence_distance(sites.points));
}

void PlacementProblem::validate() const {
  sites.validate();
  const long n = static_cast<long>(sites.points.cols());
  std::vector<int> sorted_keep = keep;
  std::sort(sorted_keep.begin(), sorted_keep.end());
  for (std::size_t k = 0; k < sorted_keep.size(); ++k) {
    if (sorted_keep[k] < 0 || sorted_keep[k] >= n) {
      throw InvalidArgument("keep", "site " + std::to_string(sorted_keep[k]) +
                                        " is not one of the " + std::to_string(n) + " sites");
    }
    if (k > 0 && sorted_keep[k] == sorted_keep[k - 1]) {
      throw InvalidArgument("keep", "site " + std::to_string(sorted_keep[k]) + " is kept twice");
    }
  }
  if (markers > n) {
    throw InvalidArgument("markers",
                          std::to_string(markers) + " exceeds the " + std::to_string(n) + " sites");
  }
  if (markers < sites.min_visible) {
    throw InvalidArgument("markers", "must be at least min_visible (" +
                                         std::to_string(sites.min_visible) + "), got " +
                                         std::to_string(markers));
  }
  if (static_cast<long>(keep.size()) > markers) {
    throw InvalidArgument("markers", "the " + std::to_string(keep.size()) +
                                         " kept markers exceed " + std::to_string(markers));
  }
  if (!(min_separation >= 0.0) || !std::isfinite(min_separation)) {
    throw InvalidArgument("min_separation", "must be a finite number >= 0");
  }
  if (!(min_distance_difference >= 0.0) || !std::isfinite(min_distance_difference)) {
    throw InvalidArgument("min_distance_difference", "must be a finite number >= 0");
  }
  for (std::size_t i = 0; i < keep.size(); ++i) {
    for (std::size_t j = i + 1; j < keep.size(); ++j) {
      const double d = (sites.points.col(keep[i]) - sites.points.col(keep[j])).norm();
      const std::string pair =
          "kept sites " + std::to_string(keep[i]) + " and " + std::to_string(keep[j]);
      if (d < min_separation) throw InvalidArgument("min_separation", pair + " are closer than it");
      if (d < least_separation()) throw InvalidArgument("keep", pair + " coincide");
    }
  }
}

const char* to_string(CrbStatistic statistic) {
  switch (statistic) {
    case CrbStatistic::kWorst:
      return "worst";
    case CrbStatistic::kP95:
      return "p95";
    case CrbStatistic::kMedian:
      return "median";
  }
  return "unknown";
}

std::optional<CrbStatistic> parse_crb_statistic(const std::string& name) {
  for (CrbStatistic s : {CrbStatistic::kWorst, CrbStatistic::kP95, CrbStatistic::kMedian}) {
    if (name == to_string(s)) return s;
  }
  return std::nullopt;
}

bool PlaceOptions::is_valid(std::string* why) const {
  if (!search.is_valid(why)) return false;
  if (min_coverage && !(*min_coverage > 0.0 && *min_coverage <= 1.0)) {
    return vantage::internal::invalid_option(why, "min_coverage", "must be in (0, 1]");
  }
  if (tracker && camera) {
    return vantage::internal::invalid_option(why, "tracker", "goes with no camera objective");
  }
  if (camera) {
    std::string camera_why;
    if (!camera->model_options().is_valid(&camera_why)) {
      return vantage::internal::invalid_option(why, "camera", camera_why);
    }
    if (!camera->crb.aim) {
      return vantage::internal::invalid_option(why, "camera.aim",
                                               "must be given (the point the camera looks at)");
    }
    if (camera->distances.size() > static_cast<std::size_t>(CameraObjective::kMaxDistances)) {
      return vantage::internal::invalid_option(
          why, "camera.distances",
          "at most " + std::to_string(CameraObjective::kMaxDistances) + " distances");
    }
    for (const double d : camera->distances) {
      if (!(d > 0.0) || !std::isfinite(d)) {
        return vantage::internal::invalid_option(why, "camera.distances",
                                                 "must be finite numbers > 0");
      }
    }
    if (vantage::internal::first_repeat(camera->distances) >= 0) {
      return vantage::internal::invalid_option(why, "camera.distances", "a distance repeats");
    }
  }
  if (tracker) {
    if (tracker->targets.empty()) {
      return vantage::internal::invalid_option(why, "tracker.targets", "give at least one");
    }
    for (const Eigen::Vector3d& target : tracker->targets) {
      if (!target.allFinite()) {
        return vantage::internal::invalid_option(why, "tracker.targets", "must be finite");
      }
    }
    std::string tracker_why;
    if (!tracker->fle.is_valid(&tracker_why)) {
      return vantage::internal::invalid_option(why, "tracker.fle", tracker_why);
    }
    if (!tracker->search.is_valid(&tracker_why)) {
      return vantage::internal::invalid_option(why, "tracker.search", tracker_why);
    }
  }
  if (coverage_samples < 100) {
    return vantage::internal::invalid_option(why, "coverage_samples", "must be >= 100");
  }
  if (exhaustive_limit < 0) {
    return vantage::internal::invalid_option(why, "exhaustive_limit", "must be >= 0");
  }
  if (random_trials < 0 || random_trials > PlaceOptions::kMaxRandomTrials) {
    return vantage::internal::invalid_option(
        why, "random_trials",
        "must be in [0, " + std::to_string(PlaceOptions::kMaxRandomTrials) +
            "] (every trial's subset is kept for the median, about 140 bytes each)");
  }
  if (perturbations < 0) {
    return vantage::internal::invalid_option(why, "perturbations", "must be >= 0");
  }
  if (threads < 0) return vantage::internal::invalid_option(why, "threads", "must be >= 0");
  return true;
}

const char* to_string(PlacementResult::Status status) {
  switch (status) {
    case PlacementResult::Status::kComplete:
      return "complete";
    case PlacementResult::Status::kIncomplete:
      return "incomplete";
  }
  return "unknown";
}

PlacementResult place_markers(const PlacementProblem& problem, const PlaceOptions& options) {
  vantage::internal::check_options("options", options);
  problem.validate();
  if (options.robust_dropout && problem.markers <= problem.sites.min_visible) {
    throw InvalidArgument("markers", "robust_dropout needs more markers than min_visible (" +
                                         std::to_string(problem.sites.min_visible) + ")");
  }
  if (options.camera && options.camera->sites.entries.cols() != problem.sites.points.cols()) {
    throw InvalidArgument(
        "camera.sites",
        "must hold the problem's " + std::to_string(problem.sites.points.cols()) + " sites");
  }
  if (options.tracker && problem.markers > TrackerObjective::kMaxMarkers) {
    throw InvalidArgument("markers", "the tracker objective takes at most " +
                                         std::to_string(TrackerObjective::kMaxMarkers) +
                                         " markers (the TRE search's limit), got " +
                                         std::to_string(problem.markers));
  }
  internal::PlacementSearch search(problem, options);
  const int directions = search.coverage().directions();
  PlacementResult out;

  std::optional<internal::Scored> random_best;
  out.random_baseline = search.baseline(&random_best);

  std::optional<internal::Scored> best;
  if (options.exhaustive_limit > 0 &&
      search.subset_count(options.exhaustive_limit) <= options.exhaustive_limit) {
    out.search = "exhaustive";
    best = search.exhaustive(&out.subsets);
  } else {
    out.search = "greedy+swap";
    best = search.greedy(&out.steps);
    if (best) best = search.swaps(*best, &out.swaps);
    // The answer is never worse than the baseline it reports: swaps from its best as well.
    if (random_best && (!best || search.better(*random_best, *best))) {
      const internal::Scored from_random = search.swaps(*random_best, &out.swaps);
      if (!best || search.better(from_random, *best)) best = from_random;
    }
    if (best) best = perturbed_search(search, *best, options, &out);
  }
  if (!best) {
    throw InvalidArgument("min_separation",
                          "no " + std::to_string(problem.markers) +
                              " sites satisfy the separation and distance-difference constraints");
  }
  out.chosen = best->chosen;
  out.value = value_of(*best, directions, search.affine());
  if (options.robust_dropout) out.robust = robust_value(search, out.chosen);
  out.evaluations = search.evaluations();
  out.status = best->covered >= search.required() ? PlacementResult::Status::kComplete
                                                  : PlacementResult::Status::kIncomplete;
  {
    std::vector<int> all(static_cast<std::size_t>(problem.sites.points.cols()));
    for (std::size_t s = 0; s < all.size(); ++s) all[s] = static_cast<int>(s);
    out.all_sites_coverage =
        directions == 0 ? 0.0
                        : static_cast<double>(search.coverage().key(all).covered) / directions;
  }
  if (out.status == PlacementResult::Status::kIncomplete) {
    out.covering_markers = search.covering_markers();
    // An approach samples (direction, distance) pairs: docs/math.md §21, "An approach".
    const bool approach = options.camera && options.camera->distances.size() > 1;
    out.message = "no placement of " + std::to_string(problem.markers) + " markers found makes " +
                  std::to_string(search.required()) + " of the " + std::to_string(directions) +
                  (approach ? " (workspace direction, distance) samples of the approach trackable"
                            : " workspace directions trackable");
  }
  return out;
}

}  // namespace vantage::design

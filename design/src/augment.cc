// augment_layout(): the greedy steps (designer.h), then the direct optimiser for comparison
// (direct_search.h). docs/math.md §18.

#include "vantage/design/augment.h"

#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

#include "addition_space.h"
#include "designer.h"
#include "direct_search.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/tracker/identification.h"

namespace vantage::design {
namespace {

std::string format_difference(double d) {
  std::ostringstream out;
  out << d;
  return out.str();
}

// The constraint applies to a point layout whose own markers keep it.
void check_distance_difference(const Layout& layout, double gap) {
  if (!(gap > 0.0)) return;
  if (layout.mode != LayoutMode::kPoints) {
    vantage::internal::fail("min_distance_difference", "needs a point layout (markers)");
  }
  const tracker::DistanceDifference d = tracker::min_distance_difference(layout.entries);
  if (d.value < gap) {
    vantage::internal::fail("min_distance_difference",
                            "the layout's own distances " + layout.entry_name(d.pair_a.first) +
                                "-" + layout.entry_name(d.pair_a.second) + " and " +
                                layout.entry_name(d.pair_b.first) + "-" +
                                layout.entry_name(d.pair_b.second) + " differ by only " +
                                format_difference(d.value) + " < " + format_difference(gap));
  }
}

// Point mode: a candidate within the augmenter's separation (internal::kMinSeparation of the
// search box's largest side) of a marker or of another candidate would add a zero free vector.
void check_point_candidates(const Layout& layout, double margin) {
  if (layout.mode != LayoutMode::kPoints || layout.candidates.cols() == 0) return;
  const Eigen::Vector3d lo = layout.entries.rowwise().minCoeff();
  const Eigen::Vector3d hi = layout.entries.rowwise().maxCoeff();
  const double min_distance =
      internal::kMinSeparation * (1.0 + 2.0 * margin) * (hi - lo).maxCoeff();
  for (Eigen::Index c = 0; c < layout.candidates.cols(); ++c) {
    const Eigen::Vector3d x = layout.candidates.col(c);
    for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
      if ((x - layout.entries.col(i)).norm() <= min_distance) {
        throw InvalidArgument("candidates", static_cast<long>(c), "coincides with", "points",
                              static_cast<long>(i));
      }
    }
    for (Eigen::Index d = 0; d < c; ++d) {
      if ((x - layout.candidates.col(d)).norm() <= min_distance) {
        throw InvalidArgument("candidates", static_cast<long>(c), "coincides with", "candidates",
                              static_cast<long>(d));
      }
    }
  }
}

}  // namespace

const char* to_string(DirectResult::Status status) {
  return status == DirectResult::Status::kOk ? "ok" : "skipped";
}

const char* to_string(AugmentResult::Status status) {
  switch (status) {
    case AugmentResult::Status::kOk:
      return "ok";
    case AugmentResult::Status::kNotCertified:
      return "not_certified";
    case AugmentResult::Status::kNoCandidates:
      return "no_candidates";
    case AugmentResult::Status::kNoFeasibleAddition:
      return "no_feasible_addition";
  }
  return "unknown";
}

bool AugmentOptions::is_valid(std::string* why) const {
  using vantage::internal::invalid_option;
  if (add < 0) return invalid_option(why, "add", "must be >= 0");
  if (!(margin >= 0.0 && margin <= kMaxMargin)) {
    return invalid_option(why, "margin", "must be in [0, 100]");
  }
  if (circle_samples < 4) return invalid_option(why, "circle_samples", "must be >= 4");
  if (grid_samples < 2) return invalid_option(why, "grid_samples", "must be >= 2");
  if (refine_starts < 1) return invalid_option(why, "refine_starts", "must be >= 1");
  if (search_budget < 0) return invalid_option(why, "search_budget", "must be >= 0");
  if (!(search_tolerance >= 1e-9 && search_tolerance <= 0.1)) {
    return invalid_option(why, "search_tolerance", "must be in [1e-9, 0.1]");
  }
  if (!(refine_tolerance > 0.0 && refine_tolerance <= 0.1)) {
    return invalid_option(why, "refine_tolerance", "must be in (0, 0.1]");
  }
  if (!(tie_tolerance >= 0.0 && tie_tolerance <= 1e-3)) {
    return invalid_option(why, "tie_tolerance", "must be in [0, 1e-3]");
  }
  if (direct_starts < 1) return invalid_option(why, "direct_starts", "must be >= 1");
  if (direct_evaluations_per_start < 10) {
    return invalid_option(why, "direct_evaluations_per_start", "must be >= 10");
  }
  if (!(coplanarity_threshold >= 0.0)) {
    return invalid_option(why, "coplanarity_threshold", "must be >= 0");
  }
  if (!(min_distance_difference >= 0.0) || !std::isfinite(min_distance_difference)) {
    return invalid_option(why, "min_distance_difference", "must be a finite number >= 0");
  }
  return true;
}

void check_augmentation(const Layout& layout, const AugmentOptions& options) {
  vantage::internal::check_options("options", options);
  layout.validate();
  if (options.candidates_only && layout.candidates.cols() == 0) {
    vantage::internal::fail("options.candidates_only", "needs a layout with candidates");
  }
  check_point_candidates(layout, options.margin);
  check_distance_difference(layout, options.min_distance_difference);
}

AugmentResult augment_layout(const Layout& layout, const AugmentOptions& options) {
  check_augmentation(layout, options);
  AugmentResult result;
  result.min_distance_difference = options.min_distance_difference;
  const Eigen::Matrix3Xd initial_vectors = data_vectors(layout).vectors;
  result.initial = evaluate_worst_case(initial_vectors);
  result.global_solves = 1;
  result.initial_vector_count = static_cast<int>(initial_vectors.cols());
  result.initial_ceiling = pbar_ceiling(result.initial_vector_count);
  result.initial_coplanarity = coplanarity(initial_vectors, options.coplanarity_threshold);
  bool certified = result.initial.certified;
  // Each step runs on the layout the previous one left (additions appended, used candidates
  // removed), exactly as a fresh run on that layout would: candidate_ids maps its remaining
  // candidates back to the input's.
  Layout current_layout = layout;
  std::vector<int> candidate_ids(static_cast<std::size_t>(layout.candidates.cols()));
  std::iota(candidate_ids.begin(), candidate_ids.end(), 0);
  WorstCase current = result.initial;
  for (int s = 0; s < options.add; ++s) {
    if (options.progress) {
      options.progress("step " + std::to_string(s + 1) + "/" + std::to_string(options.add));
    }
    internal::Designer designer(current_layout, options);
    bool out_of_candidates = false;
    bool no_feasible = false;
    AugmentStep st = designer.step(current, &out_of_candidates, &no_feasible);
    result.global_solves += designer.solves();
    if (out_of_candidates) {
      result.status = AugmentResult::Status::kNoCandidates;
      result.message = "the candidates ran out after " + std::to_string(s) + " step(s)";
      break;
    }
    if (no_feasible) {
      result.status = AugmentResult::Status::kNoFeasibleAddition;
      result.message = "no candidate or searched position keeps the distance difference >= " +
                       format_difference(options.min_distance_difference) + " after " +
                       std::to_string(s) + " step(s)";
      break;
    }
    if (st.candidate_index >= 0) {
      const auto used = candidate_ids.begin() + st.candidate_index;
      st.candidate_index = *used;
      candidate_ids.erase(used);
    }
    current_layout = designer.layout();
    certified = certified && st.worst.certified;
    current = st.worst;
    result.steps.push_back(st);
  }
  result.final_pbar_min = current.pbar_min;
  result.final_coplanarity =
      coplanarity(data_vectors(current_layout).vectors, options.coplanarity_threshold);
  result.augmented = current_layout;
  if (options.run_direct && options.add > 0 && result.status == AugmentResult::Status::kOk) {
    if (options.progress) options.progress("direct optimiser");
    // The final layout's search box holds the input's and every greedy addition (each lies in
    // the box of the layout it was added to, which the final markers' box contains).
    internal::Designer designer(current_layout, options);
    result.direct = options.candidates_only
                        ? internal::exhaustive_candidates(layout, options, current.t, &designer)
                        : internal::multistart_search(layout, options, result, &designer);
    result.global_solves += designer.solves();
    if (result.direct.status == DirectResult::Status::kOk) {
      certified = certified && result.direct.worst.certified;
    }
  } else {
    result.direct.message = "not run";
  }
  if (!certified && result.status == AugmentResult::Status::kOk) {
    result.status = AugmentResult::Status::kNotCertified;
    result.message = "a global worst-viewpoint certificate did not close";
  }
  return result;
}

}  // namespace vantage::design

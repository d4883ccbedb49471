// augment_layout(): the greedy steps (designer.h), then the direct optimiser for comparison
// (direct_search.h). docs/math.md §18.

#include "vantage/design/augment.h"

#include <cmath>
#include <string>

#include "designer.h"
#include "direct_search.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::design {

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
  }
  return "unknown";
}

bool AugmentOptions::is_valid(std::string* why) const {
  using vantage::internal::invalid_option;
  if (add < 0) return invalid_option(why, "add", "must be >= 0");
  if (!(margin >= 0.0) || !std::isfinite(margin)) {
    return invalid_option(why, "margin", "must be finite and >= 0");
  }
  if (circle_samples < 4) return invalid_option(why, "circle_samples", "must be >= 4");
  if (grid_samples < 2) return invalid_option(why, "grid_samples", "must be >= 2");
  if (refine_starts < 1) return invalid_option(why, "refine_starts", "must be >= 1");
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
  return true;
}

AugmentResult augment_layout(const Layout& layout, const AugmentOptions& options) {
  vantage::internal::check_options("options", options);
  layout.validate();
  if (options.candidates_only && layout.candidates.cols() == 0) {
    vantage::internal::fail("candidates", "candidates_only needs a layout with candidates");
  }
  internal::Designer designer(layout, options);
  AugmentResult result;
  result.initial = designer.evaluate(designer.vectors());
  result.initial_vector_count = designer.vector_count();
  result.initial_ceiling = pbar_ceiling(result.initial_vector_count);
  result.initial_coplanarity = coplanarity(designer.vectors(), options.coplanarity_threshold);
  bool certified = result.initial.certified;
  WorstCase current = result.initial;
  for (int s = 0; s < options.add; ++s) {
    if (options.progress) {
      options.progress("step " + std::to_string(s + 1) + "/" + std::to_string(options.add));
    }
    bool out_of_candidates = false;
    AugmentStep st = designer.step(current, &out_of_candidates);
    if (out_of_candidates) {
      result.status = AugmentResult::Status::kNoCandidates;
      result.message = "the candidates ran out after " + std::to_string(s) + " step(s)";
      break;
    }
    certified = certified && st.worst.certified;
    current = st.worst;
    result.steps.push_back(st);
  }
  result.final_pbar_min = current.pbar_min;
  result.final_coplanarity = coplanarity(designer.vectors(), options.coplanarity_threshold);
  result.augmented = layout;
  const Eigen::Index n0 = layout.entries.cols();
  const Eigen::Index added = static_cast<Eigen::Index>(result.steps.size());
  result.augmented.entries.conservativeResize(3, n0 + added);
  result.augmented.weights.conservativeResize(n0 + added);
  for (Eigen::Index j = 0; j < added; ++j) {
    result.augmented.entries.col(n0 + j) = result.steps[j].added;
    result.augmented.weights(n0 + j) = 1.0;
  }
  if (options.run_direct && options.add > 0 &&
      result.status != AugmentResult::Status::kNoCandidates) {
    if (options.progress) options.progress("direct optimiser");
    result.direct = options.candidates_only
                        ? internal::exhaustive_candidates(layout, options, current.t, &designer)
                        : internal::multistart_search(layout, options, result, &designer);
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
  result.global_solves = designer.solves();
  return result;
}

}  // namespace vantage::design

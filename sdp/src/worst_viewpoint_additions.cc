#include "vantage/sdp/worst_viewpoint_additions.h"

#include <string>

#include "global_search.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {

WorstViewpointWithAdditions::WorstViewpointWithAdditions(const Eigen::Matrix3Xd& base, double level,
                                                         const WorstViewpointOptions& options)
    : tie_tolerance_(options.tie_tolerance) {
  std::string why;
  if (!options.is_valid(&why)) {
    throw InvalidArgument("WorstViewpointWithAdditions: options: " + why);
  }
  if (!(level > 0.0 && level <= 1.0)) {
    throw InvalidArgument("WorstViewpointWithAdditions: level must be in (0, 1]");
  }
  if (base.cols() < 1) throw InvalidArgument("WorstViewpointWithAdditions: base is empty");
  base_ = normalized_columns(base, "WorstViewpointWithAdditions: base");
  distinct_base_ = internal::distinct_directions(base_);
  frontier_ = std::make_unique<internal::Frontier>(
      internal::collect_frontier(distinct_base_, level, options));
}

WorstViewpointWithAdditions::~WorstViewpointWithAdditions() = default;
WorstViewpointWithAdditions::WorstViewpointWithAdditions(WorstViewpointWithAdditions&&) noexcept =
    default;
WorstViewpointWithAdditions& WorstViewpointWithAdditions::operator=(
    WorstViewpointWithAdditions&&) noexcept = default;

double WorstViewpointWithAdditions::level() const { return frontier_->level; }

long WorstViewpointWithAdditions::frontier_patches() const {
  return static_cast<long>(frontier_->patches.size());
}

WorstViewpoint WorstViewpointWithAdditions::solve(const Eigen::Matrix3Xd& added,
                                                  const WorstViewpointOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) {
    throw InvalidArgument("WorstViewpointWithAdditions::solve: options: " + why);
  }
  if (options.tie_tolerance != tie_tolerance_) {
    throw InvalidArgument(
        "WorstViewpointWithAdditions::solve: options.tie_tolerance differs from the frontier's");
  }
  if (added.cols() < 1) throw InvalidArgument("WorstViewpointWithAdditions::solve: added is empty");
  const Eigen::Matrix3Xd added_unit =
      normalized_columns(added, "WorstViewpointWithAdditions::solve: added");
  Eigen::Matrix3Xd all(3, base_.cols() + added.cols());
  all << base_, added_unit;
  Eigen::Matrix3Xd searched(3, distinct_base_.cols() + added.cols());
  searched << distinct_base_, added_unit;
  internal::SearchOutcome search = internal::search_frontier(
      *frontier_, searched, static_cast<int>(distinct_base_.cols()), options);
  if (search.below_level) {
    ++fallbacks_;
    const long frontier_work = search.patches;
    search = internal::search_worst_viewpoint(internal::distinct_directions(all), options);
    search.patches += frontier_work;
  }
  return internal::worst_viewpoint_result(all, search, options);
}

}  // namespace vantage::sdp

#include "vantage/commands/limits.h"

#include <algorithm>
#include <cstdio>

#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/design/augment.h"

namespace vantage::commands {

void check_limit(const std::string& what, long count, long limit, const std::string& command,
                 bool allow_large, const LimitWords& words) {
  if (allow_large || count <= limit) return;
  throw InvalidArgument(what, std::to_string(count) + " exceeds the limit of " +
                                  std::to_string(limit) + " for " + words.command_prefix + command +
                                  words.command_suffix + " (" + words.lift + " lifts it)");
}

double estimated_design_seconds(const Layout& layout, int add, bool candidates_only,
                                long search_budget) {
  const bool points = layout.mode == LayoutMode::kPoints;
  const double m = points ? static_cast<double>(free_vector_count(layout.entries.cols() + add))
                          : static_cast<double>(layout.entries.cols()) + add;
  const long extra_budget = search_budget - design::AugmentOptions{}.search_budget;
  const double step =
      points && !candidates_only
          ? kDesignPointStepSeconds +
                kDesignSecondsPerSolveVector * static_cast<double>(std::max(0L, extra_budget))
          : 0.0;
  const double per_vector =
      points ? kDesignPointSecondsPerVector : kDesignDirectionSecondsPerVector;
  return add * (step + per_vector * m);
}

void check_time_limit(const std::string& what, double seconds, double limit,
                      const std::string& command, bool allow_large, const LimitWords& words) {
  if (allow_large || seconds <= limit) return;
  char text[64];
  std::snprintf(text, sizeof text, "about %.0f s of CPU exceeds the budget of %.0f s", seconds,
                limit);
  throw InvalidArgument(what, text + std::string(" for ") + words.command_prefix + command +
                                  words.command_suffix + " (README \"Limits\"; " + words.lift +
                                  " lifts it)");
}

long data_vector_count(const Layout& layout) {
  const Eigen::Index n = layout.entries.cols();
  return static_cast<long>(layout.mode == LayoutMode::kPoints ? free_vector_count(n) : n);
}

}  // namespace vantage::commands

#pragma once

// Private to vantage::design: which lattice directions each site is seen from, and the
// coverage of a choice of sites read from counts (docs/math.md §21, "The search").

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "vantage/visibility/visibility.h"

namespace vantage::design::internal {

/// Coverage and potential of a choice: compared in that order.
struct CoverageKey {
  int covered = 0;     ///< lattice directions of the workspace that see >= min_visible markers
  long potential = 0;  ///< sum over directions of min(count, min_visible)

  bool operator==(const CoverageKey& o) const {
    return covered == o.covered && potential == o.potential;
  }
  bool operator<(const CoverageKey& o) const {
    return covered != o.covered ? covered < o.covered : potential < o.potential;
  }
};

/// One bit per site and lattice direction of the workspace: the site's cone holds the direction
/// and its occlusion grid has it clear (the test of visibility::direction_visibility()).
class SiteCoverage {
 public:
  SiteCoverage(const visibility::VisibilityProblem& sites, int lattice_samples);
  /// The bits of `sites` sites over `directions` directions from sees(site, direction); a
  /// direction is covered when it sees at least `min_visible` chosen sites.
  SiteCoverage(int sites, int directions, int min_visible,
               const std::function<bool(int, int)>& sees);

  int directions() const { return directions_; }
  int min_visible() const { return min_visible_; }
  bool sees(int site, int d) const { return (bits(site)[d >> 6] >> (d & 63)) & 1U; }
  const std::uint64_t* bits(int site) const {
    return words_.data() + static_cast<std::size_t>(site) * words_per_site_;
  }
  int words() const { return words_per_site_; }

  /// The per-direction counts of a choice.
  std::vector<std::uint16_t> counts(const std::vector<int>& chosen) const;
  /// The key of counts.
  CoverageKey key(const std::vector<std::uint16_t>& counts) const;
  /// The key of a choice.
  CoverageKey key(const std::vector<int>& chosen) const { return key(counts(chosen)); }

 private:
  int directions_ = 0;
  int min_visible_ = 3;
  int words_per_site_ = 0;
  std::vector<std::uint64_t> words_;
};

/// The counts of a current choice and the keys of its one-site changes, exact from bit sets.
class CoverageCounts {
 public:
  CoverageCounts(const SiteCoverage& coverage, const std::vector<int>& chosen);

  CoverageKey key() const { return key_; }
  /// The key with site c added.
  CoverageKey with_added(int c) const;
  /// Prepares with_swapped() for the removal of chosen site `removed`.
  void prepare_removal(int removed);
  /// The key with the prepared site removed and site c added.
  CoverageKey with_swapped(int c) const;

 private:
  static int popcount_and(const std::uint64_t* a, const std::vector<std::uint64_t>& b, int words);

  const SiteCoverage& coverage_;
  std::vector<std::uint16_t> counts_;
  CoverageKey key_;
  std::vector<std::uint64_t> one_short_;  // count == k - 1
  std::vector<std::uint64_t> below_;      // count < k
  CoverageKey removed_key_;               // the key without the prepared site
  std::vector<std::uint64_t> removed_one_short_;
  std::vector<std::uint64_t> removed_below_;
};

}  // namespace vantage::design::internal

// Coverage of a choice of sites from per-site bit sets (docs/math.md §21, "The search").

#include "placement_coverage.h"

#include <algorithm>

#include "vantage/visibility/workspace_lattice.h"

namespace vantage::design::internal {

SiteCoverage::SiteCoverage(const visibility::VisibilityProblem& sites, int lattice_samples)
    : min_visible_(sites.min_visible) {
  const Eigen::Matrix3Xd lattice =
      visibility::workspace_lattice(sites.workspace, lattice_samples).directions;
  directions_ = static_cast<int>(lattice.cols());
  words_per_site_ = (directions_ + 63) / 64;
  const int n = static_cast<int>(sites.points.cols());
  words_.assign(static_cast<std::size_t>(n) * words_per_site_, 0);
  for (int s = 0; s < n; ++s) {
    std::uint64_t* w = words_.data() + static_cast<std::size_t>(s) * words_per_site_;
    for (int d = 0; d < directions_; ++d) {
      const Eigen::Vector3d a = lattice.col(d);
      if (sites.normals.col(s).dot(a) < sites.cos_cone(s)) continue;
      if (sites.occlusion != nullptr && sites.occlusion->blocked(sites.occlusion_marker(s), a)) {
        continue;
      }
      w[d >> 6] |= std::uint64_t{1} << (d & 63);
    }
  }
}

SiteCoverage::SiteCoverage(int sites, int directions, int min_visible,
                           const std::function<bool(int, int)>& sees)
    : directions_(directions), min_visible_(min_visible), words_per_site_((directions + 63) / 64) {
  words_.assign(static_cast<std::size_t>(sites) * words_per_site_, 0);
  for (int s = 0; s < sites; ++s) {
    std::uint64_t* w = words_.data() + static_cast<std::size_t>(s) * words_per_site_;
    for (int d = 0; d < directions_; ++d) {
      if (sees(s, d)) w[d >> 6] |= std::uint64_t{1} << (d & 63);
    }
  }
}

std::vector<std::uint16_t> SiteCoverage::counts(const std::vector<int>& chosen) const {
  std::vector<std::uint16_t> out(static_cast<std::size_t>(directions_), 0);
  for (int s : chosen) {
    const std::uint64_t* w = bits(s);
    for (int k = 0; k < words_per_site_; ++k) {
      std::uint64_t word = w[k];
      while (word != 0) {
        const int bit = __builtin_ctzll(word);
        ++out[static_cast<std::size_t>(64 * k + bit)];
        word &= word - 1;
      }
    }
  }
  return out;
}

CoverageKey SiteCoverage::key(const std::vector<std::uint16_t>& counts) const {
  CoverageKey out;
  for (std::uint16_t c : counts) {
    if (c >= min_visible_) ++out.covered;
    out.potential += std::min<int>(c, min_visible_);
  }
  return out;
}

namespace {

// Bit d of `out` set iff pred(counts[d]).
template <typename Pred>
void mask(const std::vector<std::uint16_t>& counts, int words, Pred pred,
          std::vector<std::uint64_t>* out) {
  out->assign(static_cast<std::size_t>(words), 0);
  for (std::size_t d = 0; d < counts.size(); ++d) {
    if (pred(counts[d])) (*out)[d >> 6] |= std::uint64_t{1} << (d & 63);
  }
}

}  // namespace

CoverageCounts::CoverageCounts(const SiteCoverage& coverage, const std::vector<int>& chosen)
    : coverage_(coverage), counts_(coverage.counts(chosen)), key_(coverage.key(counts_)) {
  const int k = coverage.min_visible();
  mask(
      counts_, coverage.words(), [k](int c) { return c == k - 1; }, &one_short_);
  mask(
      counts_, coverage.words(), [k](int c) { return c < k; }, &below_);
}

int CoverageCounts::popcount_and(const std::uint64_t* a, const std::vector<std::uint64_t>& b,
                                 int words) {
  int total = 0;
  for (int k = 0; k < words; ++k)
    total += __builtin_popcountll(a[k] & b[static_cast<std::size_t>(k)]);
  return total;
}

CoverageKey CoverageCounts::with_added(int c) const {
  const int words = coverage_.words();
  CoverageKey out = key_;
  out.covered += popcount_and(coverage_.bits(c), one_short_, words);
  out.potential += popcount_and(coverage_.bits(c), below_, words);
  return out;
}

void CoverageCounts::prepare_removal(int removed) {
  const int k = coverage_.min_visible();
  std::vector<std::uint16_t> without = counts_;
  for (int d = 0; d < coverage_.directions(); ++d) {
    if (coverage_.sees(removed, d)) --without[static_cast<std::size_t>(d)];
  }
  removed_key_ = coverage_.key(without);
  mask(
      without, coverage_.words(), [k](int c) { return c == k - 1; }, &removed_one_short_);
  mask(
      without, coverage_.words(), [k](int c) { return c < k; }, &removed_below_);
}

CoverageKey CoverageCounts::with_swapped(int c) const {
  const int words = coverage_.words();
  CoverageKey out = removed_key_;
  out.covered += popcount_and(coverage_.bits(c), removed_one_short_, words);
  out.potential += popcount_and(coverage_.bits(c), removed_below_, words);
  return out;
}

}  // namespace vantage::design::internal

#include "vantage/report/dropout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "vantage/analysis/common.h"
#include "vantage/analysis/parallel.h"

namespace vantage::report {
namespace {

// p-bar_min values closer than this rank as equal harm.
constexpr double kHarmResolution = 1e-12;

// The data vectors left without entry k.
Eigen::Matrix3Xd remaining_vectors(const DataVectors& data, int k) {
  Eigen::Matrix3Xd kept(3, data.vectors.cols());
  Eigen::Index count = 0;
  for (Eigen::Index c = 0; c < data.vectors.cols(); ++c) {
    const bool touches =
        data.pairs.empty() ? c == k : data.pairs[c].first == k || data.pairs[c].second == k;
    if (!touches) kept.col(count++) = data.vectors.col(c);
  }
  return kept.leftCols(count);
}

DropoutEntry analyse_without(const DataVectors& data, int k,
                             const sdp::WorstViewpointOptions& options) {
  const Eigen::Matrix3Xd vectors = remaining_vectors(data, k);
  DropoutEntry entry;
  entry.index = k;
  entry.n_vectors = static_cast<int>(vectors.cols());
  entry.worst = vectors.cols() == 1
                    ? sdp::certified_worst_end_on(vectors.col(0))
                    : sdp::certified_worst(sdp::global_worst_viewpoint(vectors, options), vectors);
  return entry;
}

}  // namespace

bool DropoutOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!worst_viewpoint.is_valid(&inner)) {
    if (why) *why = "worst_viewpoint." + inner;
    return false;
  }
  if (threads < 0) {
    if (why) *why = "threads must be >= 0";
    return false;
  }
  return true;
}

const char* to_string(DropoutAnalysis::Status status) {
  return status == DropoutAnalysis::Status::kCertified ? "certified" : "not_certified";
}

DropoutAnalysis dropout_analysis(const Layout& layout, const DropoutOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("dropout_analysis: options." + why);
  const DataVectors data = data_vectors(layout);
  const int n = static_cast<int>(layout.entries.cols());

  DropoutAnalysis result;
  result.entries.resize(n);
  // The entries already run on every thread asked for: each search then stays on its own (its
  // result does not depend on it).
  sdp::WorstViewpointOptions search = options.worst_viewpoint;
  if (thread_count(options.threads, n) > 1) search.threads = 1;
  parallel_blocks(n, options.threads, [&](long begin, long end) {
    for (long k = begin; k < end; ++k) {
      result.entries[k] = analyse_without(data, static_cast<int>(k), search);
    }
  });

  result.by_harm.resize(n);
  std::iota(result.by_harm.begin(), result.by_harm.end(), 0);
  // Values equal to rounding (symmetric markers) keep index order.
  auto key = [&](int k) { return std::round(result.entries[k].worst.pbar_min / kHarmResolution); };
  std::stable_sort(result.by_harm.begin(), result.by_harm.end(),
                   [&](int a, int b) { return key(a) < key(b); });

  std::string uncertified;
  for (const DropoutEntry& entry : result.entries) {
    if (!entry.worst.certified)
      uncertified += (uncertified.empty() ? "" : ", ") + std::to_string(entry.index);
  }
  result.status = uncertified.empty() ? DropoutAnalysis::Status::kCertified
                                      : DropoutAnalysis::Status::kNotCertified;
  if (!uncertified.empty()) {
    result.message = "the global worst viewpoint without entries " + uncertified +
                     " is not certified (patch budget exhausted)";
  }
  return result;
}

}  // namespace vantage::report

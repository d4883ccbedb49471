#include "vantage/report/dropout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
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
  if (vectors.cols() == 1) {
    entry.worst_viewpoint = sdp::upper_hemisphere(vectors.col(0).normalized());
    entry.worst_viewpoints = {entry.worst_viewpoint};
    entry.t = 1.0;
    entry.pbar_min = 0.0;
    entry.max_worst_case_error_deg = 90.0;
    entry.certified = true;
    return entry;
  }
  const sdp::WorstViewpoint global = sdp::global_worst_viewpoint(vectors, options);
  entry.worst_viewpoint = global.viewpoint;
  entry.worst_viewpoints = global.viewpoints;
  entry.t = global.t;
  entry.pbar_min = global.pbar_min;
  for (const Eigen::Vector3d& a : global.viewpoints) {
    entry.max_worst_case_error_deg =
        std::max(entry.max_worst_case_error_deg, worst_case_errors_deg(vectors, a).maxCoeff());
  }
  entry.certified = global.status == sdp::WorstViewpoint::Status::kCertified;
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
  auto key = [&](int k) { return std::round(result.entries[k].pbar_min / kHarmResolution); };
  std::stable_sort(result.by_harm.begin(), result.by_harm.end(),
                   [&](int a, int b) { return key(a) < key(b); });

  std::string uncertified;
  for (const DropoutEntry& entry : result.entries) {
    if (!entry.certified)
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

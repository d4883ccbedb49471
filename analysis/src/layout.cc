#include "vantage/analysis/layout.h"

#include <cmath>
#include <string>
#include <utility>

#include "vantage/analysis/common.h"

namespace vantage {

const char* to_string(LayoutMode mode) {
  return mode == LayoutMode::kPoints ? "points" : "vectors";
}

const char* Layout::entries_field() const { return to_string(mode); }

namespace {

[[noreturn]] void fail(const std::string& field, Eigen::Index index, const std::string& problem) {
  throw InvalidArgument(field + "[" + std::to_string(index) + "]: " + problem);
}

}  // namespace

namespace {

/// Checks a direction: finite, non-zero, and of a length that normalises without under- or
/// overflow.
void check_direction(const Eigen::Vector3d& v, const std::string& field, Eigen::Index i) {
  if (!v.allFinite()) fail(field, i, "not a finite number");
  const double length = v.stableNorm();
  if (length == 0.0) fail(field, i, "zero-length vector");
  if (length < Layout::kMinLength || length > Layout::kMaxLength) {
    fail(field, i, "length outside [1e-150, 1e150], cannot be normalised safely");
  }
}

void check_point(const Eigen::Vector3d& p, const std::string& field, Eigen::Index i) {
  if (!p.allFinite()) fail(field, i, "not a finite number");
  if (p.lpNorm<Eigen::Infinity>() > Layout::kMaxLength) {
    fail(field, i, "coordinates beyond +-1e150");
  }
}

}  // namespace

void Layout::validate() const {
  const std::string field = entries_field();
  const Eigen::Index n = entries.cols();
  const bool points = mode == LayoutMode::kPoints;
  if (n < (points ? 3 : 2)) {
    throw InvalidArgument(field +
                          (points ? ": need at least 3 points (2 free vectors), got "
                                  : ": need at least 2 vectors, got ") +
                          std::to_string(n));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (points) {
      check_point(entries.col(i), field, i);
    } else {
      check_direction(entries.col(i), field, i);
    }
  }
  if (points) {
    for (Eigen::Index j = 1; j < n; ++j) {
      for (Eigen::Index i = 0; i < j; ++i) {
        if ((entries.col(j) - entries.col(i)).stableNorm() < kMinLength) {
          fail(field, j, "coincides with " + field + "[" + std::to_string(i) + "]");
        }
      }
    }
  }
  if (weights.size() != n) {
    throw InvalidArgument("weights: expected " + std::to_string(n) + " entries (one per " +
                          (mode == LayoutMode::kPoints ? "point" : "vector") + "), got " +
                          std::to_string(weights.size()));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!std::isfinite(weights(i))) fail("weights", i, "not a finite number");
    if (!(weights(i) > 0.0)) fail("weights", i, "must be > 0");
    if (weights(i) > kMaxWeight) fail("weights", i, "must be <= 1e100");
  }
  for (Eigen::Index i = 0; i < candidates.cols(); ++i) {
    if (points) {
      check_point(candidates.col(i), "candidates", i);
    } else {
      check_direction(candidates.col(i), "candidates", i);
    }
  }
}

DataVectors data_vectors(const Layout& layout, PairWeighting weighting) {
  layout.validate();
  DataVectors out;
  if (layout.mode == LayoutMode::kVectors) {
    out.vectors = layout.entries;
    out.weights = layout.weights;
    return out;
  }
  const Eigen::Matrix2Xi pairs = free_vector_pairs(layout.entries, FreeVectorSet::kAllPairs);
  FreeVectorsOf<3> free =
      build_free_vectors<3>(layout.entries, layout.entries, layout.weights, pairs, weighting);
  out.vectors = std::move(free.z_object);
  out.weights = std::move(free.weights);
  out.pairs.reserve(pairs.cols());
  for (Eigen::Index k = 0; k < pairs.cols(); ++k) out.pairs.emplace_back(pairs(0, k), pairs(1, k));
  return out;
}

}  // namespace vantage

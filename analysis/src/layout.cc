#include "vantage/analysis/layout.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "vantage/analysis/common.h"

namespace vantage {

const char* to_string(LayoutMode mode) {
  return mode == LayoutMode::kPoints ? "points" : "vectors";
}

const char* to_string(LayoutSensor::Kind kind) {
  return kind == LayoutSensor::Kind::kTracker ? "tracker" : "camera";
}

const char* Layout::entries_field() const { return to_string(mode); }

namespace {

[[noreturn]] void fail(const std::string& field, Eigen::Index index, const std::string& problem) {
  throw InvalidArgument(field, static_cast<long>(index), problem);
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

// Sweeps the points in order of their coordinate of largest spread, comparing each with the
// following ones within the threshold along that axis: O(n log n) for spread-out layouts instead
// of all n^2 / 2 pairs. Reports the coinciding pair (i < j) with the smallest j, then i.
void check_coincidence(const Eigen::Matrix3Xd& points, const std::string& field) {
  const Eigen::Index n = points.cols();
  const double threshold = Layout::coincidence_distance(points);
  Eigen::Index axis = 0;
  (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).maxCoeff(&axis);
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return points(axis, a) < points(axis, b) || (points(axis, a) == points(axis, b) && a < b);
  });
  Eigen::Index best_i = -1, best_j = -1;
  for (std::size_t a = 0; a < order.size(); ++a) {
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Eigen::Index p = order[a], q = order[b];
      if (points(axis, q) - points(axis, p) > threshold) break;
      if (!((points.col(q) - points.col(p)).stableNorm() < threshold)) continue;
      const Eigen::Index i = std::min(p, q), j = std::max(p, q);
      if (best_j < 0 || j < best_j || (j == best_j && i < best_i)) {
        best_i = i;
        best_j = j;
      }
    }
  }
  if (best_j >= 0) {
    throw InvalidArgument(field, static_cast<long>(best_j), "coincides with", field,
                          static_cast<long>(best_i));
  }
}

// Names, when given: one per entry, non-empty, each used once (reported at its second use).
void check_names(const std::vector<std::string>& names, Eigen::Index n, bool points) {
  if (names.empty()) return;
  if (static_cast<Eigen::Index>(names.size()) != n) {
    throw InvalidArgument("names: expected " + std::to_string(n) + " entries (one per " +
                          (points ? "point" : "vector") + "), got " + std::to_string(names.size()));
  }
  std::unordered_map<std::string, Eigen::Index> first;
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::string& name = names[static_cast<std::size_t>(i)];
    if (name.empty()) fail("names", i, "empty name");
    const auto [previous, inserted] = first.emplace(name, i);
    if (!inserted) fail("names", i, "repeats names[" + std::to_string(previous->second) + "]");
  }
}

}  // namespace

// Relative, so that scaling a layout by 1e-100 or 1e100 changes nothing: the free vector of two
// points this close is at the rounding level of the coordinates (2^-52 relative), so its
// direction is noise.
double Layout::coincidence_distance(const Eigen::Matrix3Xd& points) {
  const double scale = points.size() == 0 ? 0.0 : points.cwiseAbs().maxCoeff();
  return std::max(kCoincidenceRelative * scale, kMinLength);
}

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
  if (points) check_coincidence(entries, field);
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
  check_names(names, n, points);
  if (visibility) {
    if (!points) throw InvalidArgument("normals", "only point layouts have marker normals");
    validate_visibility(*visibility, n);
  }
  if (workspace) validate_workspace(*workspace);
}

std::string Layout::entry_name(Eigen::Index i) const {
  if (!names.empty()) return names[static_cast<std::size_t>(i)];
  return (mode == LayoutMode::kPoints ? "p" : "v") + std::to_string(i);
}

std::string unused_entry_name(const Layout& layout, const std::string& prefix) {
  std::unordered_set<std::string> taken;
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) taken.insert(layout.entry_name(i));
  for (long k = 1;; ++k) {
    std::string name = prefix + std::to_string(k);
    if (taken.count(name) == 0) return name;
  }
}

Layout without_entry(const Layout& layout, Eigen::Index k) {
  const Eigen::Index n = layout.entries.cols();
  VANTAGE_CHECK(k >= 0 && k < n, "without_entry: no such entry");
  auto drop = [&](auto& m) {
    using M = std::decay_t<decltype(m)>;
    M kept(m.rows(), m.cols() - 1);
    kept << m.leftCols(k), m.rightCols(m.cols() - 1 - k);
    m = kept;
  };
  auto drop_element = [&](Eigen::VectorXd& v) {
    Eigen::VectorXd kept(v.size() - 1);
    kept << v.head(k), v.tail(v.size() - 1 - k);
    v = kept;
  };
  Layout out = layout;
  out.placement.reset();
  drop(out.entries);
  drop_element(out.weights);
  out.names.clear();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (i != k) out.names.push_back(layout.entry_name(i));
  }
  if (out.visibility) {
    drop(out.visibility->normals);
    drop_element(out.visibility->cone_half_angle_deg);
    out.visibility->min_visible = std::min<int>(out.visibility->min_visible,
                                                static_cast<int>(std::max<Eigen::Index>(n - 1, 3)));
  }
  return out;
}

void append_entry(Layout* layout, const Eigen::Vector3d& x, const std::string& name_prefix) {
  const Eigen::Index n = layout->entries.cols();
  layout->placement.reset();
  if (!layout->names.empty()) layout->names.push_back(unused_entry_name(*layout, name_prefix));
  if (layout->visibility) {
    MarkerVisibility& v = *layout->visibility;
    const Eigen::Vector3d outward = x - layout->entries.rowwise().mean();
    const double length = outward.norm();
    v.normals.conservativeResize(3, n + 1);
    v.normals.col(n) = length > 0.0 ? Eigen::Vector3d(outward / length) : Eigen::Vector3d::UnitZ();
    const double widest = v.cone_half_angle_deg.size() > 0 ? v.cone_half_angle_deg.maxCoeff()
                                                           : MarkerVisibility::kDefaultConeDeg;
    v.cone_half_angle_deg.conservativeResize(n + 1);
    v.cone_half_angle_deg(n) = widest;
  }
  layout->entries.conservativeResize(3, n + 1);
  layout->entries.col(n) = x;
  layout->weights.conservativeResize(n + 1);
  layout->weights(n) = 1.0;
}

Eigen::Index free_vector_count(Eigen::Index points) {
  if (points < 2) return 0;
  return points % 2 == 0 ? points / 2 * (points - 1) : points * ((points - 1) / 2);
}

DataVectors data_vectors(const Layout& layout, PairWeighting weighting) {
  layout.validate();
  DataVectors out;
  if (layout.mode == LayoutMode::kVectors) {
    out.vectors = layout.entries;
    out.weights = layout.weights;
    return out;
  }
  const Eigen::Index n = layout.entries.cols();
  const Eigen::Index m = free_vector_count(n);
  if (m > Layout::kMaxFreeVectors) {
    throw InvalidArgument("points: " + std::to_string(n) + " points give " + std::to_string(m) +
                          " free vectors, more than " + std::to_string(Layout::kMaxFreeVectors));
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

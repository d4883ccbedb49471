#pragma once

/// vantage's one validation grammar. INTERNAL: not installed and not part of the API. Every
/// library module (analysis, sdp, design, io) includes it as "vantage/analysis/internal/checks.h":
/// the analysis include directory is public to every target that links vantage::analysis, and
/// vantage_add_library() leaves include/vantage/<module>/internal/ out of the installed headers.
///
/// Every message reads "<arg>: <problem>" or "<arg>[<i>]: <problem>": <arg> is the caller's
/// argument name (or "<arg>.<field>" for an options field), <i> the column or entry, <problem> a
/// lower-case phrase ("not finite", "zero length", "must be positive and finite"). Failed checks
/// throw vantage::InvalidArgument; Options::is_valid() reports through invalid_option() so that
/// its *why reads "<field>: <problem>" and check_options() throws "<arg>.<field>: <problem>".
/// A check that passes allocates nothing, so solvers that promise no allocation can use them.

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/common.h"

namespace vantage::internal {

/// Tolerance on | ||v|| - 1 | of a vector that must have unit length.
inline constexpr double kUnitTolerance = 1e-9;

/// Throws InvalidArgument("<arg>: <problem>").
[[noreturn]] void fail(std::string_view arg, std::string_view problem);

/// Throws InvalidArgument("<arg>[<index>]: <problem>").
[[noreturn]] void fail_at(std::string_view arg, Eigen::Index index, std::string_view problem);

/// For Options::is_valid(): stores "<field>: <problem>" in *why (when why is not null) and
/// returns false, so that `return invalid_option(why, "tol", "must be > 0");` reads as the rule.
bool invalid_option(std::string* why, std::string_view field, std::string_view problem);

/// Throws InvalidArgument("<arg>.<why>"): the failure of Options::is_valid() for argument `arg`.
[[noreturn]] void fail_options(std::string_view arg, std::string_view why);

/// Throws InvalidArgument("<arg>.<field>: <problem>") when options.is_valid(&why) is false,
/// e.g. "options.degenerate_gap: must be in [0, 1)".
template <class Options>
void check_options(std::string_view arg, const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) fail_options(arg, why);
}

/// "<arg>: need at least <minimum> <noun>, got <count>" when count < minimum.
void check_min_count(std::string_view arg, Eigen::Index count, Eigen::Index minimum,
                     std::string_view noun);

/// "<arg>: has <count> <noun>, expected <expected> (one per column of <reference>)" when
/// count != expected.
void check_count_matches(std::string_view arg, Eigen::Index count, Eigen::Index expected,
                         std::string_view reference, std::string_view noun = "columns");

/// What a weight may be.
enum class WeightRule {
  kPositive,     ///< every weight > 0 and finite
  kNonNegative,  ///< every weight >= 0 and finite, at least one > 0
};

/// Weights: empty (all 1), or `expected` entries (one per column of `reference`) obeying `rule`.
/// Messages: "<arg>: has 3 entries, expected 4 (one per column of z_object)",
/// "<arg>[2]: must be positive and finite", "<arg>[2]: must be >= 0 and finite",
/// "<arg>: all zero, at least one must be positive".
void check_weights(std::string_view arg, const Eigen::VectorXd& weights, Eigen::Index expected,
                   std::string_view reference, WeightRule rule = WeightRule::kPositive);

/// "<arg>: must be positive and finite, got <value>" unless 0 < value < inf.
void check_positive_finite(std::string_view arg, double value);

/// "<arg>: must be a finite unit vector" unless every entry is finite and
/// | ||v|| - 1 | <= tolerance.
void check_unit_vector(std::string_view arg, const Eigen::Vector3d& v,
                       double tolerance = kUnitTolerance);

/// "<arg>[i]: not finite" for the first column with a NaN or an infinity.
template <class Derived>
void check_finite_columns(std::string_view arg, const Eigen::MatrixBase<Derived>& m) {
  if (m.allFinite()) return;
  for (Eigen::Index i = 0; i < m.cols(); ++i) {
    if (!m.col(i).allFinite()) fail_at(arg, i, "not finite");
  }
}

/// "<arg>[i]: not finite" or "<arg>[i]: zero length" for the first bad column.
template <class Derived>
void check_nonzero_finite_columns(std::string_view arg, const Eigen::MatrixBase<Derived>& m) {
  check_finite_columns(arg, m);
  for (Eigen::Index i = 0; i < m.cols(); ++i) {
    if (!(m.col(i).squaredNorm() > 0.0)) fail_at(arg, i, "zero length");
  }
}

/// "<arg>[i]: must be a finite unit vector" for the first column that is not one.
template <class Derived>
void check_unit_columns(std::string_view arg, const Eigen::MatrixBase<Derived>& m,
                        double tolerance = kUnitTolerance) {
  for (Eigen::Index i = 0; i < m.cols(); ++i) {
    if (!m.col(i).allFinite() || !(std::abs(m.col(i).norm() - 1.0) <= tolerance)) {
      fail_at(arg, i, "must be a finite unit vector");
    }
  }
}

/// Entry i of a weight vector; empty weights mean all 1.
inline double weight_at(const Eigen::VectorXd& weights, Eigen::Index i) {
  return weights.size() == 0 ? 1.0 : weights(i);
}

/// "<arg>: points <j> and <i> coincide" for the first pair of equal columns, j < i. O(n^2).
void check_distinct_columns(std::string_view arg, const Eigen::Matrix3Xd& points);

/// The index of the first of `values` equal to an earlier one, or -1 when they are distinct
/// (e.g. an approach's camera distances, which must not repeat). O(n^2).
long first_repeat(const std::vector<double>& values);

/// The point sets of a pose solve: `measured` has one column per column of `model`
/// ("<measured_arg>: has 7 points, expected 8 (one per column of <model_arg>)"), at least
/// `minimum` of them, every column finite, and weights as check_weights() ("weights").
template <class Measured>
void check_correspondences(std::string_view model_arg, const Eigen::Matrix3Xd& model,
                           std::string_view measured_arg,
                           const Eigen::MatrixBase<Measured>& measured,
                           const Eigen::VectorXd& weights, Eigen::Index minimum) {
  check_count_matches(measured_arg, measured.cols(), model.cols(), model_arg, "points");
  check_min_count(model_arg, model.cols(), minimum, "points");
  check_weights("weights", weights, model.cols(), model_arg);
  check_finite_columns(model_arg, model);
  check_finite_columns(measured_arg, measured);
}

}  // namespace vantage::internal

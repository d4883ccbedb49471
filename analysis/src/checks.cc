#include "vantage/analysis/internal/checks.h"

#include <cmath>
#include <sstream>

namespace vantage::internal {

void fail(std::string_view arg, std::string_view problem) {
  throw InvalidArgument(std::string(arg), std::string(problem));
}

void fail_at(std::string_view arg, Eigen::Index index, std::string_view problem) {
  throw InvalidArgument(std::string(arg), static_cast<long>(index), std::string(problem));
}

void fail_options(std::string_view arg, std::string_view why) {
  // why is "<field>: <problem>" (invalid_option()): the field is "<arg>.<field>".
  const std::size_t colon = why.find(": ");
  if (colon == std::string_view::npos) throw InvalidArgument(std::string(arg), std::string(why));
  throw InvalidArgument(std::string(arg) + "." + std::string(why.substr(0, colon)),
                        std::string(why.substr(colon + 2)));
}

bool invalid_option(std::string* why, std::string_view field, std::string_view problem) {
  if (why != nullptr) {
    *why = field;
    *why += ": ";
    *why += problem;
  }
  return false;
}

void check_min_count(std::string_view arg, Eigen::Index count, Eigen::Index minimum,
                     std::string_view noun) {
  if (count >= minimum) return;
  std::ostringstream out;
  out << "need at least " << minimum << " " << noun << ", got " << count;
  fail(arg, out.str());
}

void check_count_matches(std::string_view arg, Eigen::Index count, Eigen::Index expected,
                         std::string_view reference, std::string_view noun) {
  if (count == expected) return;
  std::ostringstream out;
  out << "has " << count << " " << noun << ", expected " << expected << " (one per column of "
      << reference << ")";
  fail(arg, out.str());
}

void check_weights(std::string_view arg, const Eigen::VectorXd& weights, Eigen::Index expected,
                   std::string_view reference, WeightRule rule) {
  if (weights.size() == 0) return;
  check_count_matches(arg, weights.size(), expected, reference, "entries");
  const bool positive = rule == WeightRule::kPositive;
  if (weights.allFinite() && (positive ? (weights.array() > 0.0).all()
                                       : (weights.array() >= 0.0).all() && weights.sum() > 0.0)) {
    return;
  }
  for (Eigen::Index i = 0; i < weights.size(); ++i) {
    const double w = weights(i);
    if (!std::isfinite(w) || (positive ? !(w > 0.0) : !(w >= 0.0))) {
      fail_at(arg, i, positive ? "must be positive and finite" : "must be >= 0 and finite");
    }
  }
  fail(arg, "all zero, at least one must be positive");
}

void check_positive_finite(std::string_view arg, double value) {
  if (value > 0.0 && std::isfinite(value)) return;
  std::ostringstream out;
  out << "must be positive and finite, got " << value;
  fail(arg, out.str());
}

void check_unit_vector(std::string_view arg, const Eigen::Vector3d& v, double tolerance) {
  if (v.allFinite() && std::abs(v.norm() - 1.0) <= tolerance) return;
  fail(arg, "must be a finite unit vector");
}

void check_distinct_columns(std::string_view arg, const Eigen::Matrix3Xd& points) {
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    for (Eigen::Index j = 0; j < i; ++j) {
      if (points.col(i) == points.col(j)) {
        fail(arg, "points " + std::to_string(j) + " and " + std::to_string(i) + " coincide");
      }
    }
  }
}

long first_repeat(const std::vector<double>& values) {
  for (std::size_t i = 1; i < values.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (values[j] == values[i]) return static_cast<long>(i);
    }
  }
  return -1;
}

}  // namespace vantage::internal

#pragma once

// Private: argument checks of the affine estimators (affine_orientation.cc, affine_pose.cc,
// affine_cross_check.cc). Each throws vantage::InvalidArgument naming the argument.

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <string>

#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"

namespace vantage::internal {

/// For is_valid(): stores `text` in *why (when given) and returns false.
inline bool invalid(std::string* why, const std::string& text) {
  if (why) *why = text;
  return false;
}

inline std::string indexed(const char* name, Eigen::Index i) {
  return std::string(name) + "[" + std::to_string(i) + "]";
}

inline double weight_at(const Eigen::VectorXd& w, Eigen::Index i) {
  return w.size() == 0 ? 1.0 : w(i);
}

inline void check_weights(const Eigen::VectorXd& w, Eigen::Index n) {
  if (w.size() != 0 && w.size() != n) {
    std::ostringstream out;
    out << "weights has " << w.size() << " entries, expected " << n;
    throw InvalidArgument(out.str());
  }
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    if (!(w(i) > 0.0 && std::isfinite(w(i))))
      throw InvalidArgument(indexed("weights", i) + " must be positive and finite");
  }
}

/// Shared checks of the vector problems (Prop. 4, Lemma 7, LUB, cross-check).
template <int Rows>
void validate_vectors(const Eigen::Matrix3Xd& z,
                      const Eigen::Matrix<double, Rows, Eigen::Dynamic>& d,
                      const Eigen::VectorXd& w, Eigen::Index min_count, const char* d_name) {
  if (z.cols() != d.cols()) {
    std::ostringstream out;
    out << "z_object has " << z.cols() << " columns but " << d_name << " has " << d.cols();
    throw InvalidArgument(out.str());
  }
  if (z.cols() < min_count) {
    std::ostringstream out;
    out << "z_object: need at least " << min_count << " vectors, got " << z.cols();
    throw InvalidArgument(out.str());
  }
  check_weights(w, z.cols());
  for (Eigen::Index i = 0; i < z.cols(); ++i) {
    if (!z.col(i).allFinite()) throw InvalidArgument(indexed("z_object", i) + " is not finite");
    if (!(z.col(i).squaredNorm() > 0.0))
      throw InvalidArgument(indexed("z_object", i) + " has zero length");
    if (!d.col(i).allFinite()) throw InvalidArgument(indexed(d_name, i) + " is not finite");
  }
}

inline void check_alpha(double alpha) {
  if (!(alpha > 0.0 && std::isfinite(alpha)))
    throw InvalidArgument("alpha must be positive and finite");
}

inline void check_count(Eigen::Index n, const AffineOrientationOptions& options, const char* hint) {
  if (n > options.max_vectors) {
    std::ostringstream out;
    out << "z_object: " << n << " vectors exceed options.max_vectors = " << options.max_vectors
        << " (Prop. 4 solves 2^" << n << " problems)" << hint;
    throw InvalidArgument(out.str());
  }
}

/// Checks of the pose estimators' points (affine_pose.cc, refined_pose.cc): the same number of
/// model and measured points, n >= 3, finite, no two model points equal, valid weights.
template <int Rows>
void check_pose_points(const Eigen::Matrix3Xd& model,
                       const Eigen::Matrix<double, Rows, Eigen::Dynamic>& image,
                       const Eigen::VectorXd& w, const char* image_name) {
  if (model.cols() != image.cols()) {
    std::ostringstream out;
    out << "model_object has " << model.cols() << " points but " << image_name << " has "
        << image.cols();
    throw InvalidArgument(out.str());
  }
  if (model.cols() < 3) {
    throw InvalidArgument("model_object: need at least 3 points, got " +
                          std::to_string(model.cols()));
  }
  check_weights(w, model.cols());
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    if (!model.col(i).allFinite())
      throw InvalidArgument(indexed("model_object", i) + " is not finite");
    if (!image.col(i).allFinite()) throw InvalidArgument(indexed(image_name, i) + " is not finite");
    for (Eigen::Index j = 0; j < i; ++j) {
      if (model.col(i) == model.col(j)) {
        throw InvalidArgument("model_object: points " + std::to_string(j) + " and " +
                              std::to_string(i) + " coincide");
      }
    }
  }
}

template <typename Options>
void check_options(const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
}

}  // namespace vantage::internal

// validate_correspondences(): estimate_pose()'s input checks, naming the Correspondences fields
// (the fields of a correspondence file) so that no front end has to rename an error.

#include <cmath>
#include <string>

#include "vantage/analysis/estimate_pose.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/layout.h"

namespace vantage {
namespace {

/// "the perspective method" (for "required by ...").
std::string method_phrase(PoseMethod method) {
  return std::string("the ") + to_string(method) + " method";
}

void require(bool present, const char* field, PoseMethod method) {
  if (!present) throw InvalidArgument(field, "missing, required by " + method_phrase(method));
}

void refuse(bool present, const char* field, PoseMethod method, const char* why) {
  if (present) {
    throw InvalidArgument(field,
                          std::string("not used by ") + method_phrase(method) + " (" + why + ")");
  }
}

void check_count(const char* field, Eigen::Index got, Eigen::Index expected,
                 const char* reference) {
  if (got == expected) return;
  throw InvalidArgument(field, "has " + std::to_string(got) + " entries, expected " +
                                   std::to_string(expected) + " (one per entry of " + reference +
                                   ")");
}

/// Finite columns whose coordinates stay within Layout::kMaxLength, so that differences and
/// squares are finite.
template <int Rows>
void check_coordinates(const char* field, const Eigen::Matrix<double, Rows, Eigen::Dynamic>& m) {
  for (Eigen::Index k = 0; k < m.cols(); ++k) {
    if (!m.col(k).allFinite()) throw InvalidArgument(field, static_cast<long>(k), "not finite");
    if (!(m.col(k).cwiseAbs().maxCoeff() <= Layout::kMaxLength)) {
      throw InvalidArgument(field, static_cast<long>(k),
                            "a coordinate beyond 1e150 (differences and squares would overflow)");
    }
  }
}

void check_camera(const Camera& camera) {
  if (!(camera.focal_length >= 0.0 && camera.focal_length <= Layout::kMaxLength)) {
    throw InvalidArgument("camera.focal",
                          "must be a finite number > 0 and at most 1e150 (pixels), or absent");
  }
  if (!camera.principal_point.allFinite() ||
      !(camera.principal_point.cwiseAbs().maxCoeff() <= Layout::kMaxLength)) {
    throw InvalidArgument("camera.principal_point", "must be two finite numbers (pixels)");
  }
}

void check_weights(const Eigen::VectorXd& weights, Eigen::Index n, const char* reference) {
  if (weights.size() == 0) return;
  check_count("weights", weights.size(), n, reference);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!(weights(k) > 0.0 && weights(k) <= Layout::kMaxWeight)) {
      throw InvalidArgument("weights", static_cast<long>(k), "must be positive and finite");
    }
  }
}

void check_min_count(const char* field, Eigen::Index n, Eigen::Index minimum, const char* noun,
                     PoseMethod method) {
  if (n >= minimum) return;
  throw InvalidArgument(field, "has " + std::to_string(n) + " " + noun + ", " +
                                   method_phrase(method) + " needs at least " +
                                   std::to_string(minimum));
}

void check_distinct(const Eigen::Matrix3Xd& model) {
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    for (Eigen::Index j = 0; j < i; ++j) {
      if (model.col(i) == model.col(j)) {
        throw InvalidArgument("model", static_cast<long>(i),
                              "coincides with model[" + std::to_string(j) + "]");
      }
    }
  }
}

/// Prop. 4 solves 2^m sign patterns: an explicit set beyond the limit is refused.
void check_free_vector_budget(PoseMethod method, Eigen::Index n, const PoseOptions& options) {
  const bool enumerates = method == PoseMethod::kAffine || method == PoseMethod::kAffineRefined ||
                          method == PoseMethod::kPerspective;
  if (!enumerates || options.free_vectors == FreeVectorSet::kAuto) return;
  const Eigen::Index m = free_vector_count(n, options.free_vectors);
  const int limit = options.orientation.max_vectors;
  if (m <= limit) return;
  throw InvalidArgument("model", std::to_string(n) + " points give " + std::to_string(m) +
                                     " free vectors, more than the limit " + std::to_string(limit) +
                                     " of Prop. 4 (2^" + std::to_string(m) +
                                     " sign patterns); the auto free-vector set stays within it");
}

void check_directions(PoseMethod method, const Correspondences& data) {
  if (method != PoseMethod::kAffine && method != PoseMethod::kStandard) {
    throw InvalidArgument("directions", method_phrase(method) +
                                            " needs marker points (only affine and standard "
                                            "take direction data)");
  }
  require(data.model.cols() > 0, "model", method);
  require(data.image.cols() > 0, "image", method);
  check_count("image", data.image.cols(), data.model.cols(), "model");
  check_min_count("model", data.model.cols(), 2, "vectors", method);
  check_coordinates<3>("model", data.model);
  check_coordinates<2>("image", data.image);
  for (Eigen::Index k = 0; k < data.model.cols(); ++k) {
    if (!(data.model.col(k).squaredNorm() > 0.0)) {
      throw InvalidArgument("model", static_cast<long>(k), "zero vector");
    }
  }
  check_weights(data.weights, data.model.cols(), "model");
}

}  // namespace

bool PoseOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!orientation.is_valid(&inner)) return internal::invalid_option(why, "orientation", inner);
  if (!branches.is_valid(&inner)) return internal::invalid_option(why, "branches", inner);
  return true;
}

void validate_correspondences(PoseMethod method, const Correspondences& data,
                              const PoseOptions& options) {
  internal::check_options("options", options);
  check_camera(data.camera);
  if (data.directions) {
    check_directions(method, data);
    return;
  }
  const Eigen::Index n = data.model.cols();
  switch (pose_data(method)) {
    case PoseData::kImage:
    case PoseData::kPlanar:
      require(n > 0, "model", method);
      require(data.image.cols() > 0, "image", method);
      check_count("image", data.image.cols(), n, "model");
      check_min_count("model", n, pose_data(method) == PoseData::kPlanar ? 1 : 3, "points", method);
      check_coordinates<3>("model", data.model);
      check_coordinates<2>("image", data.image);
      break;
    case PoseData::kMeasured:
      require(n > 0, "model", method);
      require(data.measured.cols() > 0, "measured", method);
      check_count("measured", data.measured.cols(), n, "model");
      check_min_count("model", n, 3, "points", method);
      check_coordinates<3>("model", data.model);
      check_coordinates<3>("measured", data.measured);
      break;
    case PoseData::kTwoViews:
      require(data.image1.cols() > 0, "image1", method);
      require(data.image2.cols() > 0, "image2", method);
      refuse(data.weights.size() > 0, "weights", method, "the two-view algorithm is unweighted");
      check_count("image2", data.image2.cols(), data.image1.cols(), "image1");
      check_min_count("image1", data.image1.cols(), 8, "points", method);
      check_coordinates<2>("image1", data.image1);
      check_coordinates<2>("image2", data.image2);
      return;
  }
  if (pose_data(method) == PoseData::kPlanar) {
    for (Eigen::Index k = 0; k < n; ++k) {
      if (data.model(2, k) != 0.0) {
        throw InvalidArgument("model", static_cast<long>(k),
                              "z must be 0 (the 2-D pose takes planar points)");
      }
    }
  } else {
    check_distinct(data.model);
  }
  check_weights(data.weights, n, "model");
  check_free_vector_budget(method, n, options);
}

}  // namespace vantage

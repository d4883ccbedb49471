#pragma once

/// Two measures of a set of data vectors that every layout report shows beside its worst
/// viewpoint: the ceiling no layout of m vectors can beat, and how close the vectors are to a
/// plane (the two-fold ambiguity risk).

#include <Eigen/Core>

namespace vantage::sdp {

/// The ceiling of docs/math.md §15: p-bar_min <= cos(pi / (2 m)) for m >= 1 data vectors
/// (covering the sphere with m zones needs total width >= pi; Jiang & Polyanskii 2017).
/// Throws InvalidArgument for m < 1.
double pbar_ceiling(long m);

/// How close the data vectors are to one plane: the two-fold ambiguity risk.
struct Coplanarity {
  /// Smallest singular value of [n_1 ... n_m] / sqrt(m) (n_i = z_i / ||z_i||): 0 for coplanar
  /// vectors, 1/sqrt(3) = 0.577 for an isotropic set (e.g. Z = I); about the RMS sine of the
  /// angle between the vectors and their best-fit plane.
  double smallest_singular_value = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< normal of the best-fit plane
  double threshold = 0.1;                             ///< the threshold it was judged by
  bool nearly_coplanar = false;                       ///< smallest_singular_value < threshold
};

/// Coplanarity of `vectors` (3 x m, m >= 1, non-zero finite columns). threshold >= 0.
/// Throws InvalidArgument on bad input.
Coplanarity coplanarity(const Eigen::Matrix3Xd& vectors, double threshold = 0.1);

}  // namespace vantage::sdp

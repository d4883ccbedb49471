#pragma once

/// The certified worst case of a set of data vectors seen whole (Theorem 6, Eq. 31): the one
/// record that every result with such a worst case composes (a design step, a dropout entry),
/// and the one place that turns a WorstViewpoint into it.

#include <Eigen/Core>
#include <vector>

#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {

/// The global worst viewpoint of a set of data vectors, its error bound and its certificate.
struct CertifiedWorst {
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();  ///< the reported optimum, upper hemisphere
  std::vector<Eigen::Vector3d> viewpoints;  ///< every global optimum up to sign, viewpoint first
  double t = 0.0;                           ///< max_a min_i |a.n_i| (Eq. 31)
  double pbar_min = 1.0;                    ///< sqrt(1 - t^2) (Eq. 29 corrected, docs/math.md §12)
  /// Largest worst-case angular error of Eq. (30) over the data vectors and every worst
  /// viewpoint, in degrees (max_worst_case_error_deg below).
  double max_worst_case_error_deg = 0.0;
  bool certified = false;  ///< WorstViewpoint::certified(): the certificate closed
};

/// The record of `worst`, the global worst viewpoint of `vectors` (3 x m, the vectors it was
/// computed for). A search that stopped without listing its optima lists `worst.viewpoint`.
CertifiedWorst certified_worst(const WorstViewpoint& worst, const Eigen::Matrix3Xd& vectors);

/// The record of one data vector `v` (non-zero): it is seen end-on from its own direction,
/// t = 1, p-bar_min = 0, and the error is the limit arccos(p-bar_min) = 90 degrees (docs/math.md
/// §11). Certified: the optimum is exact.
CertifiedWorst certified_worst_end_on(const Eigen::Vector3d& v);

/// The largest Eq. (30) error over the columns of `vectors` and the directions `viewpoints`
/// (vantage::worst_case_errors_deg, analysis/error_bounds.h), degrees; 0 when `viewpoints` is
/// empty.
double max_worst_case_error_deg(const Eigen::Matrix3Xd& vectors,
                                const std::vector<Eigen::Vector3d>& viewpoints);

}  // namespace vantage::sdp

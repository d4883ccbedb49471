#pragma once

// Private: the sign-enumeration engine of Prop. 4 (affine_orientation.cc): the problem in object
// units, the Gray-code walk with the update of Eq. (17), the podium of best patterns, and the
// three enumerations of SignEnumeration.

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/quaternion.h"

namespace vantage::internal {

/// Checks of the vector problems (Prop. 4, Lemma 7, LUB, cross-check): d has one column per
/// column of z, at least min_count of them, z columns finite and non-zero, d columns finite.
template <int Rows>
void validate_vectors(const Eigen::Matrix3Xd& z,
                      const Eigen::Matrix<double, Rows, Eigen::Dynamic>& d,
                      const Eigen::VectorXd& w, Eigen::Index min_count, const char* d_name) {
  check_count_matches(d_name, d.cols(), z.cols(), "z_object");
  check_min_count("z_object", z.cols(), min_count, "vectors");
  check_weights("weights", w, z.cols(), "z_object");
  check_nonzero_finite_columns("z_object", z);
  check_finite_columns(d_name, d);
}

/// "z_object: <n> vectors exceed options.max_vectors = <m> (...)<hint>" when n > max_vectors.
inline void check_count(Eigen::Index n, const AffineOrientationOptions& options, const char* hint) {
  if (n <= options.max_vectors) return;
  std::ostringstream out;
  out << n << " vectors exceed options.max_vectors = " << options.max_vectors
      << " (Prop. 4 solves 2^" << n << " problems)" << hint;
  fail("z_object", out.str());
}

/// Everything the per-pattern work needs, in object units (d scaled by alpha).
struct AffineProblem {
  Eigen::Matrix2Xd d;     // alpha d_i
  Eigen::VectorXd w;      // explicit weights
  Eigen::VectorXd v_z;    // |v_zi| >= 0, object units
  std::vector<int> free;  // vectors with two signs, in enumeration bit order
  int clamped = 0;
  int in_plane = 0;
  // J_2d(R) = trace(S) - r3^T S r3 - 2 sum_{k<2} R.row(k) G.col(k) + dd, with
  // S = sum w z z^T, G = sum w z (alpha d)^T, dd = sum w |alpha d|^2.
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> G = Eigen::Matrix<double, 3, 2>::Zero();
  double dd = 0.0;
  double energy = 0.0;  // sum w |z|^2
};

AffineProblem prepare(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d, double alpha,
                      const Eigen::VectorXd& weights, const AffineOrientationOptions& options);

/// J_2d = sum w |P R z - d_object|^2 summed directly.
double residual_direct(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d_object,
                       const Eigen::VectorXd& w, const Eigen::Matrix3d& R);

/// D of Eq. (2) for the pattern whose bit b (over `order`) negates v_z(order[b]).
Eigen::Matrix4d pattern_d(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d_object,
                          const Eigen::VectorXd& v_z, const Eigen::VectorXd& w,
                          const std::vector<int>& order, std::uint64_t signs);

/// The Gray-code walk over the sign patterns of `order`: the all-positive pattern first, then at
/// step k the sign of bit ctz(k) toggles; D changes by Eq. (17) with the factor of docs/math.md §9,
/// Delta D = -2 w_j v_zj K(e_z, z_j) (v_zj the value before the toggle), and the third column h
/// of H = sum w z v^T by -2 w_j v_zj z_j. visit(D, h, signs) is called for each of the 2^m
/// patterns; nothing is allocated inside the walk.
class GrayCodeWalk {
 public:
  GrayCodeWalk(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d_object,
               const Eigen::VectorXd& v_z, const Eigen::VectorXd& w, std::vector<int> order)
      : order_(std::move(order)), D_(pattern_d(z, d_object, v_z, w, order_, 0)) {
    const Eigen::Vector3d e_z = Eigen::Vector3d::UnitZ();
    h_.setZero();
    for (Eigen::Index i = 0; i < z.cols(); ++i) h_ += weight_at(w, i) * v_z(i) * z.col(i);
    step_d_.reserve(order_.size());
    step_h_.reserve(order_.size());
    for (const int j : order_) {
      step_d_.push_back(-2.0 * weight_at(w, j) * v_z(j) * quaternion_k(e_z, z.col(j)));
      step_h_.push_back(-2.0 * weight_at(w, j) * v_z(j) * z.col(j));
    }
  }

  std::uint64_t patterns() const { return std::uint64_t{1} << order_.size(); }

  /// Visits the first steps + 1 patterns.
  template <typename Visit>
  void run(std::uint64_t steps, Visit&& visit) {
    std::uint64_t signs = 0;
    visit(D_, h_, signs);
    for (std::uint64_t k = 1; k <= steps; ++k) {
      const int b = __builtin_ctzll(k);
      const std::uint64_t bit = std::uint64_t{1} << b;
      if (signs & bit) {  // v_zj currently negative: the step has the opposite sign
        D_ -= step_d_[b];
        h_ -= step_h_[b];
      } else {
        D_ += step_d_[b];
        h_ += step_h_[b];
      }
      signs ^= bit;
      visit(D_, h_, signs);
    }
  }

 private:
  std::vector<int> order_;
  Eigen::Matrix4d D_;
  Eigen::Vector3d h_;
  std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>> step_d_;
  std::vector<Eigen::Vector3d, Eigen::aligned_allocator<Eigen::Vector3d>> step_h_;
};

/// The kPodiumSize best patterns seen so far, by increasing J_2d. More than two are kept
/// because flipping the sign of a near-zero v_z gives a near-copy of the winner; the runner-up
/// that measures the two-fold ambiguity is the best pattern with a distinct rotation.
struct Podium {
  static constexpr int kPodiumSize = 64;
  double j[kPodiumSize];
  std::uint64_t signs[kPodiumSize];
  int count = 0;
  /// J_2d a pattern must beat to enter (+infinity until the podium is full).
  double threshold = std::numeric_limits<double>::infinity();

  void offer(double value, std::uint64_t pattern) {
    if (!(value < threshold)) return;
    int at = count < kPodiumSize ? count++ : kPodiumSize - 1;
    for (; at > 0 && value < j[at - 1]; --at) {
      j[at] = j[at - 1];
      signs[at] = signs[at - 1];
    }
    j[at] = value;
    signs[at] = pattern;
    if (count == kPodiumSize) threshold = j[kPodiumSize - 1];
  }
};

/// kGrayCode (quartic = true) or kGrayCodeEigen (false): every pattern offered to the podium;
/// *fallbacks counts the patterns sent to top_eigenpair() and its full-solver fallbacks.
void enumerate_gray_code(const Eigen::Matrix3Xd& z, const AffineProblem& problem,
                         const AffineOrientationOptions& options, bool quartic, Podium* podium,
                         std::uint64_t* fallbacks);

/// kNaive: D recomputed and fully eigen-solved per pattern, J_2d summed over all vectors.
void enumerate_naive(const Eigen::Matrix3Xd& z, const AffineProblem& problem, Podium* podium);

}  // namespace vantage::internal

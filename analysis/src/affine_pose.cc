
#include "vantage/analysis/affine_pose.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/StdVector>
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <random>
#include <sstream>
#include <vector>

#include "vantage/analysis/common.h"

namespace vantage {

const char* to_string(SignEnumeration enumeration) {
  switch (enumeration) {
    case SignEnumeration::kGrayCode:
      return "gray_code";
    case SignEnumeration::kGrayCodeEigen:
      return "gray_code_eigen";
    case SignEnumeration::kNaive:
      return "naive";
  }
  return "unknown";
}

const char* to_string(AffineStatus status) {
  switch (status) {
    case AffineStatus::kOk:
      return "ok";
    case AffineStatus::kAmbiguous:
      return "ambiguous";
    case AffineStatus::kDegenerate:
      return "degenerate";
  }
  return "unknown";
}

const char* to_string(FreeVectorSet set) {
  switch (set) {
    case FreeVectorSet::kAllPairs:
      return "all_pairs";
    case FreeVectorSet::kMaxSpanningTree:
      return "max_spanning_tree";
  }
  return "unknown";
}

const char* to_string(PairWeighting weighting) {
  switch (weighting) {
    case PairWeighting::kGeometricMean:
      return "geometric_mean";
    case PairWeighting::kArithmeticMean:
      return "arithmetic_mean";
  }
  return "unknown";
}

namespace {

bool fail(std::string* why, const char* text) {
  if (why) *why = text;
  return false;
}

}  // namespace

bool AffineOrientationOptions::is_valid(std::string* why) const {
  if (!(max_vectors >= 1 && max_vectors <= kMaxAffineVectorsCeiling))
    return fail(why, "max_vectors must be in [1, 30]");
  if (!(in_plane_tolerance >= 0.0 && in_plane_tolerance < 1.0))
    return fail(why, "in_plane_tolerance must be in [0, 1)");
  if (!(ambiguity_tolerance >= 0.0)) return fail(why, "ambiguity_tolerance must be >= 0");
  if (!(distinct_rotation_angle >= 0.0)) return fail(why, "distinct_rotation_angle must be >= 0");
  if (!(degenerate_gap >= 0.0 && degenerate_gap < 1.0))
    return fail(why, "degenerate_gap must be in [0, 1)");
  if (!(eigen.fallback_relative_gap >= 0.0 && eigen.fallback_relative_gap < 1.0))
    return fail(why, "eigen.fallback_relative_gap must be in [0, 1)");
  return true;
}

bool AffinePoseOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!orientation.is_valid(&inner)) {
    if (why) *why = "orientation." + inner;
    return false;
  }
  if (!(focal_length >= 0.0 && std::isfinite(focal_length)))
    return fail(why, "focal_length must be finite and >= 0 (0: unknown)");
  return true;
}

bool AffineCrossCheckOptions::is_valid(std::string* why) const {
  if (!(starts >= 1)) return fail(why, "starts must be >= 1");
  if (!(x_tolerance > 0.0)) return fail(why, "x_tolerance must be > 0");
  if (!(max_evaluations >= 1)) return fail(why, "max_evaluations must be >= 1");
  return true;
}

namespace {

using Matrix4dVector = std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>;

std::string indexed(const char* name, Eigen::Index i) {
  return std::string(name) + "[" + std::to_string(i) + "]";
}

double weight_at(const Eigen::VectorXd& w, Eigen::Index i) { return w.size() == 0 ? 1.0 : w(i); }

void check_weights(const Eigen::VectorXd& w, Eigen::Index n) {
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

void check_alpha(double alpha) {
  if (!(alpha > 0.0 && std::isfinite(alpha)))
    throw InvalidArgument("alpha must be positive and finite");
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
                      const Eigen::VectorXd& weights, const AffineOrientationOptions& options) {
  const Eigen::Index n = z.cols();
  AffineProblem problem;
  problem.d = alpha * d;
  problem.w = weights.size() == 0 ? Eigen::VectorXd::Ones(n) : weights;
  problem.v_z = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double zz = z.col(i).squaredNorm();
    const double missing = zz - problem.d.col(i).squaredNorm();  // Eq. (21) times alpha^2
    if (missing < 0.0 && -missing > options.in_plane_tolerance * zz) {
      ++problem.clamped;  // DESIGN.md note 7: |d_i| > |z_i| / alpha
    } else if (missing <= options.in_plane_tolerance * zz) {
      ++problem.in_plane;
    } else {
      problem.v_z(i) = std::sqrt(missing);
      problem.free.push_back(static_cast<int>(i));
    }
    const double wi = problem.w(i);
    problem.S.noalias() += wi * z.col(i) * z.col(i).transpose();
    problem.G.noalias() += wi * z.col(i) * problem.d.col(i).transpose();
    problem.dd += wi * problem.d.col(i).squaredNorm();
    problem.energy += wi * zz;
  }
  return problem;
}

double residual_from_moments(const AffineProblem& problem, const Eigen::Matrix3d& R) {
  const Eigen::Vector3d r3 = R.row(2).transpose();
  const double j = problem.S.trace() - r3.dot(problem.S * r3) -
                   2.0 * (R.row(0).dot(problem.G.col(0)) + R.row(1).dot(problem.G.col(1))) +
                   problem.dd;
  return std::max(0.0, j);
}

double residual_direct(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d_object,
                       const Eigen::VectorXd& w, const Eigen::Matrix3d& R) {
  double j = 0.0;
  for (Eigen::Index i = 0; i < z.cols(); ++i) {
    j += weight_at(w, i) * (R.topRows<2>() * z.col(i) - d_object.col(i)).squaredNorm();
  }
  return j;
}

/// D of Eq. (2) for the pattern whose bit b (over `order`) negates v_z(order[b]).
Eigen::Matrix4d pattern_d(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d_object,
                          const Eigen::VectorXd& v_z, const Eigen::VectorXd& w,
                          const std::vector<int>& order, std::uint64_t signs) {
  Eigen::VectorXd signed_v_z = v_z;
  for (std::size_t b = 0; b < order.size(); ++b) {
    if ((signs >> b) & 1u) signed_v_z(order[b]) = -signed_v_z(order[b]);
  }
  Eigen::Matrix4d D = Eigen::Matrix4d::Zero();
  for (Eigen::Index i = 0; i < z.cols(); ++i) {
    const Eigen::Vector3d v(d_object(0, i), d_object(1, i), signed_v_z(i));
    D += weight_at(w, i) * quaternion_k(v, z.col(i));
  }
  return D;
}

/// The Gray-code walk over the sign patterns of `order`: the all-positive pattern first, then at
/// step k the sign of bit ctz(k) toggles; D changes by Eq. (17) with DESIGN.md note 2's factor,
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
  Matrix4dVector step_d_;
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

/// Pattern-independent part of kGrayCode's per-pattern solve. H = [a b h] with a, b fixed.
struct QuarticSolver {
  Eigen::Vector3d a, b, a_cross_b;
  double ab2 = 0.0;           // |a|^2 + |b|^2
  double axb2 = 0.0;          // |a x b|^2
  double lambda_bound = 0.0;  // sum w |z| |v| >= lambda_max for every pattern
  double fallback_gap = 0.0;

  /// Upper bound on lambda_max for the third column h without any other knowledge:
  /// lambda_max = s1 + s2 +- s3 <= min(sum w |z||v|, sqrt(3 |H|^2), sqrt(|H|^2 + 2 sqrt(3)
  /// |adj H|)) with s the singular values of H.
  double cold_bound(const Eigen::Vector3d& h) const {
    const double f2 = ab2 + h.squaredNorm();
    const double adj2 = axb2 + b.cross(h).squaredNorm() + h.cross(a).squaredNorm();
    return std::min(
        {lambda_bound, std::sqrt(3.0 * f2), std::sqrt(f2 + 2.0 * std::sqrt(3.0 * adj2))});
  }

  static constexpr int kMaxIterations = 100;
  /// Laguerre stops once a step is below kLaguerreStop * x: the error left is of order
  /// kLaguerreStop^3 x (cubic convergence).
  static constexpr double kLaguerreStop = 1e-4;
  /// Steps every lane takes before the first convergence test (see solve_lanes).
  static constexpr int kLockstepIterations = 2;
};

/// One Laguerre step on x^4 + c2 x^2 + c1 x + c0 (DESIGN.md note 8). For a polynomial with only
/// real roots Laguerre's method converges monotonically (and cubically) to the largest root
/// from any start above it; with degree 4 its step is 4 p / (p' + sqrt(3 (3 p'^2 - 4 p p''))).
/// At (or, by rounding, just below) the root p <= 0 and the step is 0, as is any non-positive
/// or NaN step, so further steps never move a converged x. Works on doubles and on Eigen arrays.
template <typename T>
T laguerre_step(const T& x, const T& c2, const T& c1, const T& c0) {
  const T x2 = x * x;
  const T p = (x2 + c2) * x2 + c1 * x + c0;
  const T dp = (4.0 * x2 + 2.0 * c2) * x + c1;
  const T ddp = 12.0 * x2 + 2.0 * c2;
  const T disc = (3.0 * (3.0 * dp * dp - 4.0 * p * ddp)).max(T::Zero());
  const T step = 4.0 * p / (dp + disc.sqrt());
  return (p > 0.0 && step > 0.0).select(step, T::Zero());
}

/// One Halley step 2 p p' / (2 p'^2 - p p'') on the same quartic: cubically convergent like
/// Laguerre's, without the square root. Above the largest root of a real-rooted quartic,
/// u = p p'' / p'^2 is in [0, 3/4] and Halley's step (p / p') / (1 - u / 2) never exceeds
/// Laguerre's (4 p / p') / (1 + 3 sqrt(1 - 4 u / 3)) (the difference reduces to 4 u^2 >= 0), so
/// it never overshoots the root either: safe from any upper bound, and best once close.
template <typename T>
T halley_step(const T& x, const T& c2, const T& c1, const T& c0) {
  const T x2 = x * x;
  const T p = (x2 + c2) * x2 + c1 * x + c0;
  const T dp = (4.0 * x2 + 2.0 * c2) * x + c1;
  const T ddp = 12.0 * x2 + 2.0 * c2;
  const T step = 2.0 * p * dp / (2.0 * dp * dp - p * ddp);
  return (p > 0.0 && step > 0.0).select(step, T::Zero());
}

inline double laguerre_step(double x, double c2, double c1, double c0) {
  using One = Eigen::Array<double, 1, 1>;
  return laguerre_step(One(x), One(c2), One(c1), One(c0))(0);
}

#if defined(__GNUC__)
// Inline Eigen's per-expression loops into the caller (GCC and Clang; no ISA assumption).
#define VANTAGE_FLATTEN __attribute__((flatten))
#else
#define VANTAGE_FLATTEN
#endif

/// kGrayCode's lanes: the top kLaneBits sign bits are fixed per lane and the Gray code walks
/// the others, so each step solves kLanes independent patterns. Their root finders run in
/// lockstep on Eigen arrays (SIMD packets of the build's baseline ISA, no branches per lane), so
/// the kLanes dependency chains (each warm-started from its own previous root) overlap.
constexpr int kLaneBits = 4;
constexpr int kLanes = 1 << kLaneBits;
using LaneArray = Eigen::Array<double, kLanes, 1>;

/// Per-lane result of one Gray-code step.
struct LaneSolve {
  LaneArray lambda;  // largest root of the quartic
  LaneArray j;       // J_2d of the viewpoint FOAM gives for it; -1: not trusted, fall back
};

/// The quartic's largest root from the upper bounds x, FOAM's viewpoint r3 and J_2d for kLanes
/// third columns h. Every lane takes one Laguerre step (robust from a far start) and one Halley
/// step; if some lane's last step still exceeded kLaguerreStop * x, all take another Halley
/// step, and a lane still not converged continues alone with Laguerre. Steps on a converged lane
/// are 0 or refine it, so the lockstep never loses accuracy against per-lane stopping.
VANTAGE_FLATTEN void solve_lanes(const QuarticSolver& solver, const AffineProblem& problem,
                                 const LaneArray& hx, const LaneArray& hy, const LaneArray& hz,
                                 LaneArray x, LaneSolve* out) {
  const Eigen::Vector3d& a = solver.a;
  const Eigen::Vector3d& b = solver.b;
  const Eigen::Vector3d& c = solver.a_cross_b;
  const LaneArray hh = hx * hx + hy * hy + hz * hz;
  const LaneArray ha = a.x() * hx + a.y() * hy + a.z() * hz;
  const LaneArray hb = b.x() * hx + b.y() * hy + b.z() * hz;
  const LaneArray f2 = solver.ab2 + hh;                        // |H|_F^2
  const LaneArray det = c.x() * hx + c.y() * hy + c.z() * hz;  // det H
  // |adj H|_F^2 = |a x b|^2 + |b x h|^2 + |h x a|^2 by Lagrange's identity.
  const LaneArray adj2 = solver.axb2 + solver.ab2 * hh - ha * ha - hb * hb;
  // (x^2 - f2)^2 - 8 x det - 4 adj2 = x^4 + c2 x^2 + c1 x + c0 (DESIGN.md note 8).
  const LaneArray c2 = -2.0 * f2;
  const LaneArray c1 = -8.0 * det;
  const LaneArray c0 = f2 * f2 - 4.0 * adj2;
  x -= laguerre_step(x, c2, c1, c0);
  LaneArray step = halley_step(x, c2, c1, c0);
  x -= step;
  if ((step - QuarticSolver::kLaguerreStop * x).maxCoeff() > 0.0) {  // a packed max, no branches
    step = halley_step(x, c2, c1, c0);
    x -= step;
    for (int t = 0; t < kLanes; ++t) {
      double s = step(t);
      for (int it = QuarticSolver::kLockstepIterations + 1;
           s > QuarticSolver::kLaguerreStop * x(t) && it < QuarticSolver::kMaxIterations; ++it) {
        s = laguerre_step(x(t), c2(t), c1(t), c0(t));
        x(t) -= s;
      }
    }
  }
  // FOAM: the third row of A = [(kappa + f2) B + lambda adj(B^T) - B B^T B] / zeta, B = H^T.
  const LaneArray kappa = 0.5 * (x * x - f2);
  const LaneArray zeta = kappa * x - det;
  const LaneArray g = kappa + f2 - hh;
  const LaneArray inv_zeta = 1.0 / zeta;
  LaneArray rx = (g * hx + x * c.x() - ha * a.x() - hb * b.x()) * inv_zeta;
  LaneArray ry = (g * hy + x * c.y() - ha * a.y() - hb * b.y()) * inv_zeta;
  LaneArray rz = (g * hz + x * c.z() - ha * a.z() - hb * b.z()) * inv_zeta;
  // |r3| = 1 up to the root's error: one Newton step of 1/sqrt restores unit length.
  const LaneArray unit = 1.5 - 0.5 * (rx * rx + ry * ry + rz * rz);
  rx *= unit;
  ry *= unit;
  rz *= unit;
  // J_2d = tr S - r3^T S r3 - 2 (lambda - r3^T h) + sum w |alpha d|^2 (moment form).
  const Eigen::Matrix3d& S = problem.S;
  const LaneArray srs = S(0, 0) * rx * rx + S(1, 1) * ry * ry + S(2, 2) * rz * rz +
                        2.0 * (S(0, 1) * rx * ry + S(0, 2) * rx * rz + S(1, 2) * ry * rz);
  const LaneArray rh = rx * hx + ry * hy + rz * hz;
  out->lambda = x;
  // A lane FOAM cannot trust (zeta <= fallback_gap lambda^3), or whose J_2d is NaN (overflow),
  // gets j = -1 and falls back to top_eigenpair(); so no entry of j is NaN.
  const LaneArray j = (S.trace() + problem.dd) - srs - 2.0 * (x - rh);
  out->j = (x > 0.0 && zeta > solver.fallback_gap * x * x * x && j == j)
               .select(j.max(LaneArray::Zero()), LaneArray::Constant(-1.0));
}

void enumerate_gray_code(const Eigen::Matrix3Xd& z, const AffineProblem& problem,
                         const AffineOrientationOptions& options, bool quartic, Podium* podium,
                         std::uint64_t* fallbacks) {
  std::uint64_t used_fallback = 0;
  const auto eigen_path = [&](const Eigen::Matrix4d& D, std::uint64_t signs) {
    const TopEigenpair top = top_eigenpair(D, options.eigen);
    used_fallback += top.used_fallback ? 1 : 0;
    podium->offer(residual_from_moments(problem, rotation_from_quaternion(top.vector)), signs);
  };
  if (!quartic) {
    GrayCodeWalk walk(z, problem.d, problem.v_z, problem.w, problem.free);
    walk.run(walk.patterns() - 1, [&](const Eigen::Matrix4d& D, const Eigen::Vector3d&,
                                      std::uint64_t signs) { eigen_path(D, signs); });
    *fallbacks = used_fallback;
    return;
  }

  QuarticSolver solver;
  solver.a = problem.G.col(0);
  solver.b = problem.G.col(1);
  solver.a_cross_b = solver.a.cross(solver.b);
  solver.ab2 = solver.a.squaredNorm() + solver.b.squaredNorm();
  solver.axb2 = solver.a_cross_b.squaredNorm();
  for (Eigen::Index i = 0; i < z.cols(); ++i) {
    const double v_norm =
        std::sqrt(problem.d.col(i).squaredNorm() + problem.v_z(i) * problem.v_z(i));
    solver.lambda_bound += problem.w(i) * z.col(i).norm() * v_norm;
  }
  solver.fallback_gap = options.eigen.fallback_relative_gap;

  // With m <= kLaneBits free vectors only 2^m lanes are active; the others repeat lane 0 and
  // are ignored.
  const int m = static_cast<int>(problem.free.size());
  const int lane_bits = std::min(m, kLaneBits);
  const int lanes = 1 << lane_bits;
  const int low_bits = m - lane_bits;
  const std::vector<int> low(problem.free.begin(), problem.free.begin() + low_bits);
  GrayCodeWalk walk(z, problem.d, problem.v_z, problem.w, low);
  // Offsets of lane t (bit k of t negates v_z of free vector low_bits + k) from the walk's H, D.
  LaneArray lane_hx = LaneArray::Zero(), lane_hy = LaneArray::Zero(), lane_hz = LaneArray::Zero();
  Eigen::Matrix4d lane_d[kLanes];
  for (int t = 0; t < kLanes; ++t) {
    lane_d[t].setZero();
    for (int k = 0; k < lane_bits && t < lanes; ++k) {
      if (!((t >> k) & 1)) continue;
      const int j = problem.free[low_bits + k];
      const double scale = -2.0 * problem.w(j) * problem.v_z(j);
      lane_hx(t) += scale * z(0, j);
      lane_hy(t) += scale * z(1, j);
      lane_hz(t) += scale * z(2, j);
      lane_d[t] += scale * quaternion_k(Eigen::Vector3d::UnitZ(), z.col(j));
    }
  }
  // lambda_max = max_R trace(R H) moves by at most |Delta h| when h changes, so the previous
  // root plus |Delta h| bounds the next one from above: a warm start for the root finder.
  std::vector<double> step_norm;
  for (const int j : low)
    step_norm.push_back(2.0 * problem.w(j) * problem.v_z(j) * z.col(j).norm());
  const double slack = 1e-12 * solver.lambda_bound;
  LaneArray previous = LaneArray::Constant(-1.0);  // < 0: no warm start
  std::uint64_t previous_signs = 0;
  LaneSolve solved;
  walk.run(walk.patterns() - 1, [&](const Eigen::Matrix4d& D, const Eigen::Vector3d& h_low,
                                    std::uint64_t low_signs) {
    const double step =
        low_signs == previous_signs ? 0.0 : step_norm[__builtin_ctzll(low_signs ^ previous_signs)];
    previous_signs = low_signs;
    const LaneArray hx = h_low.x() + lane_hx;
    const LaneArray hy = h_low.y() + lane_hy;
    const LaneArray hz = h_low.z() + lane_hz;
    LaneArray warm = previous + (step + slack);
    if (previous.minCoeff() < 0.0) {
      for (int t = 0; t < kLanes; ++t) {
        if (previous(t) < 0.0)
          warm(t) = solver.cold_bound(Eigen::Vector3d(hx(t), hy(t), hz(t))) + slack;
      }
    }
    solve_lanes(solver, problem, hx, hy, hz, warm, &solved);
    previous = solved.lambda;
    if (!(solved.j.minCoeff() < podium->threshold)) return;  // nothing to offer or fall back
    for (int t = 0; t < lanes; ++t) {
      const std::uint64_t signs = low_signs | (static_cast<std::uint64_t>(t) << low_bits);
      if (solved.j(t) < 0.0) {
        previous(t) = -1.0;
        ++used_fallback;
        eigen_path(D + lane_d[t], signs);
      } else if (solved.j(t) < podium->threshold) {
        podium->offer(solved.j(t), signs);
      }
    }
  });
  *fallbacks = used_fallback;
}

void enumerate_naive(const Eigen::Matrix3Xd& z, const AffineProblem& problem, Podium* podium) {
  const std::uint64_t patterns = std::uint64_t{1} << problem.free.size();
  for (std::uint64_t signs = 0; signs < patterns; ++signs) {
    const Eigen::Matrix4d D = pattern_d(z, problem.d, problem.v_z, problem.w, problem.free, signs);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(D);
    const Eigen::Matrix3d R = rotation_from_quaternion(solver.eigenvectors().col(3).normalized());
    podium->offer(residual_direct(z, problem.d, problem.w, R), signs);
  }
}

/// Theorem 1 on one sign pattern, from scratch.
OrientationResult solve_pattern(const Eigen::Matrix3Xd& z, const AffineProblem& problem,
                                std::uint64_t signs, const AffineOrientationOptions& options,
                                Eigen::VectorXd* signed_v_z) {
  Eigen::VectorXd v_z = problem.v_z;
  for (std::size_t b = 0; b < problem.free.size(); ++b) {
    if ((signs >> b) & 1u) v_z(problem.free[b]) = -v_z(problem.free[b]);
  }
  Eigen::Matrix3Xd v(3, z.cols());
  v.topRows<2>() = problem.d;
  v.row(2) = v_z.transpose();
  OrientationOptions theorem1;
  theorem1.eigen = options.eigen;
  theorem1.degenerate_gap = options.degenerate_gap;
  if (signed_v_z) *signed_v_z = v_z;
  return absolute_orientation(z, v, problem.w, theorem1);
}

AffineOrientationResult solve_affine(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d,
                                     double alpha, const Eigen::VectorXd& weights,
                                     const AffineOrientationOptions& options) {
  const AffineProblem problem = prepare(z, d, alpha, weights, options);
  Podium podium;
  AffineOrientationResult result;
  result.alpha = alpha;
  switch (options.enumeration) {
    case SignEnumeration::kGrayCode:
      enumerate_gray_code(z, problem, options, true, &podium, &result.eigen_fallbacks);
      break;
    case SignEnumeration::kGrayCodeEigen:
      enumerate_gray_code(z, problem, options, false, &podium, &result.eigen_fallbacks);
      break;
    case SignEnumeration::kNaive:
      enumerate_naive(z, problem, &podium);
      break;
  }
  result.sign_patterns = std::uint64_t{1} << problem.free.size();
  result.clamped = problem.clamped;
  result.in_plane = problem.in_plane;

  // Re-solve the winner (and runner-up) from scratch: exact R, free of update rounding, and the
  // eigen gap for the degeneracy test.
  Eigen::VectorXd v_z;
  const OrientationResult winner = solve_pattern(z, problem, podium.signs[0], options, &v_z);
  result.R_camera_object = winner.R_camera_object;
  result.eigen_gap = winner.eigen_gap;
  result.v_z = v_z / alpha;
  result.residual = residual_direct(z, problem.d, problem.w, result.R_camera_object);

  if (podium.count > 1) {
    // The runner-up is the best pattern whose rotation differs from the winner's by more than
    // distinct_rotation_angle (near-copies of the winner are skipped); when every kept pattern
    // is a near-copy, the second best is reported.
    for (int k = 1; k < podium.count; ++k) {
      const OrientationResult other = solve_pattern(z, problem, podium.signs[k], options, nullptr);
      const double angle = rotation_angle_between(result.R_camera_object, other.R_camera_object);
      if (k == 1 || angle > options.distinct_rotation_angle) {
        result.runner_up_R_camera_object = other.R_camera_object;
        result.runner_up_residual = residual_direct(z, problem.d, problem.w, other.R_camera_object);
        result.ambiguity_margin = std::max(0.0, result.runner_up_residual - result.residual);
        result.runner_up_angle = angle;
      }
      if (angle > options.distinct_rotation_angle) break;
    }
  } else {
    result.runner_up_residual = std::numeric_limits<double>::infinity();
    result.ambiguity_margin = std::numeric_limits<double>::infinity();
  }

  if (winner.status == OrientationStatus::kDegenerate) {
    result.status = AffineStatus::kDegenerate;
    result.message = "the winning sign pattern's 3-D problem is degenerate: " + winner.message;
  } else if (result.ambiguity_margin <= options.ambiguity_tolerance * problem.energy &&
             result.runner_up_angle > options.distinct_rotation_angle) {
    std::ostringstream out;
    out << "two poses fit equally well (runner-up " << result.runner_up_angle
        << " rad away, margin " << result.ambiguity_margin
        << "): coplanar vectors give the two-fold affine ambiguity";
    result.status = AffineStatus::kAmbiguous;
    result.message = out.str();
  }
  return result;
}

void check_count(Eigen::Index n, const AffineOrientationOptions& options, const char* hint) {
  if (n > options.max_vectors) {
    std::ostringstream out;
    out << "z_object: " << n << " vectors exceed options.max_vectors = " << options.max_vectors
        << " (Prop. 4 solves 2^" << n << " problems)" << hint;
    throw InvalidArgument(out.str());
  }
}

void check_options(const AffineOrientationOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
}

}  // namespace

AffineOrientationResult affine_orientation(const Eigen::Matrix3Xd& z_object,
                                           const Eigen::Matrix2Xd& d_image, double alpha,
                                           const Eigen::VectorXd& weights,
                                           const AffineOrientationOptions& options) {
  check_options(options);
  validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  check_alpha(alpha);
  check_count(z_object.cols(), options, "");
  return solve_affine(z_object, d_image, alpha, weights, options);
}

LubScale lub_scale(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image) {
  validate_vectors<2>(z_object, d_image, {}, 1, "d_image");
  LubScale lub;
  for (Eigen::Index i = 0; i < z_object.cols(); ++i) {
    const double ratio = d_image.col(i).norm() / z_object.col(i).norm();
    if (ratio > lub.max_ratio) {
      lub.max_ratio = ratio;
      lub.limiting = i;
    }
  }
  if (!(lub.max_ratio > 0.0)) {
    throw InvalidArgument("d_image: every image vector is zero, the scale is unbounded (Eq. 23)");
  }
  lub.alpha = 1.0 / lub.max_ratio;
  return lub;
}

ProjectionFractions projection_fractions(const Eigen::Matrix3Xd& z_object,
                                         const Eigen::Matrix2Xd& d_image, double alpha) {
  validate_vectors<2>(z_object, d_image, {}, 1, "d_image");
  check_alpha(alpha);
  ProjectionFractions out;
  out.p.resize(z_object.cols());
  for (Eigen::Index i = 0; i < z_object.cols(); ++i) {
    out.p(i) = alpha * d_image.col(i).norm() / z_object.col(i).norm();  // Eq. (19)
  }
  out.p_bar = out.p.maxCoeff();  // Eq. (24)
  if (!(out.p_bar > 0.0)) {
    throw InvalidArgument("d_image: every image vector is zero, p_bar = 0 (Eq. 24)");
  }
  out.beta = 1.0 / out.p_bar;  // Eq. (25)
  return out;
}

AffineOrientationResult affine_orientation_unknown_scale(const Eigen::Matrix3Xd& z_object,
                                                         const Eigen::Matrix2Xd& d_image,
                                                         const Eigen::VectorXd& weights,
                                                         const AffineOrientationOptions& options) {
  check_options(options);
  validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  check_count(z_object.cols(), options, "");
  return solve_affine(z_object, d_image, lub_scale(z_object, d_image).alpha, weights, options);
}

double affine_residual(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image,
                       double alpha, const Eigen::Matrix3d& R_camera_object,
                       const Eigen::VectorXd& weights) {
  validate_vectors<2>(z_object, d_image, weights, 1, "d_image");
  check_alpha(alpha);
  return residual_direct(z_object, alpha * d_image, weights, R_camera_object);
}

// ---------------------------------------------------------------------------------------------
// Prop. 8 and the baselines.

namespace {

template <int Rows>
void validate_points(const Eigen::Matrix3Xd& model,
                     const Eigen::Matrix<double, Rows, Eigen::Dynamic>& image,
                     const Eigen::VectorXd& w, const AffinePoseOptions& options,
                     const char* image_name) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
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

Eigen::Matrix2Xi free_vector_pairs(const Eigen::Matrix3Xd& model, FreeVectorSet set) {
  const int n = static_cast<int>(model.cols());
  if (set == FreeVectorSet::kAllPairs) {
    Eigen::Matrix2Xi pairs(2, n * (n - 1) / 2);
    int k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) pairs.col(k++) << i, j;
    return pairs;
  }
  // Prim's algorithm for the maximum spanning tree of the distances |z_i - z_j|.
  Eigen::Matrix2Xi pairs(2, n - 1);
  std::vector<bool> in_tree(n, false);
  std::vector<double> best(n, -1.0);
  std::vector<int> parent(n, 0);
  in_tree[0] = true;
  for (int j = 1; j < n; ++j) best[j] = (model.col(j) - model.col(0)).norm();
  for (int k = 0; k < n - 1; ++k) {
    int next = -1;
    for (int j = 0; j < n; ++j)
      if (!in_tree[j] && (next < 0 || best[j] > best[next])) next = j;
    in_tree[next] = true;
    pairs.col(k) << std::min(parent[next], next), std::max(parent[next], next);
    for (int j = 0; j < n; ++j) {
      const double distance = (model.col(j) - model.col(next)).norm();
      if (!in_tree[j] && distance > best[j]) {
        best[j] = distance;
        parent[j] = next;
      }
    }
  }
  return pairs;
}

template <int Rows>
void build_free_vectors(const Eigen::Matrix3Xd& model,
                        const Eigen::Matrix<double, Rows, Eigen::Dynamic>& measured,
                        const Eigen::VectorXd& weights, const AffinePoseOptions& options,
                        Eigen::Matrix2Xi* pairs, Eigen::Matrix3Xd* z,
                        Eigen::Matrix<double, Rows, Eigen::Dynamic>* d, Eigen::VectorXd* w) {
  *pairs = free_vector_pairs(model, options.free_vectors);
  const Eigen::Index m = pairs->cols();
  z->resize(3, m);
  d->resize(Rows, m);
  w->resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const int i = (*pairs)(0, k);
    const int j = (*pairs)(1, k);
    z->col(k) = model.col(i) - model.col(j);
    d->col(k) = measured.col(i) - measured.col(j);
    const double wi = weight_at(weights, i);
    const double wj = weight_at(weights, j);
    (*w)(k) = options.pair_weighting == PairWeighting::kGeometricMean ? std::sqrt(wi * wj)
                                                                      : 0.5 * (wi + wj);
  }
}

/// Eq. (36) for p_x, p_y, Eq. (37) for p_z, and J of Eq. (35).
void finish_affine_pose(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                        const Eigen::VectorXd& weights, const AffinePoseOptions& options,
                        AffinePoseResult* result) {
  const Eigen::Matrix3d& R = result->R_camera_object;
  const double alpha = result->alpha;
  double weight_sum = 0.0;
  Eigen::Vector3d z_sum = Eigen::Vector3d::Zero();
  Eigen::Vector2d q_sum = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double wi = weight_at(weights, i);
    weight_sum += wi;
    z_sum += wi * model.col(i);
    q_sum += wi * image.col(i);
  }
  result->p_camera_object.head<2>() = (alpha * q_sum - R.topRows<2>() * z_sum) / weight_sum;
  result->depth_known = options.focal_length > 0.0;
  result->p_camera_object.z() = result->depth_known ? alpha * options.focal_length : 0.0;
  double j = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    j += weight_at(weights, i) *
         (R.topRows<2>() * model.col(i) + result->p_camera_object.head<2>() - alpha * image.col(i))
             .squaredNorm();
  }
  result->residual = j;
  result->status = result->orientation.status;
  result->message = result->orientation.message;
}

}  // namespace

FreeVectors affine_free_vectors(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                                const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  validate_points<2>(model_object, image, weights, options, "image");
  FreeVectors out;
  build_free_vectors<2>(model_object, image, weights, options, &out.pairs, &out.z_object,
                        &out.d_image, &out.weights);
  return out;
}

AffinePoseResult affine_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                             const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  const FreeVectors free = affine_free_vectors(model_object, image, weights, options);
  check_count(free.z_object.cols(), options.orientation,
              options.free_vectors == FreeVectorSet::kAllPairs
                  ? "; use FreeVectorSet::kMaxSpanningTree for n - 1 free vectors"
                  : "");
  AffinePoseResult result;
  result.pairs = free.pairs;
  result.orientation = affine_orientation_unknown_scale(free.z_object, free.d_image, free.weights,
                                                        options.orientation);
  result.R_camera_object = result.orientation.R_camera_object;
  result.alpha = result.orientation.alpha;
  finish_affine_pose(model_object, image, weights, options, &result);
  return result;
}

AffinePoseResult standard_affine_pose(const Eigen::Matrix3Xd& model_object,
                                      const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                                      const AffinePoseOptions& options) {
  const FreeVectors free = affine_free_vectors(model_object, image, weights, options);
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, free.z_object.cols());
  v.topRows<2>() = free.d_image;
  if (!(v.squaredNorm() > 0.0)) {
    throw InvalidArgument("image: all image points coincide, the scale is undefined");
  }
  OrientationOptions theorem1;
  theorem1.eigen = options.orientation.eigen;
  theorem1.degenerate_gap = options.orientation.degenerate_gap;
  const OrientationResult solve = absolute_orientation(free.z_object, v, free.weights, theorem1);

  AffinePoseResult result;
  result.pairs = free.pairs;
  result.R_camera_object = solve.R_camera_object;
  result.alpha = solve.alpha;  // Eq. (4)
  AffineOrientationResult& o = result.orientation;
  o.R_camera_object = solve.R_camera_object;
  o.alpha = solve.alpha;
  o.residual = residual_direct(free.z_object, solve.alpha * free.d_image, free.weights,
                               solve.R_camera_object);
  o.runner_up_residual = std::numeric_limits<double>::infinity();
  o.ambiguity_margin = std::numeric_limits<double>::infinity();
  o.v_z = Eigen::VectorXd::Zero(free.z_object.cols());
  o.sign_patterns = 1;
  o.eigen_gap = solve.eigen_gap;
  if (solve.status == OrientationStatus::kDegenerate) {
    o.status = AffineStatus::kDegenerate;
    o.message = solve.message;
  }
  finish_affine_pose(model_object, image, weights, options, &result);
  return result;
}

PoseResult full_3d_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix3Xd& measured,
                        const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  validate_points<3>(model_object, measured, weights, options, "measured");
  Eigen::Matrix2Xi pairs;
  Eigen::Matrix3Xd z, m;
  Eigen::VectorXd w;
  build_free_vectors<3>(model_object, measured, weights, options, &pairs, &z, &m, &w);
  if (!(m.squaredNorm() > 0.0)) {
    throw InvalidArgument("measured: all measured points coincide, the scale is undefined");
  }
  OrientationOptions theorem1;
  theorem1.eigen = options.orientation.eigen;
  theorem1.degenerate_gap = options.orientation.degenerate_gap;
  const OrientationResult solve = absolute_orientation(z, m, w, theorem1);

  PoseResult result;
  result.R_camera_object = solve.R_camera_object;
  result.alpha = solve.alpha;
  result.eigen_gap = solve.eigen_gap;
  result.used_fallback = solve.used_fallback;
  result.status = solve.status;
  result.message = solve.message;
  double weight_sum = 0.0;
  Eigen::Vector3d z_sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d q_sum = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < model_object.cols(); ++i) {
    const double wi = weight_at(weights, i);
    weight_sum += wi;
    z_sum += wi * model_object.col(i);
    q_sum += wi * measured.col(i);
  }
  result.p_camera_object = (solve.alpha * q_sum - solve.R_camera_object * z_sum) / weight_sum;
  double j = 0.0;
  for (Eigen::Index i = 0; i < model_object.cols(); ++i) {
    j += weight_at(weights, i) * (solve.R_camera_object * model_object.col(i) +
                                  result.p_camera_object - solve.alpha * measured.col(i))
                                     .squaredNorm();
  }
  result.residual = j;  // Eq. (12)
  return result;
}

// ---------------------------------------------------------------------------------------------
// NLopt cross-check.

namespace {

struct CrossCheckData {
  const Eigen::Matrix3Xd* z;
  const Eigen::Matrix2Xd* d_object;
  const Eigen::VectorXd* w;
  Eigen::Matrix3d start;
  int evaluations = 0;
};

Eigen::Matrix3d rotation_at(const Eigen::Matrix3d& start, const double* x) {
  const Eigen::Vector3d omega(x[0], x[1], x[2]);
  const double angle = omega.norm();
  if (angle == 0.0) return start;
  return start * Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

double cross_check_objective(unsigned, const double* x, double*, void* data) {
  auto* c = static_cast<CrossCheckData*>(data);
  ++c->evaluations;
  return residual_direct(*c->z, *c->d_object, *c->w, rotation_at(c->start, x));
}

}  // namespace

AffineCrossCheckResult minimize_affine_residual(const Eigen::Matrix3Xd& z_object,
                                                const Eigen::Matrix2Xd& d_image, double alpha,
                                                const Eigen::VectorXd& weights,
                                                const AffineCrossCheckOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
  validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  check_alpha(alpha);
  const Eigen::Matrix2Xd d_object = alpha * d_image;
  const Eigen::VectorXd w = weights.size() == 0 ? Eigen::VectorXd::Ones(z_object.cols()) : weights;

  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal;
  AffineCrossCheckResult result;
  result.residual = std::numeric_limits<double>::infinity();
  for (int s = 0; s < options.starts; ++s) {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    CrossCheckData data{&z_object, &d_object, &w, q.normalized().toRotationMatrix()};
    nlopt::opt opt(nlopt::LN_BOBYQA, 3);
    opt.set_lower_bounds(std::vector<double>(3, -M_PI));
    opt.set_upper_bounds(std::vector<double>(3, M_PI));
    opt.set_min_objective(cross_check_objective, &data);
    opt.set_xtol_abs(options.x_tolerance);
    opt.set_maxeval(options.max_evaluations);
    opt.set_initial_step(0.5);
    std::vector<double> x(3, 0.0);
    double f = std::numeric_limits<double>::infinity();
    try {
      opt.optimize(x, f);
    } catch (const nlopt::roundoff_limited&) {
      // x and f hold the best point found: converged to rounding, an acceptable outcome.
    } catch (const std::exception&) {
      ++result.failed_starts;
    }
    result.evaluations += data.evaluations;
    const Eigen::Matrix3d R = rotation_at(data.start, x.data());
    const double j = residual_direct(z_object, d_object, w, R);
    if (j < result.residual) {
      result.residual = j;
      result.R_camera_object = R;
    }
  }
  return result;
}

// ---------------------------------------------------------------------------------------------

namespace internal {

Eigen::Matrix4d affine_pattern_d(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_object,
                                 const Eigen::VectorXd& v_z, const Eigen::VectorXd& weights,
                                 std::uint64_t signs) {
  std::vector<int> order(z_object.cols());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  return pattern_d(z_object, d_object, v_z, weights, order, signs);
}

Eigen::Matrix4d affine_gray_code_d(const Eigen::Matrix3Xd& z_object,
                                   const Eigen::Matrix2Xd& d_object, const Eigen::VectorXd& v_z,
                                   const Eigen::VectorXd& weights, std::uint64_t steps,
                                   std::uint64_t* signs) {
  std::vector<int> order(z_object.cols());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  GrayCodeWalk walk(z_object, d_object, v_z, weights, order);
  Eigen::Matrix4d last;
  walk.run(steps, [&](const Eigen::Matrix4d& D, const Eigen::Vector3d&, std::uint64_t s) {
    last = D;
    *signs = s;
  });
  return last;
}

}  // namespace internal

}  // namespace vantage

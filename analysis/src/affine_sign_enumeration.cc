#include "affine_sign_enumeration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace vantage::internal {

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
      ++problem.clamped;  // docs/math.md §8: |d_i| > |z_i| / alpha
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

namespace {

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

/// One Laguerre step on x^4 + c2 x^2 + c1 x + c0 (docs/math.md §5). For a polynomial with only
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
  // (x^2 - f2)^2 - 8 x det - 4 adj2 = x^4 + c2 x^2 + c1 x + c0 (docs/math.md §5).
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

// The quartic solver's constants for the problem: G's columns a, b and the bound on lambda.
QuarticSolver quartic_solver(const Eigen::Matrix3Xd& z, const AffineProblem& problem,
                             const AffineOrientationOptions& options) {
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
  return solver;
}

// Offsets of lane t (bit k of t negates v_z of free vector low_bits + k) from the walk's H, D;
// lanes past 2^lane_bits stay zero.
void lane_offsets(const Eigen::Matrix3Xd& z, const AffineProblem& problem, int lane_bits,
                  LaneArray* lane_hx, LaneArray* lane_hy, LaneArray* lane_hz,
                  Eigen::Matrix4d* lane_d) {
  const int m = static_cast<int>(problem.free.size());
  const int lanes = 1 << lane_bits;
  const int low_bits = m - lane_bits;
  for (int t = 0; t < kLanes; ++t) {
    lane_d[t].setZero();
    for (int k = 0; k < lane_bits && t < lanes; ++k) {
      if (!((t >> k) & 1)) continue;
      const int j = problem.free[low_bits + k];
      const double scale = -2.0 * problem.w(j) * problem.v_z(j);
      (*lane_hx)(t) += scale * z(0, j);
      (*lane_hy)(t) += scale * z(1, j);
      (*lane_hz)(t) += scale * z(2, j);
      lane_d[t] += scale * quaternion_k(Eigen::Vector3d::UnitZ(), z.col(j));
    }
  }
}

}  // namespace

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

  const QuarticSolver solver = quartic_solver(z, problem, options);

  // With m <= kLaneBits free vectors only 2^m lanes are active; the others repeat lane 0 and
  // are ignored.
  const int m = static_cast<int>(problem.free.size());
  const int lane_bits = std::min(m, kLaneBits);
  const int lanes = 1 << lane_bits;
  const int low_bits = m - lane_bits;
  const std::vector<int> low(problem.free.begin(), problem.free.begin() + low_bits);
  GrayCodeWalk walk(z, problem.d, problem.v_z, problem.w, low);
  // Offsets of each lane from the walk's H, D.
  LaneArray lane_hx = LaneArray::Zero(), lane_hy = LaneArray::Zero(), lane_hz = LaneArray::Zero();
  Eigen::Matrix4d lane_d[kLanes];
  lane_offsets(z, problem, lane_bits, &lane_hx, &lane_hy, &lane_hz, lane_d);
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

}  // namespace vantage::internal

#pragma once

/// Theorem 6 (McInroy et al., Sec. III.D): the worst-case viewpoint of a set of data vectors.
///
/// A viewpoint is a unit vector a (the camera's optical axis, the third row of R_camera_object).
/// From a, data vector z_i keeps the fraction p_i = sqrt(1 - (a.n_i)^2) of its norm in the image,
/// n_i = z_i / ||z_i||. The worst viewpoint minimises p-bar = max_i p_i (Eq. 27), i.e. it solves
///
///   t* = max_{||a|| = 1} min_i |a.n_i|          (Eq. 31),   p-bar_min = sqrt(1 - t*^2)
///
/// (docs/math.md §12: the printed Eq. 29, 1 - t^2, is a misprint). a and -a are the same
/// viewpoint; results are reported with a in the upper hemisphere (z > 0, ties by y > 0, x > 0).
///
/// The paper's LMI (Eq. 28) fixes a sign s_i per vector and solves one *sign cell*:
///   max t  s.t.  [[s_i a.n_i, t], [t, s_i a.n_i]] >= 0,  [[I, a], [a^T, 1]] >= 0,
/// which is local to that cell (docs/math.md §13). Its optimum is the distance from the origin to
/// conv{s_i n_i} (docs/math.md §13). global_worst_viewpoint() maximises over all cells by branch
/// and bound on the sphere with exact per-cell solutions, and returns a certificate.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "vantage/sdp/lmi.h"

namespace vantage::sdp {

/// The columns of `vectors` scaled to unit length, each on its own scale (unit_direction() of
/// vantage/analysis/scaling.h), so any non-zero finite length works, beside any other. Throws
/// InvalidArgument (naming `argument`) when a column is zero or not finite.
Eigen::Matrix3Xd normalized_columns(const Eigen::Matrix3Xd& vectors, const char* argument);

/// min_i |a.n_i| for unit columns n_i and a unit a: the objective of Eq. (31).
double min_abs_projection(const Eigen::Matrix3Xd& unit_vectors, const Eigen::Vector3d& a);

/// p-bar(a) = max_i |a x n_i| (= sqrt(1 - min_i (a.n_i)^2), Eq. 27) for unit columns n_i and a
/// unit a, from the cross products: it keeps its digits where t = min_i |a.n_i| rounds to 1
/// (every n_i within 1e-8 rad of a), which sqrt(1 - t^2) cannot.
double pbar_at(const Eigen::Matrix3Xd& unit_vectors, const Eigen::Vector3d& a);

/// p-bar = sqrt(1 - t^2) for t in [0, 1] (clamped), Eq. (29) corrected (docs/math.md §12).
double pbar_from_t(double t);

/// The representative of {a, -a} in the upper hemisphere: z > 0, or z = 0 and y > 0, or
/// z = y = 0 and x >= 0.
Eigen::Vector3d upper_hemisphere(const Eigen::Vector3d& a);

/// The paper's signs (Sec. III.D, end of the proof of Theorem 6): s_i = +1 when n_i is in the
/// upper hemisphere (z > 0, ties broken by y > 0, then x > 0), else -1.
Eigen::VectorXd upper_hemisphere_signs(const Eigen::Matrix3Xd& vectors);

/// Result of one cell LMI (Eq. 28) solved on an SDP backend.
struct CellViewpoint {
  enum class Status {
    kOk,            ///< the SDP has a solution and t > CellViewpoint::kEmptyCellT
    kEmptyCell,     ///< t <= kEmptyCellT: 0 is in conv{s_i n_i}, no viewpoint has all s_i a.n_i > 0
    kSolverFailed,  ///< the SDP status has no solution (see `sdp`)
  };
  /// t at or below which a cell counts as empty (the SDP tolerance is 1e-8 relative).
  static constexpr double kEmptyCellT = 1e-7;

  Status status = Status::kSolverFailed;
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();  ///< a / ||a||, upper hemisphere
  double t = 0.0;                                        ///< the LMI's optimal t (Eq. 28)
  double pbar_at =
      1.0;  ///< p-bar(a) = sqrt(1 - t^2) at `viewpoint`, the cell's optimum, as pbar_at()
  /// The backend's raw result (y = [a; t]) of the last LMI solved: on lmi_vectors of the cell's
  /// vectors (see solve_cell_lmi()).
  SdpResult sdp;
  int lmi_solves = 0;   ///< LMIs solved (constraint generation rounds)
  int lmi_vectors = 0;  ///< data vectors (2x2 blocks) in the last LMI
  std::string message;
};

/// "ok", "empty_cell" or "solver_failed".
const char* to_string(CellViewpoint::Status status);

/// The LMI of Eq. (28) on the columns p_i = s_i n_i (signed unit vectors), whole: variables
/// y = [a_x, a_y, a_z, t], objective min -t, blocks [[p_i.a, t], [t, p_i.a]] >= 0 (one dense 2x2
/// per column, in order) and [[I, a], [a^T, 1]] >= 0 (the last, dense 4x4). For solving it on
/// another backend or as a reference; solve_cell_lmi() is the checked, faster way.
LmiProblem cell_lmi_problem(const Eigen::Matrix3Xd& signed_unit_vectors);

/// The cell LMI of Eq. (28) for data vectors (3 x m, m >= 1, non-zero columns; normalised here)
/// and signs s_i (m entries, each +1 or -1), solved with options.backend. Variables y = [a; t],
/// objective min -t, blocks: one dense 2x2 block per vector and one dense 4x4 block.
/// Up to 32 vectors the LMI is solved whole. Beyond, by constraint generation (docs/math.md §13):
/// first on the 32 vectors nearest to active at the cell's minimum-norm direction, then with the
/// vectors its answer violates by more than options.tolerance added, until none is (the answer of
/// a subset's LMI is then the whole cell's optimum to the SDP's tolerance: the subset's optimum is
/// at least the cell's, and it is feasible for the cell), or on all m after 8 rounds. Every
/// answer is checked against all m vectors, so the guess only decides how fast it converges.
/// t is min_i s_i a.n_i over all m vectors at a = y.head<3>() normalised.
/// Throws InvalidArgument on bad vectors, signs or options.
CellViewpoint solve_cell_lmi(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& signs,
                             const SdpOptions& options = {});

/// The signs the paper's single LMI is solved with. The paper negates vectors only because the
/// LMI needs every s_i a.n_i > 0 ("this condition cannot be satisfied unless all of the data
/// vectors are in the same hemisphere"): when the vectors as given already lie in one open
/// hemisphere (0 not in conv{n_i}) they are kept (all s_i = +1), otherwise
/// upper_hemisphere_signs() negates those not in the upper hemisphere. This reproduces the
/// paper's Fig. 3 value (0.95, docs/math.md §13) for Z = I plus (1, 1, -2)/sqrt(6).
Eigen::VectorXd paper_signs(const Eigen::Matrix3Xd& vectors);

/// The paper's answer: solve_cell_lmi() with paper_signs(). Local to one cell, so its t is <=
/// the global t* (its p-bar >= the global p-bar_min).
CellViewpoint paper_worst_viewpoint(const Eigen::Matrix3Xd& vectors,
                                    const SdpOptions& options = {});

/// Options of global_worst_viewpoint().
struct WorstViewpointOptions {
  /// Required t_upper - t_lower of the certificate. Dimensionless, in [1e-15, 1e-3].
  double certificate_tolerance = 1e-9;
  /// Cells whose optimum is within this of t* are reported as further global optima (ties, e.g.
  /// the four of Z = I). Dimensionless, in [0, 1e-3].
  double tie_tolerance = 1e-9;
  /// Patch budget of the branch and bound, >= 1 (a search split in two halves gives each
  /// max_patches / 2, at least 1). When exhausted the result is kNotCertified.
  long max_patches = 50'000'000;
  /// Viewpoints to try first (any length > 0 and sign), e.g. the optima of a layout that differs
  /// by a few vectors: the best value min_i |a.n_i| attained at them is a lower bound on t* that
  /// the branch and bound prunes with from its first patch. Hints are never reported as optima
  /// (only cell optima are) and do not enter t_upper: they change the work, not the answer.
  std::vector<Eigen::Vector3d> hints;
  /// Stop as soon as an attained value exceeds this (status kStoppedAbove): for callers that
  /// only need to know whether t* <= stop_above, e.g. to rank candidate layouts. Not NaN;
  /// +infinity never stops.
  double stop_above = std::numeric_limits<double>::infinity();
  /// Threads the branch and bound may use, 1 or 2. A layout of 2000 or more distinct directions
  /// without a finite stop_above is searched as two halves of the sphere (each with half of
  /// max_patches, docs/math.md §14), on two threads when this is 2; the result (viewpoints, t,
  /// certificate, patch count) is the same for 1 and 2.
  int threads = 2;
  /// Also solve the best cell's LMI (Eq. 28) on the SDP backend and compare (confirmation).
  bool confirm_with_sdp = false;
  SdpOptions sdp;  ///< backend options of the confirmation solve

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// The global worst viewpoint with its certificate.
struct WorstViewpoint {
  enum class Status {
    kCertified,     ///< t_upper - t_lower <= certificate_tolerance (and, when asked, the SDP
                    ///< confirmation agrees within kSdpAgreement)
    kNotCertified,  ///< patch budget exhausted: t_upper - t_lower > certificate_tolerance
    kSdpDisagrees,  ///< certified, but the confirming cell LMI differs by more than kSdpAgreement
    kStoppedAbove,  ///< an attained value t_lower exceeded options.stop_above, so t* > stop_above;
                    ///< the search stopped there (t_upper = 1, viewpoints = {viewpoint}, no SDP
                    ///< confirmation)
  };
  /// |t_sdp - t| above which the SDP confirmation counts as a disagreement (CSDP stops at
  /// relative accuracy 1e-8; the LMI's t is accurate to about 1e-7).
  static constexpr double kSdpAgreement = 1e-6;

  Status status = Status::kNotCertified;
  /// The best attained global optimum, upper hemisphere (so t_upper - t_lower is not widened by
  /// the tie_tolerance); among optima whose values agree to rounding (1e-14) the first by
  /// largest z, then y, then x.
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();
  /// Every global optimum up to sign within tie_tolerance of t: `viewpoint` first, the others
  /// by decreasing value.
  std::vector<Eigen::Vector3d> viewpoints;
  double t = 0.0;              ///< min_i |a.n_i| at `viewpoint` (= t_lower)
  double pbar_min = 1.0;       ///< p-bar_min = sqrt(1 - t^2), as pbar_at(n, viewpoint)
  double t_upper = 1.0;        ///< proven upper bound on min_i |a.n_i| over the whole sphere
  double t_lower = 0.0;        ///< attained value (t)
  long cells_solved = 0;       ///< exact cell problems (minimum-norm points) solved
  long patches = 0;            ///< spherical patches visited by the branch and bound
  bool sdp_confirmed = false;  ///< confirm_with_sdp was set and the confirmation ran
  CellViewpoint confirmation;  ///< the confirming cell LMI (when sdp_confirmed)
  std::string message;

  /// The one criterion of "certified" everywhere in vantage: status == kCertified (the
  /// certificate closed and, when asked, the SDP confirmation agrees).
  bool certified() const { return status == Status::kCertified; }
};

/// "certified", "not_certified", "sdp_disagrees" or "stopped_above".
const char* to_string(WorstViewpoint::Status status);

/// The global worst viewpoint: t* = max over all sign cells (docs/math.md §13) without
/// enumerating the 2^(m-1) sign patterns. Branch and bound over spherical patches of the three
/// cube faces +x, +y, +z (antipodes are the same viewpoint): a patch of centre c and angular
/// radius r has the upper bound min_i sin(min(pi/2, asin|c.n_i| + r)); patches no great circle
/// n_i^perp crosses lie in one cell whose optimum is solved exactly as the minimum-norm point of
/// conv{s_i n_i} (docs/math.md §13, Wolfe's algorithm); patches whose bound is below the best
/// attained value are pruned. Parallel and antiparallel repeats (unit columns equal within 1e-15 up
/// to sign) are searched once; t and the viewpoints are evaluated on every column. Each reported
/// optimum is its cell's minimum-norm point solved again on every column, so t and the viewpoints
/// depend on the cells found, not on the search's path (hints, frontiers) to the last bit. Time
/// about (patches at the scale asin(t*) / 2, ~m^2 / 26 for random layouts) x (circles near a
/// patch); memory O(m) (depth-first). vectors: 3 x m, m >= 2, non-zero finite columns (parallel,
/// duplicated and antiparallel columns are fine: all parallel gives t = 1, p-bar = 0).
/// Throws InvalidArgument on bad input or options.
WorstViewpoint global_worst_viewpoint(const Eigen::Matrix3Xd& vectors,
                                      const WorstViewpointOptions& options = {});

/// Options of crosscheck_worst_viewpoint().
struct CrossCheckOptions {
  /// Fibonacci samples over the upper hemisphere; 0 = automatic: a spacing of half the optimal
  /// inradius asin(t_reference) (8 pi / asin(t_reference)^2 samples), at least 20000, but at
  /// most 400000 and max_sample_products / m (so the sampling costs a bounded time).
  int samples = 0;
  /// Bound of the automatic sample count: samples x m dot products, >= 1e5.
  double max_sample_products = 4e7;
  /// Best samples (in distinct sign cells) polished by NLopt, >= 1.
  int polish_starts = 16;
  /// |t_nlopt - t_reference| at or below which the two agree. Dimensionless, > 0.
  double agreement = 1e-6;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Independent NLopt cross-check of t*.
struct CrossCheck {
  /// Empty when the cross-check ran. kWithoutNlopt ("built without NLopt",
  /// vantage/analysis/build_options.h) when vantage was built without NLopt: nothing ran, method
  /// is "skipped", agrees is false (nothing was compared) and message says why; a report shows
  /// it as "skipped: built without NLopt".
  std::string skipped;
  std::string method;  ///< "nlopt_multistart_cobyla" ("skipped" when skipped)
  double t = 0.0;      ///< best min_i |a.n_i| found (attained at `viewpoint`)
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();
  double difference = 0.0;  ///< t - t_reference
  bool agrees = false;      ///< |difference| <= agreement
  int samples = 0;          ///< Fibonacci samples evaluated
  /// Angular spacing of the samples, sqrt(2 pi / samples) rad. When it is below asin(t) the
  /// samples alone put a start inside every cell as large as the optimal one.
  double sample_spacing = 0.0;
  /// sample_spacing < asin(t_reference): the samples put a start in every cell as large as the
  /// optimal one. false (large layouts, whose sample count is bounded): other cells are only
  /// spot-checked, and agreement mainly rests on re-solving the reference viewpoints' cells.
  bool samples_cover_cells = false;
  int polished = 0;  ///< starts polished: samples in distinct sign cells, then reference_viewpoints
  std::string message;  ///< empty when it agrees; otherwise says so loudly
};

/// Global maximisation of min_i |a.n_i| on the unit sphere independent of the branch and bound's
/// bounds and of its minimum-norm-point solver, and of CSDP: Fibonacci sampling of the hemisphere
/// (a bounded number of samples, see CrossCheckOptions::samples), then the best samples in
/// distinct sign cells, and every viewpoint in `reference_viewpoints`, polished by NLopt's COBYLA
/// on the start's sign cell posed as min ||a||^2 s.t. s_i n_i.a >= t0 (t = t0 / ||a*||). The
/// polish works in coordinates shifted to the start (a = a0 + d), so narrow cones, where t is
/// close to 1 and the constraints differ by 1e-6, keep their digits; it starts with the
/// constraints nearest to active and adds any the result violates, so a polish costs O(m) per
/// round, not an NLopt problem with m constraints.
///
/// Independence: with reference_viewpoints, the reference's own cells are re-solved by a
/// different method (NLopt, all constraints checked), which confirms t_reference is attained as
/// a cell optimum; whether another cell is better is checked only by the samples, which resolve
/// every cell at least as large as the optimal one when sample_spacing < asin(t). Reports
/// whether it agrees with t_reference; it never replaces the answer it checks. Built without
/// NLopt it checks its input, runs nothing and says so (CrossCheck::skipped).
CrossCheck crosscheck_worst_viewpoint(
    const Eigen::Matrix3Xd& vectors, double t_reference, const CrossCheckOptions& options = {},
    const std::vector<Eigen::Vector3d>& reference_viewpoints = {});

}  // namespace vantage::sdp

#pragma once

/// Marker-set design: the inductive augmenter of McInroy et al., Sec. III.E, done globally.
///
/// The paper (text around Fig. 3): "since a represents the worst case viewpoint, a data vector
/// added in the space perpendicular to a converts this worst case viewpoint into an ideal
/// viewpoint ... a good set of n data vectors can be found inductively by repeating applying
/// Theorem 6 and adding data points in a^perp". With the single-cell LMI of Eq. (28) that rule
/// reports gains that are not real (docs/math.md §13: Z = I plus a vector in a^perp gives the
/// paper's 0.95, but the global p-bar_min stays 0.8165). Here every step uses the *global* worst
/// viewpoints (sdp::global_worst_viewpoint, all sign cells, certified) and keeps the addition
/// that maximises the new global p-bar_min.
///
/// Facts the augmenter relies on and reports:
///  - Adding data never lowers p-bar_min (t = max_a min_i |a.n_i| can only fall).
///  - One more vector c raises p-bar_min only if it "kills" every current worst viewpoint a_k,
///    i.e. |a_k.c| < t for all k. Candidates that do not are scored without a solve (their t is
///    unchanged and the surviving worst viewpoints are those they do not kill), and whether any
///    c at all can kill them all is decided exactly: min over unit c of max_k |a_k.c| is
///    attained at c = a_i x a_j or c = (a_i - s a_j) x (a_i - s' a_k) (s, s' = +-1), so it is
///    the minimum over those finitely many points. Z = I has four worst viewpoints (+-1,+-1,1)/
///    sqrt(3) with sum_k (a_k.c)^2 = 4/3 for every unit c, so no single vector can raise 0.8165.
///  - Ceiling (docs/math.md §15): m data vectors never give p-bar_min above cos(pi/(2m)).
///  - Coplanar layouts reach high p-bar_min but carry the two-fold (Necker) ambiguity of affine
///    pose; their coplanarity is reported as a number.
///
/// Direction mode adds unit directions. Point mode adds a marker position p, which adds the n
/// free vectors p - z_i (Prop. 8) to the analysis.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/sdp/certified_worst.h"
#include "vantage/sdp/layout_measures.h"

namespace vantage::design {

/// The global worst case of a set of data vectors: the one evaluation the augmenter repeats,
/// sdp's one record of a certified worst case (t, p-bar_min, every worst viewpoint, the largest
/// Eq. (30) error over them, the certificate).
using WorstCase = sdp::CertifiedWorst;

/// The global worst case of `vectors` (3 x m, m >= 2, non-zero finite columns), from
/// sdp::global_worst_viewpoint. Throws InvalidArgument on bad vectors.
WorstCase evaluate_worst_case(const Eigen::Matrix3Xd& vectors);

/// The ceiling cos(pi / (2 m)) and the coplanarity measure live with the layout report
/// (sdp/layout_measures.h); the augmenter reports both for every step.
using sdp::Coplanarity;
using sdp::coplanarity;
using sdp::pbar_ceiling;

/// Options of augment_layout().
struct AugmentOptions {
  int add = 1;  ///< K: additions, >= 0 (0 only analyses)
  /// Choose only among the layout's `candidates` (must then be non-empty); a candidate is used
  /// at most once. Otherwise candidates, when given, are evaluated alongside the free search.
  bool candidates_only = false;
  /// Point mode: the search box is the bounding box of the markers grown on every side by
  /// margin times its largest side. In [0, kMaxMargin], dimensionless.
  double margin = 0.25;
  /// The largest margin: the search box is then 201 times the layout's extent, and the
  /// augmenter's separation (a new marker or candidate closer than 1e-9 of the box's largest
  /// side to another marker adds a zero free vector) still 2e-7 of the layout. A larger margin
  /// would make that separation swallow the layout itself (1e8: 0.2 of it, and every candidate
  /// would coincide with a marker).
  static constexpr double kMaxMargin = 100.0;
  /// Direction mode: coarse samples per great circle a^perp (half circle, c ~ -c), >= 4.
  int circle_samples = 72;
  /// Point mode: coarse grid points per box axis, >= 2.
  int grid_samples = 11;
  /// Best coarse candidates polished by a local compass search, >= 1.
  int refine_starts = 3;
  /// Point mode: after the grid and its polish, a branch and bound over the search box
  /// (docs/math.md §18) looks for better positions and proves how good the best is. Its budget
  /// per step, in global solves times the layout's data vectors (a solve costs about 1 us of CPU
  /// per data vector on the 2-core machine of docs/benchmarks.md, so 450 000 is about half a
  /// second; a 5-marker layout, 20 data vectors, gets 22 500 solves, enough to finish); >= 0 (0:
  /// grid and polish only).
  long search_budget = 450'000;
  /// Point mode: the branch and bound drops a part of the box once it proves no position
  /// there has t below the best found minus this. In [1e-9, 0.1].
  double search_tolerance = 1e-4;
  /// Compass search stops when its step (radians on the sphere; fraction of the box's largest
  /// side in point mode) falls below this. In (0, 0.1].
  double refine_tolerance = 1e-7;
  /// New t within this of another counts as equal (then fewer worst viewpoints, then the larger
  /// kill margin wins). In [0, 1e-3].
  double tie_tolerance = 1e-9;
  /// Run the direct optimiser (all K additions at once) for comparison.
  bool run_direct = true;
  /// Direct optimiser: multi-start count (the first start is the greedy answer), >= 1.
  int direct_starts = 6;
  /// Direct optimiser: objective evaluations (global worst-viewpoint solves) per start, >= 10.
  int direct_evaluations_per_start = 400;
  /// Seed of the direct optimiser's random starts.
  unsigned seed = 1;
  /// Coplanarity::nearly_coplanar threshold on the smallest singular value, >= 0.
  double coplanarity_threshold = 0.1;
  /// Spare the global solves work that cannot change the answer: each solve starts from the
  /// worst viewpoints of the current layout and of the previous solve (a lower bound to prune
  /// with), and a candidate's solve stops as soon as it proves the candidate cannot rank where
  /// it would be used (a t above the incumbent's, or above the refine_starts-th best coarse one,
  /// by more than tie_tolerance). false solves every candidate from scratch to its certificate:
  /// the same choices, slower (the reference the tests compare with).
  bool prune_solves = true;
  /// Point mode: every addition keeps vantage::tracker::min_distance_difference() of the markers at
  /// or above this (ART's identification rule, docs/math.md §24; the check `vantage place` uses),
  /// in the layout's units, >= 0 and finite (0: no constraint; > 0 needs a point layout that
  /// keeps it itself). A position that breaks it scores t = +infinity, so no step chooses it
  /// (the branch and bound's lower bound, on the unconstrained t, stays valid); a step whose
  /// every option breaks it ends the run (Status::kNoFeasibleAddition). The direct optimiser
  /// is constrained too: additions that break it score t = 1 and are never kept (docs/math.md
  /// §18).
  double min_distance_difference = 0.0;

  /// Called with the stage about to run ("step 2/5", "direct optimiser", then "direct optimiser,
  /// start 3/8" per multistart start), e.g. to show progress; empty: nothing is called.
  std::function<void(const std::string& stage)> progress;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// One greedy step.
struct AugmentStep {
  /// The added unit direction (direction mode) or marker position (point mode).
  Eigen::Vector3d added = Eigen::Vector3d::Zero();
  int candidate_index = -1;  ///< index into Layout::candidates when chosen from them, else -1
  WorstCase worst;           ///< of the augmented layout after this step
  int vector_count = 0;      ///< data vectors after this step (free vectors in point mode)
  double ceiling = 1.0;      ///< pbar_ceiling(vector_count)
  bool improved = false;     ///< p-bar_min rose by more than the tie tolerance (in t)
  /// Exact answer to "can any single vector raise p-bar_min here?" in direction mode; false
  /// means provably not. Always true in point mode (a marker adds several vectors at once).
  bool single_vector_can_improve = true;
  /// min over unit c of max_k |a_k.c| over the worst viewpoints before the step; a single
  /// vector can raise p-bar_min iff this is below t (direction mode).
  double best_kill_level = 0.0;
  /// Angle (degrees) between the added direction and the nearest plane a_k^perp of a worst
  /// viewpoint before the step (direction mode; 0 = exactly the paper's rule).
  double angle_from_worst_plane_deg = 0.0;
  long global_solves = 0;  ///< global worst-viewpoint solves spent on this step
  long screened = 0;       ///< candidates scored without a solve (they kill no worst viewpoint
                           ///< set completely)
  /// Point mode, free search: what the branch and bound over the search box proved. No
  /// position of the box outside `search_unresolved` cells (each narrower than a thousandth of
  /// the box, next to a marker or a ridge of t) adds a marker with t below search_t_lower;
  /// search_closed: it ended by exhausting the box, not its budget (then
  /// search_t_lower >= worst.t - search_tolerance unless unresolved cells are lower).
  double search_t_lower = 0.0;
  bool search_closed = false;
  long search_unresolved = 0;
  long search_solves = 0;  ///< global solves the branch and bound spent
  std::string note;        ///< plain words: what happened, and why when nothing improved
};

/// The direct optimiser's answer.
struct DirectResult {
  enum class Status {
    kOk,       ///< ran; pbar_min is the best found (multi-start local, not a proof)
    kSkipped,  ///< not run: options.run_direct false, K = 0, too many candidate subsets, or
               ///< the continuous search of a build without NLopt (message says which)
  };
  Status status = Status::kSkipped;
  std::vector<Eigen::Vector3d> added;  ///< the K directions or positions
  std::vector<int> candidate_indices;  ///< candidates-only: their indices
  WorstCase worst;                     ///< of the layout with all K added
  long global_solves = 0;
  std::string method;  ///< "nlopt_sbplx_multistart" or "exhaustive_candidates"
  std::string message;
};

/// "ok" or "skipped".
const char* to_string(DirectResult::Status status);

/// Result of augment_layout().
struct AugmentResult {
  enum class Status {
    kOk,            ///< every global solve was certified
    kNotCertified,  ///< some global solve's certificate did not close (see message)
    kNoCandidates,  ///< candidates-only and the candidates ran out before K steps
    /// min_distance_difference > 0 and no candidate or searched position of a step keeps it;
    /// the steps before are kept
    kNoFeasibleAddition,
  };
  Status status = Status::kOk;
  std::string message;
  /// AugmentOptions::min_distance_difference of the run (0: none), echoed for the report.
  double min_distance_difference = 0.0;
  WorstCase initial;
  int initial_vector_count = 0;
  double initial_ceiling = 1.0;
  Coplanarity initial_coplanarity;
  std::vector<AugmentStep> steps;
  double final_pbar_min = 0.0;
  Coplanarity final_coplanarity;
  /// The input layout with the additions appended (weights 1; in a named layout named
  /// "added1", "added2", ..., the first names not yet taken) and the candidates they used
  /// removed (they are entries now): the layout a further step starts from.
  Layout augmented;
  DirectResult direct;
  long global_solves = 0;  ///< total, greedy and direct
};

/// "ok", "not_certified", "no_candidates" or "no_feasible_addition".
const char* to_string(AugmentResult::Status status);

/// Everything augment_layout() refuses before it searches, so that a front end can refuse bad
/// input before anything else: invalid options ("options.<field>"), an invalid layout,
/// candidates_only without candidates ("options.candidates_only"), a point-mode candidate within
/// the augmenter's separation of a marker or of another candidate ("candidates[2]: coincides with
/// points[1]"), and min_distance_difference > 0 on vectors or on markers that do not keep it
/// ("min_distance_difference"). Throws InvalidArgument.
void check_augmentation(const Layout& layout, const AugmentOptions& options);

/// Greedy augmentation, K = options.add steps. At each step: the global worst viewpoints a_k of
/// the current layout; candidates = coarse samples of every great circle a_k^perp (the paper's
/// rule), the points c = a_i x a_j, and the minimisers of max_k |a_k.c| (where a single vector
/// kills all a_k at once) in direction mode; a grid over the grown bounding box in point mode;
/// the layout's unused candidates always (only them with candidates_only). Candidates are scored
/// by the new global t (lower is better), then fewer worst viewpoints, then the larger kill
/// margin min_k (t - |a_k.c|) over the viewpoints they kill; the best few are polished by a
/// compass search on the sphere (or in the box). Adding never lowers p-bar_min.
/// Then, when asked, the direct optimiser: NLopt Subplex over all K additions at once (unit
/// directions, or positions in the box), multi-start from the greedy answer and seeded random
/// starts (not run when vantage is built without NLopt: direct.message says so); with
/// candidates_only, an exhaustive search over K-subsets of the candidates (no NLopt needed).
/// Throws InvalidArgument as check_augmentation() does.
AugmentResult augment_layout(const Layout& layout, const AugmentOptions& options = {});

}  // namespace vantage::design

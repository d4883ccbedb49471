#pragma once

/// Placing markers on a body: K of N candidate sites (docs/math.md §21).
///
/// Each site is a point on the body with its outward normal and cone; the body's mesh, when
/// there is one, shadows them (docs/math.md §20). place_markers() chooses K sites (kept markers
/// included) that first make every workspace direction trackable, then maximise the certified
/// worst-case p-bar_min under visibility (or, robustly, the worst of it over the loss of any one
/// marker), under a minimum separation and a minimum distance difference. Small instances are
/// searched exhaustively, larger ones greedily and then by swaps; the report says how far from
/// optimal the answer may be (greedy steps, random baseline).

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/tracker/identification.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/tracker/tre_search.h"
#include "vantage/visibility/visibility.h"

namespace vantage::design {

/// Candidate sites on a body: the markers of a VisibilityProblem (points, unit normals, cone
/// cosines, min_visible, workspace, and the occlusion grid of every site, or null).
struct PlacementProblem {
  visibility::VisibilityProblem sites;
  /// Sites that are already markers (kept: always chosen, counted in `markers`), distinct.
  std::vector<int> keep;
  int markers = 0;              ///< K: the markers of the answer, kept ones included
  double min_separation = 0.0;  ///< least distance between chosen markers, >= 0
  /// Least |d_ij - d_kl| of distinct pairs of chosen markers, >= 0: the chosen sites must have
  /// vantage::tracker::min_distance_difference() >= this (tracker/identification.h, docs/math.md
  /// §24).
  double min_distance_difference = 0.0;

  /// The least distance of two chosen sites: min_separation, or the distance below which two
  /// sites coincide (Layout::coincidence_distance) when that is larger. Two coincident sites are
  /// never both chosen: a layout file refuses coincident markers.
  double least_separation() const;

  /// Throws InvalidArgument naming the field: "markers" (K above the sites, below
  /// min_visible, below the kept markers), "keep", "min_separation" (also when kept markers
  /// violate it), "min_distance_difference", and the sites' own fields.
  void validate() const;
};

/// Which value of rot_rms_deg over the workspace the `camera` objective minimises.
enum class CrbStatistic {
  kWorst,   ///< the largest over the trackable lattice directions
  kP95,     ///< the 95th percentile (nearest rank) over them
  kMedian,  ///< the median (nearest rank)
};

/// "worst", "p95" or "median".
const char* to_string(CrbStatistic statistic);
/// The statistic of its name, or none.
std::optional<CrbStatistic> parse_crb_statistic(const std::string& name);

/// The `camera` objective (docs/math.md §21, "Objectives"): the pinhole CRB of §22 instead of the
/// paper's scale-free bound. A lattice direction a is trackable by a choice when the camera at
/// crb.aim + D a sees at least max(3, min_visible) of its markers and their Fisher information
/// is not singular (§22); the objective is the statistic of rot_rms_deg over the trackable
/// directions, and coverage counts the directions that see enough markers.
struct CameraObjective {
  /// The sites as a point layout on the body (the points of PlacementProblem::sites, with their
  /// normals, cones, min_visible, workspace and mesh): each site is seen by its own line of sight.
  Layout sites;
  /// The camera: distance, focal length, noise, samples (the lattice) and the aim point, which
  /// must be given (a choice's centroid would move the cameras with the choice).
  camera::PoseCrbOptions crb;
  CrbStatistic statistic = CrbStatistic::kWorst;
  /// An approach (docs/math.md §21, "An approach"): the camera distances D_1..D_n, distinct,
  /// each above the sites' radius about the aim, at most kMaxDistances (crb.distance is then not
  /// used); empty: crb.distance alone. The samples
  /// are the (direction, D_k) pairs and the value is the largest over k of the statistic at D_k.
  std::vector<double> distances;
  static constexpr int kMaxDistances = LayoutSensor::kMaxDistances;

  /// The distances of the samples: `distances`, or crb.distance alone.
  std::vector<double> sample_distances() const {
    return distances.empty() ? std::vector<double>{crb.distance} : distances;
  }
  /// The camera of the model: `crb` at the first sample distance (crb.distance is not used
  /// with an approach).
  camera::PoseCrbOptions model_options() const {
    camera::PoseCrbOptions out = crb;
    out.distance = sample_distances().front();
    return out;
  }
};

/// The `tracker` objective (docs/math.md §21, "Objectives"): the target registration error of
/// §23 instead of the paper's bound. The value of a choice is the largest, over the targets, of
/// the certified bound on the worst RMS TRE over its tracked directions (tre_worst()'s
/// rms_bound, in the sites' length unit): what `vantage tre` reports on the placed layout as
/// worst.rms_bound. At most 63 markers (the TRE search's limit).
struct TrackerObjective {
  static constexpr int kMaxMarkers = 63;
  std::vector<Eigen::Vector3d> targets;  ///< in the sites' frame, at least one, finite
  tracker::FleModel fle;
  tracker::TreSearchOptions search;  ///< its stop_above is the search's own
};

/// Options of place_markers().
struct PlaceOptions {
  /// The certified analysis of each subset (docs/math.md §20); its certificate_tolerance is the
  /// resolution at which two placements are told apart.
  visibility::VisibilitySearchOptions search;
  int coverage_samples = 20000;  ///< the coverage lattice's density on the sphere, >= 100
  bool robust_dropout = false;   ///< objective 3 of docs/math.md §21
  /// The `camera` objective; none: the paper's bound under visibility (`affine`).
  std::optional<CameraObjective> camera;
  /// The `tracker` objective (not with `camera`); none: `affine` (or `camera`).
  std::optional<TrackerObjective> tracker;
  /// Least coverage of a complete placement, in (0, 1]; none: every lattice direction of the
  /// workspace but one. Above it, coverage no longer ranks placements: the objective does.
  std::optional<double> min_coverage;
  /// Search every feasible subset when there are at most this many K-subsets of the free
  /// sites, >= 0 (0: never).
  long exhaustive_limit = 5000;
  /// Random feasible subsets of the baseline, in [0, kMaxRandomTrials]: each is kept until the
  /// median is taken (about 140 bytes), so 1e9 would need 140 GB.
  int random_trials = 1000;
  static constexpr int kMaxRandomTrials = 1'000'000;
  /// Rounds of iterated local search after the swaps (docs/math.md §21, "Search"), >= 0: each
  /// replaces a third of the answer's free markers (at least two) at random and swaps again; the
  /// better answer is kept. 0: greedy and swaps only.
  int perturbations = 0;
  std::uint64_t seed = 1;  ///< the baseline's and the perturbations' random engines
  int threads = 0;         ///< >= 0 (0: all cores); the answer does not depend on it
  /// Called with a stage ("greedy 3/12", "swaps, pass 2") from the calling thread, or empty.
  std::function<void(const std::string&)> progress;

  bool is_valid(std::string* why = nullptr) const;
};

/// What one choice of sites promises (docs/math.md §21's objective).
struct PlacementValue {
  double coverage = 0.0;  ///< trackable fraction of the workspace's lattice directions
  /// The objective, smaller is better: t_upper (affine), the statistic of rot_rms_deg in
  /// degrees (camera) or the worst RMS TRE bound in the sites' unit (tracker); +inf when nothing
  /// is trackable (camera, tracker).
  double objective = 1.0;
  /// The affine objective's certified worst case t_upper (1 when nothing is trackable) and
  /// p-bar_min = sqrt(1 - t_upper^2); 1 and 0 with the other objectives.
  double t_upper = 1.0;
  double pbar_min = 0.0;
  visibility::VisibilityWorstViewpoint::Status status =
      visibility::VisibilityWorstViewpoint::Status::kUntrackable;
};

/// The placement after greedy step k (k markers chosen).
struct PlacementStep {
  int k = 0;
  int added = -1;  ///< the site added at this step (-1 for the kept markers' row)
  PlacementValue value;
};

/// The random feasible subsets of the baseline.
struct RandomBaseline {
  int trials = 0;    ///< feasible subsets drawn (fewer than asked when few are feasible)
  int complete = 0;  ///< of them, how many cover min_coverage of the lattice
  double best_coverage = 0.0;
  double best_pbar_min = 0.0;    ///< of the best trial by the objective
  double median_pbar_min = 0.0;  ///< median over the trials (0 for an untrackable trial)
  /// The objective of the best trial, and its median over the trials (an incomplete trial counts
  /// as 1 for t, +inf for degrees). For the affine objective, t_upper.
  double best_objective = 1.0;
  double median_objective = 1.0;
  std::vector<int> best;  ///< the best trial's sites, increasing
};

/// The worst single loss (with robust_dropout).
struct RobustValue {
  double coverage = 0.0;       ///< least coverage over the loss of one marker
  double pbar_min = 0.0;       ///< least certified p-bar_min over the loss of one marker
  double objective = 1.0;      ///< largest objective value over the loss of one marker
  int worst_lost_marker = -1;  ///< the site whose loss gives it
};

/// The answer of place_markers().
struct PlacementResult {
  enum class Status {
    kComplete,    ///< the answer covers at least min_coverage of the workspace's lattice
    kIncomplete,  ///< no K-subset found covers that much; `chosen` is the best coverage
  };
  Status status = Status::kIncomplete;
  std::vector<int> chosen;  ///< site indices, increasing (kept sites included)
  PlacementValue value;     ///< of `chosen`, at the search's tolerance
  std::optional<RobustValue> robust;
  std::string search;                ///< "exhaustive" or "greedy+swap"
  std::vector<PlacementStep> steps;  ///< greedy construction (empty when exhaustive)
  int swaps = 0;                     ///< improving swaps made after the greedy
  int improving_perturbations = 0;   ///< perturbation rounds that found a better answer
  long evaluations = 0;              ///< certified searches run (not counting the baseline)
  long subsets = 0;                  ///< feasible subsets searched exhaustively
  RandomBaseline random_baseline;
  /// When incomplete: the markers at which greedy by coverage alone covers the lattice (an upper
  /// bound on the smallest complete K), or none when all sites together do not.
  std::optional<int> covering_markers;
  double all_sites_coverage = 0.0;  ///< coverage with every site chosen
  std::string message;
};

/// "complete" or "incomplete".
const char* to_string(PlacementResult::Status status);

/// Chooses the sites (docs/math.md §21). Deterministic for a seed and any thread count.
/// Throws InvalidArgument on a bad problem or options.
PlacementResult place_markers(const PlacementProblem& problem, const PlaceOptions& options = {});

/// Candidate sites sampled on a mesh (docs/math.md §21, "Sites").
struct SurfaceSites {
  Eigen::Matrix3Xd points;     ///< 3 x N
  Eigen::Matrix3Xd normals;    ///< outward unit normals of the sites' triangles
  std::vector<int> triangles;  ///< the triangle of each site
  int drawn = 0;               ///< samples drawn before thinning
};

/// `count` area-uniform samples of `mesh` from an engine seeded with `seed`, thinned to
/// `min_separation` (>= 0) in the order drawn; normals flipped when the mesh's signed volume is
/// negative, then turned outward one site at a time by outward_normals() (site_filters.h). Throws
/// InvalidArgument ("body: ...") for a bad mesh, count < 1, or a mesh of zero area.
SurfaceSites sample_surface_sites(const Mesh& mesh, int count, double min_separation,
                                  std::uint64_t seed);

}  // namespace vantage::design

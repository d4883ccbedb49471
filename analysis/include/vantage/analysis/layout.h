#pragma once

/// A fiducial layout: what the user hands vantage to analyse (README.md, "File formats").
///
/// Direction mode holds the data vectors z_i of the paper directly. Point mode holds marker
/// positions; the analysis then uses the free vectors z_j - z_i (i < j) of Prop. 8, each with a
/// pair weight (sqrt(w_i w_j) by default).

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/marker_visibility.h"

namespace vantage {

/// Which kind of entries a layout holds.
enum class LayoutMode {
  kVectors,  ///< entries are data vectors z_i (object frame)
  kPoints,   ///< entries are marker positions (object frame)
};

/// "vectors" or "points".
const char* to_string(LayoutMode mode);

/// Where the markers of a placed layout came from (`vantage place`, docs/math.md §21): kept in
/// the file so that figures can show the sites that were not chosen and the greedy steps.
struct LayoutPlacement {
  std::string sites;        ///< the candidates' source (a mesh or a sites file), as given
  std::vector<int> chosen;  ///< the site of each marker, in the order of the entries (-1: kept)
  std::string objective;    ///< what was optimised, in words
  Eigen::Matrix3Xd site_points;   ///< every candidate site
  Eigen::Matrix3Xd site_normals;  ///< their outward unit normals
  double min_separation = 0.0;    ///< least distance between the chosen markers (centres)
  /// The markers' diameter (0: points): spheres whose centres sit half of it off the surface
  /// along the site normals; the entries and site_points are the centres.
  double marker_diameter = 0.0;
  /// One greedy step: k markers chosen, the trackable fraction of the workspace and the
  /// certified p-bar_min under visibility over its trackable part.
  struct Step {
    int k = 0;
    double pbar_min = 0.0;
    double coverage = 0.0;
    /// The camera or tracker objective's search value (degrees; layout units): +inf when the
    /// choice is incomplete (below the least coverage) or, for a camera, past the first-order
    /// limit; NaN when not recorded (the affine objective).
    double objective = std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<Step> steps;  ///< the greedy construction (empty when searched exhaustively)
  /// The random baseline of the same K: feasible subsets drawn (0: none recorded) and the best
  /// and median p-bar_min among them.
  int random_trials = 0;
  double random_best_pbar_min = 0.0;
  double random_median_pbar_min = 0.0;
  /// With a camera or tracker objective: the best and median objective of the random subsets
  /// and the written layout's objective value (as Step::objective: +inf none, NaN not recorded;
  /// the baseline's are NaN when no trial was drawn).
  double random_best_objective = std::numeric_limits<double>::quiet_NaN();
  double random_median_objective = std::numeric_limits<double>::quiet_NaN();
  double objective_value = std::numeric_limits<double>::quiet_NaN();
};

/// The sensor a layout was placed for (`vantage place --objective camera|tracker`; docs/math.md
/// §21, "Objectives"), kept in the file so that `vantage analyze` evaluates the layout for it.
/// Kept through edits of the entries: it describes the sensor, not the markers.
struct LayoutSensor {
  enum class Kind {
    kCamera,   ///< a pinhole camera: the pose CRB of §22 over the workspace
    kTracker,  ///< a 3-D optical tracker: the certified worst RMS TRE of §23
  };
  Kind kind = Kind::kCamera;
  // A camera (`vantage crb`'s options).
  /// D, layout units: one, or the distances of an approach (docs/math.md §21, "An approach").
  std::vector<double> distances;
  static constexpr int kMaxDistances = 64;        ///< of an approach (each is one map to evaluate)
  double focal_px = 0.0;                          ///< f, pixels
  double noise_px = 0.0;                          ///< S, pixels per coordinate
  int samples = 0;                                ///< directions of the lattice
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();  ///< the point the camera looks at
  std::string statistic;  ///< "worst", "p95" or "median" of the rotation RMS
  // A tracker (`vantage tre`'s options).
  std::vector<Eigen::Vector3d> targets;
  double fle_rms = 0.0;  ///< > 0: the FLE given as an RMS (`--fle-rms`); 0: the sigmas below
  double fle_sigma_perp = 0.0;
  double fle_sigma_axial = 0.0;
};

/// "camera" or "tracker".
const char* to_string(LayoutSensor::Kind kind);

/// A layout in the object frame.
struct Layout {
  static constexpr double kMinLength = 1e-150;  ///< squares of lengths stay normal doubles
  static constexpr double kMaxLength = 1e150;   ///< squares and differences stay finite
  static constexpr double kMaxWeight = 1e100;   ///< weighted sums of squares stay finite
  /// Most free vectors data_vectors() builds (about 4 500 points; 240 MB of vectors).
  static constexpr Eigen::Index kMaxFreeVectors = 10'000'000;
  /// Points closer than this times the largest coordinate magnitude (or than kMinLength)
  /// coincide: their free vector is at the rounding level of the coordinates.
  static constexpr double kCoincidenceRelative = 1e-12;

  /// The distance below which two of `points` coincide (scale-invariant, see
  /// kCoincidenceRelative).
  static double coincidence_distance(const Eigen::Matrix3Xd& points);

  std::string name;
  std::string description;  ///< free text, kept when the layout is written back
  LayoutMode mode = LayoutMode::kVectors;
  Eigen::Matrix3Xd entries;     ///< one vector (direction mode) or point (point mode) per column
  Eigen::VectorXd weights;      ///< one positive weight per entry
  Eigen::Matrix3Xd candidates;  ///< allowed additions for design (may have zero columns)
  /// The entries' names (a CSV marker's name, an AprilTag corner's "tag3_c0"), one per entry
  /// in the order of `entries`, or empty when the entries are unnamed. Every edit that removes
  /// or adds an entry removes or adds its name, so a marker keeps its name through every command.
  std::vector<std::string> names;
  /// Point mode: how the markers are seen on their body (normals, cones, mesh; docs/math.md
  /// §20), or none: every camera sees every marker (the paper's model).
  std::optional<MarkerVisibility> visibility;
  /// The directions the analysis covers; none: the whole sphere.
  std::optional<LayoutWorkspace> workspace;
  /// How `vantage place` chose the markers, or none. Dropped by every edit of the entries.
  std::optional<LayoutPlacement> placement;
  /// The sensor the layout was placed for, or none.
  std::optional<LayoutSensor> sensor;

  /// Throws InvalidArgument naming the field and index of the first violation: fewer than 2
  /// vectors or 3 points (point mode needs at least 2 free vectors), non-finite values, a vector
  /// whose length is 0 or outside [kMinLength, kMaxLength] (so it normalises safely), point
  /// coordinates beyond kMaxLength, coincident points (closer than 1e-12 times the largest
  /// coordinate magnitude, or than kMinLength: scale-invariant; checked in O(n log n) for
  /// spread-out points),
  /// weights of the wrong length, non-finite, <= 0 or above kMaxWeight, bad candidates, names
  /// that are given but not one per entry, empty, or repeated.
  /// Field names are those of the file format: "vectors", "points", "weights", "candidates",
  /// "names".
  void validate() const;

  /// "vectors" or "points": the file-format name of the entries field.
  const char* entries_field() const;

  /// The name of entry i (0 <= i < entries.cols()): names[i], or "p<i>" (point mode) / "v<i>"
  /// (direction mode) for an unnamed layout.
  std::string entry_name(Eigen::Index i) const;
};

/// A name for one more entry of `layout` that none of its entries has: "<prefix><k>" with the
/// smallest k >= 1 (entry_name() of every entry counts as taken).
std::string unused_entry_name(const Layout& layout, const std::string& prefix);

/// The layout without entry k (0 <= k < entries.cols()): its weight, name, and on a body its
/// normal and cone go with it (the names of the others are kept, given or not).
Layout without_entry(const Layout& layout, Eigen::Index k);

/// Appends entry x with weight 1 (named "<name_prefix><k>" when the layout's entries are named,
/// see unused_entry_name()). On a body the new marker looks out from the layout's centroid (the
/// --normals radial rule; +z at the centroid itself) with the layout's widest cone, until the
/// user says otherwise.
void append_entry(Layout* layout, const Eigen::Vector3d& x, const std::string& name_prefix);

/// The data vectors an analysis works on, with their weights.
struct DataVectors {
  Eigen::Matrix3Xd vectors;  ///< 3 x m
  Eigen::VectorXd weights;   ///< m positive weights
  /// Point mode: the marker pair (i, j), i < j, of each free vector z_j - z_i. Empty in
  /// direction mode.
  std::vector<std::pair<int, int>> pairs;
};

/// n (n - 1) / 2 without overflow: the number of free vectors of n points.
Eigen::Index free_vector_count(Eigen::Index points);

/// The layout's data vectors: its entries in direction mode, all free vectors z_j - z_i (i < j,
/// in lexicographic order of (i, j), built by build_free_vectors of free_vectors.h) in point
/// mode. Validates the layout first; throws InvalidArgument when point mode would give more than
/// Layout::kMaxFreeVectors.
DataVectors data_vectors(const Layout& layout,
                         PairWeighting weighting = PairWeighting::kGeometricMean);

}  // namespace vantage

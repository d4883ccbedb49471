#pragma once

// `vantage place` as both front ends run it (README, "vantage place"; docs/math.md §21): the
// checks of the arguments, the candidate sites (sampled on a mesh or read) with the kept markers,
// the placement, the placed layout and its analysis, and the JSON object of `vantage place
// --json`. The `vantage` command and vantage.place() call these, so that the checks and the
// fields are defined once. Errors name the CLI's flags ("--markers", "BODY/--sites"); Python
// renames them to its keywords.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/design/placement.h"
#include "vantage/design/placement_layout.h"
#include "vantage/report/layout_report.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::place_json {

using Json = nlohmann::ordered_json;

/// The arguments of a placement, with the CLI's defaults.
struct Request {
  std::string body;   ///< mesh to sample (positional), or empty
  std::string sites;  ///< --sites file, or empty
  int candidates = 500;
  bool candidates_given = false;
  int markers = 0;
  std::string out;  ///< the placed layout's file, or empty (Python: not written)
  double min_separation = 0.0;
  /// --marker-diameter: spheres of this diameter whose centres sit half of it off the surface
  /// along the site normals (0: point markers at the sites).
  double marker_diameter = 0.0;
  std::string keep;
  bool robust_dropout = false;
  double min_distance_difference = 0.0;
  std::uint64_t seed = 1;
  int threads = 0;
  int random_trials = 1000;
  int perturbations = 0;  ///< --perturbations: iterated local search rounds after the swaps
  long exhaustive_limit = 5000;
  double certificate_tolerance = visibility::VisibilitySearchOptions{}.certificate_tolerance;
  bool overwrite = false;
  /// "affine" (the paper's bound under visibility), "camera" (the pinhole CRB, §22) or
  /// "tracker" (the target registration error, §23).
  std::string objective = "affine";
  /// The camera objective's settings (--distance, --focal, --noise-px, --statistic,
  /// --crb-samples, --aim: none for the centre of the sites' bounding box).
  double distance = 0.0;
  /// --distances D1,D2,...: an approach, instead of --distance (docs/math.md §21).
  std::vector<double> distances;
  double focal = 0.0;
  double noise_px = 0.0;
  std::string statistic = "worst";
  int crb_samples = 2000;
  std::optional<Eigen::Vector3d> aim;
  /// The tracker objective's settings: the targets in the sites' frame (--target, repeatable)
  /// and the FLE (exactly one of --fle-rms and --fle-sigma; FleModel::from_rms tells which).
  std::vector<Eigen::Vector3d> targets;
  std::optional<tracker::FleModel> fle;
  /// --min-coverage in (0, 1], or below 0 for every lattice direction but one.
  double min_coverage = -1.0;
  /// --allow-partial: an incomplete placement is written (with a warning), not refused.
  bool allow_partial = false;
  /// --exclude: keep-out volumes (meshes in the body's frame); the sampled sites inside one, or
  /// within the marker diameter of its surface, are dropped.
  std::vector<std::string> exclude;
  /// --region: the part of the body to sample (a mesh on the body's surface), or empty for the
  /// whole body; visibility and occlusion stay the whole body's.
  std::string region;

  /// The least distance between chosen markers: --min-separation, at least the diameter.
  double separation() const { return std::max(min_separation, marker_diameter); }

  /// The body mesh or the sites file, as given.
  const std::string& source() const { return sites.empty() ? body : sites; }
};

/// Checks the arguments alone, before any file is read (an empty `out` is not checked: the CLI
/// requires it itself). Throws InvalidArgument naming the flag.
void check_request(const Request& request);

/// The candidate sites (sampled on the body, or read) and the kept markers appended.
struct Sites {
  Layout layout;          ///< the candidates, then the kept markers not at a site
  int n_candidates = 0;   ///< the leading columns of `layout` that are candidates
  int drawn = 0;          ///< the samples drawn on the body (the sites' count when read)
  int excluded = 0;       ///< sampled sites dropped by the --exclude volumes
  std::vector<int> keep;  ///< the kept markers' columns
};

/// The candidate sites on a body already loaded (`mesh`, which the sites layout names by
/// `body_path`): sampled (on --region when given) and oriented per site by the whole body,
/// without the sites the --exclude volumes drop, `apply_visibility` applied, moved to the
/// sphere centres with a diameter, the kept markers appended and the problem checked.
/// candidate_sites() reads the body and calls this; the viewer calls it with the body it shows.
Sites sites_on_body(const Request& request, const Mesh& mesh, const std::string& body_path,
                    const std::function<void(Layout*)>& apply_visibility);

/// Reads the sites file with `read_sites` (the front end's format and visibility options), or
/// samples the body and applies the visibility options with `apply_visibility`; appends the
/// kept markers and checks the problem (K against the sites, min_visible, the kept markers).
Sites candidate_sites(const Request& request,
                      const std::function<Layout(const std::string&)>& read_sites,
                      const std::function<void(Layout*)>& apply_visibility);

/// The chosen markers as a layout on the body, and `vantage analyze`'s report of it.
struct PlacedLayout {
  Layout layout;
  report::LayoutReport report;
  /// The camera objective: `vantage crb`'s map of the placed layout with the same camera.
  std::optional<camera::PoseCrbMap> crb;
  /// The camera the objective used (the aim resolved), when the objective is the camera.
  std::optional<camera::PoseCrbOptions> camera;
  /// The tracker objective: `vantage tre`'s report of the placed layout at the targets.
  std::optional<tracker::TreReport> tre;
  /// The camera or tracker objective: the placed layout evaluated for its sensor block, as
  /// `vantage analyze` evaluates the written file (crb, camera and tre are its parts).
  std::optional<sensor_json::Evaluation> sensor;
  std::vector<std::string> site_names;  ///< the name of every site and kept marker
};

/// A finished placement: complete when it covers min_coverage of the workspace and the placed
/// layout's analysis is certified (affine), trackable (camera) or its worst TRE certified at every
/// target (tracker); only then is it written, or also when incomplete with allow_partial.
struct Outcome {
  design::PlacementResult result;
  PlacedLayout placed;
  bool complete = false;
  /// The objective's value of the placed layout as `vantage analyze`, `crb` or `tre` reports it
  /// (affine: the worst error, degrees; camera: the statistic of the crb map, degrees; tracker:
  /// the largest worst.rms_bound over the targets, the layout's length unit). +inf: untrackable.
  double objective_value = 0.0;
};

/// The camera objective's options of a request on `sites` (the aim resolved), or none.
std::optional<design::CameraObjective> camera_objective(const Request& request,
                                                        const Layout& sites);

/// The tracker objective's options of a request, or none.
std::optional<design::TrackerObjective> tracker_objective(const Request& request);

/// The search's options of a request on the sites `sites` (as a layout): its sizes, seed,
/// threads, least coverage, robust objective, and the camera or tracker objective; `progress`
/// (or empty) gets the stages.
design::PlaceOptions place_options(const Request& request, const Layout& sites,
                                   const std::function<void(const std::string&)>& progress);

/// Runs design::place_markers() on the sites and analyses the placed layout; `progress` (or
/// empty) gets the stages.
Outcome place(const Request& request, const Sites& sites,
              const std::function<void(const std::string&)>& progress);

/// The layout of result.chosen (sites first, kept markers last, in index order) with the
/// visibility block, workspace and placement record, and its analysis.
PlacedLayout placed_layout(const Request& request, const Layout& sites, int n_candidates,
                           const design::PlacementResult& result,
                           const std::optional<design::CameraObjective>& camera = std::nullopt,
                           const std::optional<design::TrackerObjective>& tracker = std::nullopt);

/// Why the placement is not written.
std::string failure_message(const design::PlacementResult& result, const PlacedLayout& placed);

/// The JSON object of `vantage place --json`; "written" is request.out when `written`, else null.
Json report(const Request& request, const Sites& sites, const Outcome& outcome, bool written);

}  // namespace vantage::place_json

#pragma once

/// "Place K markers on this body" (docs/math.md §21) for the viewer's design panel: the sites
/// sampled on the layout's body mesh, design::place_markers on them, and the placed layout, as
/// `vantage place BODY` builds them (design/placement_layout.h).

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/design/placement.h"

namespace vantage::viewer {

/// The design panel's placement controls: `vantage place BODY`'s options (README, "vantage
/// place"), with the body and its cones, min_visible and workspace from the layout.
struct PlaceSettings {
  int markers = 8;              ///< K
  int candidates = 500;         ///< N: sites sampled on the body
  double min_separation = 0.0;  ///< layout units; also thins the sites
  /// Spheres of this diameter resting on the surface (0: point markers); the separation is at
  /// least the diameter.
  double marker_diameter = 0.0;
  bool robust_dropout = false;
  std::uint64_t seed = 1;  ///< of the site sampling and the random baseline
  int random_trials = design::PlaceOptions{}.random_trials;
  int threads = 0;  ///< of the occlusion grid and the search (0: all cores)
  /// Least coverage of a complete placement, in (0, 1]; below 0: every lattice direction of the
  /// workspace but one.
  double min_coverage = -1.0;
  /// The workspace of the placement; none: the layout's own.
  std::optional<LayoutWorkspace> workspace;
  /// "affine", "camera" or "tracker" (docs/math.md §21, "Objectives").
  std::string objective = "affine";
  /// The camera objective: distance (layout units), focal length and noise (pixels), statistic.
  double distance = 0.0;
  /// An approach instead of `distance`: the camera distances D1, D2, ... (`vantage place
  /// --distances`; docs/math.md §21, "An approach"); empty: `distance` alone.
  std::vector<double> distances;
  double focal = 0.0;
  double noise_px = 0.0;
  std::string statistic = "worst";
  /// The tracker objective: one target (layout frame) and an isotropic FLE RMS.
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double fle_rms = 0.0;
  /// Keep-out volumes (mesh files in the body's frame) and the part of the body to sample (a mesh
  /// file, or empty for the whole body): `vantage place`'s --exclude and --region.
  std::vector<std::string> exclude;
  std::string region;
};

/// One placement on a layout's body.
struct PlaceOutcome {
  std::uint64_t revision = 0;  ///< revision of the layout it started from
  PlaceSettings settings;
  int n_candidates = 0;  ///< sites after thinning and the keep-out volumes
  int excluded = 0;      ///< sampled sites the keep-out volumes dropped
  design::PlacementResult result;
  /// As `vantage place` decides it: the coverage reached and the placed layout's analysis
  /// certified (affine), trackable (camera) or certified at the target (tracker).
  bool complete = false;
  /// The objective's value on the placed layout: the worst-case error (affine) or the camera's
  /// statistic in degrees, the worst RMS TRE in layout units (tracker); +inf when none.
  double objective_value = 0.0;
  /// Why an incomplete placement is not applied (`vantage place`'s message), or empty.
  std::string failure;
  /// The chosen sites as markers (with the sensor block for camera and tracker), set only when
  /// the placement is complete.
  Layout placed;
  double seconds = 0.0;
  std::string error;  ///< non-empty when the input was refused or the search threw
};

/// True when `layout` is on a body: a point layout with normals and a body mesh.
bool is_on_body(const Layout& layout);

/// The sites of `layout`'s body as a layout, as `vantage place BODY` makes them
/// (place_json::sites_on_body: sampled on the region, without the keep-out volumes' sites, at
/// the sphere centres with a diameter), each with the cone of the layout's first marker, and the
/// layout's min_visible, body and workspace (or the settings'). Throws InvalidArgument when the
/// layout is not on a body, or as `vantage place` refuses the settings.
Layout body_sites(const Layout& layout, const PlaceSettings& settings);

/// Synchronous placement: the settings checked as `vantage place` checks its options, body_sites()
/// (sphere centres with a diameter), then `vantage place`'s own run on them (place_json::place:
/// the occlusion grid, design::place_markers with the objective, the placed layout and its
/// evaluation). `progress` (or empty) gets each stage. Never throws: errors go to
/// PlaceOutcome::error (named as `vantage place`'s options).
PlaceOutcome place_on_body(const Layout& layout, std::uint64_t revision,
                           const PlaceSettings& settings,
                           const std::function<void(const std::string&)>& progress = {});

}  // namespace vantage::viewer

#pragma once

/// "Place K markers on this body" (docs/math.md §21) for the viewer's design panel: the sites
/// sampled on the layout's body mesh, design::place_markers on them, and the placed layout, as
/// `vantage place BODY` builds them (design/placement_layout.h).

#include <cstdint>
#include <functional>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/design/placement.h"

namespace vantage::viewer {

/// The design panel's placement controls.
struct PlaceSettings {
  int markers = 8;              ///< K
  int candidates = 500;         ///< N: sites sampled on the body
  double min_separation = 0.0;  ///< layout units; also thins the sites
  bool robust_dropout = false;
  std::uint64_t seed = 1;  ///< of the site sampling and the random baseline
  int random_trials = design::PlaceOptions{}.random_trials;
  int threads = 0;  ///< of the occlusion grid and the search (0: all cores)
};

/// One placement on a layout's body.
struct PlaceOutcome {
  std::uint64_t revision = 0;  ///< revision of the layout it started from
  PlaceSettings settings;
  int n_candidates = 0;  ///< sites after thinning
  design::PlacementResult result;
  /// The chosen sites as markers (design::placed_layout), set only when result is complete.
  Layout placed;
  double seconds = 0.0;
  std::string error;  ///< non-empty when the input was refused or the search threw
};

/// True when `layout` is on a body: a point layout with normals and a body mesh.
bool is_on_body(const Layout& layout);

/// The sites of `layout`'s body as a layout: design::sample_surface_sites(body, candidates,
/// min_separation, seed), each with the cone of the layout's first marker, and the layout's
/// min_visible, body and workspace. Throws InvalidArgument when the layout is not on a body.
Layout body_sites(const Layout& layout, const PlaceSettings& settings);

/// Synchronous placement: body_sites(), their occlusion grid (visibility::VisibilityModel::of at
/// its default resolution, as `vantage place`), design::place_markers, and for a complete result
/// the placed layout. `progress` (or empty) gets each stage. Never throws: errors go to
/// PlaceOutcome::error.
PlaceOutcome place_on_body(const Layout& layout, std::uint64_t revision,
                           const PlaceSettings& settings,
                           const std::function<void(const std::string&)>& progress = {});

}  // namespace vantage::viewer

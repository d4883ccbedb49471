#pragma once

/// Placement as layouts (docs/math.md §21): the candidate sites sampled on a body as a point
/// layout, and the layout of the chosen sites with its placement record. `vantage place` and
/// the viewer's design panel both build their layouts here.

#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/design/placement.h"

namespace vantage::design {

/// The sites of sample_surface_sites() as a point layout on `body`: unnamed entries of unit
/// weight, the sites' outward normals, every cone `cone_half_angle_deg`, min_visible 3, the
/// mesh `body` read from `body_path`, no workspace. The caller adds min_visible and workspace.
Layout surface_sites_layout(const SurfaceSites& sites, const Mesh& body,
                            const std::string& body_path,
                            double cone_half_angle_deg = MarkerVisibility::kDefaultConeDeg);

/// The name of site `s` of a sites layout: its entry name, or "site<s>" for unnamed sites.
std::string site_name(const Layout& sites, int s);

/// How placed_layout() records the placement.
struct PlacedLayoutRecord {
  std::string sites;             ///< the candidates' source (a mesh or a sites file), as given
  int n_candidates = 0;          ///< the leading columns of the sites that are candidates
  bool robust_dropout = false;   ///< the objective of the search
  std::string objective;         ///< the objective in words; empty: the affine objective's
  double min_separation = 0.0;   ///< the least distance between chosen markers
  double marker_diameter = 0.0;  ///< the spheres' diameter (0: point markers)
};

/// Throws InvalidArgument "marker_diameter" unless `diameter` is finite, >= 0 and at most
/// `extent`, the size of the body the spheres rest on (a sphere wider than the whole body is a
/// number in another unit, docs/math.md §21, "Physical markers").
void check_marker_diameter(double diameter, double extent);

/// The diagonal of the bounding box of `points` (0 for none).
double extent(const Eigen::Matrix3Xd& points);

/// The centres of spheres of `diameter` resting on a surface at `points` with outward unit
/// `normals`: each point diameter / 2 along its normal (docs/math.md §21, "Physical markers").
/// Throws InvalidArgument "marker_diameter" unless it is finite and >= 0 (the callers check it
/// against the body's size with check_marker_diameter()).
Eigen::Matrix3Xd sphere_centres(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                double diameter);

/// The sites (points on a surface with outward unit normals) moved to the sphere centres above.
/// Visibility and occlusion are then those of the centres.
Layout sphere_centres(Layout sites, double diameter);

/// The layout of result.chosen (in index order) on the sites' body, named "<sites' name>
/// (placed)" (once: a placed layout placed again keeps its name): each marker the site's
/// point, normal, cone and name (site_name()), the sites' min_visible, body and workspace, and
/// `placement` filled (chosen as candidate indices, -1 for a kept marker past n_candidates; the
/// candidates' points and normals; the greedy steps' p-bar_min). The sites need visibility.
Layout placed_layout(const Layout& sites, const PlacementResult& result,
                     const PlacedLayoutRecord& record);

}  // namespace vantage::design

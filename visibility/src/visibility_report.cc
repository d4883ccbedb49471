// analyze_visibility(): the worst viewpoint of a body's markers, its coverage and dropout
// (docs/math.md §20), with the occlusion grid cast on the body's mesh when it has one.

#include "vantage/visibility/visibility_report.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/parallel.h"
#include "vantage/visibility/exact_visibility.h"
#include "vantage/visibility/visibility_model.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::visibility {
namespace {

double error_deg(const VisibilityWorstViewpoint& w) {
  if (w.status == VisibilityWorstViewpoint::Status::kUntrackable) return 90.0;
  return std::asin(std::clamp(w.t, 0.0, 1.0)) * kDegreesPerRadian;
}

/// The problem without marker k (the grid without its rows).
VisibilityProblem without(const VisibilityProblem& p, int k, const OcclusionGrid* grid) {
  const Eigen::Index n = p.points.cols();
  VisibilityProblem out = p;
  out.points.resize(3, n - 1);
  out.normals.resize(3, n - 1);
  out.cos_cone.resize(n - 1);
  for (Eigen::Index i = 0, j = 0; i < n; ++i) {
    if (i == k) continue;
    out.points.col(j) = p.points.col(i);
    out.normals.col(j) = p.normals.col(i);
    out.cos_cone(j++) = p.cos_cone(i);
  }
  out.min_visible = std::min<int>(p.min_visible, static_cast<int>(n - 1));
  out.occlusion = grid;
  return out;
}

void add_dropout(const VisibilityProblem& problem, const VisibilityReportOptions& options,
                 const OcclusionGrid* grid, VisibilityReport* report) {
  const int n = static_cast<int>(problem.points.cols());
  report->dropout.assign(static_cast<std::size_t>(n), {});
  if (n - 1 < 3) {
    for (int k = 0; k < n; ++k) {
      VisibilityDropoutEntry& e = report->dropout[static_cast<std::size_t>(k)];
      e.lost = k;
      e.status = VisibilityWorstViewpoint::Status::kUntrackable;
      e.max_worst_case_error_deg = 90.0;
    }
  } else {
    parallel_blocks(n, options.threads, [&](long begin, long end) {
      for (long k = begin; k < end; ++k) {
        const OcclusionGrid reduced =
            grid != nullptr ? grid->without(static_cast<int>(k)) : OcclusionGrid();
        const VisibilityProblem p =
            without(problem, static_cast<int>(k), grid != nullptr ? &reduced : nullptr);
        const VisibilityWorstViewpoint w = visibility_worst_viewpoint(p, options.search);
        VisibilityDropoutEntry& e = report->dropout[static_cast<std::size_t>(k)];
        e.lost = static_cast<int>(k);
        e.status = w.status;
        e.t = w.t;
        e.pbar_min = w.pbar_min;
        e.max_worst_case_error_deg = error_deg(w);
        e.trackable_fraction = visibility_coverage(p, options.coverage_samples).trackable_fraction;
      }
    });
  }
  report->dropout_by_harm.resize(static_cast<std::size_t>(n));
  std::iota(report->dropout_by_harm.begin(), report->dropout_by_harm.end(), 0);
  std::stable_sort(report->dropout_by_harm.begin(), report->dropout_by_harm.end(),
                   [&](int a, int b) {
                     const VisibilityDropoutEntry& x = report->dropout[static_cast<std::size_t>(a)];
                     const VisibilityDropoutEntry& y = report->dropout[static_cast<std::size_t>(b)];
                     if (x.max_worst_case_error_deg != y.max_worst_case_error_deg) {
                       return x.max_worst_case_error_deg > y.max_worst_case_error_deg;
                     }
                     return x.trackable_fraction < y.trackable_fraction;
                   });
}

/// The markers whose cones admit a lattice direction of the workspace, at every one of which
/// the body hides them (docs/math.md §20, "Markers the body hides").
std::vector<int> hidden_by_body(const VisibilityProblem& problem, int samples) {
  const std::size_t n = static_cast<std::size_t>(problem.points.cols());
  std::vector<char> faced(n, 0);
  std::vector<char> seen(n, 0);
  const Eigen::Matrix3Xd a = workspace_lattice(problem.workspace, samples).directions;
  for (Eigen::Index k = 0; k < a.cols(); ++k) {
    const Eigen::Vector3d d = a.col(k);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index c = static_cast<Eigen::Index>(i);
      if (problem.normals.col(c).dot(d) >= problem.cos_cone(c)) faced[i] = 1;
    }
    for (int i : direction_visibility(problem, d).visible) seen[static_cast<std::size_t>(i)] = 1;
  }
  std::vector<int> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (faced[i] && !seen[i]) out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace

bool VisibilityReportOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!search.is_valid(&inner)) return vantage::internal::invalid_option(why, "search", inner);
  if (!(occlusion_resolution_deg >= 0.45 && occlusion_resolution_deg <= 30.0)) {
    return vantage::internal::invalid_option(why, "occlusion_resolution_deg",
                                             "must be in [0.45, 30]");
  }
  if (coverage_samples < 100) {
    return vantage::internal::invalid_option(why, "coverage_samples", "must be >= 100");
  }
  if (threads < 0) return vantage::internal::invalid_option(why, "threads", "must be >= 0");
  return true;
}

VisibilityProblem visibility_problem(const Layout& layout, const OcclusionGrid* occlusion) {
  if (layout.mode != LayoutMode::kPoints || !layout.visibility) {
    throw InvalidArgument("normals", "visibility needs a point layout with normals");
  }
  const MarkerVisibility& v = *layout.visibility;
  VisibilityProblem p;
  p.points = layout.entries;
  p.normals = v.normals;
  p.cos_cone.resize(v.cone_half_angle_deg.size());
  for (Eigen::Index i = 0; i < p.cos_cone.size(); ++i) {
    // cos(90 deg) is 0 exactly, so that opposite faces' cones meet at their edge (std::cos
    // gives 6e-17: a sliver no marker sees); a full cone sees every direction.
    const double cone = v.cone_half_angle_deg(i);
    p.cos_cone(i) = cone >= 180.0 ? -1.0 : cone == 90.0 ? 0.0 : std::cos(cone / kDegreesPerRadian);
  }
  p.min_visible = v.min_visible;
  if (layout.workspace && layout.workspace->half_angle_deg < 180.0) {
    p.workspace = Workspace{layout.workspace->axis,
                            std::cos(layout.workspace->half_angle_deg / kDegreesPerRadian)};
  }
  p.occlusion = occlusion;
  return p;
}

VisibilityReport analyze_visibility(const Layout& layout, const VisibilityReportOptions& options) {
  vantage::internal::check_options("options", options);
  VisibilityReport report;
  const VisibilityModel model =
      VisibilityModel::of(layout, options.occlusion_resolution_deg, options.threads);
  const VisibilityProblem& problem = model.problem();
  const OcclusionGrid* grid = problem.occlusion;
  if (model.has_body()) {
    const Mesh& mesh = *layout.visibility->body;
    report.with_body = true;
    report.occlusion_resolution_deg = model.resolution_deg();
    // Spheres (a placement's marker_diameter) have their centres half of it off the surface.
    const double radius = layout.placement ? 0.5 * layout.placement->marker_diameter : 0.0;
    const double far = VisibilityReport::kOffSurface * mesh.size() + radius;
    for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
      report.distance_to_body.push_back(distance_to_mesh(mesh, layout.entries.col(i)));
      if (report.distance_to_body.back() > far) report.off_body.push_back(static_cast<int>(i));
    }
  }
  report.min_visible = problem.min_visible;
  report.workspace = layout.workspace;
  report.worst = visibility_worst_viewpoint(problem, options.search);
  if (model.has_body() && report.worst.status != VisibilityWorstViewpoint::Status::kUntrackable) {
    report.exact_viewpoint =
        ExactVisibility(problem, *layout.visibility->body).at(report.worst.viewpoint);
  }
  report.max_worst_case_error_deg = error_deg(report.worst);
  report.coverage = visibility_coverage(problem, options.coverage_samples);
  if (model.has_body()) report.hidden_by_body = hidden_by_body(problem, options.coverage_samples);
  if (options.dropout) add_dropout(problem, options, grid, &report);
  return report;
}

bool VisibilityReport::is_usable() const {
  if (!worst.certified() || exact_viewpoint_disagrees()) return false;
  for (const VisibilityDropoutEntry& e : dropout) {
    if (e.status == VisibilityWorstViewpoint::Status::kNotCertified) return false;
  }
  return true;
}

const char* VisibilityReport::certificate_status() const {
  if (worst.certified() && exact_viewpoint_disagrees()) return "not_certified";
  if (worst.certified() && with_body) return "certified_at_resolution";
  return to_string(worst.status);
}

const char* VisibilityReport::entry_status(const VisibilityDropoutEntry& entry) const {
  if (with_body && entry.status == VisibilityWorstViewpoint::Status::kCertified) {
    return "certified_at_resolution";
  }
  return to_string(entry.status);
}

bool VisibilityReport::exact_viewpoint_disagrees() const {
  return exact_viewpoint && exact_viewpoint->visible != worst.visible_markers;
}

std::string VisibilityReport::message() const {
  std::ostringstream out;
  if (!worst.certified()) out << "visibility: " << worst.message;
  if (worst.certified() && exact_viewpoint_disagrees()) {
    out << "visibility: under exact rays the worst viewpoint sees "
        << exact_viewpoint->visible.size() << " markers, not the occlusion grid's "
        << worst.visible_markers.size()
        << (exact_viewpoint->trackable ? "" : ", and is not trackable")
        << ": the grid's cells decide its neighbourhood wrongly, and the answer does not hold";
  }
  int uncertified = 0;
  for (const VisibilityDropoutEntry& e : dropout) {
    uncertified += e.status == VisibilityWorstViewpoint::Status::kNotCertified;
  }
  if (uncertified > 0) {
    if (out.tellp() > 0) out << "; ";
    out << "visibility dropout: " << uncertified << " entries not certified";
  }
  return out.str();
}

}  // namespace vantage::visibility

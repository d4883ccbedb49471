// `vantage place`'s candidate sites: the sites file read, or the body mesh sampled (--region,
// --exclude), with the kept markers appended and the problem checked against them.

#include "vantage/commands/place_json.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "place_internal.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/against_source.h"
#include "vantage/design/site_filters.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/mesh_file.h"
#include "vantage/io/printable.h"

namespace vantage::place_json {

using internal::place_refuse;

namespace {

// A file's own errors that name no field of it (cannot be read, a directory; every reader's
// message starts with the file's name) named as the option that gave the file. Errors that name
// a field of the file keep it (Python's ValueError.field, .index and .source).
template <typename Call>
auto place_reading(const std::string& option, const std::string& path, Call&& call) {
  try {
    return call();
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    if (e.field().empty() && message.rfind(io::printable(path) + ": ", 0) == 0) {
      place_refuse(option, message);
    }
    throw;
  }
}

// The site at exactly the position of kept marker i, or -1.
int place_site_at(const Layout& sites, const Eigen::Vector3d& p) {
  for (Eigen::Index j = 0; j < sites.entries.cols(); ++j) {
    if (sites.entries.col(j) == p) return static_cast<int>(j);
  }
  return -1;
}

// --marker-diameter against the size of the body (the mesh, or the sites' extent).
void place_check_diameter(const Request& request, double extent) {
  try {
    design::check_marker_diameter(request.marker_diameter, extent);
  } catch (const InvalidArgument& e) {
    place_refuse("--marker-diameter", e.problem());
  }
}

// A mesh named by `option` (BODY, --region, --exclude), read or refused naming the option.
Mesh place_read_mesh(const std::string& option, const std::string& path) {
  try {
    return io::read_mesh(path);
  } catch (const InvalidArgument& e) {
    place_refuse(option, e.what());
  }
}

// Region sites farther than this fraction of the body's size from the body: the region is not
// on the body (another frame or unit).
constexpr double kRegionOffBody = 1e-3;

// The sites sampled on the body mesh (or on its --region), oriented per site by the whole body,
// without the sites the --exclude volumes drop, as a point layout on the body.
Layout place_sampled_sites(const Request& request, const Mesh& mesh, const std::string& body_path,
                           int* drawn, int* excluded) {
  place_check_diameter(request, mesh.size());
  const std::string sampled_option = request.region.empty() ? "BODY" : "--region";
  const std::string sampled_path = request.region.empty() ? request.body : request.region;
  const Mesh part = request.region.empty() ? mesh : place_read_mesh("--region", request.region);
  design::SurfaceSites sampled;
  try {
    sampled =
        design::sample_surface_sites(part, request.candidates, request.separation(), request.seed);
  } catch (const InvalidArgument& e) {
    place_refuse(sampled_option, sampled_path + ": " + e.what());
  }
  if (!request.region.empty()) {
    // Each region site on the body, with the body's triangle there: the whole body orients it.
    const double tolerance = kRegionOffBody * mesh.size();
    std::vector<int> on_body(static_cast<std::size_t>(sampled.points.cols()));
    for (Eigen::Index i = 0; i < sampled.points.cols(); ++i) {
      const MeshPoint nearest = nearest_mesh_point(mesh, sampled.points.col(i));
      if (nearest.distance > tolerance) {
        place_refuse("--region", request.region + ": not on the body " + request.body +
                                     " (a point of it is farther than 1e-3 of the body's size "
                                     "from its surface: another frame or unit?)");
      }
      on_body[static_cast<std::size_t>(i)] = static_cast<int>(nearest.triangle);
    }
    sampled.normals = design::outward_normals(mesh, sampled.points, sampled.normals, on_body);
  }
  std::vector<design::KeepOut> volumes;
  for (const std::string& path : request.exclude) {
    const Mesh volume = place_read_mesh("--exclude", path);
    try {
      volumes.emplace_back(volume, request.marker_diameter);
    } catch (const InvalidArgument& e) {
      place_refuse("--exclude", path + ": " + e.what());
    }
  }
  *drawn = sampled.drawn;
  *excluded = design::drop_excluded_sites(volumes, &sampled);
  if (sampled.points.cols() == 0) {
    place_refuse("--exclude", "the keep-out volumes hold every sampled site");
  }
  Layout sites = design::surface_sites_layout(sampled, mesh, body_path);
  sites.name = std::filesystem::path(request.body).stem().string();
  return sites;
}

// The kept markers: a kept marker at a site's very position keeps that site; the others are
// appended to the sites (their normals and cones from their file).
std::vector<int> place_append_kept(const Request& request, Layout* sites) {
  if (request.keep.empty()) return {};
  Layout kept =
      place_reading("--keep", request.keep, [&] { return io::load_layout(request.keep); });
  if (kept.mode != LayoutMode::kPoints || !kept.visibility) {
    place_refuse("--keep", request.keep +
                               ": expected points with \"normals\" (the markers already on "
                               "the body)");
  }
  std::vector<int> at_sites;
  std::vector<Eigen::Index> appended;
  for (Eigen::Index i = 0; i < kept.entries.cols(); ++i) {
    const int site = place_site_at(*sites, kept.entries.col(i));
    if (site >= 0) {
      at_sites.push_back(site);
    } else {
      appended.push_back(i);
    }
  }
  if (appended.size() != static_cast<std::size_t>(kept.entries.cols())) {
    Layout rest = kept;
    rest.entries.resize(3, static_cast<Eigen::Index>(appended.size()));
    rest.visibility->normals.resize(3, rest.entries.cols());
    rest.visibility->cone_half_angle_deg.resize(rest.entries.cols());
    rest.names.clear();
    for (std::size_t k = 0; k < appended.size(); ++k) {
      const Eigen::Index i = appended[k], to = static_cast<Eigen::Index>(k);
      rest.entries.col(to) = kept.entries.col(i);
      rest.visibility->normals.col(to) = kept.visibility->normals.col(i);
      rest.visibility->cone_half_angle_deg(to) = kept.visibility->cone_half_angle_deg(i);
      if (!kept.names.empty()) rest.names.push_back(kept.names[static_cast<std::size_t>(i)]);
    }
    kept = rest;
  }
  std::vector<int> out = at_sites;
  const Eigen::Index n = sites->entries.cols();
  const Eigen::Index f = kept.entries.cols();
  if (f == 0) return out;
  std::vector<std::string> names;
  for (Eigen::Index i = 0; i < n; ++i) names.push_back(sites->entry_name(i));
  for (Eigen::Index i = 0; i < f; ++i) {
    const std::string name = kept.names.empty() ? "kept" + std::to_string(i + 1) : kept.names[i];
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      place_refuse("--keep", request.keep + ": marker name \"" + io::excerpt(name) +
                                 "\" is also a site's name");
    }
    names.push_back(name);
  }
  MarkerVisibility& v = *sites->visibility;
  sites->entries.conservativeResize(3, n + f);
  sites->entries.rightCols(f) = kept.entries;
  sites->weights = Eigen::VectorXd::Ones(n + f);
  v.normals.conservativeResize(3, n + f);
  v.normals.rightCols(f) = kept.visibility->normals;
  v.cone_half_angle_deg.conservativeResize(n + f);
  v.cone_half_angle_deg.tail(f) = kept.visibility->cone_half_angle_deg;
  sites->names = names;
  commands::against_source(request.keep, [&] { sites->validate(); });
  for (Eigen::Index i = 0; i < f; ++i) out.push_back(static_cast<int>(n + i));
  return out;
}

void place_check_problem(const Request& request, const Layout& sites, std::size_t kept) {
  const long n = static_cast<long>(sites.entries.cols());
  const int min_visible = sites.visibility->min_visible;
  if (request.markers > n) {
    place_refuse("--markers", std::to_string(request.markers) + " exceeds the " +
                                  std::to_string(n) + " sites" +
                                  (kept > 0 ? " and kept markers" : ""));
  }
  if (request.markers < min_visible) {
    place_refuse("--markers", "must be at least min_visible (" + std::to_string(min_visible) +
                                  "), got " + std::to_string(request.markers));
  }
  if (static_cast<long>(kept) > request.markers) {
    place_refuse("--markers", "the " + std::to_string(kept) + " kept markers exceed " +
                                  std::to_string(request.markers));
  }
  if (request.robust_dropout && request.markers <= min_visible) {
    place_refuse("--robust-dropout", "needs --markers above min_visible (" +
                                         std::to_string(min_visible) +
                                         "): a lost marker leaves too few otherwise");
  }
}

// The sites' common end: the sphere centres, the kept markers, the problem checked.
Sites place_finish_sites(const Request& request, Sites out) {
  if (request.marker_diameter > 0.0) {
    out.layout = design::sphere_centres(std::move(out.layout), request.marker_diameter);
  }
  out.n_candidates = static_cast<int>(out.layout.entries.cols());
  out.keep = place_append_kept(request, &out.layout);
  place_check_problem(request, out.layout, out.keep.size());
  return out;
}

}  // namespace

Sites sites_on_body(const Request& request, const Mesh& mesh, const std::string& body_path,
                    const std::function<void(Layout*)>& apply_visibility) {
  Sites out;
  out.layout = place_sampled_sites(request, mesh, body_path, &out.drawn, &out.excluded);
  apply_visibility(&out.layout);
  return place_finish_sites(request, std::move(out));
}

Sites candidate_sites(const Request& request,
                      const std::function<Layout(const std::string&)>& read_sites,
                      const std::function<void(Layout*)>& apply_visibility) {
  if (request.sites.empty()) {
    return sites_on_body(request, place_read_mesh("BODY", request.body),
                         std::filesystem::absolute(request.body).lexically_normal().string(),
                         apply_visibility);
  }
  Sites out;
  out.layout = place_reading("--sites", request.sites, [&] { return read_sites(request.sites); });
  if (out.layout.mode != LayoutMode::kPoints) {
    place_refuse("--sites",
                 request.sites + ": expected a point layout (\"points\" with \"normals\")");
  }
  if (!out.layout.visibility) {
    place_refuse("--sites", request.sites + ": the sites need \"normals\" (or --normals radial)");
  }
  out.drawn = static_cast<int>(out.layout.entries.cols());
  place_check_diameter(request, design::extent(out.layout.entries));
  return place_finish_sites(request, std::move(out));
}

}  // namespace vantage::place_json

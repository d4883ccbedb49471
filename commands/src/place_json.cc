#include "vantage/commands/place_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/design/site_filters.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/mesh_file.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"
#include "vantage/report/json_number.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::place_json {
namespace {

constexpr int kMaxCandidates = 20000;
// The camera objective's lattice: each evaluation is linear in it.
constexpr int kMaxCrbSamples = 1'000'000;

[[noreturn]] void place_refuse(const std::string& field, const std::string& message) {
  throw InvalidArgument(field, message);
}

// The library's InvalidArgument from data read from `source`, reported against the file.
template <typename Call>
auto place_against(const std::string& source, Call&& call) {
  try {
    return call();
  } catch (const InvalidArgument& e) {
    throw e.against(source);
  }
}

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

bool place_valid_utf8(const std::string& text) {
  try {
    static_cast<void>(Json(text).dump());
  } catch (const Json::type_error&) {
    return false;
  }
  return true;
}

std::string place_percent(double fraction) {
  std::ostringstream out;
  out.precision(4);
  const double x = 100.0 * fraction;
  out << (x == 0.0 ? 0.0 : x);  // never "-0", as the CLI's format_number
  return out.str() + " %";
}

// The site at exactly the position of kept marker i, or -1.
int place_site_at(const Layout& sites, const Eigen::Vector3d& p) {
  for (Eigen::Index j = 0; j < sites.entries.cols(); ++j) {
    if (sites.entries.col(j) == p) return static_cast<int>(j);
  }
  return -1;
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
Layout place_sampled_sites(const Request& request, int* drawn, int* excluded) {
  const Mesh mesh = place_read_mesh("BODY", request.body);
  const std::string sampled_option = request.region.empty() ? "BODY" : "--region";
  const std::string sampled_path = request.region.empty() ? request.body : request.region;
  const Mesh part = request.region.empty() ? mesh : place_read_mesh("--region", request.region);
  design::SurfaceSites sampled;
  try {
    sampled =
        design::sample_surface_sites(part, request.candidates, request.separation(), request.seed);
    if (!request.region.empty()) {
      sampled.normals = design::outward_normals(mesh, sampled.points, sampled.normals);
    }
  } catch (const InvalidArgument& e) {
    place_refuse(sampled_option, sampled_path + ": " + e.what());
  }
  if (!request.region.empty()) {
    const double tolerance = kRegionOffBody * mesh.size();
    for (Eigen::Index i = 0; i < sampled.points.cols(); ++i) {
      if (distance_to_mesh(mesh, sampled.points.col(i)) > tolerance) {
        place_refuse("--region", request.region + ": not on the body " + request.body +
                                     " (a point of it is farther than 1e-3 of the body's size "
                                     "from its surface: another frame or unit?)");
      }
    }
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
  Layout sites = design::surface_sites_layout(
      sampled, mesh, std::filesystem::absolute(request.body).lexically_normal().string());
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
      place_refuse("--keep", request.keep + ": marker name \"" + name + "\" is also a site's name");
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
  place_against(request.keep, [&] { sites->validate(); });
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

// Site s as the JSON names it: its index among the candidates, or -1 for a kept marker.
int place_candidate_index(int s, int n_candidates) { return s < n_candidates ? s : -1; }

Json place_steps_json(const design::PlacementResult& r) {
  Json steps = Json::array();
  for (const design::PlacementStep& s : r.steps) {
    steps.push_back({{"k", s.k},
                     {"added", s.added},
                     {"coverage", s.value.coverage},
                     {"pbar_min", s.value.pbar_min}});
  }
  return steps;
}

void check_positive(double value, const char* option) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    place_refuse(option, "must be a finite number > 0 with --objective camera");
  }
}

void check_camera(const Request& request) {
  check_positive(request.distance, "--distance");
  check_positive(request.focal, "--focal");
  check_positive(request.noise_px, "--noise-px");
  if (!design::parse_crb_statistic(request.statistic)) {
    place_refuse("--statistic", "expected worst, p95 or median, got \"" + request.statistic + "\"");
  }
  if (request.crb_samples < 100 || request.crb_samples > kMaxCrbSamples) {
    place_refuse("--crb-samples", "must be in [100, " + std::to_string(kMaxCrbSamples) + "], got " +
                                      std::to_string(request.crb_samples));
  }
  if (request.aim && !request.aim->allFinite()) place_refuse("--aim", "must be finite");
}

// The FLE's option as the request was given it.
const char* fle_option(const Request& request) {
  return request.fle && !request.fle->from_rms ? "--fle-sigma" : "--fle-rms";
}

void check_tracker(const Request& request) {
  if (request.targets.empty()) {
    place_refuse("--target", "give at least one X,Y,Z with --objective tracker");
  }
  for (const Eigen::Vector3d& target : request.targets) {
    if (!target.allFinite()) place_refuse("--target", "must be finite");
  }
  if (!request.fle) {
    place_refuse("--fle-rms", "give --fle-rms F or --fle-sigma SP,SD with --objective tracker");
  }
  std::string why;
  if (!request.fle->is_valid(&why)) place_refuse(fle_option(request), why);
  if (request.markers > design::TrackerObjective::kMaxMarkers) {
    place_refuse("--markers", "the tracker objective takes at most " +
                                  std::to_string(design::TrackerObjective::kMaxMarkers) +
                                  " markers (the TRE search's limit), got " +
                                  std::to_string(request.markers));
  }
}

// The TRE's numeric range (docs/math.md §23) on the sites, before any search.
void check_tracker_range(const Request& request, const Eigen::Matrix3Xd& sites) {
  const long n = static_cast<long>(request.targets.size());
  for (long i = 0; i < n; ++i) {
    try {
      tracker::check_tre_range(sites, request.targets[static_cast<std::size_t>(i)], *request.fle,
                               n > 1 ? i : -1);
    } catch (const InvalidArgument& e) {
      if (e.field() == "target") place_refuse("--target", e.what());
      if (e.field().rfind("fle.", 0) == 0) place_refuse(fle_option(request), e.what());
      place_refuse(request.sites.empty() ? "BODY" : "--sites", e.what());
    }
  }
}

void check_objective(const Request& request) {
  const bool camera = request.objective == "camera";
  const bool tracker = request.objective == "tracker";
  if (!camera && !tracker && request.objective != "affine") {
    place_refuse("--objective",
                 "expected affine, camera or tracker, got \"" + request.objective + "\"");
  }
  if (camera) check_camera(request);
  if (tracker) check_tracker(request);
  const std::pair<bool, const char*> camera_only[] = {
      {request.distance != 0.0, "--distance"},
      {request.focal != 0.0, "--focal"},
      {request.noise_px != 0.0, "--noise-px"},
      {request.statistic != "worst", "--statistic"},
      {request.crb_samples != Request{}.crb_samples, "--crb-samples"},
      {request.aim.has_value(), "--aim"}};
  for (const auto& [given, option] : camera_only) {
    if (given && !camera) place_refuse(option, "goes with --objective camera");
  }
  if (!tracker && !request.targets.empty()) {
    place_refuse("--target", "goes with --objective tracker");
  }
  if (!tracker && request.fle) place_refuse(fle_option(request), "goes with --objective tracker");
}

// The camera objective in words, with the `vantage crb` options that reproduce its numbers.
std::string camera_words(const Request& request, const camera::PoseCrbOptions& camera) {
  std::ostringstream out;
  out.precision(17);
  const Eigen::Vector3d& aim = *camera.aim;
  out << "camera: the " << request.statistic
      << " rot_rms over the workspace of vantage crb --distance " << camera.distance << " --focal "
      << camera.focal_length << " --noise-px " << camera.noise_px << " --samples " << camera.samples
      << " --aim " << aim.x() << "," << aim.y() << "," << aim.z();
  return out.str();
}

// The tracker objective in words, with the `vantage tre` options that reproduce its numbers.
std::string tracker_words(const design::TrackerObjective& tracker) {
  std::ostringstream out;
  out.precision(17);
  out << "tracker: the largest worst.rms_bound over the targets of vantage tre";
  for (const Eigen::Vector3d& t : tracker.targets) {
    out << " --target " << t.x() << "," << t.y() << "," << t.z();
  }
  if (tracker.fle.from_rms) {
    out << " --fle-rms " << tracker.fle.rms();
  } else {
    out << " --fle-sigma " << tracker.fle.sigma_perp << "," << tracker.fle.sigma_axial;
  }
  return out.str();
}

// The largest certified bound on the worst RMS TRE over the targets of a tre report (+inf when a
// target is tracked from nowhere).
double tre_objective(const tracker::TreReport& report) {
  double out = 0.0;
  for (const tracker::TreTargetReport& t : report.targets) {
    if (t.extremes.worst.status == tracker::TreExtreme::Status::kUntracked) {
      return std::numeric_limits<double>::infinity();
    }
    out = std::max(out, t.extremes.worst.rms_bound);
  }
  return out;
}

// Every target's worst is certified.
bool tre_certified(const tracker::TreReport& report) {
  return std::all_of(
      report.targets.begin(), report.targets.end(),
      [](const tracker::TreTargetReport& t) { return t.extremes.worst.certified(); });
}

// The camera's statistic of a crb map, degrees (+inf when untrackable).
double crb_statistic(const camera::PoseCrbMap& map, design::CrbStatistic statistic) {
  if (map.status != camera::PoseCrbMap::Status::kOk) return std::numeric_limits<double>::infinity();
  switch (statistic) {
    case design::CrbStatistic::kWorst:
      return map.worst.rot_rms_deg;
    case design::CrbStatistic::kP95:
      return map.percentiles.p95;
    case design::CrbStatistic::kMedian:
      return map.percentiles.p50;
  }
  return map.worst.rot_rms_deg;
}

Json place_vector(const Eigen::Vector3d& v) { return Json{v.x(), v.y(), v.z()}; }

// The tracker objective's block: `vantage tre`'s worst of each target on the placed layout.
void place_tracker_json(const Outcome& outcome, Json* out) {
  const tracker::TreReport& tre = *outcome.placed.tre;
  (*out)["search_value"] = report::json_number(outcome.result.value.objective);
  Json fle = {{"sigma_perp", tre.fle.sigma_perp}, {"sigma_axial", tre.fle.sigma_axial}};
  if (tre.fle.from_rms) fle["rms"] = tre.fle.rms();
  (*out)["fle"] = fle;
  Json targets = Json::array();
  for (const tracker::TreTargetReport& t : tre.targets) {
    const tracker::TreExtreme& w = t.extremes.worst;
    targets.push_back({{"target", place_vector(t.target)},
                       {"status", tracker::to_string(w.status)},
                       {"rms", w.rms},
                       {"rms_bound", w.rms_bound},
                       {"direction", place_vector(w.direction)}});
  }
  (*out)["targets"] = targets;
}

Json place_objective_json(const Request& request, const Outcome& outcome) {
  const design::PlacementResult& r = outcome.result;
  Json out;
  out["name"] = request.objective;
  if (outcome.placed.tre) {
    // A length in the layout's unit, not degrees.
    out["value"] = report::json_number(outcome.objective_value);
  } else {
    out["value_deg"] = report::json_number(outcome.objective_value);
  }
  out["min_coverage"] = request.min_coverage == -1.0 ? Json("all lattice directions but one")
                                                     : Json(request.min_coverage);
  if (outcome.placed.tre) {
    place_tracker_json(outcome, &out);
    return out;
  }
  if (!outcome.placed.crb) {
    out["scale_free"] = true;
    return out;
  }
  const camera::PoseCrbOptions& c = *outcome.placed.camera;
  const camera::PoseCrbMap& map = *outcome.placed.crb;
  out["statistic"] = request.statistic;
  out["search_value_deg"] = report::json_number(r.value.objective);
  out["camera"] = {{"distance", c.distance},
                   {"focal_px", c.focal_length},
                   {"noise_px", c.noise_px},
                   {"samples", c.samples},
                   {"aim", {c.aim->x(), c.aim->y(), c.aim->z()}}};
  Json crb = {{"status", camera::to_string(map.status)},
              {"trackable_fraction", map.trackable_fraction}};
  if (map.status == camera::PoseCrbMap::Status::kOk) {
    crb["worst"] = {
        {"rot_rms_deg", map.worst.rot_rms_deg},
        {"trans_rms", map.worst.trans_rms},
        {"direction", {map.worst.direction.x(), map.worst.direction.y(), map.worst.direction.z()}}};
    crb["percentiles"] = {
        {"p50", map.percentiles.p50}, {"p95", map.percentiles.p95}, {"p99", map.percentiles.p99}};
  }
  out["crb"] = crb;
  return out;
}

}  // namespace

std::optional<design::CameraObjective> camera_objective(const Request& request,
                                                        const Layout& sites) {
  if (request.objective != "camera") return std::nullopt;
  design::CameraObjective out;
  out.sites = sites;
  out.statistic = *design::parse_crb_statistic(request.statistic);
  out.crb.distance = request.distance;
  out.crb.focal_length = request.focal;
  out.crb.noise_px = request.noise_px;
  out.crb.samples = request.crb_samples;
  out.crb.threads = request.threads;
  if (!request.aim) {
    const Eigen::Vector3d low = sites.entries.rowwise().minCoeff();
    const Eigen::Vector3d high = sites.entries.rowwise().maxCoeff();
    out.crb.aim = 0.5 * (low + high);
  } else {
    out.crb.aim = request.aim;
  }
  return out;
}

std::optional<design::TrackerObjective> tracker_objective(const Request& request) {
  if (request.objective != "tracker") return std::nullopt;
  design::TrackerObjective out;
  out.targets = request.targets;
  out.fle = *request.fle;
  return out;
}

void check_request(const Request& request) {
  if (request.body.empty() == request.sites.empty()) {
    place_refuse("BODY/--sites", "give a body mesh or --sites SITES.json, not both or neither");
  }
  if (!request.sites.empty() && (!request.exclude.empty() || !request.region.empty())) {
    place_refuse(request.region.empty() ? "--exclude" : "--region",
                 "applies to the sites sampled on a body mesh, not to --sites");
  }
  if (!request.sites.empty() && request.candidates_given) {
    place_refuse("--candidates", "samples the body mesh; --sites gives the candidates itself");
  }
  // At least 3: a placement chooses at least min_visible >= 3 markers among the sites.
  if (request.candidates < 3 || request.candidates > kMaxCandidates) {
    place_refuse("--candidates", "must be in [3, " + std::to_string(kMaxCandidates) + "], got " +
                                     std::to_string(request.candidates));
  }
  if (request.markers < 1) {
    place_refuse("--markers", "must be >= 1, got " + std::to_string(request.markers));
  }
  if (!(request.min_separation >= 0.0) || !std::isfinite(request.min_separation)) {
    place_refuse("--min-separation", "must be a finite number >= 0");
  }
  if (!(request.marker_diameter >= 0.0) || !std::isfinite(request.marker_diameter)) {
    place_refuse("--marker-diameter", "must be a finite number >= 0");
  }
  if (request.min_separation > 0.0 && request.min_separation < request.marker_diameter) {
    place_refuse("--min-separation", "below --marker-diameter: two markers would overlap");
  }
  if (!(request.min_distance_difference >= 0.0) ||
      !std::isfinite(request.min_distance_difference)) {
    place_refuse("--min-distance-difference", "must be a finite number >= 0");
  }
  if (request.threads < 0) place_refuse("--threads", "must be >= 0 (0: all cores)");
  if (request.random_trials < 0) place_refuse("--random-trials", "must be >= 0");
  if (request.perturbations < 0) place_refuse("--perturbations", "must be >= 0");
  if (request.exhaustive_limit < 0) place_refuse("--exhaustive-limit", "must be >= 0");
  if (!(request.certificate_tolerance >= 1e-15 && request.certificate_tolerance <= 1e-3)) {
    place_refuse("--certificate-tolerance", "must be in [1e-15, 1e-3]");
  }
  check_objective(request);
  if (request.min_coverage != -1.0 &&
      !(request.min_coverage > 0.0 && request.min_coverage <= 1.0)) {
    place_refuse("--min-coverage", "must be in (0, 1]");
  }
  if (request.out.empty()) return;
  if (!place_valid_utf8(request.out)) place_refuse("--out", "the file name is not valid UTF-8");
  bool json = false;
  try {
    json = io::layout_write_format(request.out) == io::LayoutFormat::kJson;
    if (json) io::check_write_target(request.out, request.overwrite);
  } catch (const InvalidArgument& e) {
    place_refuse("--out", e.what());
  }
  if (!json) {
    place_refuse("--out", request.out +
                              ": write the placed layout as .json (it keeps normals, body, "
                              "workspace and the placement record)");
  }
}

Sites candidate_sites(const Request& request,
                      const std::function<Layout(const std::string&)>& read_sites,
                      const std::function<void(Layout*)>& apply_visibility) {
  Sites out;
  if (!request.sites.empty()) {
    out.layout = place_reading("--sites", request.sites, [&] { return read_sites(request.sites); });
    if (out.layout.mode != LayoutMode::kPoints) {
      place_refuse("--sites",
                   request.sites + ": expected a point layout (\"points\" with \"normals\")");
    }
    if (!out.layout.visibility) {
      place_refuse("--sites", request.sites + ": the sites need \"normals\" (or --normals radial)");
    }
    out.drawn = static_cast<int>(out.layout.entries.cols());
  } else {
    out.layout = place_sampled_sites(request, &out.drawn, &out.excluded);
    apply_visibility(&out.layout);
  }
  if (request.marker_diameter > 0.0) {
    out.layout = design::sphere_centres(std::move(out.layout), request.marker_diameter);
  }
  out.n_candidates = static_cast<int>(out.layout.entries.cols());
  out.keep = place_append_kept(request, &out.layout);
  place_check_problem(request, out.layout, out.keep.size());
  return out;
}

Outcome place(const Request& request, const Sites& sites,
              const std::function<void(const std::string&)>& progress) {
  if (progress) progress("occlusion grid");
  const visibility::VisibilityModel model = place_against(request.source(), [&] {
    return visibility::VisibilityModel::of(
        sites.layout, visibility::VisibilityModel::kDefaultResolutionDeg, request.threads);
  });
  design::PlacementProblem problem;
  problem.sites = model.problem();
  problem.keep = sites.keep;
  problem.markers = request.markers;
  problem.min_separation = request.separation();
  problem.min_distance_difference = request.min_distance_difference;
  design::PlaceOptions options;
  options.robust_dropout = request.robust_dropout;
  options.random_trials = request.random_trials;
  options.perturbations = request.perturbations;
  options.exhaustive_limit = request.exhaustive_limit;
  options.seed = request.seed;
  options.threads = request.threads;
  options.search.certificate_tolerance = request.certificate_tolerance;
  options.progress = progress;
  if (request.min_coverage != -1.0) options.min_coverage = request.min_coverage;
  Outcome out;
  try {
    options.camera = camera_objective(request, sites.layout);
    options.tracker = tracker_objective(request);
    if (options.tracker) check_tracker_range(request, problem.sites.points);
    out.result = design::place_markers(problem, options);
  } catch (const InvalidArgument& e) {
    if (e.field() == "distance") place_refuse("--distance", e.what());
    place_refuse(e.field() == "min_separation" ? "--min-separation" : "--markers", e.what());
  }
  if (progress) progress("final analysis");
  std::optional<camera::PoseCrbOptions> camera;
  if (options.camera) camera = options.camera->crb;
  out.placed =
      placed_layout(request, sites.layout, sites.n_candidates, out.result, camera, options.tracker);
  const bool covered = out.result.status == design::PlacementResult::Status::kComplete;
  if (out.placed.tre) {
    out.objective_value = tre_objective(*out.placed.tre);
    out.complete = covered && std::isfinite(out.objective_value) && tre_certified(*out.placed.tre);
  } else if (out.placed.crb) {
    out.objective_value = crb_statistic(*out.placed.crb, options.camera->statistic);
    out.complete = covered && out.placed.crb->status == camera::PoseCrbMap::Status::kOk;
  } else {
    out.objective_value = out.placed.report.visibility
                              ? out.placed.report.visibility->max_worst_case_error_deg
                              : 90.0;
    out.complete =
        covered && out.placed.report.visibility && out.placed.report.visibility->worst.certified();
  }
  return out;
}

PlacedLayout placed_layout(const Request& request, const Layout& sites, int n_candidates,
                           const design::PlacementResult& result,
                           const std::optional<camera::PoseCrbOptions>& camera,
                           const std::optional<design::TrackerObjective>& tracker) {
  PlacedLayout out;
  for (Eigen::Index i = 0; i < sites.entries.cols(); ++i) {
    out.site_names.push_back(design::site_name(sites, static_cast<int>(i)));
  }
  design::PlacedLayoutRecord record;
  record.sites = request.source();
  record.n_candidates = n_candidates;
  record.robust_dropout = request.robust_dropout;
  record.min_separation = request.separation();
  record.marker_diameter = request.marker_diameter;
  if (camera) record.objective = camera_words(request, *camera);
  if (tracker) record.objective = tracker_words(*tracker);
  out.layout = design::placed_layout(sites, result, record);
  report::LayoutReportOptions options;
  options.visibility.search.certificate_tolerance = request.certificate_tolerance;
  options.visibility.threads = request.threads;
  out.report = report::analyze_layout(out.layout, options);
  if (camera) {
    out.camera = camera;
    out.crb = camera::pose_crb_map(camera::PoseCrbModel(out.layout, *camera));
  }
  if (tracker) {
    tracker::TreOptions tre;
    tre.fle = tracker->fle;
    tre.search = tracker->search;
    tre.threads = request.threads;
    out.tre = tracker::tre_report(out.layout, tracker->targets, tre);
  }
  return out;
}

std::string failure_message(const design::PlacementResult& result, const PlacedLayout& placed) {
  if (result.status == design::PlacementResult::Status::kIncomplete) {
    std::string message = result.message + ": the best covers " +
                          place_percent(result.value.coverage) + " of the workspace";
    if (result.covering_markers) {
      message += "; greedy by coverage covers it with " + std::to_string(*result.covering_markers) +
                 " markers";
    } else {
      message += "; all sites together cover " + place_percent(result.all_sites_coverage);
    }
    return message;
  }
  if (placed.tre) {
    return tre_objective(*placed.tre) == std::numeric_limits<double>::infinity()
               ? "the placed layout tracks a target from no direction of the workspace"
               : "the placed layout's worst TRE is not certified at every target";
  }
  if (placed.crb) {
    return "the placed layout is not trackable by the camera: " +
           camera::untrackable_reason(*placed.crb, placed.camera->distance);
  }
  const visibility::VisibilityReport& v = *placed.report.visibility;
  return "the placed layout's analysis is not certified: " + v.message();
}

Json report(const Request& request, const Sites& sites, const Outcome& outcome, bool written) {
  const design::PlacementResult& r = outcome.result;
  const PlacedLayout& placed = outcome.placed;
  const int n_candidates = sites.n_candidates;
  Json out;
  out["sites"] = request.source();
  out["status"] = design::to_string(r.status);
  Json chosen = Json::array();
  Json kept = Json::array();
  for (int s : r.chosen) {
    if (s < n_candidates) {
      chosen.push_back(s);
    } else {
      kept.push_back(placed.site_names[static_cast<std::size_t>(s)]);
    }
  }
  out["chosen"] = chosen;
  out["kept"] = kept;
  out["n_candidates"] = n_candidates;
  if (request.sites.empty()) {
    out["drawn"] = sites.drawn;
    out["excluded"] = sites.excluded;
  }
  out["markers"] = request.markers;
  out["min_separation"] = request.separation();
  out["marker_diameter"] = request.marker_diameter;
  out["search"] = r.search;
  const Json analysis = Json::parse(report::to_json(placed.report));
  out["visibility"] = analysis.contains("visibility") ? analysis["visibility"] : Json();
  out["coverage"] = placed.report.visibility->coverage.trackable_fraction;
  out["pbar_min"] = placed.report.visibility->worst.pbar_min;
  out["random_baseline"] = {{"trials", r.random_baseline.trials},
                            {"complete", r.random_baseline.complete},
                            {"best_coverage", r.random_baseline.best_coverage},
                            {"best_pbar_min", r.random_baseline.best_pbar_min},
                            {"median_pbar_min", r.random_baseline.median_pbar_min}};
  out["objective"] = place_objective_json(request, outcome);
  out["steps"] = place_steps_json(r);
  if (r.robust) {
    out["robust"] = {
        {"pbar_min", r.robust->pbar_min},
        {"worst_lost_marker", place_candidate_index(r.robust->worst_lost_marker, n_candidates)},
        {"worst_lost_name",
         placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]},
        {"coverage", r.robust->coverage}};
    if (outcome.placed.crb || outcome.placed.tre) {
      out["robust"]["objective"] = report::json_number(r.robust->objective);
    }
  }
  out["swaps"] = r.swaps;
  if (r.search != "exhaustive") {
    out["perturbations"] = request.perturbations;
    out["improving_perturbations"] = r.improving_perturbations;
  }
  out["evaluations"] = r.evaluations;
  if (r.search == "exhaustive") out["subsets"] = r.subsets;
  if (r.status == design::PlacementResult::Status::kIncomplete) {
    out["covering_markers"] = r.covering_markers ? Json(*r.covering_markers) : Json();
    out["all_sites_coverage"] = r.all_sites_coverage;
  }
  out["written"] = written ? Json(request.out) : Json();
  return out;
}

}  // namespace vantage::place_json

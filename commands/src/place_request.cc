// `vantage place`'s checks of a request before any file is read, and the camera and tracker
// objectives it asks for.

#include "vantage/commands/place_json.h"

#include <cmath>
#include <utility>

#include "place_internal.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"

namespace vantage::place_json {

using internal::place_refuse;

namespace {

constexpr int kMaxCandidates = 20000;
// The camera objective's lattice: each evaluation is linear in it.
constexpr int kMaxCrbSamples = 1'000'000;

void check_positive(double value, const char* option) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    place_refuse(option, "must be a finite number > 0 with --objective camera");
  }
}

void check_distances(const Request& request) {
  if (request.distances.empty()) {
    check_positive(request.distance, "--distance");
    return;
  }
  if (request.distance != 0.0) place_refuse("--distances", "goes without --distance");
  if (request.distances.size() > static_cast<std::size_t>(LayoutSensor::kMaxDistances)) {
    place_refuse("--distances", "at most " + std::to_string(LayoutSensor::kMaxDistances) +
                                    " distances, got " + std::to_string(request.distances.size()));
  }
  for (const double d : request.distances) check_positive(d, "--distances");
  if (const long k = vantage::internal::first_repeat(request.distances); k >= 0) {
    place_refuse("--distances", "distance " + std::to_string(k + 1) + " repeats an earlier one");
  }
  // Each evaluation is linear in the (direction, distance) samples, and the search keeps a pose
  // and a visibility bit per site for each.
  if (static_cast<double>(request.crb_samples) * static_cast<double>(request.distances.size()) >
      kMaxCrbSamples) {
    place_refuse("--distances", std::to_string(request.distances.size()) +
                                    " distances of --crb-samples " +
                                    std::to_string(request.crb_samples) + " exceed " +
                                    std::to_string(kMaxCrbSamples) + " samples");
  }
}

void check_camera(const Request& request) {
  check_distances(request);
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
      {!request.distances.empty(), "--distances"},
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

}  // namespace

namespace internal {

[[noreturn]] void place_refuse(const std::string& field, const std::string& message) {
  throw InvalidArgument(field, message);
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

}  // namespace internal

std::optional<design::CameraObjective> camera_objective(const Request& request,
                                                        const Layout& sites) {
  if (request.objective != "camera") return std::nullopt;
  design::CameraObjective out;
  out.sites = sites;
  out.statistic = *design::parse_crb_statistic(request.statistic);
  out.crb.distance = request.distances.empty() ? request.distance : request.distances.front();
  out.distances = request.distances;
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
  // The FLE as the layout's sensor block records it (an RMS as its rms()), so that the search
  // ranks by the value `vantage analyze` reports on the written file.
  out.fle = sensor_json::fle_model(sensor_json::tracker_sensor(out));
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
  if (request.random_trials < 0 || request.random_trials > design::PlaceOptions::kMaxRandomTrials) {
    place_refuse("--random-trials", "must be in [0, " +
                                        std::to_string(design::PlaceOptions::kMaxRandomTrials) +
                                        "] (every trial's subset is kept for the median)");
  }
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
  if (!io::is_valid_utf8(request.out)) place_refuse("--out", "the file name is not valid UTF-8");
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
                              "workspace and the placement record); `vantage layout convert` "
                              "then writes a tracker's .rom or .ini from it");
  }
}

}  // namespace vantage::place_json

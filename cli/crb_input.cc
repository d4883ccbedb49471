#include "crb_input.h"

#include "vantage/commands/point_text.h"

#include <sstream>
#include <utility>

#include "limits.h"

namespace vantage::cli {

void CrbCameraArgs::add_options(CLI::App* sub, bool required) {
  distance_option = sub->add_option("--distance", distance,
                                    "camera distance from the markers' centroid, layout units");
  focal_option = sub->add_option("--focal", focal, "focal length, pixels, > 0");
  noise_option = sub->add_option("--noise-px", noise_px, "pixel noise per coordinate, pixels, > 0");
  if (required) {
    distance_option->required();
    focal_option->required();
    noise_option->required();
  }
  sub->add_option("--principal-point", principal_point, "principal point CX CY, pixels")
      ->expected(2);
  sub->add_option("--aim", aim,
                  "X,Y,Z: the point the camera looks at, object frame (default: the markers' "
                  "centroid)");
  sub->add_option("--sweep-distance", sweep_distance,
                  "D1:D2:N: the worst and median bound at N distances from D1 to D2 (N at most " +
                      std::to_string(kMaxCrbSweepDistances) +
                      ", README \"Limits\"; `crb --allow-large` lifts it)");
  sub->add_option("--samples", samples,
                  "directions of the CRB map, as a density: this many on the whole sphere (a "
                  "workspace gets its share, at least 100)")
      ->capture_default_str();
}

camera::PoseCrbOptions CrbCameraArgs::options() const {
  camera::PoseCrbOptions options;
  options.distance = distance;
  options.focal_length = focal;
  options.noise_px = noise_px;
  if (!principal_point.empty()) options.principal_point = {principal_point[0], principal_point[1]};
  options.samples = samples;
  options.threads = threads;
  if (!aim.empty()) options.aim = commands::parse_point(aim, "--aim");
  return options;
}

std::optional<camera::PoseCrbSweep> CrbCameraArgs::sweep() const {
  if (sweep_distance.empty()) return std::nullopt;
  return parse_sweep(sweep_distance);
}

camera::PoseCrbSweep parse_sweep(const std::string& text) {
  std::istringstream in(text);
  camera::PoseCrbSweep sweep;
  char colon1 = 0, colon2 = 0;
  if (!(in >> sweep.from >> colon1 >> sweep.to >> colon2 >> sweep.count) || colon1 != ':' ||
      colon2 != ':' || !(in >> std::ws).eof()) {
    throw InvalidArgument("--sweep-distance", "expected D1:D2:N, got \"" + text + "\"");
  }
  return sweep;
}

InvalidArgument crb_option_error(const InvalidArgument& e, const std::string& file) {
  static const std::pair<const char*, const char*> kOptions[] = {
      {"distance", "--distance"},
      {"focal_length", "--focal"},
      {"noise_px", "--noise-px"},
      {"principal_point", "--principal-point"},
      {"samples", "--samples"},
      {"threads", "--threads"},
      {"direction", "--direction"},
      {"sweep_distance", "--sweep-distance"},
      {"aim", "--aim"}};
  for (const auto& [field, option] : kOptions) {
    if (e.field() == field) return e.renamed(option, std::nullopt);
  }
  return e.against(file);
}

}  // namespace vantage::cli

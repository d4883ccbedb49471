#include "objective_input.h"

#include <optional>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/commands/point_text.h"

namespace vantage::cli {

CLI::Option* ObjectiveArgs::add_options(CLI::App* sub, place_json::Request* request,
                                        const std::string& frame, const std::string& aim_default) {
  CLI::Option* objective =
      sub->add_option("--objective", request->objective,
                      "affine: the paper's scale-free bound under visibility; camera: the pinhole "
                      "pose CRB; tracker: the RMS TRE at --target (docs/math.md §21)")
          ->capture_default_str();
  sub->add_option("--distance", request->distance,
                  "camera objective: distance of the camera from the aim point, layout units");
  distances_option =
      sub->add_option("--distances", distances_text,
                      "camera objective: D1,D2,... an approach instead of --distance: the largest "
                      "over these distances of the statistic");
  sub->add_option("--focal", request->focal, "camera objective: focal length, pixels");
  sub->add_option("--noise-px", request->noise_px,
                  "camera objective: pixel noise per coordinate, pixels");
  sub->add_option("--statistic", request->statistic,
                  "camera objective: worst, p95 or median of rot_rms over the workspace")
      ->capture_default_str();
  sub->add_option("--crb-samples", request->crb_samples,
                  "camera objective: lattice density, directions on the whole sphere (vantage crb "
                  "--samples)")
      ->capture_default_str();
  sub->add_option(
      "--aim", aim_text,
      "camera objective: X,Y,Z, the point the camera looks at (default: " + aim_default + ")");
  tre.add_options(sub, false);
  tre.target_option->description("tracker objective: target X,Y,Z in " + frame +
                                 " frame (repeatable)");
  tre.fle_rms_option->description("tracker objective: isotropic FLE, RMS of the 3-D error");
  tre.fle_sigma_option->description(
      "tracker objective: anisotropic FLE SP,SD, sd across and along the line of sight");
  return objective;
}

void ObjectiveArgs::parse(place_json::Request* request) const {
  if (!aim_text.empty()) request->aim = commands::parse_point(aim_text, "--aim");
  if (distances_option != nullptr && distances_option->count() > 0) {
    const std::optional<std::vector<double>> distances = commands::parse_numbers(distances_text);
    if (!distances || distances->empty()) {
      throw InvalidArgument("--distances", "expected comma-separated numbers D1,D2,...");
    }
    request->distances = *distances;
  }
  if (!tre.targets.empty()) request->targets = tre.parsed_targets();
  if (tre.fle_rms || !tre.fle_sigma.empty()) request->fle = tre.parsed_fle();
}

}  // namespace vantage::cli

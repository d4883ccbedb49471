#include "tre_input.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "crb_input.h"
#include "vantage/commands/point_text.h"

namespace vantage::cli {

void TreTargetArgs::add_options(CLI::App* sub, bool with_direction) {
  target_option =
      sub->add_option("--target", targets, "target X,Y,Z in the tool frame (repeatable)");
  fle_rms_option =
      sub->add_option("--fle-rms", fle_rms, "isotropic FLE, RMS of the 3-D marker error");
  fle_sigma_option = sub->add_option(
      "--fle-sigma", fle_sigma, "anisotropic FLE SP,SD: sd across and along the line of sight");
  if (!with_direction) return;
  direction_option =
      sub->add_option("--direction", direction,
                      "also the TRE at this line of sight AX,AY,AZ (tool toward tracker)");
}

std::vector<Eigen::Vector3d> TreTargetArgs::parsed_targets() const {
  if (targets.empty()) throw InvalidArgument("--target", "give at least one X,Y,Z");
  std::vector<Eigen::Vector3d> out;
  for (const std::string& text : targets) out.push_back(commands::parse_point(text, "--target"));
  return out;
}

tracker::FleModel TreTargetArgs::parsed_fle() const {
  const bool sigma = !fle_sigma.empty();
  if (fle_rms.has_value() == sigma) {
    throw InvalidArgument("--fle-rms", "give exactly one of --fle-rms F and --fle-sigma SP,SD");
  }
  if (fle_rms) {
    if (!(std::isfinite(*fle_rms) && *fle_rms > 0.0)) {
      throw InvalidArgument("--fle-rms", "must be a finite number > 0");
    }
    return tracker::FleModel::isotropic(*fle_rms);
  }
  std::istringstream in(fle_sigma);
  tracker::FleModel fle;
  char comma = 0;
  if (!(in >> fle.sigma_perp >> comma >> fle.sigma_axial) || comma != ',' ||
      !(in >> std::ws).eof() || !fle.is_valid()) {
    throw InvalidArgument(
        "--fle-sigma",
        "expected SP,SD, two finite numbers >= 0 not both 0, got \"" + fle_sigma + "\"");
  }
  return fle;
}

std::optional<Eigen::Vector3d> TreTargetArgs::parsed_direction() const {
  if (direction.empty()) return std::nullopt;
  return commands::parse_direction(direction, "--direction");
}

InvalidArgument tre_option_error(const InvalidArgument& e, const std::string& file) {
  static const std::pair<const char*, const char*> kOptions[] = {
      {"target", "--target"},
      {"fle.sigma_perp", "--fle-sigma"},
      {"fle.sigma_axial", "--fle-sigma"},
      {"direction", "--direction"},
      {"radius", "--radius"},
      {"monte_carlo_trials", "--monte-carlo"},
      {"threads", "--threads"}};
  for (const auto& [field, option] : kOptions) {
    if (e.field() == field) return e.renamed(option, std::nullopt);
  }
  return e.against(file);
}

}  // namespace vantage::cli

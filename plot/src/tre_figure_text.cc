#include "tre_figure_text.h"

#include <cmath>
#include <cstdio>

#include "style.h"

namespace vantage::plot::internal {

Rgb tre_curve_colour(const std::string& label) {
  if (label == "worst") return kWorstViewpointColour;
  if (label == "best") return kTreBestColour;
  return kTreDirectionColour;
}

std::string tre_number_text(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.3g", x);
  return buffer;
}

std::string tre_fle_text(const tracker::FleModel& fle) {
  // Four digits: NDI's 0.0995 and 0.2985 as given.
  auto digits4 = [](double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.4g", x);
    return std::string(buffer);
  };
  if (fle.from_rms) return "FLE isotropic, RMS " + digits4(fle.rms());
  return "FLE sd " + digits4(fle.sigma_perp) + " across, " + digits4(fle.sigma_axial) +
         " along the line of sight";
}

std::string tre_vector_text(const Eigen::Vector3d& v, int decimals) {
  auto shown = [decimals](double x) {
    std::string text = fixed(x, decimals);
    // Trailing zeros say nothing: "1.000" reads "1", "0.250" reads "0.25".
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? std::string("0") : text;
  };
  return "(" + shown(v.x()) + ", " + shown(v.y()) + ", " + shown(v.z()) + ")";
}

std::string tre_curve_text(const tracker::TreCurve& curve) {
  const std::string what = curve.label == "direction" ? "--direction" : curve.label;
  std::string text = what + " line of sight " + tre_vector_text(curve.direction, 3);
  if (!curve.tracked) return text + ": not tracked";
  return text + ", " + std::to_string(curve.visible_markers.size()) + " markers";
}

void write_tre_direction(CsvWriter& csv, const tracker::TreCurve* curve, int markers) {
  if (curve == nullptr) {
    csv << ""
        << ""
        << "" << static_cast<long>(markers);
    return;
  }
  csv << curve->direction.x() << curve->direction.y() << curve->direction.z()
      << static_cast<long>(curve->visible_markers.size());
}

}  // namespace vantage::plot::internal

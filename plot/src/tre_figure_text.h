#pragma once

// What the TRE figures (tre_figures.h) write the same way: the FLE, a direction, a marker list,
// the series' colours and a CSV row's direction. Private to vantage::plot.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "output_file.h"
#include "vantage/plot/colormap.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/tracker/tre_sweeps.h"

namespace vantage::plot::internal {

/// The curves' colours: the worst red (kWorstViewpointColour), the best blue, --direction green,
/// the isotropic formula grey (dashed).
inline constexpr Rgb kTreBestColour{31, 120, 180};
inline constexpr Rgb kTreDirectionColour{51, 160, 44};
inline constexpr Rgb kTreIsotropicColour{90, 90, 90};

/// The colour of curve label "worst", "best" or "direction".
Rgb tre_curve_colour(const std::string& label);

/// "FLE sd 0.0995 across, 0.2985 along the line of sight" or "FLE isotropic, RMS 0.25"
/// (four significant digits).
std::string tre_fle_text(const tracker::FleModel& fle);

/// "(0.287, 0, 0.958)": a unit direction or a point with `decimals` digits.
std::string tre_vector_text(const Eigen::Vector3d& v, int decimals);

/// A number with 3 significant digits at most ("1.18", "0.422", "150").
std::string tre_number_text(double x);

/// "worst line of sight (0, 0, 1), 4 markers": a curve's legend text.
std::string tre_curve_text(const tracker::TreCurve& curve);

/// The direction's three columns and the visible count of a CSV row; empty direction columns
/// and `markers` for the isotropic formula (curve null).
void write_tre_direction(CsvWriter& csv, const tracker::TreCurve* curve, int markers);

}  // namespace vantage::plot::internal

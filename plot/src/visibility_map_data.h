#pragma once

// What the two whole-sphere figures (visibility_maps.h) share: checking their data, the
// picture's samples, the CSV grid's cells and the error of a direction. Private to vantage::plot.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

#include "vantage/plot/visibility_maps.h"

namespace vantage::plot::internal {

/// Throws InvalidArgument naming `figure` for missing model or report, or grids out of range.
void check_map_data(const VisibilityMapData& data, const char* figure);

/// data.samples when given (checked against samples_per_axis), else sampled into *owned.
const SphereSamples& picture_samples(const VisibilityMapData& data, const FigureOptions& options,
                                     std::unique_ptr<SphereSamples>* owned);

/// Calls cell(disc, a, visibility) for every cell inside either disc of the CSV's grid, disc 0
/// first, row by row from the top.
void for_each_csv_cell(const VisibilityMapData& data,
                       const std::function<void(int, const Eigen::Vector3d&,
                                                const visibility::DirectionVisibility&)>& cell);

/// asin t in degrees (t clamped to [0, 1]).
double visibility_error_deg(double t);

/// The worst viewpoint's line of the legends: "error 25.90° (p̄_min 0.8995), 7 markers seen".
std::string worst_summary(const visibility::VisibilityReport& report);

}  // namespace vantage::plot::internal

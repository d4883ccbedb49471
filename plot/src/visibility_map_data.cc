#include "visibility_map_data.h"

#include <algorithm>
#include <cmath>

#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/viewpoint_map.h"

namespace vantage::plot::internal {

void check_map_data(const VisibilityMapData& data, const char* figure) {
  const std::string where = std::string("write_") + figure;
  if (data.model == nullptr) throw InvalidArgument(where + ": model is null");
  if (data.report == nullptr) throw InvalidArgument(where + ": report is null");
  for (const int n : {data.samples_per_axis, data.csv_samples_per_axis}) {
    if (n < kMinMapSamples || n > kMaxMapSamples) {
      throw InvalidArgument(where + ": samples_per_axis and csv_samples_per_axis must be in [" +
                            std::to_string(kMinMapSamples) + ", " + std::to_string(kMaxMapSamples) +
                            "]");
    }
  }
  if (data.samples != nullptr && data.samples->samples_per_axis != data.samples_per_axis) {
    throw InvalidArgument(where + ": samples were taken on another grid");
  }
}

const SphereSamples& picture_samples(const VisibilityMapData& data, const FigureOptions& options,
                                     std::unique_ptr<SphereSamples>* owned) {
  if (data.samples != nullptr) return *data.samples;
  *owned = std::make_unique<SphereSamples>(
      sample_sphere(*data.model, data.samples_per_axis, options.threads));
  return **owned;
}

void for_each_csv_cell(const VisibilityMapData& data,
                       const std::function<void(int, const Eigen::Vector3d&,
                                                const visibility::DirectionVisibility&)>& cell) {
  const int n = std::min(data.csv_samples_per_axis, data.samples_per_axis);
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, n),
                                 SphereSamples::cell_centre(n - 1 - r, n));
        if (xy.squaredNorm() > 1.0) continue;
        const Eigen::Vector3d a = direction_from_sphere_map(d, xy);
        cell(d, a, data.model->at(a));
      }
    }
  }
}

double visibility_error_deg(double t) {
  return kDegreesPerRadian * std::asin(std::clamp(t, 0.0, 1.0));
}

std::string worst_summary(const visibility::VisibilityReport& report) {
  const std::size_t seen = report.worst.visible_markers.size();
  return "error " + fixed(report.max_worst_case_error_deg, 2) + "° (p̄_min " +
         fixed(report.worst.pbar_min, 4) + "), " + std::to_string(seen) + " marker" +
         (seen == 1 ? "" : "s") + " seen";
}

}  // namespace vantage::plot::internal

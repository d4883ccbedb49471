#pragma once

// The JSON object of `vantage crb --json` (issue 21; README, "vantage crb"), from the one
// PoseCrbReport of camera::pose_crb_report(). Shared by the `vantage` command and the Python module
// (vantage.crb(...).to_dict()), so that both give exactly the same fields.

#include <nlohmann/json.hpp>

#include "vantage/camera/pose_crb.h"
#include "vantage/camera/pose_crb_tags.h"

namespace vantage::crb_json {

using Json = nlohmann::ordered_json;

/// {direction, trackable, unbounded, rot_rms_deg, trans_rms, visible_markers} (+ covariance when
/// `with_covariance`; rot_rms_deg and trans_rms are null when not trackable, unbounded included).
Json at_direction(const camera::PoseCrbAt& at, bool with_covariance);

/// The whole report: camera, markers, visibility, at_direction (when asked), worst, best,
/// trackable_fraction, unbounded_fraction, percentiles {p50, p95, p99}, sliver,
/// worst_region_width_deg, affine_bound_deg, samples, status and sweep_distance (when asked).
Json report(const camera::PoseCrbReport& report);

/// The tag sweep: {faces: [{centre, normal, extent, tags}], rows: [{tags_per_side, tags, fill,
/// tag_size, tag_pixels, status, trackable_fraction, unbounded_fraction, worst, median,
/// percentiles}]}.
Json tag_sweep(const std::vector<camera::TagFace>& faces,
               const std::vector<camera::TagSweepRow>& rows);

}  // namespace vantage::crb_json

#pragma once

// The JSON object of `vantage crb --json` (issue 21; README, "vantage crb"), from the one
// PoseCrbReport of sdp::pose_crb_report(). Shared by the `vantage` command and the Python module
// (vantage.crb(...).to_dict()), so that both give exactly the same fields.

#include <nlohmann/json.hpp>

#include "vantage/sdp/pose_crb.h"
#include "vantage/sdp/pose_crb_tags.h"

namespace vantage::crb_json {

using Json = nlohmann::ordered_json;

/// {direction, rot_rms_deg, trans_rms, visible_markers} (+ covariance when `with_covariance`;
/// rot_rms_deg and trans_rms are null when not trackable).
Json at_direction(const sdp::PoseCrbAt& at, bool with_covariance);

/// The whole report: camera, markers, visibility, at_direction (when asked), worst, best,
/// trackable_fraction, percentiles {p50, p95, p99}, sliver, worst_region_width_deg,
/// affine_bound_deg, samples, status and sweep_distance (when asked).
Json report(const sdp::PoseCrbReport& report);

/// The tag sweep: {faces: [{centre, normal, extent, tags}], rows: [{tags_per_side, tags, fill,
/// tag_size, tag_pixels, status, trackable_fraction, worst, median, percentiles}]}.
Json tag_sweep(const std::vector<sdp::TagFace>& faces, const std::vector<sdp::TagSweepRow>& rows);

}  // namespace vantage::crb_json

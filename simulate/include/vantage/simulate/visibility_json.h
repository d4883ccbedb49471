#pragma once

/// JSON of the bound check under visibility (visibility_check.h): the "visibility" object of
/// `vantage simulate --json` and the per-trial values shard files carry for `--merge`, in the
/// style of report_json.h (non-finite numbers as null).

#include <string>
#include <vector>

#include "vantage/simulate/report_json.h"
#include "vantage/simulate/visibility_check.h"

namespace vantage::simulate {

/// {"model", "min_visible", "workspace" (null or {"axis", "half_angle_deg"}),
/// "occlusion_resolution_deg" (null without a body), "trackable_fraction", "coverage_samples",
/// "worst_viewpoint", "worst_visible_markers", "t_upper", "t_lower", "pbar_min", "bound_deg",
/// "trials", "draws", "visible_markers" (a summary), "max_view_t", "bound_checked", and with the
/// affine camera "max_error_deg", "max_ratio", "max_view_ratio", "max_view_excess_over_tolerance",
/// "max_abs_eq26_mismatch_deg", "max_eq26_mismatch_over_tolerance", "passed", "message"}.
Json to_json(const VisibilityCheck& check);

/// The setup fields of to_json() read back (for --merge); throws InvalidArgument naming `source`
/// and the field ("visibility.t_upper") on a bad shape.
VisibilitySetup visibility_setup_from_json(const Json& visibility, const std::string& source);

/// Per-trial values: {"direction": [[ax, ay, az], ...], "visible": [[i, ...], ...], "draws",
/// "t", "pbar", "max_error_rad", "max_mismatch_rad", "max_mismatch_ratio", "view_excess_ratio"}.
Json visibility_trials_json(const std::vector<VisibilityTrial>& trials);

/// The inverse of visibility_trials_json(); throws InvalidArgument naming `source` on a bad
/// shape.
std::vector<VisibilityTrial> visibility_trials_from_json(const Json& json,
                                                         const std::string& source);

}  // namespace vantage::simulate

#pragma once

// The JSON object of `vantage tre --json` (issue 20; README, "vantage tre"), from the one
// TreReport of tracker::tre_report(). The names are fixed by the issue: targets [{target,
// rms_isotropic, at_direction, worst, best, monte_carlo}], fle, model.

#include <nlohmann/json.hpp>
#include <string>

#include "vantage/tracker/tre_report.h"

namespace vantage::tre_json {

using Json = nlohmann::ordered_json;

/// {direction, rms, visible_markers, certified, status, rms_bound, patches}.
Json extreme(const tracker::TreExtreme& extreme);

/// The whole report.
Json report(const tracker::TreReport& report);

/// Why the report is a failure, when a target is tracked from no direction (the command's exit
/// status 1, Python's NumericalError "untracked"); empty otherwise.
std::string untracked_reason(const tracker::TreReport& report);

}  // namespace vantage::tre_json

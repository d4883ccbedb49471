#pragma once

/// JSON of the simulation results, in one place: the `vantage simulate --json` fields and the
/// per-trial values that shard files carry so that `--merge` recomputes medians and percentiles
/// exactly. Non-finite numbers are written as null and read back as NaN.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vantage/simulate/bound_check.h"
#include "vantage/simulate/monte_carlo.h"
#include "vantage/simulate/statistics.h"

namespace vantage::simulate {

using Json = nlohmann::ordered_json;

/// {"median", "mean", "p95", "max", "count"}.
Json to_json(const Summary& summary);

/// {name: {"trials", "rot_err_deg", "trans_err", "trans_err_rel", "trans_err_deg", "scale_err",
/// "time_us", "failures", "by_status", "wrong_but_ok"}} in registry order.
Json estimators_json(const std::vector<EstimatorSummary>& summaries);

/// {"trials", "vectors", "max_abs_eq26_mismatch_deg", "max_error_deg", "bound_deg", "pbar_min",
/// "max_ratio", "max_eq26_mismatch_over_tolerance", "passed", "message" (empty when passed),
/// "affine_relation": [{"estimator", "free_vectors", "own_bound_deg",
/// "own_pbar_min", "rot_err_deg", "exceeds_bound", "exceeds_own_bound"}]}.
Json to_json(const BoundCheck& check);

/// Per-trial values: {"trial": [...], "estimators": {name: {"rot_err_deg": [...],
/// "trans_err", "trans_err_rel", "trans_err_deg", "scale_err", "time_us", "status", "ok"}}}.
Json per_trial_json(const MonteCarloRun& run);

/// The inverse of per_trial_json(); total_trials and seed come from the caller. Throws
/// InvalidArgument naming `source` and the field when the JSON does not have that shape.
MonteCarloRun run_from_json(const Json& per_trial, long total_trials, std::uint64_t seed,
                            const std::string& source);

/// Per-trial bound-check values: {"pbar": [...], "max_error_rad", "max_mismatch_rad",
/// "max_mismatch_ratio", "affine_rot_err_rad", "spanning_rot_err_rad"}.
Json bound_trials_json(const std::vector<BoundTrial>& trials);

/// The inverse of bound_trials_json(); throws InvalidArgument naming `source` on a bad shape.
std::vector<BoundTrial> bound_trials_from_json(const Json& json, const std::string& source);

/// A number, or null when it is not finite.
Json json_number(double x);

}  // namespace vantage::simulate

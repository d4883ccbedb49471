#include "vantage/simulate/report_json.h"

#include <cmath>
#include <limits>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

using ErrorField = double TrialError::*;
const std::vector<std::pair<const char*, ErrorField>>& error_fields() {
  static const std::vector<std::pair<const char*, ErrorField>> fields = {
      {"rot_err_deg", &TrialError::rot_err_deg},     {"trans_err", &TrialError::trans_err},
      {"trans_err_rel", &TrialError::trans_err_rel}, {"trans_err_deg", &TrialError::trans_err_deg},
      {"scale_err", &TrialError::scale_err},         {"time_us", &TrialError::time_us},
  };
  return fields;
}

using BoundField = double BoundTrial::*;
const std::vector<std::pair<const char*, BoundField>>& bound_fields() {
  static const std::vector<std::pair<const char*, BoundField>> fields = {
      {"pbar", &BoundTrial::pbar},
      {"max_error_rad", &BoundTrial::max_error_rad},
      {"max_mismatch_rad", &BoundTrial::max_mismatch_rad},
      {"max_mismatch_ratio", &BoundTrial::max_mismatch_ratio},
      {"affine_rot_err_rad", &BoundTrial::affine_rot_err_rad},
      {"spanning_rot_err_rad", &BoundTrial::spanning_rot_err_rad},
  };
  return fields;
}

[[noreturn]] void bad(const std::string& source, const std::string& field,
                      const std::string& what) {
  throw InvalidArgument(source + ": " + field + ": " + what);
}

const Json& member(const Json& object, const char* name, const std::string& source,
                   const std::string& path) {
  if (!object.is_object() || !object.contains(name)) bad(source, path + name, "missing");
  return object.at(name);
}

/// A list of numbers or nulls (NaN) of the given length.
std::vector<double> number_list(const Json& list, std::size_t size, const std::string& source,
                                const std::string& field) {
  if (!list.is_array() || list.size() != size) {
    bad(source, field, "must be a list of " + std::to_string(size) + " numbers");
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < size; ++i) {
    if (list[i].is_null()) {
      values.push_back(kNaN);
    } else if (list[i].is_number()) {
      values.push_back(list[i].get<double>());
    } else {
      bad(source, field + "[" + std::to_string(i) + "]", "not a number");
    }
  }
  return values;
}

}  // namespace

Json json_number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json to_json(const Summary& s) {
  return {{"median", json_number(s.median)},
          {"mean", json_number(s.mean)},
          {"p95", json_number(s.p95)},
          {"max", json_number(s.max)},
          {"count", s.count}};
}

Json estimators_json(const std::vector<EstimatorSummary>& summaries) {
  Json out = Json::object();
  for (const EstimatorSummary& s : summaries) {
    Json by_status = Json::object();
    for (const auto& [status, count] : s.by_status) by_status[status] = count;
    out[s.name] = {{"trials", s.trials},
                   {"rot_err_deg", to_json(s.rot_err_deg)},
                   {"trans_err", to_json(s.trans_err)},
                   {"trans_err_rel", to_json(s.trans_err_rel)},
                   {"trans_err_deg", to_json(s.trans_err_deg)},
                   {"scale_err", to_json(s.scale_err)},
                   {"time_us", to_json(s.time_us)},
                   {"failures", s.failures},
                   {"by_status", by_status},
                   {"wrong_but_ok", s.wrong_but_ok}};
  }
  return out;
}

Json to_json(const BoundCheck& check) {
  Json relations = Json::array();
  for (const PoseRelation& r : check.relations) {
    relations.push_back({{"estimator", r.estimator},
                         {"free_vectors", r.free_vectors},
                         {"own_bound_deg", json_number(r.own_bound_deg)},
                         {"own_pbar_min", json_number(r.own_pbar_min)},
                         {"rot_err_deg", to_json(r.rot_err_deg)},
                         {"exceeds_bound", r.exceeds_bound},
                         {"exceeds_own_bound", r.exceeds_own_bound}});
  }
  return {{"trials", check.trials},
          {"vectors", check.vectors},
          {"max_abs_eq26_mismatch_deg", json_number(check.max_abs_eq26_mismatch_deg)},
          {"max_error_deg", json_number(check.max_error_deg)},
          {"bound_deg", json_number(check.bound_deg)},
          {"pbar_min", json_number(check.pbar_min)},
          {"max_ratio", json_number(check.max_ratio)},
          {"max_eq26_mismatch_over_tolerance", json_number(check.max_eq26_mismatch_over_tolerance)},
          {"passed", check.passed},
          {"message", check.message},
          {"affine_relation", relations}};
}

Json per_trial_json(const MonteCarloRun& run) {
  VANTAGE_CHECK(static_cast<long>(run.trial_index.size()) == run.trials,
                "per-trial values were not kept (MonteCarloOptions::keep_trials)");
  Json estimators = Json::object();
  for (std::size_t e = 0; e < run.names.size(); ++e) {
    Json columns = Json::object();
    for (const auto& [name, field] : error_fields()) {
      Json list = Json::array();
      for (const TrialError& error : run.errors[e]) list.push_back(json_number(error.*field));
      columns[name] = list;
    }
    Json status = Json::array();
    Json ok = Json::array();
    for (const TrialError& error : run.errors[e]) {
      status.push_back(error.status);
      ok.push_back(error.ok);
    }
    columns["status"] = status;
    columns["ok"] = ok;
    estimators[run.names[e]] = columns;
  }
  return {{"trial", run.trial_index}, {"estimators", estimators}};
}

MonteCarloRun run_from_json(const Json& per_trial, long total_trials, std::uint64_t seed,
                            const std::string& source) {
  MonteCarloRun run;
  run.total_trials = total_trials;
  run.seed = seed;
  const Json& trial = member(per_trial, "trial", source, "per_trial.");
  if (!trial.is_array()) bad(source, "per_trial.trial", "must be a list of trial indices");
  for (const Json& t : trial) {
    if (!t.is_number_integer() || t.get<long>() < 0 || t.get<long>() >= total_trials) {
      bad(source, "per_trial.trial", "indices must be integers in [0, total_trials)");
    }
    run.trial_index.push_back(t.get<long>());
  }
  const std::size_t n = run.trial_index.size();
  const Json& estimators = member(per_trial, "estimators", source, "per_trial.");
  if (!estimators.is_object()) bad(source, "per_trial.estimators", "must be an object");
  for (const auto& [name, columns] : estimators.items()) {
    const std::string path = "per_trial.estimators." + name + ".";
    std::vector<TrialError> errors(n);
    for (const auto& [field_name, field] : error_fields()) {
      const std::vector<double> values =
          number_list(member(columns, field_name, source, path), n, source, path + field_name);
      for (std::size_t k = 0; k < n; ++k) errors[k].*field = values[k];
    }
    const Json& status = member(columns, "status", source, path);
    const Json& ok = member(columns, "ok", source, path);
    if (!status.is_array() || status.size() != n || !ok.is_array() || ok.size() != n) {
      bad(source, path + "status", "status and ok must be lists of one entry per trial");
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!status[k].is_string() || !ok[k].is_boolean()) {
        bad(source, path + "status[" + std::to_string(k) + "]", "must be a string (ok: a bool)");
      }
      errors[k].status = status[k].get<std::string>();
      errors[k].ok = ok[k].get<bool>();
    }
    run.names.push_back(name);
    run.errors.push_back(std::move(errors));
  }
  run.trials = static_cast<long>(n);
  for (const std::string& name : run.names) run.accumulators.emplace_back(name);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t e = 0; e < run.names.size(); ++e) run.accumulators[e].add(run.errors[e][k]);
  }
  return run;
}

Json bound_trials_json(const std::vector<BoundTrial>& trials) {
  Json out = Json::object();
  for (const auto& [name, field] : bound_fields()) {
    Json list = Json::array();
    for (const BoundTrial& t : trials) list.push_back(json_number(t.*field));
    out[name] = list;
  }
  return out;
}

std::vector<BoundTrial> bound_trials_from_json(const Json& json, const std::string& source) {
  const Json& pbar = member(json, "pbar", source, "per_trial.bound_check.");
  if (!pbar.is_array()) bad(source, "per_trial.bound_check.pbar", "must be a list");
  std::vector<BoundTrial> trials(pbar.size());
  for (const auto& [name, field] : bound_fields()) {
    const std::string path = std::string("per_trial.bound_check.") + name;
    const std::vector<double> values = number_list(
        member(json, name, source, "per_trial.bound_check."), trials.size(), source, path);
    for (std::size_t k = 0; k < trials.size(); ++k) trials[k].*field = values[k];
  }
  return trials;
}

}  // namespace vantage::simulate

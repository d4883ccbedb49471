#include "vantage/simulate/layout_simulation.h"

#include <algorithm>

#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::simulate {
namespace {

Json list(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v(i));
  return out;
}

Json layout_json(const Layout& layout) {
  Json entries = Json::array();
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
    entries.push_back(list(layout.entries.col(i)));
  }
  return {{"name", layout.name}, {"mode", to_string(layout.mode)}, {"entries", entries}};
}

Json config_json(const Layout& layout, const LayoutSimulationOptions& options) {
  const LayoutSceneOptions& scene = options.scene;
  Json viewpoint = options.worst_viewpoint ? Json("worst") : Json("random");
  if (scene.viewpoint && !options.worst_viewpoint) viewpoint = list(*scene.viewpoint);
  return {{"layout", layout_json(layout)},
          {"camera", to_string(scene.camera)},
          {"focal_px", scene.focal_px},
          {"range", scene.range},
          {"principal_point", list(scene.principal_point)},
          {"offset", list(scene.lateral_offset)},
          {"noise", to_string(scene.noise)},
          {"noise_px", scene.snr_db ? Json(nullptr) : Json(scene.noise_px)},
          {"snr_db", scene.snr_db ? Json(*scene.snr_db) : Json(nullptr)},
          {"viewpoint", viewpoint},
          {"methods", options.methods},
          {"seed", options.monte_carlo.seed},
          {"trials", options.monte_carlo.trials}};
}

}  // namespace

bool LayoutSimulationOptions::is_valid(std::string* why) const {
  std::string reason;
  if (!scene.is_valid(&reason)) {
    if (why) *why = "scene." + reason;
    return false;
  }
  if (!monte_carlo.is_valid(&reason)) {
    if (why) *why = "monte_carlo." + reason;
    return false;
  }
  if (worst_viewpoint && scene.viewpoint) {
    if (why) *why = "worst_viewpoint: scene.viewpoint is set too; give one of them";
    return false;
  }
  return true;
}

LayoutSimulation simulate_layout(const Layout& layout, const LayoutSimulationOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  const bool vectors = layout.mode == LayoutMode::kVectors;
  if (vectors && options.scene.camera == CameraModel::kPinhole) {
    throw InvalidArgument("scene.camera: pinhole needs a point layout; this one holds directions");
  }
  LayoutSceneOptions scene = options.scene;
  if (options.worst_viewpoint) {
    scene.viewpoint = sdp::global_worst_viewpoint(data_vectors(layout).vectors).viewpoint;
  }
  const MonteCarloOptions& mc = options.monte_carlo;
  const SceneGenerator generator = [&](long, TrialRandom& random) {
    return make_layout_scene(layout.entries, vectors, scene, random);
  };
  TrialRandom probe_random = TrialRandom::for_trial(mc.seed, 0);
  const std::vector<Estimator> estimators =
      select_estimators(options.methods, generator(0, probe_random), options.methods_argument);
  LayoutSimulation out;
  out.config = config_json(layout, options);
  out.shard = std::to_string(mc.shard.index) + "/" + std::to_string(mc.shard.count);
  out.run = run_monte_carlo(generator, estimators, mc);
  if (scene.camera == CameraModel::kAffine) {
    // The same trials again, streamed: one block of results at a time unless they are kept.
    const BoundLayout bound_layout = prepare_bound_layout(layout.entries, vectors);
    BoundCheckAccumulator check(bound_layout);
    const std::pair<long, long> range = shard_range(mc.trials, mc.shard);
    const long first = range.first;  // captured below: not a structured binding
    const long last = range.second;
    parallel_for_in_order<BoundTrial>(
        last - first, mc.threads, mc.progress,
        [&](long k) {
          TrialRandom random = TrialRandom::for_trial(mc.seed, first + k);
          return check_bound_trial(bound_layout, generator(0, random));
        },
        [&](long k, const BoundTrial& trial) {
          check.add(first + k, trial);
          if (mc.keep_trials) out.bound_trials.push_back(trial);
        });
    out.has_bound = true;
    out.bound = check.result();
  }
  return out;
}

Json report_json(const LayoutSimulation& simulation, bool per_trial) {
  Json out;
  out["layout"] = simulation.config["layout"]["name"];
  out["mode"] = simulation.config["layout"]["mode"];
  out["trials"] = simulation.run.trials;
  out["total_trials"] = simulation.run.total_trials;
  out["seed"] = simulation.run.seed;
  out["shard"] = simulation.shard;
  out["estimators"] = estimators_json(summarize(simulation.run));
  if (simulation.has_bound) out["bound_check"] = to_json(simulation.bound);
  out["config"] = simulation.config;
  if (per_trial) {
    Json trials = per_trial_json(simulation.run);
    if (simulation.has_bound) trials["bound_check"] = bound_trials_json(simulation.bound_trials);
    out["per_trial"] = trials;
  }
  return out;
}

}  // namespace vantage::simulate

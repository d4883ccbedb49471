#include "vantage/simulate/layout_simulation.h"

#include <algorithm>

#include <memory>

#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/simulate/visibility_json.h"
#include "vantage/simulate/visible_views.h"

namespace vantage::simulate {
namespace {

Json list(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v(i));
  return out;
}

Json columns_json(const Eigen::Matrix3Xd& m) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < m.cols(); ++i) out.push_back(list(m.col(i)));
  return out;
}

/// The layout as the run depends on it; with visibility also its body (so that shards of runs
/// on different bodies do not merge).
Json layout_json(const Layout& layout) {
  Json out = {{"name", layout.name},
              {"mode", to_string(layout.mode)},
              {"entries", columns_json(layout.entries)}};
  if (layout.visibility) {
    const MarkerVisibility& v = *layout.visibility;
    out["normals"] = columns_json(v.normals);
    out["visibility"] = {{"cone_half_angle_deg", list(v.cone_half_angle_deg)},
                         {"min_visible", v.min_visible},
                         {"body", v.body_path.empty() ? Json(nullptr) : Json(v.body_path)}};
  }
  if (layout.workspace) {
    out["workspace"] = {{"axis", list(layout.workspace->axis)},
                        {"half_angle_deg", layout.workspace->half_angle_deg}};
  }
  return out;
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
          {"aim", list(scene.aim)},
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

namespace {

/// One trial's checks: seen whole and, with visibility, on the visible markers.
struct TrialChecks {
  BoundTrial bound;
  VisibilityTrial visibility;
};

/// The trials of the shard again, streamed, for the checks (one block of results at a time
/// unless they are kept): the bound check on the affine camera and, with `views`, the check
/// under visibility (on the pinhole camera its views only).
void run_checks(const Layout& layout, const LayoutSceneOptions& scene, const MonteCarloOptions& mc,
                const VisibleViews* views, LayoutSimulation& out) {
  const bool vectors = layout.mode == LayoutMode::kVectors;
  const bool affine = scene.camera == CameraModel::kAffine;
  if (!affine && views == nullptr) return;
  std::unique_ptr<BoundLayout> bound_layout;
  std::unique_ptr<BoundCheckAccumulator> bound;
  if (affine) {
    bound_layout = std::make_unique<BoundLayout>(prepare_bound_layout(layout.entries, vectors));
    bound = std::make_unique<BoundCheckAccumulator>(*bound_layout);
  }
  std::unique_ptr<VisibilityCheckAccumulator> visibility;
  if (views) visibility = std::make_unique<VisibilityCheckAccumulator>(views->setup(), affine);
  const std::pair<long, long> range = shard_range(mc.trials, mc.shard);
  const long first = range.first;  // captured below: not a structured binding
  const long last = range.second;
  parallel_for_in_order<TrialChecks>(
      last - first, mc.threads, mc.progress,
      [&](long k) {
        TrialRandom random = TrialRandom::for_trial(mc.seed, first + k);
        TrialChecks checks;
        if (views == nullptr) {
          checks.bound = check_bound_trial(
              *bound_layout, make_layout_scene(layout.entries, vectors, scene, random));
          return checks;
        }
        const VisibleScenes scenes = views->scenes(layout.entries, scene, random);
        if (affine) {
          checks.bound = check_bound_trial(*bound_layout, scenes.whole);
          checks.visibility = check_visibility_trial(scenes.view, scenes.visible);
        } else {
          checks.visibility.direction = scenes.view.direction;
          checks.visibility.visible = scenes.view.visibility.visible;
          checks.visibility.draws = scenes.view.draws;
          checks.visibility.t = scenes.view.visibility.t;
        }
        return checks;
      },
      [&](long k, const TrialChecks& checks) {
        if (bound) bound->add(first + k, checks.bound);
        if (visibility) visibility->add(first + k, checks.visibility);
        if (mc.keep_trials && bound) out.bound_trials.push_back(checks.bound);
        if (mc.keep_trials && visibility) out.visibility_trials.push_back(checks.visibility);
      });
  if (bound) {
    out.has_bound = true;
    out.bound = bound->result();
  }
  if (visibility) {
    out.has_visibility = true;
    out.visibility = visibility->result();
  }
}

}  // namespace

LayoutSimulation simulate_layout(const Layout& layout, const LayoutSimulationOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  const bool vectors = layout.mode == LayoutMode::kVectors;
  if (vectors && options.scene.camera == CameraModel::kPinhole) {
    throw InvalidArgument("scene.camera: pinhole needs a point layout; this one holds directions");
  }
  LayoutSceneOptions scene = options.scene;
  const bool pinhole = scene.camera == CameraModel::kPinhole;
  std::unique_ptr<VisibleViews> views;
  if (layout.visibility && !vectors) {
    views = std::make_unique<VisibleViews>(layout);
    if (options.worst_viewpoint) {
      views->look_from(views->setup().worst_viewpoint, "worst_viewpoint", !pinhole);
    } else if (scene.viewpoint) {
      views->look_from(-*scene.viewpoint, "scene.viewpoint", !pinhole);
    }
  } else if (options.worst_viewpoint) {
    scene.viewpoint = sdp::global_worst_viewpoint(data_vectors(layout).vectors).viewpoint;
  }
  const MonteCarloOptions& mc = options.monte_carlo;
  const SceneGenerator generator = [&](long, TrialRandom& random) {
    if (views) return views->scenes(layout.entries, scene, random).visible;
    return make_layout_scene(layout.entries, vectors, scene, random);
  };
  // On a body the estimators are chosen on the whole layout's image: every visible set of at
  // least min_visible (>= 3) markers then fits them too (their limits are n >= 3 and n <= max).
  TrialRandom probe_random = TrialRandom::for_trial(mc.seed, 0);
  if (views && pinhole && (scene.viewpoint || options.worst_viewpoint)) {
    // A fixed pinhole view its centre cannot track is bad input, said before any trial runs.
    TrialRandom fixed_probe = probe_random;
    views->scenes(layout.entries, scene, fixed_probe);
  }
  const Scene probe = views ? make_layout_scene(layout.entries, vectors, scene, probe_random)
                            : generator(0, probe_random);
  const std::vector<Estimator> estimators =
      select_estimators(options.methods, probe, options.methods_argument);
  LayoutSimulation out;
  out.config = config_json(layout, options);
  out.shard = std::to_string(mc.shard.index) + "/" + std::to_string(mc.shard.count);
  out.run = run_monte_carlo(generator, estimators, mc);
  run_checks(layout, scene, mc, views.get(), out);
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
  if (simulation.has_visibility) out["visibility"] = to_json(simulation.visibility);
  out["config"] = simulation.config;
  if (per_trial) {
    Json trials = per_trial_json(simulation.run);
    if (simulation.has_bound) trials["bound_check"] = bound_trials_json(simulation.bound_trials);
    if (simulation.has_visibility) {
      trials["visibility"] = visibility_trials_json(simulation.visibility_trials);
    }
    out["per_trial"] = trials;
  }
  return out;
}

}  // namespace vantage::simulate

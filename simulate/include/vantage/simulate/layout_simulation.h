#pragma once

/// Monte Carlo of one layout, as `vantage simulate LAYOUT` and vantage.simulate run it: every
/// applicable estimator on seeded random views of the layout and, on the affine camera, the
/// bound check of Eq. (26) / Eq. (30) on every trial. report_json() is the object that
/// `vantage simulate --json` prints.
///
/// A point layout with normals (Layout::visibility) is simulated on its body (docs/math.md §20,
/// visible_views.h): the views are drawn from the trackable directions of the workspace and the
/// image holds the markers visible from the view only. The bound check ("bound_check") keeps its
/// meaning, the layout seen whole at the same views; the check under visibility
/// (visibility_check.h) is reported beside it ("visibility"). --viewpoint worst then looks from
/// the certified worst viewpoint under visibility, and a fixed scene.viewpoint must be trackable.

#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/simulate/bound_check.h"
#include "vantage/simulate/monte_carlo.h"
#include "vantage/simulate/report_json.h"
#include "vantage/simulate/scene.h"
#include "vantage/simulate/visibility_check.h"

namespace vantage::simulate {

struct LayoutSimulationOptions {
  LayoutSceneOptions scene;
  /// Look along the layout's certified global worst viewpoint (Theorem 6 over all sign cells),
  /// with a random roll, instead of from uniformly random directions. scene.viewpoint must then
  /// be unset.
  bool worst_viewpoint = false;
  MonteCarloOptions monte_carlo;
  std::vector<std::string> methods;          ///< estimator names; empty = every applicable one
  std::string methods_argument = "methods";  ///< how error messages name `methods`

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// A run (or the merge of sharded runs): what it is a function of, the per-trial errors and the
/// bound check.
struct LayoutSimulation {
  /// The layout and the options (shards of one run merge only when their configs agree).
  Json config;
  MonteCarloRun run;
  bool has_bound = false;  ///< affine camera: the bound check ran
  BoundCheck bound;
  /// One per trial of `run`, in its order, when its per-trial values are kept
  /// (MonteCarloOptions::keep_trials); empty otherwise.
  std::vector<BoundTrial> bound_trials;
  bool has_visibility = false;  ///< the layout has normals: simulated on its body
  VisibilityCheck visibility;
  /// One per trial of `run` (with visibility), when its per-trial values are kept.
  std::vector<VisibilityTrial> visibility_trials;
  std::string shard = "1/1";  ///< "K/N", or "merged"
};

/// Runs the estimators on options.monte_carlo.trials seeded views of `layout` (a point or a
/// vector layout; the pinhole camera needs points). Throws InvalidArgument naming the option
/// when the options are invalid or do not fit the layout.
LayoutSimulation simulate_layout(const Layout& layout, const LayoutSimulationOptions& options);

/// {"layout", "mode", "trials", "total_trials", "seed", "shard", "estimators", "bound_check"
/// (affine camera), "visibility" (a layout with normals; visibility_json.h), "config", and
/// "per_trial" when `per_trial`: what --merge needs; the run must then have kept its trials}.
Json report_json(const LayoutSimulation& simulation, bool per_trial);

}  // namespace vantage::simulate

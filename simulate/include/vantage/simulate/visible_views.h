#pragma once

/// Views of a layout on its body (docs/math.md §20), as `vantage simulate` draws them: a viewing
/// direction a (object frame, body -> camera, so the optical axis is -a: the third row of R is
/// -a) uniform over the trackable directions of the workspace, a uniform roll about it, and an
/// image of the markers visible from a only.
///
/// Drawing. Directions are drawn uniformly on the workspace (the whole sphere, or the cap
/// {a : a.axis >= cos phi} by its area) and rejected until VisibilityModel::at(a) is trackable;
/// a uniform direction with a uniform roll is a uniform rotation, so the accepted views are
/// uniform rotations conditioned on a trackable direction. The work is bounded: before the run,
/// the trackable fraction f of the workspace is estimated on a Fibonacci lattice
/// (visibility_coverage) and a layout with f below kMinTrackableFraction is refused (about 1 / f
/// draws a view); a trial that still draws kMaxDraws untrackable directions in a row stops the
/// run (with f >= 1e-3 that happens with probability below e^-100 per trial).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/simulate/random.h"
#include "vantage/simulate/scene.h"
#include "vantage/visibility/camera_visibility.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::simulate {

/// What the layout's visibility promises, computed once per run: the simulation's reference.
struct VisibilitySetup {
  bool with_body = false;  ///< "cone+mesh" (occlusion by the body) or "cone"
  int min_visible = 3;
  std::optional<LayoutWorkspace> workspace;
  std::optional<double> occlusion_resolution_deg;  ///< with a body
  double trackable_fraction = 0.0;                 ///< of the workspace (Fibonacci estimate)
  int coverage_samples = 0;                        ///< lattice directions in the workspace
  /// The certified worst viewpoint under visibility (visibility::visibility_worst_viewpoint).
  Eigen::Vector3d worst_viewpoint = Eigen::Vector3d::UnitZ();
  std::vector<int> worst_visible;  ///< markers visible from worst_viewpoint
  double t_lower = 0.0;
  double t_upper = 1.0;
  double pbar_min = 1.0;   ///< sqrt(1 - t_lower^2)
  double bound_rad = 0.0;  ///< asin(t_upper): no trackable view has a larger per-vector error

  /// "cone+mesh" or "cone".
  const char* model() const { return with_body ? "cone+mesh" : "cone"; }
};

/// One drawn view.
struct VisibleView {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< a: unit, body -> camera
  visibility::DirectionVisibility visibility;            ///< what a sees (trackable)
  long draws = 0;  ///< directions drawn for this view (0: a fixed direction)
};

/// One trial's images at one view: the visible markers' (what the estimators see) and, with
/// the same rotation, the whole layout's (the seen-whole bound check).
struct VisibleScenes {
  VisibleView view;
  Scene visible;  ///< model and image: the visible markers, in increasing marker order
  Scene whole;    ///< model and image: every marker (noise-free use only)
};

/// The views of one point layout with visibility.
class VisibleViews {
 public:
  /// Untrackable directions drawn in a row before a trial gives up.
  static constexpr long kMaxDraws = 100'000;
  /// Least trackable fraction of the workspace simulate draws views from.
  static constexpr double kMinTrackableFraction = 1e-3;
  /// Fibonacci directions of the trackable-fraction estimate (visibility_coverage).
  static constexpr int kCoverageSamples = 20'000;

  /// For a point layout with visibility (Layout::visibility): casts the occlusion grid (with a
  /// body), certifies the worst viewpoint and estimates the trackable fraction. Throws
  /// InvalidArgument naming "visibility" when no direction of the workspace is trackable or too
  /// few are (kMinTrackableFraction), std::runtime_error when the worst viewpoint cannot be
  /// certified.
  explicit VisibleViews(const Layout& layout);

  /// Every view from now on looks from direction a (unit, body -> camera). Throws
  /// InvalidArgument naming `field` when a is not trackable.
  /// With `by_direction` false (the pinhole camera, whose centre decides what it sees), a is
  /// taken as it is and scenes() checks its centre.
  void look_from(const Eigen::Vector3d& a, const std::string& field, bool by_direction = true);

  const visibility::VisibilityModel& model() const { return model_; }
  const VisibilitySetup& setup() const { return setup_; }

  /// A trackable view (the file comment), drawn from `random`. Throws std::runtime_error after
  /// kMaxDraws untrackable directions.
  VisibleView draw(TrialRandom& random) const;

  /// A view, then the roll and the noise: make_layout_scene of the visible markers, placed and
  /// scaled as the whole layout is (the same depth and offset, options.range and
  /// options.lateral_offset in sizes of the whole layout), looking along -a. `points` are the
  /// layout's markers. The roll is the same in both scenes; the whole scene's noise is its own.
  /// For the affine camera (at infinity) the visible markers are those of direction a. For the
  /// pinhole camera they are those of its centre c = -R^T p, each marker by its own line of
  /// sight (visibility::CameraVisibility, docs/math.md §22): its direction is drawn uniformly on
  /// the workspace and drawn again (up to kMaxDraws times) while the centre sees fewer than max(3,
  /// min_visible) markers or only collinear ones; a fixed view whose centre does so throws
  /// InvalidArgument naming "scene.viewpoint".
  VisibleScenes scenes(const Eigen::Matrix3Xd& points, const LayoutSceneOptions& options,
                       TrialRandom& random) const;

 private:
  Eigen::Vector3d uniform_direction(TrialRandom& random) const;
  bool trackable_set(const Eigen::Matrix3Xd& points, const std::vector<int>& visible) const;

  visibility::VisibilityModel model_;
  visibility::CameraVisibility camera_;
  VisibilitySetup setup_;
  std::optional<Eigen::Vector3d> fixed_;
};

}  // namespace vantage::simulate

#pragma once

/// The state of one vantage-viewer window, without the window: the layout document, the camera,
/// the selection, the pinned viewpoint, the latest analysis, the augmenter and the placement on a
/// body, wired to the background AnalysisWorker; for markers on a body (docs/math.md §20) also the
/// visibility model that says which markers a viewpoint sees. The drawing code (viewer/app) reads
/// it and calls its actions; the tests drive it directly.

#include <Eigen/Core>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "vantage/viewer/analysis_worker.h"
#include "vantage/viewer/camera.h"
#include "vantage/viewer/layout_document.h"
#include "vantage/viewer/viewpoint_readout.h"
#include "vantage/viewer/visibility_readout.h"

namespace vantage::viewer {

/// Outcome of ViewerSession::save.
enum class SaveOutcome {
  kSaved,             ///< written
  kNeedsOverwriteOk,  ///< the file exists and overwrite was not allowed: nothing written
  kFailed,            ///< not written; message() says why
};

/// Outcome of ViewerSession::load.
enum class LoadOutcome {
  kLoaded,          ///< read; the replaced layout is one undo step
  kNeedsDiscardOk,  ///< the layout has unsaved edits and discarding was not allowed: nothing read
  kFailed,          ///< not read; message() says why
};

class ViewerSession {
 public:
  /// Starts on `document` and asks for its analysis.
  explicit ViewerSession(LayoutDocument document);

  const LayoutDocument& document() const { return document_; }
  const Layout& layout() const { return document_.layout(); }
  /// Data vectors of the current layout (free vectors in point mode), recomputed on every change.
  const DataVectors& data() const { return data_; }
  /// The sphere shaded for the current layout, recomputed on every change.
  const SphereShading& shading() const { return shading_; }
  /// The visibility model of the current layout (its normals, cones, min_visible, workspace and
  /// body mesh, the occlusion grid cast at the report's default resolution), or null for a
  /// layout without normals. Rebuilt on every change.
  const visibility::VisibilityModel* visibility() const {
    return visibility_ ? &*visibility_ : nullptr;
  }
  /// The sphere's vertices (shading().vertices) under visibility, or null without normals.
  const VisibilityShading* visibility_shading() const {
    return visibility_shading_ ? &*visibility_shading_ : nullptr;
  }

  /// The latest analysis received (possibly of an older revision while a new one runs).
  const std::optional<AnalysisSnapshot>& analysis() const { return analysis_; }
  /// True when analysis() is of the current revision.
  bool analysis_current() const;
  /// True while an analysis or augmenter step runs or waits in the worker.
  bool working() const { return worker_.busy(); }
  bool augmenting() const { return augment_requested_; }
  /// True from place_markers() until its outcome is taken by poll().
  bool placing() const { return place_requested_; }
  /// The stage the running placement reported last, or empty.
  std::string place_progress() const { return worker_.place_progress(); }
  /// The last placement outcome received (its steps, baseline and final value), if any.
  const std::optional<PlaceOutcome>& placement() const { return placement_; }

  /// The last message for the user (an error of an action, or what the augmenter did).
  const std::string& message() const { return message_; }
  bool message_is_error() const { return message_is_error_; }

  // Actions. Each returns false, sets an error message and leaves the layout unchanged when the
  // action is refused (bad index, invalid resulting layout, unreadable file, ...).
  bool set_entry(int index, const Eigen::Vector3d& value, bool continue_edit = false);
  bool remove_entry(int index);
  /// Gives every marker the cone half-angle `degrees` (LayoutDocument::set_cone_half_angle_deg)
  /// and asks for the analysis of the new layout.
  bool set_cone_half_angle_deg(double degrees);
  /// Sets min_visible (LayoutDocument::set_min_visible) and asks for the new analysis.
  bool set_min_visible(int k);
  bool undo();
  /// Reads `path` (any layout format). With unsaved edits (document().modified()) it reads only
  /// when `discard_edits` is set (the user confirmed); undo() brings the edits back either way.
  LoadOutcome load(const std::string& path, bool discard_edits = false);
  SaveOutcome save(const std::string& path, bool overwrite);
  /// Drags the tip of vector `index` (direction mode), drawn at `tip_radius` times its unit
  /// direction, so that it lies under `pixel` of `viewport`: the new direction is where the
  /// pixel's ray meets the sphere of that radius (the intersection nearer the tip's current
  /// place; the point of the ray nearest the sphere when it misses). The vector keeps its
  /// length; continue_edit as in set_entry (one undo step per drag).
  bool drag_vector_tip(int index, const Eigen::Vector2d& pixel, const Viewport& viewport,
                       double tip_radius, bool continue_edit);
  /// Asks the worker for one augmenter step; its result is applied by poll() if the layout has not
  /// changed meanwhile (else discarded with a message). Refused (false, with a message) for a
  /// layout with marker normals: the augmenter adds markers without a normal.
  bool step_augmenter();

  /// Asks the worker to place settings.markers markers on the layout's body (place_on_body,
  /// docs/math.md §21). poll() replaces the layout by the placed one (one undo step) when the
  /// result is complete and the layout has not changed meanwhile; an incomplete result or an
  /// error leaves the layout as it is, with a message. Refused (false, with a message) for a
  /// layout without a body mesh, or while a placement runs.
  bool place_markers(const PlaceSettings& settings);

  /// Takes finished work from the worker (call once per frame). True when anything changed.
  bool poll();
  /// Polls until the current revision's analysis (and any augmenter step or placement) has arrived
  /// or `timeout` passes; true on success. For tests and screenshots.
  bool wait_until_current(std::chrono::milliseconds timeout);

  /// Camera placement for a preset; kWorst/kPaper need a current analysis (else: unchanged,
  /// returns false).
  bool apply_view(ViewPreset preset);

  OrbitCamera camera;
  int selected = -1;  ///< selected entry (vector or marker), -1 = none
  /// A viewpoint the user pinned on the sphere (unit), shown in the readout when nothing is
  /// hovered.
  std::optional<Eigen::Vector3d> pinned_viewpoint;

 private:
  void changed();
  void fail(const std::string& what);
  void inform(const std::string& what);
  bool apply_augment(AugmentOutcome outcome);
  bool apply_place(PlaceOutcome outcome);

  LayoutDocument document_;
  DataVectors data_;
  SphereShading shading_;
  std::optional<visibility::VisibilityModel> visibility_;
  std::optional<VisibilityShading> visibility_shading_;
  std::optional<AnalysisSnapshot> analysis_;
  bool augment_requested_ = false;
  bool place_requested_ = false;
  std::optional<PlaceOutcome> placement_;
  std::string message_;
  bool message_is_error_ = false;
  AnalysisWorker worker_;  // last: its thread stops before the members above go
};

}  // namespace vantage::viewer

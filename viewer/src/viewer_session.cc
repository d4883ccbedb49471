#include "vantage/viewer/viewer_session.h"

#include <exception>
#include <filesystem>
#include <sstream>
#include <thread>
#include <utility>

namespace vantage::viewer {

ViewerSession::ViewerSession(LayoutDocument document) : document_(std::move(document)) {
  changed();
}

void ViewerSession::changed() {
  data_ = data_vectors(document_.layout());
  shading_ = shade_sphere(data_.vectors);
  visibility_.reset();
  visibility_shading_.reset();
  if (document_.layout().visibility) {
    // The document holds only valid layouts, so the model builds; a failure to cast the body's
    // rays is reported and leaves the sphere shaded as seen whole.
    try {
      visibility_ = visibility::VisibilityModel::of(document_.layout());
      visibility_shading_ = shade_visibility(*visibility_, shading_.vertices);
    } catch (const std::exception& e) {
      visibility_.reset();
      fail(std::string("visibility: ") + e.what());
    }
  }
  if (selected >= document_.layout().entries.cols()) selected = -1;
  worker_.request_analysis(document_.layout(), document_.revision());
}

void ViewerSession::fail(const std::string& what) {
  message_ = what;
  message_is_error_ = true;
}

void ViewerSession::inform(const std::string& what) {
  message_ = what;
  message_is_error_ = false;
}

bool ViewerSession::analysis_current() const {
  return analysis_ && analysis_->revision == document_.revision();
}

bool ViewerSession::set_entry(int index, const Eigen::Vector3d& value, bool continue_edit) {
  try {
    document_.set_entry(index, value, continue_edit);
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
  changed();
  return true;
}

bool ViewerSession::remove_entry(int index) {
  const std::string removed_name =
      index >= 0 && index < layout().entries.cols() ? layout().entry_name(index) : "";
  try {
    document_.remove_entry(index);
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
  inform("removed " + std::string(layout().mode == LayoutMode::kPoints ? "marker " : "vector ") +
         removed_name);
  selected = -1;
  changed();
  return true;
}

bool ViewerSession::set_cone_half_angle_deg(double degrees) {
  try {
    document_.set_cone_half_angle_deg(degrees);
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
  changed();
  return true;
}

bool ViewerSession::set_min_visible(int k) {
  try {
    document_.set_min_visible(k);
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
  changed();
  return true;
}

bool ViewerSession::undo() {
  if (!document_.undo()) {
    fail("nothing to undo");
    return false;
  }
  inform("undone");
  changed();
  return true;
}

LoadOutcome ViewerSession::load(const std::string& path, bool discard_edits) {
  if (document_.modified() && !discard_edits) return LoadOutcome::kNeedsDiscardOk;
  try {
    document_.load(path);
  } catch (const std::exception& e) {
    fail(e.what());
    return LoadOutcome::kFailed;
  }
  inform("loaded " + path + " (Undo returns to the previous layout)");
  selected = -1;
  pinned_viewpoint.reset();
  changed();
  return LoadOutcome::kLoaded;
}

bool ViewerSession::drag_vector_tip(int index, const Eigen::Vector2d& pixel,
                                    const Viewport& viewport, double tip_radius,
                                    bool continue_edit) {
  if (layout().mode != LayoutMode::kVectors || index < 0 || index >= layout().entries.cols()) {
    fail("only the vectors of a direction layout can be dragged");
    return false;
  }
  const Eigen::Vector3d v = layout().entries.col(index);
  const Eigen::Vector3d direction =
      camera.pick_direction(pixel, viewport, tip_radius, tip_radius * v.normalized());
  return set_entry(index, v.norm() * direction, continue_edit);
}

SaveOutcome ViewerSession::save(const std::string& path, bool overwrite) {
  std::error_code ec;
  if (!overwrite && std::filesystem::exists(path, ec)) return SaveOutcome::kNeedsOverwriteOk;
  try {
    document_.save(path, overwrite);
  } catch (const std::exception& e) {
    fail(e.what());
    return SaveOutcome::kFailed;
  }
  inform("saved " + path);
  return SaveOutcome::kSaved;
}

bool ViewerSession::step_augmenter() {
  augment_requested_ = true;
  inform("augmenter: searching for the next " +
         std::string(layout().mode == LayoutMode::kPoints ? "marker" : "vector") + "...");
  worker_.request_augment(document_.layout(), document_.revision());
  return true;
}

bool ViewerSession::place_markers(const PlaceSettings& settings) {
  if (!is_on_body(layout())) {
    fail("place: the layout has no body mesh (load a layout with normals and a body)");
    return false;
  }
  if (place_requested_) {
    fail("place: a placement is already running");
    return false;
  }
  place_requested_ = true;
  inform("place: choosing " + std::to_string(settings.markers) + " of " +
         std::to_string(settings.candidates) + " sites on the body...");
  worker_.request_place(document_.layout(), document_.revision(), settings);
  return true;
}

bool ViewerSession::poll() {
  bool any = false;
  if (std::optional<AnalysisSnapshot> snapshot = worker_.take_analysis()) {
    analysis_ = std::move(snapshot);
    any = true;
  }
  if (std::optional<AugmentOutcome> outcome = worker_.take_augment()) {
    augment_requested_ = false;
    any = true;
    if (!apply_augment(std::move(*outcome))) return any;
  }
  if (std::optional<PlaceOutcome> outcome = worker_.take_place()) {
    place_requested_ = false;
    any = true;
    apply_place(std::move(*outcome));
  }
  return any;
}

bool ViewerSession::apply_augment(AugmentOutcome outcome) {
  if (!outcome.error.empty()) {
    fail("augmenter: " + outcome.error);
    return true;
  }
  if (outcome.revision != document_.revision()) {
    fail("augmenter: the layout changed while it ran; step discarded");
    return true;
  }
  try {
    document_.replace(std::move(outcome.augmented));
  } catch (const std::exception& e) {
    fail(std::string("augmenter: its layout was refused: ") + e.what());
    return false;
  }
  std::ostringstream note;
  note.precision(4);
  note << "added " << outcome.step.added.transpose() << " in " << outcome.seconds
       << " s: " << outcome.step.note;
  inform(note.str());
  changed();
  return true;
}

bool ViewerSession::apply_place(PlaceOutcome outcome) {
  placement_ = std::move(outcome);
  PlaceOutcome& out = *placement_;
  if (!out.error.empty()) {
    fail("place: " + out.error);
    return false;
  }
  if (!out.complete) {
    fail("place: incomplete: " + out.failure + "; the layout is kept");
    return false;
  }
  if (out.revision != document_.revision()) {
    fail("place: the layout changed while it ran; placement discarded");
    return false;
  }
  try {
    document_.replace(out.placed);
  } catch (const std::exception& e) {
    fail(std::string("place: its layout was refused: ") + e.what());
    return false;
  }
  std::ostringstream note;
  note.precision(4);
  note << "placed " << out.result.chosen.size() << " of " << out.n_candidates << " sites ("
       << out.result.search << ") in " << out.seconds << " s (Undo returns to the previous layout)";
  inform(note.str());
  selected = -1;
  pinned_viewpoint.reset();
  changed();
  return true;
}

bool ViewerSession::wait_until_current(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    poll();
    if (analysis_current() && !augment_requested_ && !place_requested_) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    worker_.wait_idle(std::min(left, std::chrono::milliseconds(50)));
  }
}

bool ViewerSession::apply_view(ViewPreset preset) {
  switch (preset) {
    case ViewPreset::kIso:
      camera.reset();
      return true;
    case ViewPreset::kTop:
      camera.look_along(Eigen::Vector3d::UnitZ());
      return true;
    case ViewPreset::kFront:
      camera.look_along(Eigen::Vector3d::UnitX());
      return true;
    case ViewPreset::kSide:
      camera.look_along(Eigen::Vector3d::UnitY());
      return true;
    case ViewPreset::kWorst:
    case ViewPreset::kPaper:
      if (!analysis_ || !analysis_->error.empty()) return false;
      if (preset == ViewPreset::kWorst && analysis_->visibility &&
          analysis_->visibility->worst.status !=
              visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
        camera.look_along(analysis_->visibility->worst.viewpoint);  // signed: the camera's side
        return true;
      }
      camera.look_along(preset == ViewPreset::kWorst ? analysis_->analysis.worst_viewpoint
                                                     : analysis_->analysis.paper_lmi.viewpoint);
      return true;
  }
  return false;
}

}  // namespace vantage::viewer

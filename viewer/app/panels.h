#pragma once

// The panel column of vantage-viewer: the layout and design panel (augmenter, undo, edit,
// remove, load/save, p_bar_min, certificate, ceiling, coplanarity; for markers on a body the
// answer with visibility first, and the cone and min_visible editors, and placing K markers on the
// body), the viewpoint readout (p_i, p_bar, Eq. 26 errors; the markers the viewpoint sees) and the
// Eq. (26) error surface with the current viewpoint on it.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vantage/viewer/viewer_session.h"

namespace vantage::viewer::app {

class Panels {
 public:
  Panels();

  /// Draws the column at x = `left` (pixels) spanning `height`. `hovered` is the viewpoint under
  /// the mouse (the readout shows it, else the pinned one, else the worst viewpoint).
  void draw(ViewerSession& session, const std::optional<Eigen::Vector3d>& hovered, float left,
            float width, float height);

  /// Keyboard shortcuts (call once per frame when ImGui does not want the keyboard).
  void handle_keys(ViewerSession& session);

 private:
  void design_panel(ViewerSession& session);
  void analysis_tab(ViewerSession& session);
  void analysis_summary(const ViewerSession& session);
  void visibility_summary(const AnalysisSnapshot& snapshot);
  void visibility_editor(ViewerSession& session);
  void placement_panel(ViewerSession& session);
  void visibility_readout(const ViewerSession& session, const Eigen::Vector3d& a);
  void entry_editor(ViewerSession& session);
  void readout_panel(const ViewerSession& session, const std::optional<Eigen::Vector3d>& hovered);
  void error_surface_panel(const ViewerSession& session,
                           const std::optional<Eigen::Vector3d>& hovered);
  void file_dialogs(ViewerSession& session);
  std::optional<Eigen::Vector3d> shown_viewpoint(const ViewerSession& session,
                                                 const std::optional<Eigen::Vector3d>& hovered,
                                                 const char** what) const;

  std::vector<double> surface_deg_;  // Eq. (26) on a kSurfaceCells^2 grid of (p, p_bar)
  std::string load_path_;
  std::string save_path_;
  std::string dialog_error_;
  bool open_load_ = false;
  bool open_save_ = false;
  bool confirm_overwrite_ = false;
  bool confirm_discard_ = false;  // the Load dialog asked whether to drop unsaved edits
  int edited_entry_ = -1;
  float edit_value_[3] = {0, 0, 0};
  std::uint64_t visibility_revision_ = 0;  // the revision the two fields below were read from
  double cone_edit_ = 0.0;
  int min_visible_edit_ = 3;
  bool was_placing_ = false;      // placing on the previous frame
  PlaceSettings place_settings_;  // the placement controls
  std::string approach_text_;     // the camera objective's distances D1,D2,... as typed
  std::uint64_t place_revision_ = ~std::uint64_t{0};  // the revision K was last read from
  bool place_seeded_ = false;  // the controls took the settings of a start-up placement
};

}  // namespace vantage::viewer::app

#include "panels.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "draw_style.h"

namespace vantage::viewer::app {
namespace {

const char* entry_word(const Layout& layout) {
  return layout.mode == LayoutMode::kPoints ? "marker" : "vector";
}

}  // namespace

void Panels::draw(ViewerSession& session, const std::optional<Eigen::Vector3d>& hovered, float left,
                  float width, float height) {
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
  const float surface_height = std::min(340.0f, 0.36f * height);
  const float design_height = 0.68f * (height - surface_height);
  ImGui::SetNextWindowPos(ImVec2(left, 0));
  ImGui::SetNextWindowSize(ImVec2(width, design_height));
  if (ImGui::Begin("Layout and design", nullptr, flags)) design_panel(session);
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(left, design_height));
  ImGui::SetNextWindowSize(ImVec2(width, height - design_height - surface_height));
  if (ImGui::Begin("Viewpoint", nullptr, flags)) readout_panel(session, hovered);
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(left, height - surface_height));
  ImGui::SetNextWindowSize(ImVec2(width, surface_height));
  if (ImGui::Begin("Eq. (26) error surface", nullptr, flags)) error_surface_panel(session, hovered);
  ImGui::End();
  file_dialogs(session);
}

void Panels::design_panel(ViewerSession& session) {
  const LayoutDocument& doc = session.document();
  const Layout& layout = doc.layout();
  ImGui::TextWrapped("%s%s", layout.name.empty() ? "(unnamed layout)" : layout.name.c_str(),
                     doc.modified() ? "  [modified]" : "");
  ImGui::TextDisabled("%s", doc.path().empty() ? "not saved to a file" : doc.path().c_str());
  ImGui::Text("%s mode: %d %ss -> %d data vectors", to_string(layout.mode),
              static_cast<int>(layout.entries.cols()), entry_word(layout),
              static_cast<int>(session.data().vectors.cols()));
  ImGui::BeginDisabled(session.augmenting() || layout.visibility.has_value());
  if (ImGui::Button(session.augmenting() ? "Augmenting..." : "Add next (A)")) {
    session.step_augmenter();
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(doc.undo_depth() == 0);
  if (ImGui::Button("Undo (Ctrl+Z)")) session.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Load...")) open_load_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Save...")) open_save_ = true;
  if (!session.message().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, session.message_is_error() ? kErrorText : kHalo);
    ImGui::TextWrapped("%s", session.message().c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Separator();
  if (!is_on_body(layout)) {
    analysis_tab(session);
    return;
  }
  // A placement that starts (the button, or --place at start-up) brings its tab to the front.
  const bool placing = session.placing();
  const bool bring_place = placing && !was_placing_;
  was_placing_ = placing;
  if (!ImGui::BeginTabBar("design tabs")) return;
  if (ImGui::BeginTabItem("Analysis")) {
    analysis_tab(session);
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Place markers", nullptr,
                          bring_place ? ImGuiTabItemFlags_SetSelected : 0)) {
    placement_panel(session);
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

void Panels::analysis_tab(ViewerSession& session) {
  analysis_summary(session);
  if (session.layout().visibility) {
    ImGui::Separator();
    visibility_editor(session);
  }
  ImGui::Separator();
  entry_editor(session);
}

void Panels::analysis_summary(const ViewerSession& session) {
  const std::optional<AnalysisSnapshot>& snap = session.analysis();
  if (!snap) {
    ImGui::TextDisabled("global analysis running...");
    return;
  }
  if (!snap->error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("analysis failed: %s", snap->error.c_str());
    ImGui::PopStyleColor();
    return;
  }
  const sdp::LayoutAnalysis& r = snap->analysis;
  if (!session.analysis_current()) ImGui::TextColored(ImVec4(1, 0.75f, 0.25f, 1), "recomputing...");
  if (snap->visibility) {
    visibility_summary(*snap);
    ImGui::TextDisabled("seen whole (every camera sees every marker):");
  }
  ImGui::Text("p\u0304_min %.6f  (max error %.2f\u00b0, Eq. 30)", r.pbar_min,
              r.max_worst_case_error_deg);
  ImGui::Text("ceiling cos(\u03c0/2m) %.6f  (m = %d)", snap->ceiling,
              static_cast<int>(snap->data.vectors.cols()));
  ImGui::Text("certificate t \u2208 [%.9f, %.9f] %s", r.certificate.t_lower, r.certificate.t_upper,
              r.certificate.certified ? "certified" : "NOT certified");
  ImGui::Text("worst viewpoint (%.3f, %.3f, %.3f)%s", r.worst_viewpoint.x(), r.worst_viewpoint.y(),
              r.worst_viewpoint.z(),
              r.worst_viewpoints.size() > 1
                  ? (" + " + std::to_string(r.worst_viewpoints.size() - 1) + " ties").c_str()
                  : "");
  ImGui::Text("paper's single LMI p\u0304 %.4f (%s)", r.paper_lmi.pbar_at,
              sdp::to_string(r.paper_lmi.status));
  ImGui::Text("NLopt cross-check %s", !r.crosscheck.ran     ? "skipped"
                                      : r.crosscheck.agrees ? "agrees"
                                                            : "DISAGREES");
  ImGui::SameLine();
  ImGui::TextDisabled("  analysis %.2f s (worker thread)", snap->seconds);
  if (snap->coplanarity.nearly_coplanar) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningText);
    ImGui::TextWrapped(
        "nearly coplanar (smallest singular value %.3f): two-fold (Necker) "
        "ambiguity of affine pose",
        snap->coplanarity.smallest_singular_value);
    ImGui::PopStyleColor();
  } else {
    ImGui::TextDisabled("coplanarity %.3f (0 = coplanar, 0.577 = isotropic)",
                        snap->coplanarity.smallest_singular_value);
  }
}

void Panels::entry_editor(ViewerSession& session) {
  const Layout& layout = session.layout();
  ImGui::Text(layout.mode == LayoutMode::kPoints ? "markers (click to select, edit below):"
                                                 : "vectors (click to select, or drag a tip):");
  const float list_height = std::max(
      110.0f, ImGui::GetContentRegionAvail().y - 1.3f * ImGui::GetFrameHeightWithSpacing());
  if (ImGui::BeginChild("entries", ImVec2(0, list_height), true)) {
    for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
      char coordinates[96];
      std::snprintf(coordinates, sizeof coordinates, "  (%.3f, %.3f, %.3f)##%d",
                    layout.entries(0, i), layout.entries(1, i), layout.entries(2, i),
                    static_cast<int>(i));
      const std::string row = layout.entry_name(i) + coordinates;
      if (ImGui::Selectable(row.c_str(), session.selected == i)) {
        session.selected = static_cast<int>(i);
      }
    }
  }
  ImGui::EndChild();
  const int sel = session.selected;
  if (sel < 0 || sel >= layout.entries.cols()) {
    ImGui::TextDisabled("select a %s to edit or remove it", entry_word(layout));
    return;
  }
  if (edited_entry_ != sel || !ImGui::IsAnyItemActive()) {
    for (int k = 0; k < 3; ++k) edit_value_[k] = static_cast<float>(layout.entries(k, sel));
    edited_entry_ = sel;
  }
  ImGui::SetNextItemWidth(250.0f);
  if (ImGui::InputFloat3("##edit", edit_value_, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue)) {
    session.set_entry(
        sel, Eigen::Vector3f(edit_value_[0], edit_value_[1], edit_value_[2]).cast<double>());
  }
  ImGui::SameLine();
  if (ImGui::Button("Remove (Del)")) session.remove_entry(sel);
}

void Panels::file_dialogs(ViewerSession& session) {
  if (open_load_) {
    ImGui::OpenPopup("Load layout");
    load_path_ = session.document().path();
    dialog_error_.clear();
    confirm_discard_ = false;
    open_load_ = false;
  }
  if (open_save_) {
    ImGui::OpenPopup("Save layout");
    save_path_ = session.document().path();
    dialog_error_.clear();
    confirm_overwrite_ = false;
    open_save_ = false;
  }
  if (ImGui::BeginPopupModal("Load layout", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", &load_path_, ImGuiInputTextFlags_EnterReturnsTrue);
    if (!dialog_error_.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
      ImGui::TextWrapped("%s", dialog_error_.c_str());
      ImGui::PopStyleColor();
    }
    if (confirm_discard_) {
      ImGui::TextColored(ImVec4(1, 0.75f, 0.25f, 1),
                         "The layout has unsaved edits. Load anyway? (Undo brings them back.)");
    }
    if (ImGui::Button(confirm_discard_ ? "Load anyway" : "Load") || enter) {
      const LoadOutcome outcome = session.load(load_path_, confirm_discard_);
      if (outcome == LoadOutcome::kLoaded) ImGui::CloseCurrentPopup();
      if (outcome == LoadOutcome::kNeedsDiscardOk) confirm_discard_ = true;
      if (outcome == LoadOutcome::kFailed) {
        dialog_error_ = session.message() + " (the current layout is kept)";
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopupModal("Save layout", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::SetNextItemWidth(420.0f);
    const bool enter = ImGui::InputText("file", &save_path_, ImGuiInputTextFlags_EnterReturnsTrue);
    if (confirm_overwrite_) {
      ImGui::TextColored(ImVec4(1, 0.75f, 0.25f, 1), "%s exists. Overwrite it?",
                         save_path_.c_str());
    }
    if (!dialog_error_.empty()) ImGui::TextWrapped("%s", dialog_error_.c_str());
    if (ImGui::Button(confirm_overwrite_ ? "Overwrite" : "Save") || enter) {
      const SaveOutcome outcome = session.save(save_path_, confirm_overwrite_);
      if (outcome == SaveOutcome::kSaved) ImGui::CloseCurrentPopup();
      if (outcome == SaveOutcome::kNeedsOverwriteOk) confirm_overwrite_ = true;
      if (outcome == SaveOutcome::kFailed) dialog_error_ = session.message();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

void Panels::handle_keys(ViewerSession& session) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) session.undo();
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O)) open_load_ = true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) open_save_ = true;
  if (io.KeyCtrl) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_A) && !session.augmenting()) session.step_augmenter();
  if (ImGui::IsKeyPressed(GLFW_KEY_DELETE) && session.selected >= 0) {
    session.remove_entry(session.selected);
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) {
    session.pinned_viewpoint.reset();
    session.selected = -1;
  }
  const std::pair<int, ViewPreset> views[] = {
      {GLFW_KEY_R, ViewPreset::kIso},   {GLFW_KEY_W, ViewPreset::kWorst},
      {GLFW_KEY_P, ViewPreset::kPaper}, {GLFW_KEY_T, ViewPreset::kTop},
      {GLFW_KEY_F, ViewPreset::kFront}, {GLFW_KEY_S, ViewPreset::kSide},
  };
  for (const auto& [key, preset] : views) {
    if (ImGui::IsKeyPressed(key)) session.apply_view(preset);
  }
}

}  // namespace vantage::viewer::app

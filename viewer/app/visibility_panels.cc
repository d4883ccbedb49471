// The panel parts for markers on a body (docs/math.md §20): the answer with visibility beside
// the seen-whole one, the cone and min_visible editors, and the markers a viewpoint sees.

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "draw_style.h"
#include "panels.h"

namespace vantage::viewer::app {
namespace {

const ImVec4 kAmber(1.0f, 0.75f, 0.25f, 1.0f);

std::string names_of(const Layout& layout, const std::vector<int>& markers) {
  std::string out;
  for (const int i : markers) {
    if (!out.empty()) out += ", ";
    out += layout.entry_name(i);
  }
  return out.empty() ? "none" : out;
}

}  // namespace

void Panels::visibility_summary(const AnalysisSnapshot& snapshot) {
  const visibility::VisibilityReport& v = *snapshot.visibility;
  const visibility::VisibilityWorstViewpoint& w = v.worst;
  char model[96];
  if (v.occlusion_resolution_deg) {
    std::snprintf(model, sizeof model, "cone+mesh, occlusion sampled at %.2f\u00b0",
                  *v.occlusion_resolution_deg);
  } else {
    std::snprintf(model, sizeof model, "cone");
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("on the body (%s; min_visible %d%s):", model, v.min_visible,
                     v.workspace ? "; in the workspace" : "");
  ImGui::PopStyleColor();
  if (w.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("no direction can track the body: %s", w.message.c_str());
    ImGui::PopStyleColor();
    return;
  }
  ImGui::Text("worst-case error with visibility %.2f\u00b0  (seen whole %.2f\u00b0)",
              v.max_worst_case_error_deg, snapshot.analysis.max_worst_case_error_deg);
  ImGui::Text("trackable %.1f %% of the %s  (lost %.1f %%)", 100.0 * v.coverage.trackable_fraction,
              v.workspace ? "workspace" : "sphere", 100.0 * v.coverage.lost_fraction);
  if (v.coverage.largest_region_center) {
    const Eigen::Vector3d& c = *v.coverage.largest_region_center;
    ImGui::TextDisabled("largest lost region: radius %.1f\u00b0 around (%.2f, %.2f, %.2f)",
                        v.coverage.largest_region_radius_deg, c.x(), c.y(), c.z());
  }
  ImGui::TextWrapped("certificate t \u2208 [%.9f, %.9f] %s", w.t_lower, w.t_upper,
                     !w.certified() ? "NOT certified"
                     : v.with_body  ? "certified on the occlusion grid, not under exact rays"
                                    : "certified");
  if (v.exact_viewpoint_disagrees()) {
    ImGui::TextWrapped("exact rays: the worst viewpoint sees %zu markers, not %zu",
                       v.exact_viewpoint->visible.size(), w.visible_markers.size());
  }
  ImGui::TextWrapped("worst viewpoint (%.3f, %.3f, %.3f), body \u2192 camera%s", w.viewpoint.x(),
                     w.viewpoint.y(), w.viewpoint.z(),
                     w.viewpoints.size() > 1
                         ? (" + " + std::to_string(w.viewpoints.size() - 1) + " ties").c_str()
                         : "");
  if (!v.off_body.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningText);
    ImGui::TextWrapped("markers off the body's surface (is it their body?): %s",
                       names_of(snapshot.layout, v.off_body).c_str());
    ImGui::PopStyleColor();
  }
}

void Panels::visibility_editor(ViewerSession& session) {
  const MarkerVisibility& vis = *session.layout().visibility;
  const double lo = vis.cone_half_angle_deg.minCoeff();
  const double hi = vis.cone_half_angle_deg.maxCoeff();
  if (visibility_revision_ != session.document().revision() || !ImGui::IsAnyItemActive()) {
    cone_edit_ = hi;
    min_visible_edit_ = vis.min_visible;
    visibility_revision_ = session.document().revision();
  }
  ImGui::Text("markers on the body:");
  ImGui::SetNextItemWidth(110.0f);
  if (ImGui::InputDouble("cone half-angle \u00b0 (all markers)", &cone_edit_, 0.0, 0.0, "%.1f",
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
    session.set_cone_half_angle_deg(cone_edit_);
  }
  if (lo != hi)
    ImGui::TextDisabled("  cones differ (%.1f\u00b0 \u2026 %.1f\u00b0): Enter sets all", lo, hi);
  ImGui::SetNextItemWidth(110.0f);
  if (ImGui::InputInt("min_visible (markers a view must see)", &min_visible_edit_, 1, 1,
                      ImGuiInputTextFlags_EnterReturnsTrue)) {
    session.set_min_visible(min_visible_edit_);
  }
  ImGui::TextDisabled("  Enter applies; the analysis reruns (Undo restores)");
}

void Panels::visibility_readout(const ViewerSession& session, const Eigen::Vector3d& a) {
  const VisibilityReadout r = read_visibility(*session.visibility(), a);
  const int markers = static_cast<int>(session.layout().entries.cols());
  if (r.state == ViewpointState::kTrackable) {
    ImGui::Text("on the body: %d of %d markers seen, error asin t(a) = %.2f\u00b0",
                static_cast<int>(r.visible.size()), markers, r.error_deg);
  } else {
    ImGui::TextColored(
        kAmber, "on the body: %d of %d markers seen: %s", static_cast<int>(r.visible.size()),
        markers, r.state == ViewpointState::kLost ? "LOST (untrackable)" : "outside the workspace");
  }
  ImGui::TextDisabled("hidden: %s", names_of(session.layout(), r.hidden).c_str());
}

}  // namespace vantage::viewer::app

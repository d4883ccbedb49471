// The viewpoint readout and the Eq. (26) error surface of the panel column.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "draw_style.h"
#include "panels.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/plot/colormap.h"

namespace vantage::viewer::app {
namespace {

constexpr int kSurfaceCells = 90;
constexpr double kSurfaceTopDeg = 90.0;  // Eq. (26) ranges over [0, 90] degrees

}  // namespace

Panels::Panels() : surface_deg_(kSurfaceCells * kSurfaceCells, -1.0) {
  for (int row = 0; row < kSurfaceCells; ++row) {
    const double pbar = (row + 0.5) / kSurfaceCells;
    for (int col = 0; col < kSurfaceCells; ++col) {
      const double p = (col + 0.5) / kSurfaceCells;
      if (p <= pbar) {
        surface_deg_[row * kSurfaceCells + col] =
            kDegreesPerRadian * lub_scale_error_angle(p, pbar);
      }
    }
  }
}

std::optional<Eigen::Vector3d> Panels::shown_viewpoint(
    const ViewerSession& session, const std::optional<Eigen::Vector3d>& hovered,
    const char** what) const {
  if (hovered) {
    *what = "under the mouse";
    return hovered;
  }
  if (session.pinned_viewpoint) {
    *what = "pinned (click the sphere; Esc clears)";
    return session.pinned_viewpoint;
  }
  if (session.analysis() && session.analysis()->error.empty()) {
    const std::optional<visibility::VisibilityReport>& body = session.analysis()->visibility;
    if (body && body->worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
      *what = "the worst viewpoint on the body (hover the sphere)";
      return body->worst.viewpoint;
    }
    *what = "the global worst viewpoint (hover the sphere)";
    return session.analysis()->analysis.worst_viewpoint;
  }
  return std::nullopt;
}

void Panels::readout_panel(const ViewerSession& session,
                           const std::optional<Eigen::Vector3d>& hovered) {
  const char* what = "";
  const std::optional<Eigen::Vector3d> a = shown_viewpoint(session, hovered, &what);
  if (!a) {
    ImGui::TextDisabled("hover the sphere to read a viewpoint");
    return;
  }
  const DataVectors& data = session.data();
  const ViewpointReadout r = read_viewpoint(data.vectors, *a);
  ImGui::TextDisabled("%s", what);
  ImGui::Text("a = (%.3f, %.3f, %.3f)", a->x(), a->y(), a->z());
  std::vector<bool> hidden;  // per marker, for markers on a body
  if (session.visibility() != nullptr) {
    visibility_readout(session, *a);
    hidden.assign(static_cast<std::size_t>(session.layout().entries.cols()), true);
    for (const int i : read_visibility(*session.visibility(), *a).visible) {
      hidden[static_cast<std::size_t>(i)] = false;
    }
    ImGui::TextDisabled("seen whole:");
  }
  ImGui::Text("p\u0304(a) = %.4f   worst-case error arccos p\u0304 = %.2f\u00b0", r.pbar_at,
              r.max_error_deg);
  std::vector<int> order(static_cast<std::size_t>(r.p.size()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return r.errors_deg(i) > r.errors_deg(j); });
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_BordersOuter | ImGuiTableFlags_SizingStretchSame;
  if (ImGui::BeginTable("readout", 3, flags, ImVec2(0, 0))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("data vector", ImGuiTableColumnFlags_WidthStretch, 2.0f);
    ImGui::TableSetupColumn("p_i");
    ImGui::TableSetupColumn("Eq. 26 error");
    ImGui::TableHeadersRow();
    for (const int i : order) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const Layout& layout = session.layout();
      const std::string name = data.pairs.empty()
                                   ? layout.entry_name(i)
                                   : layout.entry_name(data.pairs[i].first) + "\u2192" +
                                         layout.entry_name(data.pairs[i].second);
      const bool unseen = !hidden.empty() && !data.pairs.empty() &&
                          (hidden[static_cast<std::size_t>(data.pairs[i].first)] ||
                           hidden[static_cast<std::size_t>(data.pairs[i].second)]);
      if (unseen) {
        ImGui::TextDisabled("%s  (hidden)", name.c_str());
      } else {
        ImGui::Text("%s%s", name.c_str(), i == r.limiting ? "  (sets p\u0304)" : "");
      }
      ImGui::TableNextColumn();
      ImGui::Text("%.4f", r.p(i));
      ImGui::TableNextColumn();
      ImGui::Text("%.2f\u00b0", r.errors_deg(i));
    }
    ImGui::EndTable();
  }
}

void Panels::error_surface_panel(const ViewerSession& session,
                                 const std::optional<Eigen::Vector3d>& hovered) {
  ImGui::TextWrapped(
      "\u03b8(p_i, p\u0304) for the least-upper-bound scale; dots: (p_i, p\u0304) at the "
      "viewpoint; red: p\u0304_min");
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float side = std::min(ImGui::GetContentRegionAvail().y - 40.0f, 260.0f);
  const ImVec2 lo(origin.x + 44.0f, origin.y + 4.0f);  // plot box, p across, p_bar up
  const float cell = side / kSurfaceCells;
  for (int row = 0; row < kSurfaceCells; ++row) {
    for (int col = 0; col < kSurfaceCells; ++col) {
      const double v = surface_deg_[row * kSurfaceCells + col];
      const ImU32 colour = v < 0.0 ? IM_COL32(48, 48, 54, 255)
                                   : to_imgui(plot::value_colour(v, 0.0, kSurfaceTopDeg));
      const ImVec2 a(lo.x + col * cell, lo.y + side - (row + 1) * cell);
      list->AddRectFilled(a, ImVec2(a.x + cell + 0.5f, a.y + cell + 0.5f), colour);
    }
  }
  list->AddRect(lo, ImVec2(lo.x + side, lo.y + side), kAxisGrey);
  auto at = [&](double p, double pbar) {
    return ImVec2(lo.x + static_cast<float>(p) * side,
                  lo.y + side - static_cast<float>(pbar) * side);
  };
  for (const double tick : {0.0, 0.5, 1.0}) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", tick);
    list->AddText(ImVec2(at(tick, 0).x - 8, lo.y + side + 2), kAxisGrey, text);
    list->AddText(ImVec2(lo.x - 28, at(0, tick).y - 8), kAxisGrey, text);
  }
  list->AddText(ImVec2(lo.x + 0.5f * side - 4, lo.y + side + 18), kHalo, "p_i");
  list->AddText(ImVec2(origin.x, lo.y + 0.45f * side), kHalo, "p\u0304");
  list->AddText(ImVec2(at(0.55, 0.22).x, at(0.55, 0.22).y), IM_COL32(200, 200, 200, 255),
                "p_i > p\u0304");
  if (session.analysis() && session.analysis()->error.empty()) {
    const double pmin = session.analysis()->analysis.pbar_min;
    list->AddLine(at(0, pmin), at(1, pmin), to_imgui(plot::kWorstViewpointColour), 1.5f);
  }
  const char* what = "";
  if (const std::optional<Eigen::Vector3d> a = shown_viewpoint(session, hovered, &what)) {
    const ViewpointReadout r = read_viewpoint(session.data().vectors, *a);
    list->AddLine(at(0, r.pbar_at), at(r.pbar_at, r.pbar_at), kProbeColour, 1.0f);
    for (Eigen::Index i = 0; i < r.p.size(); ++i) {
      list->AddCircleFilled(at(r.p(i), r.pbar_at), 4.5f, kProbeColour);
      list->AddCircleFilled(at(r.p(i), r.pbar_at), 3.0f, to_imgui(plot::kDataVectorColour));
    }
  }
  const float legend_x = lo.x + side + 18.0f;
  const float bar_top = lo.y + 20.0f;
  const float bar_height = side - 40.0f;
  for (int k = 0; k < 48; ++k) {
    const float y0 = bar_top + bar_height * (47 - k) / 48.0f;
    list->AddRectFilled(ImVec2(legend_x, y0), ImVec2(legend_x + 14, y0 + bar_height / 48.0f + 0.5f),
                        to_imgui(plot::value_colour((k + 0.5) / 48.0)));
  }
  list->AddText(ImVec2(legend_x + 18, bar_top - 8), kAxisGrey, "90\u00b0");
  list->AddText(ImVec2(legend_x + 18, bar_top + bar_height - 8), kAxisGrey, "0\u00b0");
  ImGui::Dummy(ImVec2(side + 60.0f, side + 36.0f));
}

}  // namespace vantage::viewer::app

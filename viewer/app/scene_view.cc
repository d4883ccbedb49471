#include "scene_view.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "body_view.h"
#include "draw_style.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/colormap.h"

namespace vantage::viewer::app {
namespace {

constexpr double kVectorLength = 1.45;  // data vector arrows reach past the unit sphere
constexpr double kAxisLength = 1.6;     // worst / paper viewpoint axes
constexpr int kCirclePoints = 160;
constexpr int kLinePieces = 48;
constexpr float kHandleRadius = 10.0f;  // pixels: grab distance of a vector tip or the probe
constexpr float kClickSlop = 3.0f;      // pixels: a press released within this is a click

ImVec2 to_im(const Eigen::Vector2d& p) {
  return ImVec2(static_cast<float>(p.x()), static_cast<float>(p.y()));
}

struct Painter {
  ImDrawList* list;
  const OrbitCamera& camera;
  const Viewport& viewport;

  std::optional<ImVec2> at(const Eigen::Vector3d& p) const {
    if (camera.hidden_by_sphere(p)) return std::nullopt;
    const std::optional<Eigen::Vector2d> q = camera.project(p, viewport);
    if (!q) return std::nullopt;
    return to_im(*q);
  }

  // Draws the visible pieces of a 3-D polyline (the opaque sphere hides the rest).
  void polyline(const std::vector<Eigen::Vector3d>& points, ImU32 colour, float thickness) const {
    for (std::size_t k = 1; k < points.size(); ++k) {
      const std::optional<ImVec2> a = at(points[k - 1]);
      const std::optional<ImVec2> b = at(points[k]);
      if (a && b) list->AddLine(*a, *b, colour, thickness);
    }
  }

  void segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, ImU32 colour,
               float thickness) const {
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k <= kLinePieces; ++k) points.push_back(from + (to - from) * k / kLinePieces);
    polyline(points, colour, thickness);
  }

  void great_circle(const Eigen::Vector3d& axis, ImU32 colour, float thickness) const {
    const Eigen::Vector3d n = axis.normalized();
    const Eigen::Vector3d u = n.unitOrthogonal();
    const Eigen::Vector3d v = n.cross(u);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k <= kCirclePoints; ++k) {
      const double phi = 2.0 * kPi * k / kCirclePoints;
      points.push_back(std::cos(phi) * u + std::sin(phi) * v);
    }
    polyline(points, colour, thickness);
  }

  // `text` beside p; `below` puts it under the point (so two labels at one point stay apart).
  void label(const Eigen::Vector3d& p, const char* text, ImU32 colour, bool below = false) const {
    const std::optional<ImVec2> q = at(p);
    if (!q || *text == '\0') return;
    const ImVec2 pos(q->x + 7, below ? q->y + 8 : q->y - 22);
    const ImVec2 size = ImGui::CalcTextSize(text);
    list->AddRectFilled(ImVec2(pos.x - 2, pos.y - 1), ImVec2(pos.x + size.x + 2, pos.y + size.y),
                        IM_COL32(20, 20, 24, 200), 3.0f);
    list->AddText(pos, colour, text);
  }
};

// The visibility report of the current analysis, when the layout has normals and it is current.
const visibility::VisibilityReport* current_visibility(const ViewerSession& session) {
  if (!session.analysis_current() || !session.analysis()->error.empty()) return nullptr;
  return session.analysis()->visibility ? &*session.analysis()->visibility : nullptr;
}

// The top of the colour scale: the certified worst-case error (with visibility for markers on a
// body), or the largest shaded value while the analysis runs.
double colour_range_deg(const ViewerSession& session) {
  if (const VisibilityShading* vis = session.visibility_shading()) {
    const visibility::VisibilityReport* report = current_visibility(session);
    if (report != nullptr &&
        report->worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
      return report->max_worst_case_error_deg;
    }
    double top = 0.0;
    for (std::size_t v = 0; v < vis->states.size(); ++v) {
      if (vis->states[v] == ViewpointState::kTrackable) {
        top = std::max(top, vis->error_deg(static_cast<Eigen::Index>(v)));
      }
    }
    return top;
  }
  if (session.analysis_current() && session.analysis()->error.empty()) {
    return kDegreesPerRadian *
           std::acos(std::clamp(session.analysis()->analysis.pbar_min, 0.0, 1.0));
  }
  return session.shading().error_deg.maxCoeff();
}

// A vertex's colour: its error on the scale, or grey where it cannot track the body.
plot::Rgb vertex_colour(const ViewerSession& session, Eigen::Index v, double top) {
  const VisibilityShading* vis = session.visibility_shading();
  if (vis == nullptr) return plot::value_colour(session.shading().error_deg(v), 0.0, top);
  switch (vis->states[static_cast<std::size_t>(v)]) {
    case ViewpointState::kTrackable:
      return plot::value_colour(vis->error_deg(v), 0.0, top);
    case ViewpointState::kLost:
      return kLostGrey;
    case ViewpointState::kOutsideWorkspace:
      break;
  }
  return kOutsideGrey;
}

void draw_sphere(const Painter& paint, const ViewerSession& session) {
  const SphereShading& s = session.shading();
  const double top = colour_range_deg(session);
  const Eigen::Vector3d eye = paint.camera.eye();
  const Eigen::Vector3d back = paint.camera.back();
  const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
  std::vector<ImU32> colours(s.vertices.cols());
  std::vector<std::optional<Eigen::Vector2d>> pixels(s.vertices.cols());
  for (Eigen::Index v = 0; v < s.vertices.cols(); ++v) {
    const double light = 0.82 + 0.18 * std::max(0.0, s.vertices.col(v).dot(back));
    colours[v] = shaded(vertex_colour(session, v, top), light);
    pixels[v] = paint.camera.project(s.vertices.col(v), paint.viewport);
  }
  // Every vertex once, indices only for the triangles facing the eye (a convex surface: they
  // never overlap, so no depth sorting is needed).
  std::vector<int> visible;
  for (std::size_t k = 0; k < s.triangles.size(); ++k) {
    const std::array<int, 3>& t = s.triangles[k];
    const Eigen::Vector3d c =
        (s.vertices.col(t[0]) + s.vertices.col(t[1]) + s.vertices.col(t[2])) / 3.0;
    if (c.dot(eye - c) > 0.0 && pixels[t[0]] && pixels[t[1]] && pixels[t[2]]) {
      visible.push_back(static_cast<int>(k));
    }
  }
  const int vertex_count = static_cast<int>(s.vertices.cols());
  paint.list->PrimReserve(static_cast<int>(3 * visible.size()), vertex_count);
  const ImDrawIdx first = static_cast<ImDrawIdx>(paint.list->_VtxCurrentIdx);
  for (int v = 0; v < vertex_count; ++v) {
    paint.list->PrimWriteVtx(pixels[v] ? to_im(*pixels[v]) : ImVec2(0, 0), uv, colours[v]);
  }
  for (const int k : visible) {
    for (const int v : s.triangles[k]) paint.list->PrimWriteIdx(static_cast<ImDrawIdx>(first + v));
  }
}

void draw_world_axes(const Painter& paint) {
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
    paint.segment(e, 1.25 * e, kAxisGrey, 1.5f);
    paint.label(1.28 * e, names[k], kAxisGrey);
  }
}

void draw_data_vectors(const Painter& paint, const ViewerSession& session) {
  const DataVectors& data = session.data();
  const bool points = session.layout().mode == LayoutMode::kPoints;
  const ImU32 dark = to_imgui(plot::kDataVectorColour);
  for (Eigen::Index i = 0; i < data.vectors.cols(); ++i) {
    const Eigen::Vector3d n = data.vectors.col(i).normalized();
    bool selected = !points && i == session.selected;
    if (points && session.selected >= 0) {
      selected =
          data.pairs[i].first == session.selected || data.pairs[i].second == session.selected;
    }
    if (points && !selected) {
      for (const double s : {1.0, -1.0}) {
        if (const std::optional<ImVec2> q = paint.at(s * n)) {
          paint.list->AddCircleFilled(*q, 3.5f, kHalo);
          paint.list->AddCircleFilled(*q, 2.5f, dark);
        }
      }
      continue;
    }
    const ImU32 colour = selected ? kSelectedColour : dark;
    paint.segment(Eigen::Vector3d::Zero(), kVectorLength * n, kHalo, 6.5f);
    paint.segment(Eigen::Vector3d::Zero(), kVectorLength * n, colour, 3.5f);
    if (const std::optional<ImVec2> q = paint.at(kVectorLength * n)) {
      paint.list->AddCircleFilled(*q, 5.0f, kHalo);
      paint.list->AddCircleFilled(*q, 4.0f, colour);
    }
    if (!points) paint.label(kVectorLength * n, session.layout().entry_name(i).c_str(), kHalo);
  }
}

void draw_viewpoint_axis(const Painter& paint, const Eigen::Vector3d& a, ImU32 colour, bool ring,
                         const char* text) {
  // ring: the paper's viewpoint, labelled below; filled: a worst viewpoint, labelled above.
  paint.segment(-kAxisLength * a, kAxisLength * a, colour, 2.5f);
  for (const double s : {1.0, -1.0}) {
    if (const std::optional<ImVec2> q = paint.at(s * a)) {
      if (ring) {
        paint.list->AddCircle(*q, 10.0f, colour, 0, 3.0f);
      } else {
        paint.list->AddCircleFilled(*q, 7.5f, colour);
        paint.list->AddCircle(*q, 8.0f, kHalo, 0, 1.0f);
      }
    }
  }
  paint.label(kAxisLength * a, text, colour, ring);
}

void draw_analysis(const Painter& paint, const ViewerSession& session) {
  if (!session.analysis() || !session.analysis()->error.empty()) return;
  const sdp::LayoutAnalysis& report = session.analysis()->analysis;
  const int alpha = session.analysis_current() ? 255 : 110;  // stale while recomputing
  const ImU32 red = to_imgui(plot::kWorstViewpointColour, alpha);
  const ImU32 magenta = to_imgui(plot::kPaperLmiColour, alpha);
  draw_viewpoint_axis(paint, report.paper_lmi.viewpoint, magenta, true, "paper LMI");
  const std::optional<visibility::VisibilityReport>& body = session.analysis()->visibility;
  if (!body) {
    for (std::size_t k = 0; k < report.worst_viewpoints.size(); ++k) {
      paint.great_circle(report.worst_viewpoints[k], red, 2.0f);
      draw_viewpoint_axis(paint, report.worst_viewpoints[k], red, false, k == 0 ? "worst" : "");
    }
    return;
  }
  // Markers on a body: the worst viewpoint is signed (a camera on that side of the body); the
  // viewpoints that are worst when every marker is seen are rings on both sides.
  for (std::size_t k = 0; k < report.worst_viewpoints.size(); ++k) {
    for (const double s : {1.0, -1.0}) {
      if (const std::optional<ImVec2> q = paint.at(s * report.worst_viewpoints[k])) {
        paint.list->AddCircle(*q, 9.0f, red, 0, 2.0f);
      }
    }
    if (k == 0) paint.label(report.worst_viewpoints[k], "worst seen whole", red, true);
  }
  if (body->worst.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) return;
  for (std::size_t k = 0; k < body->worst.viewpoints.size(); ++k) {
    const Eigen::Vector3d& a = body->worst.viewpoints[k];
    paint.segment(a, kAxisLength * a, red, 2.5f);
    if (const std::optional<ImVec2> q = paint.at(a)) {
      paint.list->AddCircleFilled(*q, 7.5f, red);
      paint.list->AddCircle(*q, 8.0f, kHalo, 0, 1.0f);
    }
    if (k == 0) paint.label(kAxisLength * a, "worst on the body", red);
  }
}

void draw_probe(const Painter& paint, const std::optional<Eigen::Vector3d>& hovered,
                const std::optional<Eigen::Vector3d>& pinned) {
  if (pinned) {
    if (const std::optional<ImVec2> q = paint.at(*pinned)) {
      paint.list->AddCircleFilled(*q, kHandleRadius - 3.0f, IM_COL32(20, 20, 24, 255));
      paint.list->AddCircle(*q, kHandleRadius - 3.0f, kProbeColour, 0, 2.5f);
    }
  }
  if (hovered) {
    if (const std::optional<ImVec2> q = paint.at(*hovered)) {
      paint.list->AddCircle(*q, 9.0f, kProbeColour, 0, 2.0f);
      paint.list->AddLine(ImVec2(q->x - 14, q->y), ImVec2(q->x - 5, q->y), kProbeColour, 1.5f);
      paint.list->AddLine(ImVec2(q->x + 5, q->y), ImVec2(q->x + 14, q->y), kProbeColour, 1.5f);
    }
  }
}

void draw_colour_bar(const ViewerSession& session, const Viewport& viewport) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const double top = colour_range_deg(session);
  const float x0 = static_cast<float>(viewport.x) + 20.0f;
  const float y1 = static_cast<float>(viewport.y + viewport.height) - 34.0f;
  const float width = 260.0f;
  const int steps = 64;
  for (int k = 0; k < steps; ++k) {
    const float a = x0 + width * k / steps;
    const float b = x0 + width * (k + 1) / steps;
    list->AddRectFilled(ImVec2(a, y1 - 14), ImVec2(b + 0.5f, y1),
                        to_imgui(plot::value_colour((k + 0.5) / steps)));
  }
  list->AddRect(ImVec2(x0, y1 - 14), ImVec2(x0 + width, y1), kAxisGrey);
  char text[160];
  if (session.visibility_shading() != nullptr) {
    // Markers on a body: the error with the visible markers; grey swatches for the lost
    // directions (and those outside the workspace).
    std::snprintf(
        text, sizeof text,
        "worst-case error with the visible markers, asin t(a):  0\u00b0 \u2026 %.2f\u00b0", top);
    const float gx = x0 + width + 16.0f;
    list->AddRectFilled(ImVec2(gx, y1 - 14), ImVec2(gx + 22, y1), to_imgui(kLostGrey));
    list->AddRect(ImVec2(gx, y1 - 14), ImVec2(gx + 22, y1), kAxisGrey);
    list->AddText(ImVec2(gx + 28, y1 - 16), kHalo, "lost (untrackable)");
    if (session.layout().workspace) {
      const float wx = gx + 34.0f + ImGui::CalcTextSize("lost (untrackable)").x;
      list->AddRectFilled(ImVec2(wx, y1 - 14), ImVec2(wx + 22, y1), to_imgui(kOutsideGrey));
      list->AddRect(ImVec2(wx, y1 - 14), ImVec2(wx + 22, y1), kAxisGrey);
      list->AddText(ImVec2(wx + 28, y1 - 16), kHalo, "outside the workspace");
    }
  } else {
    std::snprintf(text, sizeof text,
                  "worst-case error arccos p\u0304(a):  0\u00b0 \u2026 %.2f\u00b0", top);
  }
  list->AddText(ImVec2(x0, y1 - 34), kHalo, text);
  std::snprintf(text, sizeof text, "0\u00b0");
  list->AddText(ImVec2(x0, y1 + 2), kAxisGrey, text);
  std::snprintf(text, sizeof text, "%.1f\u00b0", top);
  list->AddText(ImVec2(x0 + width - ImGui::CalcTextSize(text).x, y1 + 2), kAxisGrey, text);
}

}  // namespace

std::optional<Eigen::Vector3d> SceneView::handle_mouse(ViewerSession& session,
                                                       const Viewport& viewport) {
  const ImGuiIO& io = ImGui::GetIO();
  const Eigen::Vector2d mouse(io.MousePos.x, io.MousePos.y);
  const bool inside = mouse.x() >= viewport.x && mouse.x() < viewport.x + viewport.width &&
                      mouse.y() >= viewport.y && mouse.y() < viewport.y + viewport.height;
  const bool free = !io.WantCaptureMouse && inside;
  std::optional<Eigen::Vector3d> hovered;
  if (free || drag_ != Drag::kNone) hovered = session.camera.pick_sphere(mouse, viewport);
  if (free && io.MouseWheel != 0.0f) session.camera.zoom(io.MouseWheel);

  if (free && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    press_ = io.MousePos;
    moved_ = false;
    drag_ = Drag::kOrbit;
    auto near = [&](const Eigen::Vector3d& p) {
      const std::optional<Eigen::Vector2d> q = session.camera.project(p, viewport);
      return q && !session.camera.hidden_by_sphere(p) && (*q - mouse).norm() < kHandleRadius;
    };
    if (session.pinned_viewpoint && near(*session.pinned_viewpoint)) drag_ = Drag::kProbe;
    if (session.layout().mode == LayoutMode::kVectors) {
      for (Eigen::Index i = 0; i < session.layout().entries.cols(); ++i) {
        if (near(kVectorLength * session.layout().entries.col(i).normalized())) {
          drag_ = Drag::kVector;
          drag_index_ = static_cast<int>(i);
          session.selected = drag_index_;
        }
      }
    }
  }
  if (drag_ != Drag::kNone && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const ImVec2 delta = io.MouseDelta;
    if (std::hypot(io.MousePos.x - press_.x, io.MousePos.y - press_.y) > kClickSlop) moved_ = true;
    if (drag_ == Drag::kOrbit && moved_) session.camera.orbit(delta.x, delta.y);
    if (drag_ == Drag::kProbe && hovered) session.pinned_viewpoint = *hovered;
    if (drag_ == Drag::kVector && moved_ && (delta.x != 0.0f || delta.y != 0.0f)) {
      // The tip follows the mouse on its own sphere (radius kVectorLength), which the unit
      // sphere's silhouette does not contain: picking the unit sphere would miss it.
      session.drag_vector_tip(drag_index_, mouse, viewport, kVectorLength, moved_continue_);
      moved_continue_ = true;
    }
  }
  if (drag_ != Drag::kNone && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (drag_ == Drag::kOrbit && !moved_ && hovered) session.pinned_viewpoint = *hovered;
    drag_ = Drag::kNone;
    moved_continue_ = false;
  }
  return hovered;
}

std::optional<Eigen::Vector3d> SceneView::draw(ViewerSession& session, const Viewport& viewport,
                                               bool interactive) {
  std::optional<Eigen::Vector3d> hovered;
  if (interactive) hovered = handle_mouse(session, viewport);
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  list->AddRectFilled(ImVec2(static_cast<float>(viewport.x), static_cast<float>(viewport.y)),
                      ImVec2(static_cast<float>(viewport.x + viewport.width),
                             static_cast<float>(viewport.y + viewport.height)),
                      kBackground);
  const Painter paint{list, session.camera, viewport};
  draw_sphere(paint, session);
  draw_world_axes(paint);
  draw_analysis(paint, session);
  draw_data_vectors(paint, session);
  const std::optional<Eigen::Vector3d> probe =
      drag_ == Drag::kOrbit && moved_ ? std::nullopt : hovered;
  draw_probe(paint, probe, session.pinned_viewpoint);
  if (probe) {
    draw_body_inset(session, session.camera, viewport, *probe, InsetViewpoint::kHovered);
  } else if (session.pinned_viewpoint) {
    draw_body_inset(session, session.camera, viewport, *session.pinned_viewpoint,
                    InsetViewpoint::kPinned);
  } else {
    draw_body_inset(session, session.camera, viewport, session.camera.back(),
                    InsetViewpoint::kCamera);
  }
  draw_colour_bar(session, viewport);
  return hovered;
}

}  // namespace vantage::viewer::app

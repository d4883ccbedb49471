#include "body_view.h"

#include <imgui.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "draw_style.h"

namespace vantage::viewer::app {
namespace {

constexpr float kPlainSide = 170.0f;        // pixels: the inset of a layout seen whole
constexpr float kBodySideFraction = 0.36f;  // of the 3-D view's smaller side: the body inset
constexpr float kBodySideMin = 200.0f;      // pixels
constexpr float kBodySideMax = 340.0f;      // pixels
constexpr float kLabelRoom = 26.0f;         // pixels right of the image for the markers' names
constexpr float kTitleHeight = 40.0f;       // pixels above the image
constexpr double kNormalLength = 0.12;      // of the scene's size: the normals drawn at the markers
constexpr double kCreaseCos = 0.999;        // faces meeting at a smaller angle share a drawn edge
constexpr int kMaxOutlinedTriangles = 20000;  // bigger meshes are drawn without their edges

// The image plane of a camera at a (body -> camera): right x up = a, up as near the orbit
// camera's as possible, so that the inset turns with the 3-D view.
void image_axes(const OrbitCamera& camera, const Eigen::Vector3d& a, Eigen::Vector3d* right,
                Eigen::Vector3d* up) {
  Eigen::Vector3d u = camera.up() - camera.up().dot(a) * a;
  if (u.norm() > 1e-6) {
    *up = u.normalized();
    *right = up->cross(a);
  } else {
    *right = (camera.right() - camera.right().dot(a) * a).normalized();
    *up = a.cross(*right);
  }
}

struct Inset {
  ImDrawList* list;
  ImVec2 lo;
  ImVec2 hi;
  Eigen::Vector3d right;
  Eigen::Vector3d up;
  Eigen::Vector2d centre;  // image coordinates drawn at `mid`
  ImVec2 mid;
  float scale = 1.0f;

  ImVec2 at(const Eigen::Vector3d& x) const {
    return ImVec2(mid.x + scale * static_cast<float>(x.dot(right) - centre.x()),
                  mid.y - scale * static_cast<float>(x.dot(up) - centre.y()));
  }
};

// The mesh, far faces first, translucent and lit by their facing the camera; then the edges
// where faces crease (a box shows its box edges, not its triangles' diagonals).
void draw_mesh(const Inset& inset, const Mesh& mesh, const Eigen::Vector3d& a) {
  const Eigen::Index count = mesh.triangles.cols();
  std::vector<double> depth(static_cast<std::size_t>(count));
  std::vector<Eigen::Vector3d> normal(static_cast<std::size_t>(count));
  for (Eigen::Index k = 0; k < count; ++k) {
    const Eigen::Vector3d p0 = mesh.vertices.col(mesh.triangles(0, k));
    const Eigen::Vector3d p1 = mesh.vertices.col(mesh.triangles(1, k));
    const Eigen::Vector3d p2 = mesh.vertices.col(mesh.triangles(2, k));
    depth[static_cast<std::size_t>(k)] = (p0 + p1 + p2).dot(a);
    const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    normal[static_cast<std::size_t>(k)] = n.norm() > 0.0 ? n.normalized() : n;
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Eigen::Index x, Eigen::Index y) {
    return depth[static_cast<std::size_t>(x)] < depth[static_cast<std::size_t>(y)];
  });
  for (const Eigen::Index k : order) {
    const double light = 0.45 + 0.55 * std::abs(normal[static_cast<std::size_t>(k)].dot(a));
    inset.list->AddTriangleFilled(inset.at(mesh.vertices.col(mesh.triangles(0, k))),
                                  inset.at(mesh.vertices.col(mesh.triangles(1, k))),
                                  inset.at(mesh.vertices.col(mesh.triangles(2, k))),
                                  with_light(kBodyColour, light, kBodyAlpha));
  }
  if (count > kMaxOutlinedTriangles) return;
  std::map<std::pair<int, int>, std::vector<Eigen::Index>> faces_of_edge;
  for (Eigen::Index k = 0; k < count; ++k) {
    for (int e = 0; e < 3; ++e) {
      const int v0 = mesh.triangles(e, k);
      const int v1 = mesh.triangles((e + 1) % 3, k);
      faces_of_edge[{std::min(v0, v1), std::max(v0, v1)}].push_back(k);
    }
  }
  for (const auto& [edge, faces] : faces_of_edge) {
    bool crease = faces.size() != 2;
    if (!crease) {
      crease = normal[static_cast<std::size_t>(faces[0])].dot(
                   normal[static_cast<std::size_t>(faces[1])]) < kCreaseCos;
    }
    if (crease) {
      inset.list->AddLine(inset.at(mesh.vertices.col(edge.first)),
                          inset.at(mesh.vertices.col(edge.second)), kBodyEdge, 1.0f);
    }
  }
}

void draw_arrow(ImDrawList* list, const ImVec2& from, const ImVec2& to, ImU32 colour) {
  list->AddLine(from, to, colour, 1.5f);
  const float dx = to.x - from.x;
  const float dy = to.y - from.y;
  const float length = std::hypot(dx, dy);
  if (length < 6.0f) return;  // seen end on: a short stub, no head
  const float ux = dx / length;
  const float uy = dy / length;
  const float head = 5.0f;
  list->AddTriangleFilled(
      to, ImVec2(to.x - head * ux - 0.6f * head * uy, to.y - head * uy + 0.6f * head * ux),
      ImVec2(to.x - head * ux + 0.6f * head * uy, to.y - head * uy - 0.6f * head * ux), colour);
}

// The inset of markers on a body: large enough to read the markers' names around a body (it
// may cover the sphere's rim; orbiting brings any viewpoint out from under it).
float body_inset_side(const Viewport& viewport) {
  return std::clamp(
      kBodySideFraction * static_cast<float>(std::min(viewport.width, viewport.height)),
      kBodySideMin, kBodySideMax);
}

const char* inset_title(InsetViewpoint which) {
  switch (which) {
    case InsetViewpoint::kHovered:
      return "seen from a under the mouse";
    case InsetViewpoint::kPinned:
      return "seen from the pinned a";
    case InsetViewpoint::kCamera:
      break;
  }
  return "seen from this view";
}

void draw_title(const Inset& inset, const ViewerSession& session,
                const std::optional<VisibilityReadout>& seen, InsetViewpoint which) {
  char text[160];
  if (!seen) {
    inset.list->AddText(ImVec2(inset.lo.x + 6, inset.lo.y + 4), kAxisGrey, "image from this view");
    return;
  }
  inset.list->AddText(ImVec2(inset.lo.x + 6, inset.lo.y + 4), kAxisGrey, inset_title(which));
  const int markers = static_cast<int>(session.layout().entries.cols());
  const int visible = static_cast<int>(seen->visible.size());
  ImU32 colour = kHalo;
  if (seen->state == ViewpointState::kTrackable) {
    std::snprintf(text, sizeof text, "%d of %d markers seen", visible, markers);
  } else if (seen->state == ViewpointState::kLost) {
    std::snprintf(text, sizeof text, "%d of %d seen: LOST (needs %d)", visible, markers,
                  session.layout().visibility->min_visible);
    colour = kWarningText;
  } else {
    std::snprintf(text, sizeof text, "%d of %d seen: outside workspace", visible, markers);
    colour = kWarningText;
  }
  inset.list->AddText(ImVec2(inset.lo.x + 6, inset.lo.y + 21), colour, text);
}

// The markers with their normals: hidden ones grey and first, visible ones over them.
void draw_markers(const Inset& inset, const ViewerSession& session, const VisibilityReadout& seen,
                  const Mesh* mesh) {
  const Layout& layout = session.layout();
  const double size = mesh != nullptr ? mesh->size()
                                      : Eigen::Vector3d(layout.entries.rowwise().maxCoeff() -
                                                        layout.entries.rowwise().minCoeff())
                                            .norm();
  const Eigen::Matrix3Xd& normals = layout.visibility->normals;
  // Hidden markers first, so that the visible ones are drawn over them.
  for (const bool visible_pass : {false, true}) {
    const std::vector<int>& group = visible_pass ? seen.visible : seen.hidden;
    for (const int i : group) {
      const Eigen::Vector3d p = layout.entries.col(i);
      const ImVec2 q = inset.at(p);
      const bool selected = i == session.selected;
      draw_arrow(inset.list, q, inset.at(p + kNormalLength * size * normals.col(i)),
                 visible_pass ? kNormalColour : kHiddenNormal);
      const ImU32 fill = selected ? kSelectedColour : visible_pass ? kHalo : kHiddenMarker;
      inset.list->AddCircleFilled(q, visible_pass ? 5.5f : 4.5f, IM_COL32(20, 20, 24, 255));
      inset.list->AddCircleFilled(q, visible_pass ? 4.5f : 3.5f, fill);
      inset.list->AddText(ImVec2(q.x + 6, q.y - 7), visible_pass ? kHalo : kHiddenMarker,
                          layout.entry_name(i).c_str());
    }
  }
}

}  // namespace

void draw_body_inset(const ViewerSession& session, const OrbitCamera& camera,
                     const Viewport& viewport, const Eigen::Vector3d& a, InsetViewpoint which) {
  const Layout& layout = session.layout();
  const bool points = layout.mode == LayoutMode::kPoints;
  const visibility::VisibilityModel* model = session.visibility();
  std::optional<VisibilityReadout> seen;
  if (model != nullptr) seen = read_visibility(*model, a);
  const Mesh* mesh =
      layout.visibility && layout.visibility->body ? &*layout.visibility->body : nullptr;

  Inset inset;
  inset.list = ImGui::GetBackgroundDrawList();
  const float side = seen ? body_inset_side(viewport) : kPlainSide;
  inset.lo = ImVec2(static_cast<float>(viewport.x + viewport.width) - side - 14.0f,
                    static_cast<float>(viewport.y) + 14.0f);
  inset.hi = ImVec2(inset.lo.x + side, inset.lo.y + side + (seen ? kTitleHeight - 20.0f : 0.0f));
  inset.list->AddRectFilled(inset.lo, inset.hi, IM_COL32(12, 12, 16, 250), 4.0f);
  inset.list->AddRect(inset.lo, inset.hi, kAxisGrey, 4.0f);
  draw_title(inset, session, seen, which);
  if (seen) {
    image_axes(camera, seen->viewpoint, &inset.right, &inset.up);
  } else {
    inset.right = camera.right();
    inset.up = camera.up();
  }

  // Fit the markers (and the body) in the image area below the title.
  const Eigen::Vector3d origin =
      points ? Eigen::Vector3d(layout.entries.rowwise().mean()) : Eigen::Vector3d::Zero();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY);
  Eigen::Vector2d high = -low;
  auto extend = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector2d q(x.dot(inset.right), x.dot(inset.up));
    low = low.cwiseMin(q);
    high = high.cwiseMax(q);
  };
  extend(origin);
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) extend(layout.entries.col(i));
  if (mesh != nullptr) {
    for (Eigen::Index v = 0; v < mesh->vertices.cols(); ++v) extend(mesh->vertices.col(v));
  }
  if (points) {
    inset.centre = 0.5 * (low + high);
  } else {
    inset.centre = Eigen::Vector2d(origin.dot(inset.right), origin.dot(inset.up));
    high = high.cwiseMax(2.0 * inset.centre - low);
    low = 2.0 * inset.centre - high;
  }
  const float top = inset.lo.y + (seen ? kTitleHeight : 20.0f);
  const float image_width = inset.hi.x - inset.lo.x - 24.0f - (seen ? kLabelRoom : 0.0f);
  const float image_height = inset.hi.y - top - 14.0f;
  const Eigen::Vector2d span = (high - low).cwiseMax(1e-12);
  inset.scale = std::min(image_width / static_cast<float>(span.x()),
                         image_height / static_cast<float>(span.y()));
  if (!seen) inset.scale *= 0.8f;  // room for the names, as before
  inset.mid = ImVec2(0.5f * (inset.lo.x + inset.hi.x - (seen ? kLabelRoom : 0.0f)),
                     0.5f * (top + inset.hi.y - 6.0f));

  inset.list->PushClipRect(inset.lo, inset.hi, true);
  if (mesh != nullptr) draw_mesh(inset, *mesh, seen->viewpoint);
  if (!seen) {
    for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
      const ImU32 colour = i == session.selected ? kSelectedColour : kHalo;
      const ImVec2 q = inset.at(layout.entries.col(i));
      if (!points) inset.list->AddLine(inset.at(origin), q, colour, 2.0f);
      inset.list->AddCircleFilled(q, 3.5f, colour);
      inset.list->AddText(ImVec2(q.x + 4, q.y - 2), colour, layout.entry_name(i).c_str());
    }
    inset.list->PopClipRect();
    return;
  }
  draw_markers(inset, session, *seen, mesh);
  inset.list->PopClipRect();
}

}  // namespace vantage::viewer::app

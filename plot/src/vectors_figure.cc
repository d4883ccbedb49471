#include "vantage/plot/vectors_figure.h"

#include <algorithm>
#include <cmath>

#include "body_drawing.h"
#include "canvas.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

constexpr double kRadiansPerDegree = 1.0 / kDegreesPerRadian;
// Scene: entries scaled into the unit ball; the a-perp disc and the axes reach a bit further.
constexpr double kDiscRadius = 1.2;
constexpr double kAxisLength = 1.45;
constexpr double kWindow = 1.6;
constexpr int kDiscPoints = 121;
// Point layouts with more markers than this show the markers only (no free-vector lines).
constexpr Eigen::Index kMaxPairLines = 40;
// A marker's normal arrow, in the scene's units (the markers fill the unit ball), and its head.
constexpr double kNormalLength = 0.16;
constexpr double kArrowHead = 0.045;
constexpr double kArrowHeadDeg = 28.0;

Eigen::Vector3d camera_direction() {
  const double az = kVectorsAzimuthDeg * kRadiansPerDegree,
               el = kVectorsElevationDeg * kRadiansPerDegree;
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

void check_data(const VectorsFigureData& data) {
  if (data.entries.cols() == 0) throw InvalidArgument("write_vectors_figure: entries is empty");
  if (!data.entries.allFinite()) throw InvalidArgument("write_vectors_figure: entries not finite");
  if (data.worst_viewpoints.empty()) {
    throw InvalidArgument("write_vectors_figure: worst_viewpoints is empty");
  }
  if (data.names.size() != static_cast<std::size_t>(data.entries.cols())) {
    throw InvalidArgument("write_vectors_figure: names needs one per entry");
  }
  if (data.normals.cols() > 0 &&
      (data.mode != LayoutMode::kPoints || data.normals.cols() != data.entries.cols() ||
       !data.normals.allFinite())) {
    throw InvalidArgument("write_vectors_figure: normals must be finite, one per marker");
  }
  if (data.body != nullptr) data.body->validate();
}

// The map into the scene: unit-ball scaled (directions by their length relative to the longest,
// points about their centroid).
struct SceneFrame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0;
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return (p - centre) * scale; }
};

SceneFrame scene_frame(const VectorsFigureData& data) {
  SceneFrame frame;
  if (data.mode == LayoutMode::kPoints) frame.centre = data.entries.rowwise().mean();
  const double radius = (data.entries.colwise() - frame.centre).colwise().norm().maxCoeff();
  if (radius > 0.0) frame.scale = 1.0 / radius;
  return frame;
}

Eigen::Matrix3Xd scene_entries(const VectorsFigureData& data, const SceneFrame& frame) {
  Eigen::Matrix3Xd scene(3, data.entries.cols());
  for (Eigen::Index k = 0; k < scene.cols(); ++k) scene.col(k) = frame(data.entries.col(k));
  return scene;
}

bool on_body(const VectorsFigureData& data) {
  return data.mode == LayoutMode::kPoints && data.normals.cols() > 0;
}

void write_csv(const VectorsFigureData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "series,index,x,y,z,name");
  const bool points = data.mode == LayoutMode::kPoints;
  for (Eigen::Index k = 0; k < data.entries.cols(); ++k) {
    csv << (points ? "point" : "vector") << static_cast<long>(k) << data.entries(0, k)
        << data.entries(1, k) << data.entries(2, k) << data.names[static_cast<std::size_t>(k)];
    csv.end_row();
  }
  long k = 0;
  for (const Eigen::Vector3d& a : data.worst_viewpoints) {
    csv << "worst_viewpoint" << k++ << a.x() << a.y() << a.z() << "";
    csv.end_row();
  }
  const Eigen::Vector3d& lmi = data.paper_lmi_viewpoint;
  csv << "paper_lmi" << 0 << lmi.x() << lmi.y() << lmi.z() << "";
  csv.end_row();
  for (Eigen::Index k = 0; k < data.normals.cols(); ++k) {
    csv << "normal" << static_cast<long>(k) << data.normals(0, k) << data.normals(1, k)
        << data.normals(2, k) << data.names[static_cast<std::size_t>(k)];
    csv.end_row();
  }
  if (data.body_worst_viewpoint) {
    const Eigen::Vector3d& a = *data.body_worst_viewpoint;
    csv << "body_worst_viewpoint" << 0 << a.x() << a.y() << a.z() << "";
    csv.end_row();
  }
  csv.commit();
}

void line3(Canvas& canvas, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector2d a = vectors_camera_projection(from), b = vectors_camera_projection(to);
  canvas.pls().join(a.x(), a.y(), b.x(), b.y());
}

void draw_plane_disc(Canvas& canvas, const Eigen::Vector3d& a) {
  Eigen::Vector3d u = a.unitOrthogonal();
  const Eigen::Vector3d v = a.cross(u).normalized();
  std::vector<double> x(kDiscPoints), y(kDiscPoints);
  for (int k = 0; k < kDiscPoints; ++k) {
    const double phi = 2.0 * kPi * k / (kDiscPoints - 1);
    const Eigen::Vector2d p =
        vectors_camera_projection(kDiscRadius * (std::cos(phi) * u + std::sin(phi) * v));
    x[k] = p.x();
    y[k] = p.y();
  }
  canvas.fill_polygon(x, y, {66, 146, 198}, 0.22);
  canvas.pls().col0(internal::kPenPlane);
  canvas.pls().width(1.0 * internal::page_scale(canvas));
  canvas.pls().line(kDiscPoints, x.data(), y.data());
}

void draw_frame_axes(Canvas& canvas) {
  const double s = internal::page_scale(canvas);
  const char* names[3] = {"x", "y", "z"};
  canvas.pls().col0(internal::kPenGrid);
  canvas.pls().width(1.0 * s);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k) * 1.25;
    canvas.pls().lsty(3);
    line3(canvas, -axis, axis);
    canvas.pls().lsty(1);
    const Eigen::Vector2d tip = vectors_camera_projection(axis);
    canvas.label(tip.x(), tip.y(), std::string("+") + names[k], 0.0, 0.0, 0.5,
                 internal::kSmallSize * s, {120, 120, 120});
  }
}

// False for a marker the worst viewpoint on the body does not see (drawn hollow).
bool seen_from_body_worst(const VectorsFigureData& data, Eigen::Index k) {
  if (!data.body_worst_viewpoint) return true;
  const auto& v = data.body_visible_markers;
  return std::find(v.begin(), v.end(), static_cast<int>(k)) != v.end();
}

// Each marker's outward normal as a short arrow from the marker.
void draw_normals(Canvas& canvas, const VectorsFigureData& data, const Eigen::Matrix3Xd& scene) {
  const double s = internal::page_scale(canvas);
  const double head = kArrowHeadDeg / kDegreesPerRadian;
  canvas.pls().col0(internal::kPenNormal);
  canvas.pls().width(1.8 * s);
  for (Eigen::Index k = 0; k < data.normals.cols(); ++k) {
    const Eigen::Vector3d n = data.normals.col(k).normalized();
    const Eigen::Vector2d a = vectors_camera_projection(scene.col(k));
    const Eigen::Vector2d b = vectors_camera_projection(scene.col(k) + kNormalLength * n);
    canvas.pls().join(a.x(), a.y(), b.x(), b.y());
    const Eigen::Vector2d along = b - a;
    const double length = along.norm();
    // A normal along the line of sight has no visible shaft: its tip is a dot.
    if (length < 0.2 * kArrowHead) {
      canvas.marker(b.x(), b.y(), 2.0 * s, kNormalColour);
      continue;
    }
    const Eigen::Vector2d back = -along / length * std::min(kArrowHead, 0.6 * length);
    for (const double turn : {head, -head}) {
      const Eigen::Vector2d wing(std::cos(turn) * back.x() - std::sin(turn) * back.y(),
                                 std::sin(turn) * back.x() + std::cos(turn) * back.y());
      canvas.pls().join(b.x(), b.y(), b.x() + wing.x(), b.y() + wing.y());
    }
  }
}

// The worst viewpoint on the body: an arrow from the centre towards the camera.
void draw_body_worst(Canvas& canvas, const VectorsFigureData& data) {
  if (!data.body_worst_viewpoint) return;
  const double s = internal::page_scale(canvas);
  const Eigen::Vector3d a = data.body_worst_viewpoint->normalized();
  canvas.pls().col0(internal::kPenBodyWorst);
  canvas.pls().width(3.0 * s);
  line3(canvas, Eigen::Vector3d::Zero(), kAxisLength * a);
  const Eigen::Vector2d tip = vectors_camera_projection(kAxisLength * a);
  canvas.marker(tip.x(), tip.y(), 6.0 * s, kBodyWorstViewpointColour);
  canvas.label(tip.x(), tip.y(),
               "a on the body, " + internal::fixed(data.body_max_error_deg, 2) + "°", 12 * s,
               14 * s, 0.0, internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.85);
}

void draw_entries(Canvas& canvas, const VectorsFigureData& data, const Eigen::Matrix3Xd& scene) {
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  const Rgb ink = kDataVectorColour;
  const Eigen::Vector3d view = camera_direction();
  if (data.mode == LayoutMode::kVectors) {
    pls.col0(internal::kPenVector);
    pls.width(2.2 * s);
    for (Eigen::Index k = 0; k < scene.cols(); ++k) {
      line3(canvas, Eigen::Vector3d::Zero(), scene.col(k));
      const Eigen::Vector2d tip = vectors_camera_projection(scene.col(k));
      canvas.marker(tip.x(), tip.y(), 3.5 * s, ink);
      canvas.label(tip.x(), tip.y(), internal::page_label(data.names[static_cast<std::size_t>(k)]),
                   9 * s, -9 * s, 0.0, internal::kSmallSize * s, ink, {255, 255, 255}, 0.7);
    }
    return;
  }
  if (scene.cols() <= kMaxPairLines) {
    pls.col0(internal::kPenGreatCircle);
    pls.width(0.6 * s);
    for (Eigen::Index i = 0; i < scene.cols(); ++i) {
      for (Eigen::Index j = i + 1; j < scene.cols(); ++j) line3(canvas, scene.col(i), scene.col(j));
    }
  }
  // Far markers first, so that near ones are drawn over them.
  std::vector<Eigen::Index> order(scene.cols());
  for (Eigen::Index k = 0; k < scene.cols(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return scene.col(a).dot(view) < scene.col(b).dot(view);
  });
  for (Eigen::Index k : order) {
    const Eigen::Vector2d p = vectors_camera_projection(scene.col(k));
    canvas.marker(p.x(), p.y(), 5.0 * s, seen_from_body_worst(data, k) ? ink : Rgb{255, 255, 255});
  }
  for (Eigen::Index k : order) {
    const Eigen::Vector2d p = vectors_camera_projection(scene.col(k));
    canvas.label(p.x(), p.y(), internal::page_label(data.names[static_cast<std::size_t>(k)]), 8 * s,
                 -9 * s, 0.0, internal::kSmallSize * s, ink);
  }
}

void draw_viewpoint_axis(Canvas& canvas, const Eigen::Vector3d& a, Rgb colour, int pen,
                         double width, bool dashed, Canvas::Shape shape) {
  const double s = internal::page_scale(canvas);
  canvas.pls().col0(pen);
  canvas.pls().width(width * s);
  canvas.pls().lsty(dashed ? 2 : 1);
  line3(canvas, -kAxisLength * a, kAxisLength * a);
  canvas.pls().lsty(1);
  const Eigen::Vector2d tip = vectors_camera_projection(kAxisLength * a);
  const Eigen::Vector2d tail = vectors_camera_projection(-kAxisLength * a);
  canvas.marker(tip.x(), tip.y(), 6.0 * s, colour, shape);
  canvas.marker(tail.x(), tail.y(), 4.0 * s, colour, shape);
}

void draw_scene(Canvas& canvas, const VectorsFigureData& data, const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  internal::draw_title(
      canvas,
      internal::figure_title(options, "Data vectors: " + internal::layout_label(data.layout_name)),
      "orthographic view from azimuth " + fixed(kVectorsAzimuthDeg, 0) + "°, elevation " +
          fixed(kVectorsElevationDeg, 0) + "° (object frame, +z up); " +
          (data.mode == LayoutMode::kPoints ? "markers about their centroid"
                                            : "vectors scaled to the longest"));
  plstream& pls = canvas.pls();
  pls.vpas(0.02, 0.70, 0.03, 0.87, 1.0);
  pls.wind(-kWindow, kWindow, -kWindow, kWindow);
  const SceneFrame frame = scene_frame(data);
  const Eigen::Matrix3Xd scene = scene_entries(data, frame);

  draw_frame_axes(canvas);
  if (data.body != nullptr && data.mode == LayoutMode::kPoints) {
    internal::draw_body(canvas, *data.body, frame, vectors_camera_projection, camera_direction());
  }
  draw_plane_disc(canvas, data.worst_viewpoints.front());
  if (on_body(data)) draw_normals(canvas, data, scene);
  draw_entries(canvas, data, scene);
  draw_viewpoint_axis(canvas, data.paper_lmi_viewpoint, kPaperLmiColour, internal::kPenPaperLmi,
                      1.8, true, Canvas::Shape::kDiamond);
  for (std::size_t k = 0; k < data.worst_viewpoints.size(); ++k) {
    draw_viewpoint_axis(canvas, data.worst_viewpoints[k], kWorstViewpointColour,
                        internal::kPenWorst, k == 0 ? 3.0 : 1.6, false, Canvas::Shape::kCircle);
  }
  draw_body_worst(canvas, data);
  const Eigen::Vector2d tip = vectors_camera_projection(kAxisLength * data.worst_viewpoints[0]);
  canvas.label(tip.x(), tip.y(), "a (worst), p̄_min " + fixed(data.pbar_min, 4), 12 * s, 0.0, 0.0,
               internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.85);

  using Entry = Canvas::LegendEntry;
  const std::size_t ties = data.worst_viewpoints.size();
  std::vector<Entry> legend{
      Entry::line(
          ties == 1 ? "global worst viewpoint a" : std::to_string(ties) + " tied worst viewpoints",
          kWorstViewpointColour, 3.0 * s),
      Entry::text_only(
          "p̄_min " + fixed(data.pbar_min, 4) + ", error " +
          fixed(std::acos(std::clamp(data.pbar_min, 0.0, 1.0)) * kDegreesPerRadian, 2) + "°"),
      Entry::marker("plane a⊥ (first worst viewpoint)", {170, 205, 230}, Canvas::Shape::kSquare),
      Entry::line("paper's single LMI: p̄ " + fixed(data.paper_lmi_pbar, 4), kPaperLmiColour,
                  1.8 * s, true),
      Entry::marker(data.mode == LayoutMode::kPoints
                        ? std::to_string(data.entries.cols()) + " markers" +
                              (scene.cols() <= kMaxPairLines ? ", free vectors in grey" : "")
                        : std::to_string(data.entries.cols()) + " data vectors",
                    kDataVectorColour)};
  if (on_body(data)) {
    legend.push_back(Entry::line("outward normals of the markers", kNormalColour, 1.8 * s));
  }
  if (data.body != nullptr && data.mode == LayoutMode::kPoints) {
    legend.push_back(
        Entry::marker("body mesh (" + std::to_string(data.body->triangles.cols()) + " triangles)",
                      {200, 204, 208}, Canvas::Shape::kSquare));
  }
  if (data.body_worst_viewpoint) {
    legend.push_back(Entry::line("worst viewpoint on the body (toward the camera)",
                                 kBodyWorstViewpointColour, 3.0 * s));
    legend.push_back(Entry::marker("hollow: markers it does not see", {255, 255, 255}));
  }
  const double height = canvas.legend_size(legend, internal::kSmallSize * s).y();
  canvas.legend(0.985, std::max(0.22, 0.02 + height), legend, internal::kSmallSize * s, 1.0);
}

}  // namespace

Eigen::Vector2d vectors_camera_projection(const Eigen::Vector3d& p) {
  const double az = kVectorsAzimuthDeg * kRadiansPerDegree,
               el = kVectorsElevationDeg * kRadiansPerDegree;
  const Eigen::Vector3d right(-std::sin(az), std::cos(az), 0.0);
  const Eigen::Vector3d up(-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az),
                           std::cos(el));
  return {p.dot(right), p.dot(up)};
}

FigureFiles write_vectors_figure(const VectorsFigureData& data,
                                 const std::filesystem::path& directory,
                                 const FigureOptions& options) {
  check_data(data);
  const FigureFiles files = figure_files("vectors", directory, options.format);
  Canvas canvas(files.image, options);
  draw_scene(canvas, data, options);
  canvas.finish();
  write_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot

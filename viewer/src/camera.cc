#include "vantage/viewer/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::viewer {
namespace {

// A point of the sphere counts as visible when the ray meets the sphere no nearer than this
// before it (world units): surface points facing the eye are not hidden by themselves.
constexpr double kSurfaceSlack = 1e-6;

struct PresetName {
  ViewPreset preset;
  const char* name;
};
constexpr PresetName kPresetNames[] = {
    {ViewPreset::kIso, "iso"}, {ViewPreset::kWorst, "worst"}, {ViewPreset::kPaper, "paper"},
    {ViewPreset::kTop, "top"}, {ViewPreset::kFront, "front"}, {ViewPreset::kSide, "side"},
};

}  // namespace

const char* to_string(ViewPreset preset) {
  for (const PresetName& p : kPresetNames) {
    if (p.preset == preset) return p.name;
  }
  return "iso";
}

std::optional<ViewPreset> parse_view_preset(std::string_view name) {
  for (const PresetName& p : kPresetNames) {
    if (name == p.name) return p.preset;
  }
  return std::nullopt;
}

std::string view_preset_names() {
  std::string names;
  for (const PresetName& p : kPresetNames) {
    if (!names.empty()) names += "|";
    names += p.name;
  }
  return names;
}

Viewport scene_viewport(int width, int height) {
  const double column = std::min(kPanelColumnWidth, 0.45 * width);
  return {0.0, 0.0, width - column, static_cast<double>(height)};
}

void OrbitCamera::orbit(double dx_pixels, double dy_pixels) {
  yaw_deg_ = std::remainder(yaw_deg_ - kOrbitDegPerPixel * dx_pixels, 360.0);
  pitch_deg_ = std::clamp(pitch_deg_ + kOrbitDegPerPixel * dy_pixels, -90.0, 90.0);
}

void OrbitCamera::zoom(double steps) {
  distance_ = std::clamp(distance_ * std::pow(kZoomPerStep, steps), kMinDistance, kMaxDistance);
}

void OrbitCamera::reset() { *this = OrbitCamera(); }

void OrbitCamera::look_along(const Eigen::Vector3d& direction) {
  const double norm = direction.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    throw InvalidArgument("look_along: direction must be non-zero and finite");
  }
  const Eigen::Vector3d d = direction / norm;
  pitch_deg_ = kDegreesPerRadian * std::asin(std::clamp(d.z(), -1.0, 1.0));
  if (std::hypot(d.x(), d.y()) > 1e-12) yaw_deg_ = kDegreesPerRadian * std::atan2(d.y(), d.x());
}

Eigen::Vector3d OrbitCamera::back() const {
  const double yaw = yaw_deg_ / kDegreesPerRadian;
  const double pitch = pitch_deg_ / kDegreesPerRadian;
  return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}

Eigen::Vector3d OrbitCamera::right() const {
  const double yaw = yaw_deg_ / kDegreesPerRadian;
  return {-std::sin(yaw), std::cos(yaw), 0.0};
}

Eigen::Vector3d OrbitCamera::up() const { return back().cross(right()); }

double OrbitCamera::focal_pixels(const Viewport& viewport) const {
  return 0.5 * viewport.height / std::tan(0.5 * kFieldOfViewDeg / kDegreesPerRadian);
}

std::optional<Eigen::Vector2d> OrbitCamera::project(const Eigen::Vector3d& point,
                                                    const Viewport& viewport) const {
  const Eigen::Vector3d rel = point - eye();
  const double depth = -rel.dot(back());
  if (!(depth > 1e-9)) return std::nullopt;
  const double f = focal_pixels(viewport);
  return Eigen::Vector2d(viewport.x + 0.5 * viewport.width + f * rel.dot(right()) / depth,
                         viewport.y + 0.5 * viewport.height - f * rel.dot(up()) / depth);
}

Eigen::Vector3d OrbitCamera::ray_direction(const Eigen::Vector2d& pixel,
                                           const Viewport& viewport) const {
  const double f = focal_pixels(viewport);
  const double u = (pixel.x() - viewport.x - 0.5 * viewport.width) / f;
  const double v = -(pixel.y() - viewport.y - 0.5 * viewport.height) / f;
  return (u * right() + v * up() - back()).normalized();
}

std::optional<Eigen::Vector3d> OrbitCamera::pick_sphere(const Eigen::Vector2d& pixel,
                                                        const Viewport& viewport) const {
  const Eigen::Vector3d o = eye();
  const Eigen::Vector3d d = ray_direction(pixel, viewport);
  const double b = o.dot(d);
  const double disc = b * b - (o.squaredNorm() - 1.0);
  if (disc < 0.0) return std::nullopt;
  const double t = -b - std::sqrt(disc);
  if (t <= 0.0) return std::nullopt;
  return (o + t * d).normalized();
}

Eigen::Vector3d OrbitCamera::pick_direction(const Eigen::Vector2d& pixel, const Viewport& viewport,
                                            double radius, const Eigen::Vector3d& near) const {
  const Eigen::Vector3d o = eye();
  const Eigen::Vector3d d = ray_direction(pixel, viewport);
  const double b = o.dot(d);
  const double disc = b * b - (o.squaredNorm() - radius * radius);
  if (disc < 0.0) return (o - b * d).normalized();
  const double root = std::sqrt(disc);
  const Eigen::Vector3d front = o + (-b - root) * d;
  const Eigen::Vector3d back = o + (-b + root) * d;
  return ((front - near).squaredNorm() <= (back - near).squaredNorm() ? front : back).normalized();
}

bool OrbitCamera::hidden_by_sphere(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d o = eye();
  const Eigen::Vector3d rel = point - o;
  const double dist = rel.norm();
  if (!(dist > 0.0)) return false;
  const Eigen::Vector3d d = rel / dist;
  const double b = o.dot(d);
  const double disc = b * b - (o.squaredNorm() - 1.0);
  if (disc < 0.0) return false;
  const double t = -b - std::sqrt(disc);
  return t > 0.0 && t < dist - kSurfaceSlack;
}

}  // namespace vantage::viewer

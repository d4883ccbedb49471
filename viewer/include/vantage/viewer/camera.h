#pragma once

/// The orbit camera of vantage-viewer's 3-D view, kept apart from drawing so that projections can
/// be tested (and a screenshot checked) without a window.
///
/// World frame = the layout's object frame. The camera orbits the origin at `distance` on the
/// unit direction back() = (cos pitch cos yaw, cos pitch sin yaw, sin pitch) and looks at the
/// origin, i.e. along -back(). Its frame: x_camera = right(), y_camera = up(), z_camera = back()
/// (right-handed), so a point maps to camera coordinates as x_camera = R * (x_world - eye())
/// with the rows of R = [right; up; back]. A viewing direction a (the paper's viewpoint, the
/// third row of R_camera_object) and -a are the same viewpoint; look_along(a) puts the eye on +a.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

namespace vantage::viewer {

/// A pixel rectangle, origin at its top-left corner, y down (screen convention).
struct Viewport {
  double x = 0.0;
  double y = 0.0;
  double width = 1.0;   ///< pixels, > 0
  double height = 1.0;  ///< pixels, > 0
};

/// Named starting views of `--view` and of the view buttons.
enum class ViewPreset {
  kIso,    ///< oblique default: yaw 35 deg, pitch 25 deg
  kWorst,  ///< along the (first) global worst viewpoint; on the body's side for markers on a body
  kPaper,  ///< along the paper's single-LMI viewpoint
  kTop,    ///< along +z
  kFront,  ///< along +x
  kSide,   ///< along +y
};

/// "iso", "worst", "paper", "top", "front" or "side".
const char* to_string(ViewPreset preset);

/// The preset called `name` (as printed by to_string), or nullopt.
std::optional<ViewPreset> parse_view_preset(std::string_view name);

/// "iso|worst|paper|top|front|side", for help texts.
std::string view_preset_names();

/// Width of vantage-viewer's panel column, pixels (at most 45% of the window).
inline constexpr double kPanelColumnWidth = 450.0;

/// The 3-D view's viewport in a window of width x height pixels: the left part, beside the panel
/// column. Screenshot tests use it to know where a world point is drawn.
Viewport scene_viewport(int width, int height);

/// Perspective orbit camera around the origin.
class OrbitCamera {
 public:
  static constexpr double kDefaultYawDeg = 35.0;
  static constexpr double kDefaultPitchDeg = 25.0;
  static constexpr double kDefaultDistance = 5.0;  ///< world units (the sphere has radius 1)
  static constexpr double kMinDistance = 1.8;
  static constexpr double kMaxDistance = 12.0;
  static constexpr double kFieldOfViewDeg = 34.0;    ///< vertical
  static constexpr double kOrbitDegPerPixel = 0.35;  ///< drag sensitivity
  static constexpr double kZoomPerStep = 0.9;        ///< distance factor per wheel step

  /// Rotates the view: dx pixels to the right turns the world right (yaw), dy pixels down tilts it
  /// down (pitch, clamped to [-90, 90] deg).
  void orbit(double dx_pixels, double dy_pixels);
  /// Moves the eye toward the origin by kZoomPerStep per positive step, within
  /// [kMinDistance, kMaxDistance].
  void zoom(double steps);
  /// Back to the iso view at the default distance.
  void reset();
  /// Puts the eye on the axis `direction` (non-zero, finite; any length), keeping the distance.
  void look_along(const Eigen::Vector3d& direction);

  double yaw_deg() const { return yaw_deg_; }
  double pitch_deg() const { return pitch_deg_; }
  double distance() const { return distance_; }

  Eigen::Vector3d back() const;   ///< unit vector from the origin to the eye
  Eigen::Vector3d right() const;  ///< unit, horizontal (z = 0)
  Eigen::Vector3d up() const;     ///< unit, back x right
  Eigen::Vector3d eye() const { return distance_ * back(); }

  /// Pixel of a world point in `viewport`, or nullopt when the point is not in front of the eye.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point,
                                         const Viewport& viewport) const;
  /// Unit direction of the ray from the eye through `pixel`.
  Eigen::Vector3d ray_direction(const Eigen::Vector2d& pixel, const Viewport& viewport) const;
  /// The first point of the unit sphere on the ray through `pixel`, or nullopt if it misses.
  std::optional<Eigen::Vector3d> pick_sphere(const Eigen::Vector2d& pixel,
                                             const Viewport& viewport) const;
  /// The unit direction of the point where the ray through `pixel` meets the sphere of
  /// `radius` (> 0) about the origin: of its two intersections the one nearer `near`, and the
  /// point of the ray closest to the origin when the ray misses the sphere. A point at radius
  /// times the result projects to `pixel` whenever the ray meets the sphere: what a dragged
  /// vector tip (drawn at that radius) follows.
  Eigen::Vector3d pick_direction(const Eigen::Vector2d& pixel, const Viewport& viewport,
                                 double radius, const Eigen::Vector3d& near) const;
  /// True when the opaque unit sphere hides `point` from the eye (points inside it are hidden;
  /// points on its surface facing the eye are not).
  bool hidden_by_sphere(const Eigen::Vector3d& point) const;

 private:
  double focal_pixels(const Viewport& viewport) const;

  double yaw_deg_ = kDefaultYawDeg;
  double pitch_deg_ = kDefaultPitchDeg;
  double distance_ = kDefaultDistance;
};

}  // namespace vantage::viewer

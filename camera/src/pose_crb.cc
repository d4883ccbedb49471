// The pose CRB at one viewing direction (docs/math.md §22): the camera of direction a, the
// markers it sees, the analytic Jacobian of their pixels and the Fisher information.

#include "vantage/camera/pose_crb.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"
#include "vantage/visibility/camera_visibility.h"
#include "vantage/visibility/visibility.h"

namespace vantage::camera {

namespace {

// a / |a| by its own scale (a 1e200 or 1e-300 long direction alike).
Eigen::Vector3d checked_direction(const Eigen::Vector3d& a) {
  const Eigen::Vector3d unit = unit_direction(a);
  if (unit.isZero()) throw InvalidArgument("direction", "must be a finite non-zero vector");
  return unit;
}

// A reference axis for the camera's x row: the coordinate axis least aligned with a.
Eigen::Vector3d least_aligned_axis(const Eigen::Vector3d& a) {
  Eigen::Index k = 0;
  a.cwiseAbs().minCoeff(&k);
  return Eigen::Vector3d::Unit(k);
}

struct CrbOptionViolation {
  const char* field;
  const char* problem;
};

bool in_length_range(double length) {
  return length >= PoseCrbOptions::kMinLength && length <= PoseCrbOptions::kMaxLength;
}

std::optional<CrbOptionViolation> first_violation(const PoseCrbOptions& o) {
  if (!in_length_range(o.distance)) {
    return CrbOptionViolation{"distance", "must be in [1e-50, 1e50] (layout units)"};
  }
  // F is a sum of f^2 terms over S^2: f and S in [1e-50, 1e50] keep every product finite.
  if (!(o.focal_length >= PoseCrbOptions::kMinPixels) ||
      !(o.focal_length <= PoseCrbOptions::kMaxPixels)) {
    return CrbOptionViolation{"focal_length", "must be in [1e-50, 1e50] pixels"};
  }
  if (!o.principal_point.allFinite()) {
    return CrbOptionViolation{"principal_point", "must be finite"};
  }
  if (o.aim && !o.aim->allFinite()) return CrbOptionViolation{"aim", "must be finite"};
  if (!(o.noise_px >= PoseCrbOptions::kMinPixels) || !(o.noise_px <= PoseCrbOptions::kMaxPixels)) {
    return CrbOptionViolation{"noise_px", "must be in [1e-50, 1e50] pixels"};
  }
  // F ~ (f / (S z))^2 with z >= the distance's scale: the ratio and the lengths bounded keep
  // every entry of F finite.
  const double ratio = o.focal_length / o.noise_px;
  if (!(ratio >= PoseCrbOptions::kMinFocalOverNoise &&
        ratio <= PoseCrbOptions::kMaxFocalOverNoise)) {
    return CrbOptionViolation{"noise_px",
                              "the focal length over the noise must be in [1e-12, 1e12]"};
  }
  if (o.samples < 100 || o.samples > 10'000'000) {
    return CrbOptionViolation{"samples", "must be in [100, 10000000]"};
  }
  if (o.refine_starts < 1 || o.refine_starts > 1000) {
    return CrbOptionViolation{"refine_starts", "must be in [1, 1000]"};
  }
  if (o.threads < 0) return CrbOptionViolation{"threads", "must be >= 0"};
  return std::nullopt;
}

}  // namespace

bool PoseCrbOptions::is_valid(std::string* why) const {
  const std::optional<CrbOptionViolation> v = first_violation(*this);
  if (v && why != nullptr) *why = std::string(v->field) + ": " + v->problem;
  return !v;
}

struct PoseCrbModel::Impl {
  PoseCrbOptions options;
  Eigen::Matrix3Xd points;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double radius = 0.0;
  std::optional<visibility::CameraVisibility> visibility;
  std::optional<visibility::Workspace> workspace;

  void check_distance(double distance) const {
    if (!in_length_range(distance)) {
      throw InvalidArgument("distance", "must be in [1e-50, 1e50] (layout units)");
    }
    if (!(distance > radius)) {
      throw InvalidArgument(
          "distance", "must exceed the layout's radius about " +
                          std::string(options.aim ? "the aim point" : "its centroid") + ", " +
                          std::to_string(radius) + " (the camera would be among the markers)");
    }
  }
};

PoseCrbModel::PoseCrbModel(const Layout& layout, const PoseCrbOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (const std::optional<CrbOptionViolation> v = first_violation(options)) {
    throw InvalidArgument(v->field, v->problem);
  }
  layout.validate();
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("vectors", "the pose bound needs marker points, not data vectors");
  }
  Impl& m = *impl_;
  m.options = options;
  m.points = layout.entries;
  m.centroid = options.aim ? *options.aim : Eigen::Vector3d(m.points.rowwise().mean());
  m.radius = (m.points.colwise() - m.centroid).colwise().norm().maxCoeff();
  m.check_distance(options.distance);
  m.visibility.emplace(layout);
  if (layout.workspace && layout.workspace->half_angle_deg < 180.0) {
    m.workspace = visibility::Workspace{
        layout.workspace->axis, std::cos(layout.workspace->half_angle_deg / kDegreesPerRadian)};
  }
}

PoseCrbModel::~PoseCrbModel() = default;
PoseCrbModel::PoseCrbModel(PoseCrbModel&&) noexcept = default;
PoseCrbModel& PoseCrbModel::operator=(PoseCrbModel&&) noexcept = default;

const Eigen::Matrix3Xd& PoseCrbModel::points() const { return impl_->points; }
const Eigen::Vector3d& PoseCrbModel::centroid() const { return impl_->centroid; }
double PoseCrbModel::radius() const { return impl_->radius; }
const PoseCrbOptions& PoseCrbModel::options() const { return impl_->options; }
bool PoseCrbModel::with_body() const { return impl_->visibility->with_body(); }
const visibility::CameraVisibility& PoseCrbModel::visibility() const { return *impl_->visibility; }

const std::optional<visibility::Workspace>& PoseCrbModel::workspace() const {
  return impl_->workspace;
}

bool PoseCrbModel::in_workspace(const Eigen::Vector3d& a) const {
  return !impl_->workspace || a.dot(impl_->workspace->axis) >= impl_->workspace->cos_half_angle;
}

void camera_pose_toward(const Eigen::Vector3d& aim, const Eigen::Vector3d& direction,
                        double distance, Eigen::Matrix3d* R_camera_object,
                        Eigen::Vector3d* p_camera_object) {
  const Eigen::Vector3d a = checked_direction(direction);
  const Eigen::Vector3d z = -a;
  const Eigen::Vector3d reference = least_aligned_axis(a);
  const Eigen::Vector3d x = (reference - reference.dot(z) * z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  R_camera_object->row(0) = x.transpose();
  R_camera_object->row(1) = y.transpose();
  R_camera_object->row(2) = z.transpose();
  const Eigen::Vector3d c = aim + distance * a;
  *p_camera_object = -(*R_camera_object) * c;
}

void PoseCrbModel::camera_pose(const Eigen::Vector3d& direction, double distance,
                               Eigen::Matrix3d* R_camera_object,
                               Eigen::Vector3d* p_camera_object) const {
  camera_pose_toward(impl_->centroid, direction, distance, R_camera_object, p_camera_object);
}

Eigen::Matrix2Xd PoseCrbModel::project(const Eigen::Vector3d& a, double distance) const {
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  camera_pose(a, distance, &R, &p);
  const Eigen::Matrix3Xd x = (R * impl_->points).colwise() + p;
  Eigen::Matrix2Xd q(2, x.cols());
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    q.col(i) =
        impl_->options.principal_point + impl_->options.focal_length * x.col(i).head<2>() / x(2, i);
  }
  return q;
}

namespace {

// d q / d(dt, dtheta) of the camera-frame point x = r + p, r = R p_i: dq/dx = (f / z) [1 0 -x/z;
// 0 1 -y/z] and dx/d(dt, dtheta) = [I, -[r]x] (R = exp([dtheta]x) R0 rotates r, not p).
Eigen::Matrix<double, 2, 6> pixel_jacobian(const Eigen::Vector3d& r, const Eigen::Vector3d& p,
                                           double f) {
  const Eigen::Vector3d x = r + p;
  const double inv_z = 1.0 / x.z();
  Eigen::Matrix<double, 2, 3> dq_dx;
  dq_dx << f * inv_z, 0.0, -f * x.x() * inv_z * inv_z, 0.0, f * inv_z, -f * x.y() * inv_z * inv_z;
  Eigen::Matrix3d minus_skew;
  minus_skew << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0;
  Eigen::Matrix<double, 2, 6> J;
  J.leftCols<3>() = dq_dx;
  J.rightCols<3>() = dq_dx * minus_skew;
  return J;
}

}  // namespace

Eigen::MatrixXd PoseCrbModel::jacobian(const Eigen::Vector3d& a, double distance) const {
  impl_->check_distance(distance);
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  camera_pose(a, distance, &R, &p);
  const Eigen::Index n = impl_->points.cols();
  Eigen::MatrixXd J(2 * n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    J.middleRows<2>(2 * i) =
        pixel_jacobian(R * impl_->points.col(i), p, impl_->options.focal_length);
  }
  return J;
}

void PoseCrbModel::check_distance(double distance) const { impl_->check_distance(distance); }

PoseCrbAt PoseCrbModel::at(const Eigen::Vector3d& a) const {
  return at(a, impl_->options.distance);
}

PoseCrbAt PoseCrbModel::at(const Eigen::Vector3d& direction, double distance) const {
  const Impl& m = *impl_;
  m.check_distance(distance);
  PoseCrbAt out;
  out.direction = checked_direction(direction);
  out.rot_rms_deg = std::numeric_limits<double>::infinity();
  out.trans_rms = std::numeric_limits<double>::infinity();
  out.first_order_rot_rms_deg = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d c = m.centroid + distance * out.direction;
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  camera_pose(out.direction, distance, &R, &p);
  Eigen::Matrix<double, 6, 6> F = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < static_cast<int>(m.points.cols()); ++i) {
    if (!m.visibility->visible(i, c)) continue;
    out.visible_markers.push_back(i);
    F.noalias() += marker_information(m.points.col(i), R, p, m.options.focal_length);
  }
  const int seen = static_cast<int>(out.visible_markers.size());
  if (!in_workspace(out.direction) || seen < 3 || seen < m.visibility->min_visible()) return out;
  complete_pose_crb(F, m.options.noise_px, distance, &out);
  return out;
}

Eigen::Matrix<double, 6, 6> marker_information(const Eigen::Vector3d& x, const Eigen::Matrix3d& R,
                                               const Eigen::Vector3d& p, double focal_length) {
  const Eigen::Matrix<double, 2, 6> J = pixel_jacobian(R * x, p, focal_length);
  return J.transpose() * J;
}

void complete_pose_crb(const Eigen::Matrix<double, 6, 6>& F1, double noise_px, double distance,
                       PoseCrbAt* out) {
  const Eigen::Matrix<double, 6, 6> F = F1 / (noise_px * noise_px);
  // Scale translation by D so that both blocks are in radians-like units before the condition
  // test; the covariance is computed from the scaled matrix and scaled back.
  Eigen::Matrix<double, 6, 1> scale;
  scale << distance, distance, distance, 1.0, 1.0, 1.0;
  const Eigen::Matrix<double, 6, 6> F_scaled = scale.asDiagonal() * F * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(F_scaled);
  const double largest = eig.eigenvalues()(5);
  const double smallest = eig.eigenvalues()(0);
  if (!(smallest > 0.0) || !(largest <= PoseCrbAt::kMaxCondition * smallest)) {
    out->ill_conditioned = true;
    out->unbounded = true;
    return;
  }
  const Eigen::Matrix<double, 6, 6> C_scaled = eig.eigenvectors() *
                                               eig.eigenvalues().cwiseInverse().asDiagonal() *
                                               eig.eigenvectors().transpose();
  const Eigen::Matrix<double, 6, 6> C = scale.asDiagonal() * C_scaled * scale.asDiagonal();
  const double rot_rms_deg = std::sqrt(C.bottomRightCorner<3, 3>().trace()) * kDegreesPerRadian;
  out->first_order_rot_rms_deg = rot_rms_deg;
  if (!(rot_rms_deg <= PoseCrbAt::kMaxRotRmsDeg)) {
    out->unbounded = true;
    return;
  }
  out->covariance = C;
  out->trackable = true;
  out->trans_rms = std::sqrt(C.topLeftCorner<3, 3>().trace());
  out->rot_rms_deg = rot_rms_deg;
}

}  // namespace vantage::camera

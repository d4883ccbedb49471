#include "vantage/body/ray_caster.h"

#include <embree3/rtcore.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace vantage::body {

struct RayCaster::Scene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  ~Scene() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }
};

namespace {

[[noreturn]] void embree_failed(RTCDevice device, const char* what) {
  const RTCError code = device != nullptr ? rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN;
  throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                           std::to_string(static_cast<int>(code)) + ")");
}

RTCRay make_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double far) {
  RTCRay ray;
  ray.org_x = static_cast<float>(origin.x());
  ray.org_y = static_cast<float>(origin.y());
  ray.org_z = static_cast<float>(origin.z());
  ray.tnear = 0.0f;
  ray.dir_x = static_cast<float>(direction.x());
  ray.dir_y = static_cast<float>(direction.y());
  ray.dir_z = static_cast<float>(direction.z());
  ray.time = 0.0f;
  ray.tfar = far < std::numeric_limits<float>::max() ? static_cast<float>(far)
                                                     : std::numeric_limits<float>::infinity();
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

}  // namespace

RayCaster::RayCaster(const Mesh& mesh) : scene_(std::make_unique<Scene>()) {
  mesh.validate();
  scene_->device = rtcNewDevice("verbose=0");
  if (scene_->device == nullptr) embree_failed(nullptr, "rtcNewDevice");
  scene_->scene = rtcNewScene(scene_->device);
  if (scene_->scene == nullptr) embree_failed(scene_->device, "rtcNewScene");
  rtcSetSceneBuildQuality(scene_->scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(scene_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) embree_failed(scene_->device, "rtcNewGeometry");
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                              3 * sizeof(float), static_cast<std::size_t>(mesh.vertices.cols())));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
      static_cast<std::size_t>(mesh.triangles.cols())));
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    embree_failed(scene_->device, "rtcSetNewGeometryBuffer");
  }
  for (Eigen::Index k = 0; k < mesh.vertices.cols(); ++k) {
    for (int c = 0; c < 3; ++c) vertices[3 * k + c] = static_cast<float>(mesh.vertices(c, k));
  }
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    for (int c = 0; c < 3; ++c) indices[3 * k + c] = static_cast<unsigned>(mesh.triangles(c, k));
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_->scene);
  if (rtcGetDeviceError(scene_->device) != RTC_ERROR_NONE) {
    embree_failed(scene_->device, "building the scene");
  }
}

RayCaster::~RayCaster() = default;

bool RayCaster::occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                         double max_distance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, max_distance);
  rtcOccluded1(scene_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar = -inf when the ray is blocked
}

void RayCaster::occluded(const Eigen::Matrix3Xd& origins, const Eigen::Matrix3Xd& directions,
                         const Eigen::VectorXd& max_distances, std::vector<char>* blocked) const {
  const Eigen::Index count = origins.cols();
  std::vector<RTCRay> rays(static_cast<std::size_t>(count));
  for (Eigen::Index k = 0; k < count; ++k) {
    rays[static_cast<std::size_t>(k)] =
        make_ray(origins.col(k), directions.col(k), max_distances(k));
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  if (count > 0) {
    rtcOccluded1M(scene_->scene, &context, rays.data(), static_cast<unsigned>(count),
                  sizeof(RTCRay));
  }
  blocked->resize(static_cast<std::size_t>(count));
  for (Eigen::Index k = 0; k < count; ++k) {
    (*blocked)[static_cast<std::size_t>(k)] = rays[static_cast<std::size_t>(k)].tfar < 0.0f;
  }
}

}  // namespace vantage::body

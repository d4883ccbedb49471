#include "vantage/simulate/estimators.h"

#include <algorithm>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

bool is_image(const Scene& s) {
  return s.kind == SceneKind::kAffineImage || s.kind == SceneKind::kPinholeImage;
}

bool image_points(const Scene& s) { return is_image(s) && s.model.cols() >= 3; }

/// Lemma 7 enumerates 2^m patterns of the m data vectors; an image's kAuto set is bounded.
bool affine_applies(const Scene& s) {
  if (s.kind == SceneKind::kAffineVectors) return s.model.cols() <= kMaxAffineVectors;
  return image_points(s);
}

std::vector<Estimator> make_registry() {
  const auto row = [](PoseMethod method, std::function<bool(const Scene&)> applies) {
    Estimator e;
    e.name = to_string(method);
    e.description = describe(method);
    e.method = method;
    e.applies = std::move(applies);
    return e;
  };
  Estimator spanning = row(PoseMethod::kAffine, [](const Scene& s) {
    return image_points(s) && s.model.cols() - 1 <= kMaxAffineVectors;
  });
  spanning.name = "affine-spanning";
  spanning.description = "affine on the n - 1 free vectors of the maximum spanning tree";
  spanning.free_vectors = FreeVectorSet::kMaxSpanningTree;
  const auto pinhole = [](const Scene& s) {
    return s.kind == SceneKind::kPinholeImage && s.model.cols() >= 3;
  };
  return {
      row(PoseMethod::kAffine, affine_applies),
      spanning,
      row(PoseMethod::kAffineRefined,
          [](const Scene& s) { return s.kind == SceneKind::kAffineImage && s.model.cols() >= 3; }),
      row(PoseMethod::kStandard,
          [](const Scene& s) { return s.kind == SceneKind::kAffineVectors || image_points(s); }),
      row(PoseMethod::kFull3d, image_points),
      row(PoseMethod::kOiFoam, pinhole),
      row(PoseMethod::kOiSvd, pinhole),
      row(PoseMethod::kPerspective, pinhole),
      row(PoseMethod::kHaralick2d, [](const Scene& s) { return s.kind == SceneKind::kPlanar2d; }),
      row(PoseMethod::kHaralick3d, [](const Scene& s) { return s.kind == SceneKind::kPoints3d; }),
      row(PoseMethod::kTwoView,
          [](const Scene& s) { return s.kind == SceneKind::kTwoView && s.image.cols() >= 8; }),
  };
}

}  // namespace

Correspondences scene_correspondences(const Scene& scene) {
  Correspondences data;
  switch (scene.kind) {
    case SceneKind::kAffineVectors:
      data.model = scene.model;
      data.image = scene.image;
      data.directions = true;
      break;
    case SceneKind::kAffineImage:
    case SceneKind::kPinholeImage:
      data.model = scene.model;
      data.image = scene.image.colwise() - scene.principal_point;
      data.measured = scene.measured;
      data.camera.focal_length = scene.focal;
      break;
    case SceneKind::kPlanar2d:
      data.model = scene.model;
      data.image = scene.image;
      break;
    case SceneKind::kPoints3d:
      data.model = scene.model;
      data.measured = scene.measured;
      break;
    case SceneKind::kTwoView:
      data.image1 = scene.first_view;
      data.image2 = scene.image;
      data.camera.focal_length = 1.0;
      break;
  }
  return data;
}

PoseEstimate Estimator::solve(const Scene& scene) const {
  PoseOptions options;
  options.free_vectors = free_vectors;
  return estimate_pose(method, scene_correspondences(scene), options);
}

const std::vector<Estimator>& estimator_registry() {
  static const std::vector<Estimator> registry = make_registry();
  return registry;
}

const Estimator* find_estimator(const std::string& name) {
  for (const Estimator& e : estimator_registry()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::string estimator_names() {
  std::string names;
  for (const Estimator& e : estimator_registry()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

std::vector<Estimator> select_estimators(const std::vector<std::string>& names, const Scene& scene,
                                         const std::string& argument) {
  for (const std::string& name : names) {
    const Estimator* e = find_estimator(name);
    if (!e) {
      throw InvalidArgument(argument,
                            "unknown estimator '" + name + "' (known: " + estimator_names() + ")");
    }
    if (!e->applies(scene)) {
      throw InvalidArgument(argument, "estimator '" + name + "' does not apply to a " +
                                          to_string(scene.kind) + " scene of " +
                                          std::to_string(scene.model.cols()) + " entries");
    }
  }
  std::vector<Estimator> selected;
  for (const Estimator& e : estimator_registry()) {
    const bool named = std::find(names.begin(), names.end(), e.name) != names.end();
    if ((names.empty() && e.applies(scene)) || named) selected.push_back(e);
  }
  return selected;
}

}  // namespace vantage::simulate

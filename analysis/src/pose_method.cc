#include "vantage/analysis/pose_method.h"

#include "vantage/analysis/common.h"

namespace vantage {

const char* to_string(PoseMethod method) {
  switch (method) {
    case PoseMethod::kAffine:
      return "affine";
    case PoseMethod::kAffineRefined:
      return "affine-refined";
    case PoseMethod::kPerspective:
      return "perspective";
    case PoseMethod::kStandard:
      return "standard";
    case PoseMethod::kFull3d:
      return "full3d";
    case PoseMethod::kOiFoam:
      return "oi-foam";
    case PoseMethod::kOiSvd:
      return "oi-svd";
    case PoseMethod::kTwoView:
      return "two-view";
    case PoseMethod::kHaralick2d:
      return "haralick-2d";
    case PoseMethod::kHaralick3d:
      return "haralick-3d";
  }
  return "unknown";
}

std::optional<PoseMethod> parse_pose_method(std::string_view name) {
  for (PoseMethod method : kPoseMethods) {
    if (name == to_string(method)) return method;
  }
  return std::nullopt;
}

PoseMethod parse_pose_method_or_throw(std::string_view name, const std::string& field) {
  if (const std::optional<PoseMethod> method = parse_pose_method(name)) return *method;
  throw InvalidArgument(field, "unknown pose method \"" + std::string(name) +
                                   "\" (known: " + pose_method_names() + ")");
}

std::string pose_method_names() {
  std::string names;
  for (PoseMethod method : kPoseMethods) {
    names += (names.empty() ? "" : ", ") + std::string(to_string(method));
  }
  return names;
}

const char* describe(PoseMethod method) {
  switch (method) {
    case PoseMethod::kAffine:
      return "Prop. 8 / Lemma 7 [M]: free vectors, the LUB scale, 2^m sign patterns";
    case PoseMethod::kAffineRefined:
      return "Prop. 8 refined by Levenberg-Marquardt on the affine image residual";
    case PoseMethod::kPerspective:
      return "maximum-likelihood pinhole pose: Levenberg-Marquardt from POSIT / IPPE";
    case PoseMethod::kStandard:
      return "the paper's standard approach [M]: Theorem 1 with v_z = 0";
    case PoseMethod::kFull3d:
      return "the paper's full 3-D baseline [M]: Theorem 1 + Eq. 13 on 3-D measurements";
    case PoseMethod::kOiFoam:
      return "orthogonal iteration with the FOAM step [W]";
    case PoseMethod::kOiSvd:
      return "orthogonal iteration with the SVD step (Lu et al.)";
    case PoseMethod::kTwoView:
      return "the simplified linear two-view algorithm [H] Sec. 4";
    case PoseMethod::kHaralick2d:
      return "closed-form 2D-2D rigid pose [H] Sec. 2";
    case PoseMethod::kHaralick3d:
      return "3D-3D pose by the SVD [H] Sec. 3";
  }
  return "unknown";
}

PoseData pose_data(PoseMethod method) {
  switch (method) {
    case PoseMethod::kFull3d:
    case PoseMethod::kHaralick3d:
      return PoseData::kMeasured;
    case PoseMethod::kTwoView:
      return PoseData::kTwoViews;
    case PoseMethod::kHaralick2d:
      return PoseData::kPlanar;
    default:
      return PoseData::kImage;
  }
}

bool uses_free_vectors(PoseMethod method) {
  return method == PoseMethod::kAffine || method == PoseMethod::kAffineRefined ||
         method == PoseMethod::kPerspective || method == PoseMethod::kStandard ||
         method == PoseMethod::kFull3d;
}

bool is_pinhole_method(PoseMethod method) {
  return method == PoseMethod::kPerspective || method == PoseMethod::kOiFoam ||
         method == PoseMethod::kOiSvd;
}

}  // namespace vantage

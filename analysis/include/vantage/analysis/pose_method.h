#pragma once

/// The names of vantage's pose estimators: one vocabulary for `vantage pose --method`,
/// `vantage simulate --estimators`, `vantage.pose(method=...)` and estimate_pose()
/// (estimate_pose.h). The paper [M] is McInroy et al.; [H] Haralick et al.; [W] Wu & Wu
/// (docs/math.md, "Papers").

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace vantage {

/// A pose estimator.
enum class PoseMethod {
  kAffine,         ///< "affine": Prop. 8 [M] (free vectors, Lemma 7's LUB scale, Prop. 4)
  kAffineRefined,  ///< "affine-refined": Prop. 8 refined on the affine image residual
  kPerspective,    ///< "perspective": pinhole maximum likelihood (LM from POSIT / IPPE)
  kStandard,       ///< "standard": the paper's standard approach (Theorem 1 with v_z = 0) [M]
  kFull3d,         ///< "full3d": the paper's full 3-D baseline on 3-D measurements [M]
  kOiFoam,         ///< "oi-foam": orthogonal iteration with the FOAM step [W]
  kOiSvd,          ///< "oi-svd": orthogonal iteration with the SVD step (Lu et al.)
  kTwoView,        ///< "two-view": the linear two-view algorithm [H] Sec. 4
  kHaralick2d,     ///< "haralick-2d": closed-form 2D-2D rigid pose [H] Sec. 2
  kHaralick3d,     ///< "haralick-3d": 3D-3D pose by the SVD [H] Sec. 3
};

/// Every method, in the order of the enum (the order of lists and --help).
inline constexpr std::array<PoseMethod, 10> kPoseMethods = {
    PoseMethod::kAffine,    PoseMethod::kAffineRefined, PoseMethod::kPerspective,
    PoseMethod::kStandard,  PoseMethod::kFull3d,        PoseMethod::kOiFoam,
    PoseMethod::kOiSvd,     PoseMethod::kTwoView,       PoseMethod::kHaralick2d,
    PoseMethod::kHaralick3d};

/// The method's name: "affine", "affine-refined", ..., "haralick-3d".
const char* to_string(PoseMethod method);

/// The method named `name` (as to_string() spells it), or nullopt.
std::optional<PoseMethod> parse_pose_method(std::string_view name);

/// The method named `name`; throws InvalidArgument(field, "unknown pose method \"x\" (known:
/// affine, ...)") otherwise.
PoseMethod parse_pose_method_or_throw(std::string_view name, const std::string& field);

/// Every name, joined by ", ".
std::string pose_method_names();

/// One line: what the method is and where it comes from.
const char* describe(PoseMethod method);

/// What a method measures from.
enum class PoseData {
  kImage,     ///< model points and one image of them (pixels)
  kMeasured,  ///< model points and their 3-D measurements
  kTwoViews,  ///< the same points in two images (relative pose)
  kPlanar,    ///< 2-D model points (z = 0) and their moved copy in the plane
};

/// The data `method` needs.
PoseData pose_data(PoseMethod method);

/// True for the methods that use free vectors (affine, affine-refined, perspective, standard,
/// full3d): the ones --free-vectors applies to.
bool uses_free_vectors(PoseMethod method);

/// True for the methods that project through a pinhole camera (perspective, oi-foam, oi-svd):
/// without a focal length they read the image as normalised coordinates (f = 1).
bool is_pinhole_method(PoseMethod method);

}  // namespace vantage

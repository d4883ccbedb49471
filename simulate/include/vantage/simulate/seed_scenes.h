#pragma once

/// The scenes of the seed papers' simulation experiments, each as the seed describes it; where
/// the seed leaves a quantity unstated, the choice is named in the options and documented.

#include <Eigen/Core>

#include "vantage/simulate/noise.h"
#include "vantage/simulate/random.h"
#include "vantage/simulate/scene.h"

namespace vantage::simulate {

/// Haralick et al. Sec. 2.3 (2D-2D): n model points uniform in [-2, 2]^2, a rotation uniform in
/// [-15, 15] deg, a translation uniform in [-1, 1]^2, independent noise of standard deviation
/// sigma added to both coordinates of the rotated and translated points. SNR = 20 log10(4 / sigma)
/// (noise.h).
Scene make_planar_2d_scene(int n, NoiseKind noise, double sigma, TrialRandom& random);

/// Haralick et al. Sec. 3.3 (3D-3D): n points uniform in the cube [-2, 2]^3 (the seed says "at
/// random"; the cube makes the range of the points 4), a uniformly random rotation, a
/// translation uniform in [-1, 1]^3 (unstated in the seed), noise of standard deviation sigma
/// added to each coordinate of the moved points. SNR = 20 log10(4 / sigma).
Scene make_points_3d_scene(int n, NoiseKind noise, double sigma, TrialRandom& random);

/// The two-view scene of Haralick et al. Sec. 4.4 with the ranges the seed leaves unstated.
struct TwoViewScene {
  double depth_min = 4.0;  ///< depth range of the points in view 1 (object units)
  double depth_max = 6.0;
  double translation = 1.0;  ///< T uniform in [-translation, translation]^3
  double euler_deg = 15.0;  ///< each Euler angle uniform in [-euler_deg, euler_deg] (the seed's 15)
};

/// n points whose view-1 normalised images (X, Y) are uniform in [-2, 2]^2 (the seed's "object
/// image size ... from -2 to 2") at depths uniform in [depth_min, depth_max]; R from three Euler
/// angles, T uniform; a point behind or within 0.1 of camera 2 is redrawn. Independent noise of
/// standard deviation sigma on both views' normalised coordinates. SNR = 20 log10(4 / sigma).
Scene make_two_view_scene(int n, const TwoViewScene& geometry, NoiseKind noise, double sigma,
                          TrialRandom& random);

/// The pinhole scene of Wu & Wu Sec. 3, whose numbers were lost in the text conversion:
/// n points uniform in [-1, 1]^3, a uniformly random rotation (their Euler ranges cover SO(3)),
/// translation (U[-1, 1], U[-1, 1], U[8, 12]), focal 1000 px, Gaussian noise on the image with
/// sigma from the SNR on the image's peak-to-peak extent (noise.h).
Scene make_wu_scene(int n, double snr_db, TrialRandom& random);

/// Focal length of make_wu_scene(), pixels.
inline constexpr double kWuFocalPx = 1000.0;

}  // namespace vantage::simulate

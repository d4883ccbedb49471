#pragma once

/// Measurement noise of the simulations and the signal-to-noise ratios of the seed papers.
///
/// Every noise sample has mean 0 and standard deviation sigma, whatever its distribution, so a
/// Gaussian and a uniform run at the same sigma (or SNR) are comparable, as in Haralick et al.
/// [H], who vary the "kind of noise distribution" at fixed SNR.
///
/// SNR in dB, as each seed defines it (sigma = signal / 10^(SNR / 20) in all of them):
///  - [H] Sec. 2.3 (2D-2D): "20 log peak-to-peak signal / rms noise"; the points fill the
///    square [-2, 2]^2, so the signal is its side, 4.
///  - [H] Sec. 3.3 (3D-3D): "20 log (range of 3D points / standard deviation of noise)";
///    the range of a cube [-2, 2]^3 is its side, 4.
///  - [H] Sec. 4.4 (two views): SNR 92 dB <-> sigma 0.0001 and 26 dB <-> 0.2 for "an object
///    image size [that] is a square whose sides extend from -2 to 2": the same definition with
///    the peak-to-peak extent 4 of the normalised image.
///  - [W] Sec. 3 defines the standard deviation "as a function of the SNR", but the formula
///    was lost in the text conversion; vantage uses the [H] definition on the image: the
///    peak-to-peak extent of the noise-free image points, in pixels.
/// peak_to_peak() measures that extent on data; the Haralick experiments use the nominal sides.

#include <Eigen/Core>
#include <string>

#include "vantage/simulate/random.h"

namespace vantage::simulate {

/// Distribution of a noise sample.
enum class NoiseKind {
  kGaussian,  ///< N(0, sigma^2)
  kUniform,   ///< uniform on [-sqrt(3) sigma, sqrt(3) sigma] (standard deviation sigma)
};

/// "gaussian" or "uniform".
const char* to_string(NoiseKind kind);

/// "gaussian" / "uniform" to the enum; throws InvalidArgument naming `argument` otherwise.
NoiseKind parse_noise_kind(const std::string& name, const std::string& argument);

/// One sample of the given kind with standard deviation sigma >= 0. Draws the same numbers from
/// `random` whatever sigma is, so a trial's geometry does not change along an SNR sweep.
double noise_sample(NoiseKind kind, double sigma, TrialRandom& random);

/// sigma = signal / 10^(snr_db / 20): the noise of an SNR in dB for a signal of the given size
/// (the peak-to-peak extent or range of the seed's definition, see the file comment).
double sigma_from_snr(double snr_db, double signal);

/// The largest peak-to-peak extent over the coordinates (rows) of a point set: max over rows of
/// (max - min). Zero for fewer than two points.
double peak_to_peak(const Eigen::MatrixXd& points);

}  // namespace vantage::simulate

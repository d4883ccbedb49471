#include "vantage/simulate/noise.h"

#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::simulate {

const char* to_string(NoiseKind kind) {
  return kind == NoiseKind::kGaussian ? "gaussian" : "uniform";
}

NoiseKind parse_noise_kind(const std::string& name, const std::string& argument) {
  if (name == "gaussian") return NoiseKind::kGaussian;
  if (name == "uniform") return NoiseKind::kUniform;
  throw InvalidArgument(argument + ": must be gaussian or uniform, got '" + name + "'");
}

double noise_sample(NoiseKind kind, double sigma, TrialRandom& random) {
  if (kind == NoiseKind::kGaussian) return sigma * random.normal();
  return sigma * std::sqrt(3.0) * random.uniform(-1.0, 1.0);
}

double sigma_from_snr(double snr_db, double signal) {
  return signal / std::pow(10.0, snr_db / 20.0);
}

double peak_to_peak(const Eigen::MatrixXd& points) {
  if (points.cols() < 2) return 0.0;
  return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).maxCoeff();
}

}  // namespace vantage::simulate

#include "vantage/simulate/random.h"

#include <Eigen/Geometry>
#include <cmath>

namespace vantage::simulate {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t trial) {
  return splitmix64(splitmix64(seed) ^ (trial * 0xd1b54a32d192ed03ULL + 0x632be59bd9b4e019ULL));
}

double TrialRandom::uniform() {
  return static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0);
}

double TrialRandom::normal() {
  for (;;) {
    const double u = 2.0 * uniform() - 1.0;
    const double v = 2.0 * uniform() - 1.0;
    const double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
  }
}

Eigen::Matrix3d TrialRandom::rotation() {
  for (;;) {
    const double w = normal();
    const double x = normal();
    const double y = normal();
    const double z = normal();
    const double norm = std::sqrt(w * w + x * x + y * y + z * z);
    if (norm > 1e-12) return Eigen::Quaterniond(w / norm, x / norm, y / norm, z / norm).matrix();
  }
}

Eigen::Vector3d TrialRandom::unit_vector() {
  for (;;) {
    const Eigen::Vector3d v(normal(), normal(), normal());
    const double norm = v.norm();
    if (norm > 1e-12) return v / norm;
  }
}

}  // namespace vantage::simulate

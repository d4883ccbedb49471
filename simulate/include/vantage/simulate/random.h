#pragma once

/// Random numbers of one Monte Carlo trial.
///
/// Every trial draws from its own engine, seeded from (run seed, trial index) by
/// trial_seed(), so a trial's data depend on neither the thread that runs it nor the other
/// trials (threads, shards). The distributions are written here instead of taken from
/// <random>, whose normal and uniform-real algorithms differ between standard libraries: the
/// numbers are then the same with any compiler.

#include <Eigen/Core>
#include <cstdint>
#include <random>

namespace vantage::simulate {

/// The seed of trial `trial` of a run seeded with `seed`: SplitMix64 of a combination of both,
/// so that neighbouring trials and neighbouring run seeds get unrelated engines.
std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t trial);

/// A seeded engine and the draws the scenes need.
class TrialRandom {
 public:
  explicit TrialRandom(std::uint64_t seed) : engine_(seed) {}

  /// The engine of trial `trial` of a run seeded with `seed` (see trial_seed()).
  static TrialRandom for_trial(std::uint64_t seed, std::uint64_t trial) {
    return TrialRandom(trial_seed(seed, trial));
  }

  /// Uniform on [0, 1) with 53 random bits.
  double uniform();
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal (Marsaglia's polar method).
  double normal();
  /// Uniformly distributed rotation (Haar measure on SO(3)): the unit quaternion of four
  /// standard normals.
  Eigen::Matrix3d rotation();
  /// Uniform on the unit sphere.
  Eigen::Vector3d unit_vector();

 private:
  std::mt19937_64 engine_;
};

}  // namespace vantage::simulate

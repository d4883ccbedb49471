// Direction mode of the augmenter: an addition is a unit direction c (c ~ -c).

#include <algorithm>
#include <cmath>

#include "addition_space.h"
#include "kill_level.h"
#include "vantage/analysis/common.h"

namespace vantage::design::internal {
namespace {

// Direct optimiser: Subplex's first step on each raw coordinate of a direction (radians, about
// 17 degrees: a tenth of the half circle the directions live on).
constexpr double kDirectionInitialStep = 0.3;
// Compass moves per point: the 8 directions at multiples of 45 degrees in the tangent plane.
constexpr int kTangentMoves = 8;

class DirectionSpace final : public AdditionSpace {
 public:
  explicit DirectionSpace(const AugmentOptions& options) : options_(options) {}

  double scale() const override { return 1.0; }

  Eigen::Vector3d addition(const Eigen::Vector3d& raw) const override { return raw.normalized(); }

  bool new_vectors(const Eigen::Vector3d& x, const Eigen::Matrix3Xd&,
                   Eigen::Matrix3Xd* out) const override {
    out->resize(3, 1);
    out->col(0) = x.normalized();
    return true;
  }

  // The paper's rule (samples of every great circle a_k^perp, half circles since c ~ -c), then
  // the points where one direction kills every worst viewpoint at once.
  void coarse_samples(const WorstCase& current, const std::vector<Eigen::Vector3d>& kill_points,
                      std::vector<Eigen::Vector3d>* samples) const override {
    for (const Eigen::Vector3d& a : current.viewpoints) {
      Eigen::Vector3d u, v;
      perpendicular_basis(a, &u, &v);
      for (int j = 0; j < options_.circle_samples; ++j) {
        const double th = kPi * j / options_.circle_samples;
        samples->push_back(std::cos(th) * u + std::sin(th) * v);
      }
    }
    for (const Eigen::Vector3d& c : kill_points) samples->push_back(c);
  }

  bool single_addition_can_improve(double best_kill_level, double t,
                                   double tie_tolerance) const override {
    return best_kill_level < t - tie_tolerance;
  }

  double initial_compass_step() const override { return kPi / options_.circle_samples; }

  int compass_moves(const Eigen::Vector3d& x, Eigen::Vector3d* dirs) const override {
    Eigen::Vector3d u, v;
    perpendicular_basis(x, &u, &v);
    for (int k = 0; k < kTangentMoves; ++k) {
      const double phi = 2.0 * kPi * k / kTangentMoves;
      dirs[k] = std::cos(phi) * u + std::sin(phi) * v;
    }
    return kTangentMoves;
  }

  Eigen::Vector3d move(const Eigen::Vector3d& x, double step,
                       const Eigen::Vector3d& dir) const override {
    return (x + step * dir).normalized();
  }

  double angle_from_worst_planes_deg(
      const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& viewpoints) const override {
    double nearest = 1.0;
    for (const Eigen::Vector3d& a : viewpoints) nearest = std::min(nearest, std::abs(a.dot(x)));
    return std::asin(std::min(1.0, nearest)) * kDegreesPerRadian;
  }

  bool search_box(Eigen::Vector3d*, Eigen::Vector3d*) const override { return false; }

  const char* search_name() const override { return "search"; }

  bool all_new_vectors(const Eigen::Matrix3Xd& base_vectors, const Eigen::Matrix3Xd&, double,
                       const std::vector<double>& x, Eigen::Matrix3Xd* out) const override {
    const int k = static_cast<int>(x.size() / 3);
    out->resize(3, base_vectors.cols() + k);
    out->leftCols(base_vectors.cols()) = base_vectors;
    for (int j = 0; j < k; ++j) {
      const Eigen::Vector3d d(x[3 * j], x[3 * j + 1], x[3 * j + 2]);
      if (!(d.norm() > kMinCross)) return false;
      out->col(base_vectors.cols() + j) = d.normalized();
    }
    return true;
  }

  Eigen::Vector3d random_addition(RandomStarts* random) const override {
    auto& gauss = random->gauss;
    auto& rng = random->rng;
    return Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
  }

  DirectBox direct_box(int) const override {
    DirectBox box;
    box.initial_step = kDirectionInitialStep;
    return box;
  }

 private:
  const AugmentOptions& options_;
};

}  // namespace

std::unique_ptr<AdditionSpace> make_direction_space(const AugmentOptions& options) {
  return std::make_unique<DirectionSpace>(options);
}

}  // namespace vantage::design::internal

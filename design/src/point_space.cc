// Point mode of the augmenter: an addition is a marker position in the markers' bounding box
// grown by AugmentOptions::margin, and adds the free vectors p - z_i to every marker (Prop. 8).

#include <algorithm>
#include <cmath>

#include "addition_space.h"

namespace vantage::design::internal {
namespace {

// Direct optimiser: Subplex's first step on each coordinate, as a fraction of the box's largest
// side.
constexpr double kPointInitialStep = 0.1;

class PointSpace final : public AdditionSpace {
 public:
  PointSpace(const Eigen::Matrix3Xd& markers, const AugmentOptions& options) : options_(options) {
    const Eigen::Vector3d lo = markers.rowwise().minCoeff();
    const Eigen::Vector3d hi = markers.rowwise().maxCoeff();
    const double side = (hi - lo).maxCoeff();
    box_lo_ = lo.array() - options.margin * side;
    box_hi_ = hi.array() + options.margin * side;
    scale_ = (box_hi_ - box_lo_).maxCoeff();
  }

  double scale() const override { return scale_; }

  Eigen::Vector3d addition(const Eigen::Vector3d& raw) const override { return raw; }

  bool new_vectors(const Eigen::Vector3d& x, const Eigen::Matrix3Xd& markers,
                   Eigen::Matrix3Xd* out) const override {
    out->resize(3, markers.cols());
    for (Eigen::Index i = 0; i < markers.cols(); ++i) {
      out->col(i) = x - markers.col(i);
      if (out->col(i).norm() < kMinSeparation * scale_) return false;
    }
    return true;
  }

  // A regular grid_samples^3 grid over the box.
  void coarse_samples(const WorstCase&, const std::vector<Eigen::Vector3d>&,
                      std::vector<Eigen::Vector3d>* samples) const override {
    const int g = options_.grid_samples;
    for (int i = 0; i < g; ++i) {
      for (int j = 0; j < g; ++j) {
        for (int k = 0; k < g; ++k) {
          const Eigen::Vector3d f(i / (g - 1.0), j / (g - 1.0), k / (g - 1.0));
          samples->push_back(box_lo_ + f.cwiseProduct(box_hi_ - box_lo_));
        }
      }
    }
  }

  bool single_addition_can_improve(double, double, double) const override { return true; }

  double initial_compass_step() const override {
    return 1.0 / std::max(2, options_.grid_samples - 1);
  }

  // Axis and diagonal moves: the objective is a max-min with ridges that axis moves alone cannot
  // follow.
  int compass_moves(const Eigen::Vector3d&, Eigen::Vector3d* dirs) const override {
    int count = 0;
    for (int k = 0; k < 3; ++k) {
      dirs[count++] = Eigen::Vector3d::Unit(k);
      dirs[count++] = -Eigen::Vector3d::Unit(k);
    }
    for (int k = 0; k < 8; ++k) {
      dirs[count++] =
          Eigen::Vector3d(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1) / std::sqrt(3.0);
    }
    return count;
  }

  Eigen::Vector3d move(const Eigen::Vector3d& x, double step,
                       const Eigen::Vector3d& dir) const override {
    return (x + step * scale_ * dir).cwiseMax(box_lo_).cwiseMin(box_hi_);
  }

  double angle_from_worst_planes_deg(const Eigen::Vector3d&,
                                     const std::vector<Eigen::Vector3d>&) const override {
    return 0.0;
  }

  bool search_box(Eigen::Vector3d* lo, Eigen::Vector3d* hi) const override {
    *lo = box_lo_;
    *hi = box_hi_;
    return true;
  }

  const char* search_name() const override { return "search box"; }

  bool all_new_vectors(const Eigen::Matrix3Xd& base_vectors, const Eigen::Matrix3Xd& base_markers,
                       double min_separation, const std::vector<double>& x,
                       Eigen::Matrix3Xd* out) const override {
    const int k = static_cast<int>(x.size() / 3);
    const Eigen::Index n = base_markers.cols();
    Eigen::Matrix3Xd markers(3, n + k);
    markers.leftCols(n) = base_markers;
    for (int j = 0; j < k; ++j) {
      markers.col(n + j) = Eigen::Vector3d(x[3 * j], x[3 * j + 1], x[3 * j + 2]);
    }
    out->resize(3, base_vectors.cols() + k * n + k * (k - 1) / 2);
    out->leftCols(base_vectors.cols()) = base_vectors;
    Eigen::Index col = base_vectors.cols();
    for (int j = 0; j < k; ++j) {
      for (Eigen::Index i = 0; i < n + j; ++i) {
        const Eigen::Vector3d d = markers.col(n + j) - markers.col(i);
        if (d.norm() < min_separation) return false;
        out->col(col++) = d;
      }
    }
    return true;
  }

  Eigen::Vector3d random_addition(RandomStarts* random) const override {
    auto& unit = random->unit;
    auto& rng = random->rng;
    return box_lo_ +
           Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(box_hi_ - box_lo_);
  }

  DirectBox direct_box(int additions) const override {
    DirectBox box;
    box.lower.resize(3 * additions);
    box.upper.resize(3 * additions);
    for (int j = 0; j < additions; ++j) {
      for (int r = 0; r < 3; ++r) {
        box.lower[3 * j + r] = box_lo_(r);
        box.upper[3 * j + r] = box_hi_(r);
      }
    }
    box.initial_step = kPointInitialStep * scale_;
    return box;
  }

 private:
  const AugmentOptions& options_;
  Eigen::Vector3d box_lo_;
  Eigen::Vector3d box_hi_;
  double scale_ = 1.0;
};

}  // namespace

std::unique_ptr<AdditionSpace> make_point_space(const Eigen::Matrix3Xd& markers,
                                                const AugmentOptions& options) {
  return std::make_unique<PointSpace>(markers, options);
}

}  // namespace vantage::design::internal

#pragma once

// Private to vantage::design: what an "addition" is. Direction mode adds a unit direction (a
// point on the sphere, c ~ -c); point mode adds a marker position in the markers' grown bounding
// box, which adds the free vectors p - z_i to every existing marker (Prop. 8). Everything the
// augmenter does differently in the two modes lives behind this interface, so the greedy step
// (designer.h) and the direct optimiser (direct_search.h) read as one algorithm each.

#include <Eigen/Core>
#include <memory>
#include <random>
#include <vector>

#include "vantage/design/augment.h"

namespace vantage::design::internal {

/// Point mode: a new marker closer than this (times the box's largest side) to another marker
/// would make a zero free vector; such positions are rejected.
inline constexpr double kMinSeparation = 1e-9;

/// The random source of the direct optimiser's starts, one per run (the normal distribution
/// keeps state between calls).
struct RandomStarts {
  explicit RandomStarts(unsigned seed) : rng(seed) {}
  std::mt19937 rng;
  std::normal_distribution<double> gauss{0.0, 1.0};
  std::uniform_real_distribution<double> unit{0.0, 1.0};
};

class AdditionSpace {
 public:
  virtual ~AdditionSpace() = default;

  /// Length unit of the space: the search box's largest side in point mode, 1 for directions.
  virtual double scale() const = 0;

  /// The addition a layout candidate (or an optimiser's raw 3-vector) stands for: its unit
  /// direction, or the position itself.
  virtual Eigen::Vector3d addition(const Eigen::Vector3d& raw) const = 0;

  /// The data vectors that adding x to `markers` creates (one direction, or x - z_i for every
  /// marker). False when x would create a zero vector (x coincides with a marker).
  virtual bool new_vectors(const Eigen::Vector3d& x, const Eigen::Matrix3Xd& markers,
                           Eigen::Matrix3Xd* out) const = 0;

  /// The free search's coarse samples given the current worst viewpoints and the kill-level
  /// minimisers (kill_level.h), appended to *samples in a fixed order.
  virtual void coarse_samples(const WorstCase& current,
                              const std::vector<Eigen::Vector3d>& kill_points,
                              std::vector<Eigen::Vector3d>* samples) const = 0;

  /// "Can one addition raise p-bar_min?": decided exactly for a direction (its best kill level
  /// must be below t); always possible for a marker, which adds several vectors at once.
  virtual bool single_addition_can_improve(double best_kill_level, double t,
                                           double tie_tolerance) const = 0;

  /// Compass search: the first step (radians on the sphere, or a fraction of the box's side),
  /// the moves tried from x (written to dirs, at most kMaxCompassMoves; returns their count), and
  /// the point reached by one move.
  static constexpr int kMaxCompassMoves = 14;
  virtual double initial_compass_step() const = 0;
  virtual int compass_moves(const Eigen::Vector3d& x, Eigen::Vector3d* dirs) const = 0;
  virtual Eigen::Vector3d move(const Eigen::Vector3d& x, double step,
                               const Eigen::Vector3d& dir) const = 0;

  /// Angle in degrees between the added direction x and the nearest plane a_k^perp of the worst
  /// viewpoints (0 = exactly the paper's rule); 0 for a marker position, where it has no meaning.
  virtual double angle_from_worst_planes_deg(
      const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& viewpoints) const = 0;

  /// Point mode: the search box [lo, hi] (true); direction mode has none (false).
  virtual bool search_box(Eigen::Vector3d* lo, Eigen::Vector3d* hi) const = 0;

  /// Where the free search looks, for the step's note: "search" or "search box".
  virtual const char* search_name() const = 0;

  /// Direct optimiser: the data vectors of `base_vectors` plus the K additions packed in x (3K
  /// numbers) to `base_markers`; false when an addition is degenerate (a direction of length
  /// <= kMinCross, or a free vector shorter than min_separation).
  virtual bool all_new_vectors(const Eigen::Matrix3Xd& base_vectors,
                               const Eigen::Matrix3Xd& base_markers, double min_separation,
                               const std::vector<double>& x, Eigen::Matrix3Xd* out) const = 0;

  /// Direct optimiser: a random start for one addition.
  virtual Eigen::Vector3d random_addition(RandomStarts* random) const = 0;

  /// Direct optimiser: where the 3K numbers of K additions may go and its first step on each.
  struct DirectBox {
    std::vector<double> lower;  ///< 3K bounds, or empty: unbounded (directions)
    std::vector<double> upper;
    double initial_step = 0.0;  ///< in the units of the numbers
  };
  virtual DirectBox direct_box(int additions) const = 0;
};

/// Direction mode.
std::unique_ptr<AdditionSpace> make_direction_space(const AugmentOptions& options);

/// Point mode: the box is the markers' bounding box grown on every side by options.margin times
/// its largest side.
std::unique_ptr<AdditionSpace> make_point_space(const Eigen::Matrix3Xd& markers,
                                                const AugmentOptions& options);

/// The space of the layout's mode.
inline std::unique_ptr<AdditionSpace> make_addition_space(const Layout& layout,
                                                          const AugmentOptions& options) {
  return layout.mode == LayoutMode::kPoints ? make_point_space(layout.entries, options)
                                            : make_direction_space(options);
}

}  // namespace vantage::design::internal

// The Monte Carlo check of the first-order TRE (docs/math.md §23, "Monte Carlo").

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/parallel.h"
#include "vantage/tracker/target_registration.h"

namespace vantage::tracker {
namespace {

constexpr long kTreTrialsPerBlock = 1024;
// Blocks per chunk: 2^20 trials, about 0.7 s of CPU on four markers between progress calls.
constexpr long kTreBlocksPerChunk = 1024;

// Sum of |TRE|^2 over trials [begin, end) of block `block`.
double tre_block_sum(const Eigen::Matrix3Xd& tool, const Eigen::Vector3d& target,
                     const FleModel& fle, const Eigen::Matrix3d& R, long trials, std::uint64_t seed,
                     long block) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(block), static_cast<std::uint32_t>(block >> 32)};
  std::mt19937_64 rng(seq);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Index n = tool.cols();
  const Eigen::Vector3d tool_centroid = tool.rowwise().mean();
  const Eigen::Vector3d target_tracker = R * target;
  Eigen::Matrix3Xd measured(3, n);
  double sum = 0.0;
  for (long k = 0; k < trials; ++k) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3d e(fle.sigma_perp * normal(rng), fle.sigma_perp * normal(rng),
                              fle.sigma_axial * normal(rng));
      measured.col(i) = R * tool.col(i) + e;
    }
    const Eigen::Vector3d measured_centroid = measured.rowwise().mean();
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (Eigen::Index i = 0; i < n; ++i) {
      H += (tool.col(i) - tool_centroid) * (measured.col(i) - measured_centroid).transpose();
    }
    const Eigen::Matrix3d R_hat = optimal_rotation(H);
    const Eigen::Vector3d t_hat = measured_centroid - R_hat * tool_centroid;
    sum += (R.transpose() * (R_hat * target + t_hat - target_tracker)).squaredNorm();
  }
  return sum;
}

}  // namespace

TreMonteCarlo tre_monte_carlo(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                              const Eigen::Vector3d& target_tool, const FleModel& fle,
                              const Eigen::Vector3d& a, long trials, std::uint64_t seed,
                              int threads, const std::function<void(long)>& trials_done) {
  if (trials < 1) throw InvalidArgument("trials", "must be >= 1");
  std::string why;
  if (!fle.is_valid(&why)) throw InvalidArgument(why);
  const Eigen::Matrix3d cov = tre_covariance(points_tool, visible, target_tool, fle, a);
  if (cov.isZero(0.0)) {
    throw InvalidArgument("visible", "fewer than 3 markers or collinear: nothing to register");
  }
  Eigen::Matrix3Xd tool(3, static_cast<Eigen::Index>(visible.size()));
  for (std::size_t i = 0; i < visible.size(); ++i) {
    tool.col(static_cast<Eigen::Index>(i)) = points_tool.col(visible[i]);
  }
  // The tracker's +z is the line of sight: R a = e_z.
  const Eigen::Matrix3d R =
      Eigen::Quaterniond::FromTwoVectors(a.normalized(), Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  // Blocks run a chunk at a time, their sums added in block order: the memory is one chunk's
  // whatever `trials` (issue 36: 10^15 trials ended in std::bad_alloc), the total the same bits.
  const long blocks = (trials + kTreTrialsPerBlock - 1) / kTreTrialsPerBlock;
  std::vector<double> sums(static_cast<std::size_t>(std::min(blocks, kTreBlocksPerChunk)));
  double total = 0.0;
  for (long first = 0; first < blocks; first += kTreBlocksPerChunk) {
    const long chunk = std::min(kTreBlocksPerChunk, blocks - first);
    parallel_blocks(chunk, threads, [&](long begin, long end) {
      for (long b = first + begin; b < first + end; ++b) {
        const long count = std::min(kTreTrialsPerBlock, trials - b * kTreTrialsPerBlock);
        sums[static_cast<std::size_t>(b - first)] =
            tre_block_sum(tool, target_tool, fle, R, count, seed, b);
      }
    });
    for (long k = 0; k < chunk; ++k) total += sums[static_cast<std::size_t>(k)];
    if (trials_done) trials_done(std::min(trials, (first + chunk) * kTreTrialsPerBlock));
  }
  TreMonteCarlo out;
  out.trials = trials;
  out.rms = std::sqrt(total / static_cast<double>(trials));
  out.formula_rms = std::sqrt(cov.trace());
  out.rel_diff = out.rms / out.formula_rms - 1.0;
  return out;
}

}  // namespace vantage::tracker

// Proves that the orientation solvers allocate nothing per solve (STYLE.md 16), with the counter
// of tests/support/allocation_counter.h.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "support/allocation_counter.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/haralick_2d.h"

namespace vantage {
namespace {

// The determinant of a computed rotation: 1 to rounding.
constexpr double kDeterminantRounding = 1e-12;

using testing::CountAllocations;
using testing::kSeed;

constexpr int kSolves = 100;

struct Data {
  Eigen::Matrix3Xd z;
  Eigen::Matrix3Xd q;
  Eigen::VectorXd w;
};

Data make_data(int n) {
  std::mt19937 rng(kSeed + 60);
  std::normal_distribution<double> noise(0.0, 0.01);
  Data d{testing::random_points(rng, n), Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n)};
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  for (int j = 0; j < n; ++j) {
    d.q.col(j) = (R * d.z.col(j) + Eigen::Vector3d(1, 2, 5)) / 2.0;
    for (int i = 0; i < 3; ++i) d.q(i, j) += noise(rng);
    d.w(j) = 0.5 + 0.1 * j;
  }
  return d;
}

TEST(Allocation, TheCounterSeesOperatorNewAndMalloc) {
  // Without this control, a broken counter would make every test below pass.
  long with_new = 0, with_eigen = 0;
  {
    CountAllocations counter;
    std::vector<double> v(1000, 1.0);
    with_new = counter.count();
    Eigen::MatrixXd m = Eigen::MatrixXd::Ones(50, 50);  // Eigen's aligned_malloc -> malloc
    with_eigen = counter.count() - with_new;
    EXPECT_GT(v[0] + m(0, 0), 0.0);
  }
  EXPECT_GE(with_new, 1);
  EXPECT_GE(with_eigen, 1);
}

TEST(Allocation, AbsoluteOrientationAndPoseAllocateNothingPerSolve) {
  const Data d = make_data(10);
  for (const OrientationMethod method :
       {OrientationMethod::kQMethod, OrientationMethod::kSvd, OrientationMethod::kFoam}) {
    for (const bool full_solver : {false, true}) {
      OrientationOptions options;
      options.method = method;
      options.eigen.force_full_solver = full_solver;  // the fallback path, too
      OrientationResult orientation = absolute_orientation(d.z, d.q, d.w, options);  // warm-up
      PoseResult pose = absolute_pose(d.z, d.q, {}, options);
      long count = 0;
      {
        CountAllocations counter;
        for (int k = 0; k < kSolves; ++k) {
          orientation = absolute_orientation(d.z, d.q, d.w, options);
          pose = absolute_pose(d.z, d.q, {}, options);
        }
        count = counter.count();
      }
      EXPECT_EQ(count, 0) << to_string(method) << (full_solver ? " (full solver)" : "");
      EXPECT_EQ(orientation.status, OrientationStatus::kOk);
      EXPECT_EQ(pose.status, OrientationStatus::kOk);
    }
  }
}

TEST(Allocation, OptimalRotationAllocatesNothing) {
  const Data d = make_data(8);
  const Eigen::Matrix3d H = d.z * d.q.transpose();
  for (const OrientationMethod method :
       {OrientationMethod::kQMethod, OrientationMethod::kSvd, OrientationMethod::kFoam}) {
    OrientationOptions options;
    options.method = method;
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    double gap = 0.0;
    long count = 0;
    {
      CountAllocations counter;
      for (int k = 0; k < kSolves; ++k) R = optimal_rotation(H, options, &gap);
      count = counter.count();
    }
    EXPECT_EQ(count, 0) << to_string(method);
    EXPECT_GT(gap, 0.0);
    EXPECT_NEAR(R.determinant(), 1.0, kDeterminantRounding);
  }
}

TEST(Allocation, Pose2dAllocatesNothingPerSolve) {
  const Eigen::Matrix2Xd from = Eigen::Matrix2Xd::Random(2, 10);
  const Eigen::Matrix2Xd to =
      (Eigen::Rotation2Dd(0.7).toRotationMatrix() * from).colwise() + Eigen::Vector2d(0.1, 0.2);
  Pose2dResult result = pose_2d(from, to);
  long count = 0;
  {
    CountAllocations counter;
    for (int k = 0; k < kSolves; ++k) result = pose_2d(from, to);
    count = counter.count();
  }
  EXPECT_EQ(count, 0);
  EXPECT_EQ(result.status, Pose2dStatus::kOk);
}

}  // namespace
}  // namespace vantage

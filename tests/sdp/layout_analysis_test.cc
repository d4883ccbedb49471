#include "vantage/sdp/layout_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {
namespace {

// CSDP's t is accurate to about 1e-7.
constexpr double kSdp = 1e-6;

TEST(AnalyzeVectors, OrthogonalTriadReport) {
  const LayoutAnalysis r = analyze_vectors(Eigen::Matrix3d::Identity());
  EXPECT_NEAR(r.pbar_min, std::sqrt(2.0 / 3.0), 1e-9);
  EXPECT_EQ(r.worst_viewpoints.size(), 4u);
  EXPECT_TRUE(r.certificate.certified);
  EXPECT_LE(r.certificate.t_upper - r.certificate.t_lower, 1e-9);
  ASSERT_EQ(r.worst_case_errors_deg.size(), 3);
  // Every p_i equals p-bar at (1,1,1)/sqrt(3): the error is acos(p-bar) = 35.26 degrees.
  EXPECT_NEAR(r.max_worst_case_error_deg, std::acos(std::sqrt(2.0 / 3.0)) * 180.0 / M_PI, 1e-9);
  EXPECT_NEAR(r.paper_lmi.t, r.t, kSdp);
  EXPECT_EQ(r.paper_lmi.status, "ok");
  EXPECT_EQ(r.crosscheck.method, "nlopt_multistart_cobyla");
  EXPECT_TRUE(r.crosscheck.agrees) << r.crosscheck.message;
  EXPECT_EQ(r.swaps.size(), 3u);
  EXPECT_EQ(r.solver.backend, "csdp");
  EXPECT_EQ(r.solver.status, "certified");
  EXPECT_EQ(r.solver.sdp_status, "optimal");
  EXPECT_GT(r.solver.cells_solved, 0);
  EXPECT_TRUE(r.message.empty()) << r.message;
}

TEST(AnalyzeVectors, RandomLayoutIsConsistent) {
  std::mt19937 rng(testing::kSeed);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 12, 3.0);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(12, 0.5, 2.0);
  const LayoutAnalysis r = analyze_vectors(z, w);
  EXPECT_TRUE(r.certificate.certified);
  EXPECT_GE(r.paper_lmi.pbar, r.pbar_min - kSdp);
  EXPECT_TRUE(r.crosscheck.agrees) << r.crosscheck.message;
  EXPECT_EQ(r.swaps.size(), 5u);
  EXPECT_TRUE(r.worst_case_errors_deg.allFinite());
  EXPECT_NEAR(r.max_worst_case_error_deg, r.worst_case_errors_deg.maxCoeff(), 0.0);
  EXPECT_THROW(analyze_vectors(z, Eigen::VectorXd::Ones(3)), InvalidArgument);
  EXPECT_THROW(analyze_vectors(Eigen::Matrix3Xd(3, 1)), InvalidArgument);
}

}  // namespace
}  // namespace vantage::sdp

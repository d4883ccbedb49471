#include "vantage/report/dropout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::report {
namespace {

using testing::kSeed;

// Two global solves of the same vectors agree to rounding.
constexpr double kExact = 1e-12;
// The branch and bound certifies t to 1e-9 (WorstViewpointOptions::certificate_tolerance).
constexpr double kCertified = 1e-9;

// arccos of a p-bar certified to kCertified, in degrees: 57 x 1e-9 / sin(45 deg) = 8e-8.
constexpr double kCertifiedDeg = 1e-6;
// A viewpoint component at an optimum certified to 1e-9 in t: the optimum is a vertex, so the
// viewpoint moves by the same order; this leaves room.
constexpr double kCertifiedViewpoint = 1e-6;
// The same p-bar up to kExact, in degrees.
constexpr double kDegreesRounding = 1e-9;
// A dot product of a unit viewpoint with an exact vector of norm sqrt(5).
constexpr double kRounding = 1e-12;

Layout vector_layout(const Eigen::Matrix3Xd& vectors) {
  Layout layout;
  layout.mode = LayoutMode::kVectors;
  layout.entries = vectors;
  layout.weights = Eigen::VectorXd::Ones(vectors.cols());
  return layout;
}

Layout point_layout(const Eigen::Matrix3Xd& points) {
  Layout layout = vector_layout(points);
  layout.mode = LayoutMode::kPoints;
  return layout;
}

// The layout without entry k.
Layout without(const Layout& layout, int k) {
  Layout out = layout;
  const Eigen::Index n = layout.entries.cols();
  out.entries.resize(3, n - 1);
  out.weights.resize(n - 1);
  for (Eigen::Index i = 0, j = 0; i < n; ++i) {
    if (i == k) continue;
    out.entries.col(j) = layout.entries.col(i);
    out.weights(j++) = layout.weights(i);
  }
  return out;
}

TEST(Dropout, TriadWithoutOneVectorIsTwoOrthogonalVectors) {
  // Two orthogonal unit vectors: max_a min(|a.e1|, |a.e2|) = 1/sqrt(2) at a = (e1 + e2)/sqrt(2),
  // so p-bar_min = 1/sqrt(2) and the largest error is 45 degrees.
  const DropoutAnalysis result = dropout_analysis(vector_layout(Eigen::Matrix3d::Identity()));
  ASSERT_EQ(result.entries.size(), 3u);
  EXPECT_EQ(result.status, DropoutAnalysis::Status::kCertified);
  EXPECT_TRUE(result.message.empty());
  for (int k = 0; k < 3; ++k) {
    const DropoutEntry& e = result.entries[k];
    EXPECT_EQ(e.index, k);
    EXPECT_EQ(e.n_vectors, 2);
    EXPECT_NEAR(e.worst.pbar_min, std::sqrt(0.5), kCertified);
    EXPECT_NEAR(e.worst.max_worst_case_error_deg, 45.0, kCertifiedDeg);
    EXPECT_NEAR(std::abs(e.worst.viewpoint(k)), 0.0, kCertifiedViewpoint)
        << "the lost axis is in a-perp";
    EXPECT_TRUE(e.worst.certified);
  }
}

TEST(Dropout, MatchesTheAnalysisOfTheReducedLayoutAndNeverRaisesPbar) {
  std::mt19937 rng(kSeed);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::Matrix3Xd points(3, 6);
    for (Eigen::Index i = 0; i < points.size(); ++i) points.data()[i] = gauss(rng);
    const Layout layout = point_layout(points);
    const DataVectors data = data_vectors(layout);
    sdp::LayoutAnalysisOptions options;
    options.run_crosscheck = false;
    const sdp::LayoutAnalysis intact = sdp::analyze_vectors(data.vectors, data.weights, options);
    const DropoutAnalysis result = dropout_analysis(layout);
    ASSERT_EQ(result.entries.size(), 6u);
    for (int k = 0; k < 6; ++k) {
      const DropoutEntry& e = result.entries[k];
      const DataVectors reduced = data_vectors(without(layout, k));
      const sdp::LayoutAnalysis direct =
          sdp::analyze_vectors(reduced.vectors, reduced.weights, options);
      EXPECT_EQ(e.n_vectors, 10) << "5 markers left: 10 free vectors";
      EXPECT_NEAR(e.worst.pbar_min, direct.pbar_min, kExact)
          << "trial " << trial << " marker " << k;
      EXPECT_NEAR(e.worst.max_worst_case_error_deg, direct.max_worst_case_error_deg,
                  kDegreesRounding);
      EXPECT_LE(e.worst.pbar_min, intact.pbar_min + kExact);
    }
  }
}

TEST(Dropout, ByHarmIsSortedByIncreasingPbar) {
  std::mt19937 rng(kSeed + 1);
  std::normal_distribution<double> gauss;
  Eigen::Matrix3Xd vectors(3, 7);
  for (Eigen::Index i = 0; i < vectors.size(); ++i) vectors.data()[i] = gauss(rng);
  const DropoutAnalysis result = dropout_analysis(vector_layout(vectors));
  ASSERT_EQ(result.by_harm.size(), 7u);
  for (std::size_t k = 1; k < result.by_harm.size(); ++k) {
    EXPECT_LE(result.entries[result.by_harm[k - 1]].worst.pbar_min,
              result.entries[result.by_harm[k]].worst.pbar_min + kExact);
  }
}

TEST(Dropout, DeterministicForAnyThreadCount) {
  std::mt19937 rng(kSeed + 2);
  std::normal_distribution<double> gauss;
  Eigen::Matrix3Xd points(3, 7);
  for (Eigen::Index i = 0; i < points.size(); ++i) points.data()[i] = gauss(rng);
  DropoutOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const DropoutAnalysis a = dropout_analysis(point_layout(points), one);
  const DropoutAnalysis b = dropout_analysis(point_layout(points), three);
  ASSERT_EQ(a.entries.size(), b.entries.size());
  EXPECT_EQ(a.by_harm, b.by_harm);
  for (std::size_t k = 0; k < a.entries.size(); ++k) {
    EXPECT_EQ(a.entries[k].worst.pbar_min, b.entries[k].worst.pbar_min);
    EXPECT_EQ(a.entries[k].worst.viewpoint, b.entries[k].worst.viewpoint);
  }
}

TEST(Dropout, ThreeMarkersLeaveOneVectorSeenEndOn) {
  Eigen::Matrix3Xd points(3, 3);
  points << 0, 1, 0,  //
      0, 0, 2,        //
      0, 0, 0;
  const DropoutAnalysis result = dropout_analysis(point_layout(points));
  for (const DropoutEntry& e : result.entries) {
    EXPECT_EQ(e.n_vectors, 1);
    EXPECT_EQ(e.worst.pbar_min, 0.0);
    EXPECT_EQ(e.worst.max_worst_case_error_deg, 90.0);
    EXPECT_TRUE(e.worst.certified);
  }
  // Without marker 0 the free vector is p2 - p1 = (-1, 2, 0): the worst viewpoint is along it.
  EXPECT_NEAR(std::abs(result.entries[0].worst.viewpoint.dot(Eigen::Vector3d(-1, 2, 0))),
              std::sqrt(5.0), kRounding);
}

TEST(Dropout, RejectsBadOptionsAndLayouts) {
  DropoutOptions options;
  options.threads = -1;
  std::string why;
  EXPECT_FALSE(options.is_valid(&why));
  EXPECT_NE(why.find("threads"), std::string::npos);
  EXPECT_THROW(dropout_analysis(vector_layout(Eigen::Matrix3d::Identity()), options),
               InvalidArgument);
  EXPECT_THROW(dropout_analysis(vector_layout(Eigen::Matrix3Xd::Zero(3, 3))), InvalidArgument);
}

}  // namespace
}  // namespace vantage::report

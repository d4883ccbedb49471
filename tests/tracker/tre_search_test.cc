// The worst and best TRE over the tracked directions (docs/math.md §23): certified, attained at a
// tracked direction with the reported visible set, and never beaten by a dense lattice of
// directions with exact visibility; with and without normals, and the branch and bound against
// the closed form.

#include "vantage/tracker/tre_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "vantage/analysis/common.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/visibility/visibility.h"

namespace vantage::tracker {
namespace {

// Attained values are recomputed from the same formula: a few roundings.
constexpr double kRecompute = 1e-12;
// The search's default relative tolerance on the RMS, plus rounding.
constexpr double kCertificate = 1e-6 + 1e-12;
constexpr int kLattice = 40000;

visibility::VisibilityProblem five_marker_tool() {
  visibility::VisibilityProblem problem;
  problem.points.resize(3, 5);
  problem.points << 40, -20, -20, 0, 10, 0, 35, -35, 0, 10, 0, 10, 10, 45, -30;
  const Eigen::Vector3d centroid = problem.points.rowwise().mean();
  problem.normals = (problem.points.colwise() - centroid).colwise().normalized();
  problem.cos_cone = Eigen::VectorXd::Constant(5, std::cos(75.0 * kPi / 180.0));
  problem.cos_cone(4) = std::cos(100.0 * kPi / 180.0);
  problem.min_visible = 3;
  return problem;
}

visibility::VisibilityProblem seen_whole(const Eigen::Matrix3Xd& points) {
  visibility::VisibilityProblem problem;
  problem.points = points;
  problem.normals = Eigen::Matrix3Xd::Zero(3, points.cols());
  problem.normals.row(2).setOnes();
  problem.cos_cone = Eigen::VectorXd::Constant(points.cols(), -1.0);
  return problem;
}

double rms_at(const visibility::VisibilityProblem& problem, const Eigen::Vector3d& target,
              const FleModel& fle, const Eigen::Vector3d& a, bool* tracked,
              std::vector<int>* visible = nullptr) {
  const visibility::DirectionVisibility seen = visibility::direction_visibility(problem, a);
  *tracked = seen.trackable;
  if (visible != nullptr) *visible = seen.visible;
  if (!seen.trackable) return 0.0;
  return std::sqrt(tre_covariance(problem.points, seen.visible, target, fle, a).trace());
}

void expect_extremes_hold(const visibility::VisibilityProblem& problem,
                          const Eigen::Vector3d& target, const FleModel& fle,
                          const TreExtremes& e) {
  ASSERT_TRUE(e.worst.certified());
  ASSERT_TRUE(e.best.certified());
  for (const TreExtreme* x : {&e.worst, &e.best}) {
    bool tracked = false;
    std::vector<int> visible;
    const double rms = rms_at(problem, target, fle, x->direction, &tracked, &visible);
    EXPECT_TRUE(tracked);
    EXPECT_EQ(visible, x->visible_markers);
    EXPECT_NEAR(rms, x->rms, kRecompute * rms);
  }
  const Eigen::Matrix3Xd lattice = visibility::fibonacci_directions(kLattice);
  int tracked_count = 0;
  for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
    bool tracked = false;
    const double rms = rms_at(problem, target, fle, lattice.col(k), &tracked);
    if (!tracked) continue;
    ++tracked_count;
    EXPECT_LE(rms, e.worst.rms_bound * (1.0 + kRecompute));
    EXPECT_GE(rms, e.best.rms_bound * (1.0 - kRecompute));
  }
  EXPECT_GT(tracked_count, kLattice / 10);  // the loop ran on a real share of the sphere
  EXPECT_LE(e.worst.rms_bound, e.worst.rms * (1.0 + kCertificate));
  EXPECT_GE(e.best.rms_bound, e.best.rms * (1.0 - kCertificate));
}

TEST(TreSearch, WorstAndBestWithNormalsHoldOnADenseLattice) {
  const visibility::VisibilityProblem problem = five_marker_tool();
  for (const FleModel& fle :
       {FleModel{0.0995, 0.2985}, FleModel{0.3, 0.1}, FleModel::isotropic(0.25)}) {
    const Eigen::Vector3d target(0.0, 0.0, -120.0);
    const TreExtremes e = tre_extremes(problem, target, fle);
    EXPECT_FALSE(e.worst.closed_form);
    expect_extremes_hold(problem, target, fle, e);
  }
}

// Issue 36, item 2: rms_bound equalled the attained value and a direction near it exceeded it
// by 1.3e-8 relative (the patches pruned within the tolerance were forgotten). A bound must hold
// to rounding: every direction of a dense cloud about each extreme, and of the lattice, is
// within it to kRounding.
constexpr double kRounding = 1e-13;
TEST(TreSearch, TheBoundsHoldToRoundingNearTheExtremes) {
  const visibility::VisibilityProblem problem = five_marker_tool();
  std::mt19937_64 rng(36);
  std::normal_distribution<double> normal(0.0, 1.0);
  int checked = 0;
  for (const Eigen::Vector3d& target :
       {Eigen::Vector3d(40.0, 10.0, -100.0), Eigen::Vector3d(0.0, 0.0, -120.0)}) {
    for (const FleModel& fle : {FleModel{0.0995, 0.2985}, FleModel::isotropic(0.25)}) {
      const TreExtremes e = tre_extremes(problem, target, fle);
      ASSERT_TRUE(e.worst.certified());
      ASSERT_TRUE(e.best.certified());
      for (const double spread : {1e-2, 1e-4, 1e-6}) {
        for (const TreExtreme* x : {&e.worst, &e.best}) {
          for (int k = 0; k < 4000; ++k) {
            const Eigen::Vector3d a =
                (x->direction + spread * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)))
                    .normalized();
            bool tracked = false;
            const double rms = rms_at(problem, target, fle, a, &tracked);
            if (!tracked) continue;
            ++checked;
            EXPECT_LE(rms, e.worst.rms_bound * (1.0 + kRounding)) << a.transpose();
            EXPECT_GE(rms, e.best.rms_bound * (1.0 - kRounding)) << a.transpose();
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 40000);
}

// Eight sites of the capsule of examples/bodies, cones of 90 degrees, a 75-degree workspace about
// +z: sites 3 and 7 face exactly opposite ways, so their cones share one edge, the great circle
// n3.a = 0, and on every patch across it both are at their cone's edge. No direction hides both;
// a bound that counted "both hidden" (the set {0, 5, 6}, RMS 1.85 against the true worst 1.54)
// never closed, and the search ended uncertified after its 2 000 000 patches (place --objective
// tracker on the capsule took minutes).
visibility::VisibilityProblem capsule_sites() {
  visibility::VisibilityProblem problem;
  problem.points.resize(3, 8);
  problem.normals.resize(3, 8);
  problem.points.transpose() << 0.18622071843474808, 0.15233284052912704, 0.9345697040594485,
      0.021526839161344218, -0.4971659620298815, 0.20091273239294449, -0.49761961269531951,
      -0.01808099086527782, 0.43107513373313605, 0.49785022394709849, -0.016329309561715306,
      0.48854946414557832, -0.49612383459510134, 0.0068522895290595211, -0.53019718713809516,
      0.12743592512463087, 0.48322288526181245, 0.3933423808020321, 0.036336067308854129,
      -0.37873161477864825, 0.81704417202413948, -0.48628869339600223, 0.10414860177183749,
      -0.15737221543828095;
  problem.normals.transpose() << 0.37648731095875104, 0.28888814340231028, 0.88022778034359661,
      0.13052509797754613, -0.991445005432955, 0.0, -0.991445005432955, -0.13052509797754613, 0.0,
      0.991445005432955, -0.13052509797754613, 0.0, -0.98675203383402732, 0.12990726181477444,
      -0.097182956593213327, 0.13052509797754613, 0.991445005432955, 0.0, 0.10124660992845431,
      -0.76903413097047402, 0.63113835993424061, -0.991445005432955, 0.13052509797754613, 0.0;
  problem.cos_cone = Eigen::VectorXd::Zero(8);
  problem.min_visible = 3;
  problem.workspace = visibility::Workspace{Eigen::Vector3d::UnitZ(), std::cos(75.0 * kPi / 180.0)};
  return problem;
}

// A certificate of a few thousand patches, not the budget.
constexpr long kFewPatches = 100000;
void expect_certified_in_few_patches(const visibility::VisibilityProblem& problem,
                                     const Eigen::Vector3d& target) {
  const FleModel fle = FleModel::isotropic(0.25);
  const TreExtremes e = tre_extremes(problem, target, fle);
  EXPECT_LT(e.worst.patches, kFewPatches);
  expect_extremes_hold(problem, target, fle, e);
}

TEST(TreSearch, OppositeConesAreNeverHiddenTogether) {
  const visibility::VisibilityProblem problem = capsule_sites();
  ASSERT_EQ(problem.normals.col(3), -problem.normals.col(7));
  expect_certified_in_few_patches(problem, Eigen::Vector3d(0.0, 0.0, -3.0));
}

// Two markers that the body hides in complementary cells of the occlusion grid (marker 4 where
// u < -1/3 on a face, marker 5 elsewhere): no direction hides both, yet every patch across
// u = -1/3 has both mixed. Bounded cell by cell, the search certifies.
TEST(TreSearch, ComplementaryShadowsAreNeverHiddenTogether) {
  Eigen::Matrix3Xd points(3, 6);
  points << 40, -20, -20, 0, 25, -10, 0, 35, -35, 0, 20, -25, 10, 10, 45, -30, 5, 0;
  visibility::VisibilityProblem problem = seen_whole(points);
  problem.min_visible = 3;
  constexpr int kCells = 3;  // cell edges at u = +-1/3, which no patch edge meets
  OcclusionGrid grid(6, kCells);
  for (int face = 0; face < 6; ++face) {
    for (int i = 0; i < kCells; ++i) {
      for (int j = 0; j < kCells; ++j) {
        grid.set_blocked(4, face, i, j, i == 0);
        grid.set_blocked(5, face, i, j, i != 0);
      }
    }
  }
  grid.finish();
  problem.occlusion = &grid;
  expect_certified_in_few_patches(problem, Eigen::Vector3d(0.0, 0.0, -120.0));
}

// The TRE is homogeneous: markers, target and FLE all scaled by s scale every RMS by s. At the
// ends of the numeric range (docs/math.md §23) the search must still give the unit tool's
// answers times s (the cofactor inverse of Lambda left the range of doubles there: an RMS of nan).
TEST(TreSearch, ScaledToTheEndsOfTheRangeTheRmsScales) {
  const visibility::VisibilityProblem unit = five_marker_tool();
  const Eigen::Vector3d target(40.0, 10.0, -100.0);
  const FleModel fle{0.0995, 0.2985};
  const TreExtremes reference = tre_extremes(unit, target, fle);
  for (const double s : {1e-45, 1e45}) {
    visibility::VisibilityProblem scaled = unit;
    scaled.points *= s;
    const TreExtremes e =
        tre_extremes(scaled, s * target, FleModel{s * fle.sigma_perp, s * fle.sigma_axial});
    ASSERT_TRUE(e.worst.certified()) << s;
    EXPECT_NEAR(e.worst.rms / s, reference.worst.rms, 1e-9 * reference.worst.rms) << s;
    EXPECT_NEAR(e.best.rms / s, reference.best.rms, 1e-9 * reference.best.rms) << s;
    EXPECT_NEAR(e.worst.rms_bound / s, reference.worst.rms_bound, 1e-9 * reference.worst.rms) << s;
  }
}

TEST(TreSearch, WithoutNormalsTheWorstIsTheTopEigenvector) {
  const visibility::VisibilityProblem problem = seen_whole(five_marker_tool().points);
  const FleModel fle{0.0995, 0.2985};
  const Eigen::Vector3d target(5.0, 0.0, -150.0);
  const TreExtremes e = tre_extremes(problem, target, fle);
  EXPECT_TRUE(e.worst.closed_form);
  expect_extremes_hold(problem, target, fle, e);
  // The branch and bound on (nearly) the same sphere reaches the closed form's values.
  visibility::VisibilityProblem capped = problem;
  capped.workspace = visibility::Workspace{Eigen::Vector3d::UnitZ(), -1.0 + 1e-12};
  const TreExtremes searched = tre_extremes(capped, target, fle);
  EXPECT_FALSE(searched.worst.closed_form);
  ASSERT_TRUE(searched.worst.certified());
  EXPECT_NEAR(searched.worst.rms, e.worst.rms, kCertificate * e.worst.rms);
  EXPECT_NEAR(searched.best.rms, e.best.rms, kCertificate * e.best.rms);
}

TEST(TreSearch, NoTrackedDirectionIsUntracked) {
  visibility::VisibilityProblem problem = five_marker_tool();
  problem.min_visible = 5;
  problem.cos_cone.setConstant(std::cos(20.0 * kPi / 180.0));
  const TreExtremes e = tre_extremes(problem, Eigen::Vector3d::Zero(), FleModel{0.1, 0.3});
  EXPECT_EQ(e.worst.status, TreExtreme::Status::kUntracked);
  EXPECT_EQ(e.best.status, TreExtreme::Status::kUntracked);
}

}  // namespace
}  // namespace vantage::tracker

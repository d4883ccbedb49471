// place_markers() with robust_dropout (docs/math.md §21): the robust value is the worst single
// loss, as `vantage analyze --dropout` reports it, against independent certified searches of the
// answer without each marker (it was the worst loss of two markers).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/sanitized.h"

#include "vantage/analysis/common.h"
#include "vantage/design/placement.h"
#include "vantage/visibility/visibility.h"

namespace vantage::design {
namespace {

// Two certified t_upper closer than the certificate tolerance are not told apart.
constexpr double kCertificate = 2e-6;

// Eight sites on a 2 x 2 plate, two per normal; the normals tilted 30 deg from +z towards +x,
// -x, +y and -y; cones 56 deg; min_visible 3; the workspace 30 deg about +z. A direction tilted
// towards one side sees three of the four normals (the opposite one is 60 deg away), a diagonal
// one all four: after the loss of two markers a 4-subset tracks nothing, after one it does.
visibility::VisibilityProblem tilted_plate() {
  const double tilt = 30.0 * kPi / 180.0;
  const Eigen::Vector3d normals[4] = {{std::sin(tilt), 0.0, std::cos(tilt)},
                                      {-std::sin(tilt), 0.0, std::cos(tilt)},
                                      {0.0, std::sin(tilt), std::cos(tilt)},
                                      {0.0, -std::sin(tilt), std::cos(tilt)}};
  const double xy[8][2] = {{1.0, 0.1}, {0.3, -0.9},  {-1.0, 0.4}, {-0.2, 0.8},
                           {0.5, 1.0}, {-0.7, -0.3}, {0.9, -0.6}, {0.0, -1.0}};
  visibility::VisibilityProblem out;
  out.points.resize(3, 8);
  out.normals.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    out.points.col(i) = Eigen::Vector3d(xy[i][0], xy[i][1], 0.1 * i);
    out.normals.col(i) = normals[i % 4];
  }
  out.cos_cone = Eigen::VectorXd::Constant(8, std::cos(56.0 * kPi / 180.0));
  out.min_visible = 3;
  out.workspace = visibility::Workspace{Eigen::Vector3d::UnitZ(), std::cos(30.0 * kPi / 180.0)};
  return out;
}

visibility::VisibilityProblem subset(const visibility::VisibilityProblem& all,
                                     const std::vector<int>& chosen) {
  visibility::VisibilityProblem out = all;
  const Eigen::Index k = static_cast<Eigen::Index>(chosen.size());
  out.points.resize(3, k);
  out.normals.resize(3, k);
  out.cos_cone.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int s = chosen[static_cast<std::size_t>(j)];
    out.points.col(j) = all.points.col(s);
    out.normals.col(j) = all.normals.col(s);
    out.cos_cone(j) = all.cos_cone(s);
  }
  return out;
}

double t_of(const visibility::VisibilityProblem& p) {
  const visibility::VisibilityWorstViewpoint w = visibility::visibility_worst_viewpoint(p);
  EXPECT_NE(w.status, visibility::VisibilityWorstViewpoint::Status::kNotCertified);
  return w.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable ? 1.0 : w.t_upper;
}

TEST(PlaceRobust, TheRobustValueIsTheWorstSingleLoss) {
  const visibility::VisibilityProblem sites = tilted_plate();
  // Under the sanitizers K = 4 alone (the same code, a third of the time).
  for (int markers : testing::kUnderSanitizer ? std::vector<int>{4} : std::vector<int>{4, 5}) {
    SCOPED_TRACE(markers);
    PlacementProblem problem;
    problem.sites = sites;
    problem.markers = markers;
    PlaceOptions options;
    options.robust_dropout = true;
    options.random_trials = 20;
    const PlacementResult result = place_markers(problem, options);
    ASSERT_TRUE(result.robust.has_value());
    double worst = -1.0;
    int lost = -1;
    for (std::size_t m = 0; m < result.chosen.size(); ++m) {
      std::vector<int> rest = result.chosen;
      rest.erase(rest.begin() + static_cast<long>(m));
      const double t = t_of(subset(sites, rest));
      if (t > worst) {
        worst = t;
        lost = result.chosen[m];
      }
    }
    ASSERT_LT(worst, 1.0);  // trackable after any single loss
    EXPECT_NEAR(result.robust->objective, worst, kCertificate);
    EXPECT_NEAR(result.robust->pbar_min, std::sqrt(1.0 - worst * worst), kCertificate);
    EXPECT_EQ(result.robust->worst_lost_marker, lost);
  }
}

}  // namespace
}  // namespace vantage::design

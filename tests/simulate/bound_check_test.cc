#include "vantage/simulate/bound_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/io/layout_file.h"
#include "vantage/simulate/monte_carlo.h"

namespace vantage::simulate {
namespace {

constexpr long kTrials = 60;
// The acos form of Eq. (26) in analysis/error_bounds.h loses up to ~sqrt(eps) near p = p_bar.
constexpr double kAcosForm = 1e-7;
// At the worst viewpoint the limiting vector's error is asin(t_lower), the bound asin(t_upper):
// the certificate tolerance (1e-9) apart.
constexpr double kAtWorstViewpoint = 1e-6;

// p-bar_min = sqrt(1 - t^2) with t certified to the certificate tolerance (1e-9).
constexpr double kCertifiedPbar = 1e-9;
// The paper prints the triad's bound to four decimals (35.2644 degrees).
constexpr double kPaperDigits = 1e-4;

struct Case {
  std::string name;
  Eigen::Matrix3Xd entries;
  bool vectors;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  const std::filesystem::path dir = std::filesystem::path(VANTAGE_SOURCE_DIR) / "examples/layouts";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;  // JSON layouts only (YAML, CSV: io tests)
    const Layout layout = io::read_layout(entry.path().string());
    all.push_back(
        {entry.path().stem().string(), layout.entries, layout.mode == LayoutMode::kVectors});
  }
  TrialRandom random(testing::kSeed);
  for (int i = 0; i < 12; ++i) {
    const bool vectors = i % 2 == 1;
    const int n = vectors ? 3 + i % 5 : 4 + i % 3;
    Eigen::Matrix3Xd entries(3, n);
    for (int j = 0; j < n; ++j) {
      entries.col(j) = vectors ? random.unit_vector()
                               : Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1),
                                                 random.uniform(-1, 1));
    }
    all.push_back({"random" + std::to_string(i), entries, vectors});
  }
  return all;
}

BoundCheck run_check(const Case& c, const LayoutSceneOptions& scene, const BoundLayout& layout) {
  std::vector<BoundTrial> trials;
  for (long t = 0; t < kTrials; ++t) {
    TrialRandom random = TrialRandom::for_trial(11, t);
    trials.push_back(
        check_bound_trial(layout, make_layout_scene(c.entries, c.vectors, scene, random)));
  }
  return summarize_bound_check(layout, trials);
}

TEST(BoundCheck, HoldsOnEveryExampleAndRandomLayout) {
  const std::vector<Case> all = cases();
  ASSERT_GE(all.size(), 16u);
  for (const Case& c : all) {
    const BoundLayout layout = prepare_bound_layout(c.entries, c.vectors);
    LayoutSceneOptions scene;
    scene.noise_px = 3.0;  // ignored by the check: it uses the noise-free image
    const BoundCheck check = run_check(c, scene, layout);
    EXPECT_TRUE(check.passed) << c.name;
    EXPECT_LE(check.max_ratio, 1.0 + kBoundRatioTolerance) << c.name;
    EXPECT_LE(check.max_abs_eq26_mismatch_deg, kEq26Tolerance * kDegreesPerRadian) << c.name;
    EXPECT_GT(check.max_error_deg, 0.0) << c.name;
    EXPECT_EQ(check.trials, kTrials);
  }
}

TEST(BoundCheck, IsReachedAtTheWorstViewpoint) {
  for (const Case& c : cases()) {
    const BoundLayout layout = prepare_bound_layout(c.entries, c.vectors);
    LayoutSceneOptions scene;
    scene.viewpoint = layout.data.worst_viewpoint;
    const BoundCheck check = run_check(c, scene, layout);
    EXPECT_NEAR(check.max_ratio, 1.0, kAtWorstViewpoint) << c.name;
    EXPECT_TRUE(check.passed) << c.name;
  }
}

TEST(BoundCheck, TriadMatchesThePaper) {
  const BoundLayout layout = prepare_bound_layout(Eigen::Matrix3d::Identity(), true);
  EXPECT_NEAR(layout.data.pbar_min, std::sqrt(2.0 / 3.0), kCertifiedPbar);
  EXPECT_NEAR(layout.data.bound_rad * kDegreesPerRadian, 35.2644, kPaperDigits);
  EXPECT_EQ(layout.affine.free_vectors, "vectors");
}

TEST(BoundCheck, StableEq26AgreesWithTheAcosForm) {
  const Case c = cases().front();
  const BoundLayout layout = prepare_bound_layout(c.entries, c.vectors);
  int compared = 0;
  for (long t = 0; t < 20; ++t) {
    TrialRandom random = TrialRandom::for_trial(3, t);
    const VectorErrors v =
        vector_errors(layout, make_layout_scene(c.entries, c.vectors, {}, random));
    for (Eigen::Index k = 0; k < v.p.size(); ++k) {
      EXPECT_NEAR(v.eq26_rad(k), lub_scale_error_angle(std::min(v.p(k), v.pbar), v.pbar),
                  kAcosForm);
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}

TEST(BoundCheck, SpanningSubsetHasTheLargerBound) {
  int checked = 0;
  for (const Case& p : cases()) {
    if (p.vectors) continue;
    const BoundLayout layout = prepare_bound_layout(p.entries, false);
    EXPECT_LE(layout.spanning.pbar_min, layout.data.pbar_min + kCertifiedPbar) << p.name;
    EXPECT_EQ(layout.spanning.vectors.cols(), p.entries.cols() - 1);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace vantage::simulate

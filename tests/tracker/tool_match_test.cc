// The distance mismatch between tools (docs/math.md §24, Eq. 24.4) against the enumeration of
// every subset and every injective assignment, its symmetry, mirror images and the budget.

#include "vantage/tracker/tool_match.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "support/message_of.h"

namespace vantage::tracker {
namespace {

using ::testing::HasSubstr;
using testing::kSeed;
using testing::message_of;
using testing::random_points;
using testing::random_rotation;

// A perfect (zero-mismatch) match still differs from 0 by the rounding of the distances.
constexpr double kZeroMismatch = 1e-12;

double tool_distance(const Eigen::Matrix3Xd& p, int i, int j) {
  return (p.col(i) - p.col(j)).norm();
}

double mismatch_of(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, const std::vector<int>& s,
                   const std::vector<int>& sigma) {
  double worst = 0.0;
  for (std::size_t x = 0; x < s.size(); ++x) {
    for (std::size_t y = x + 1; y < s.size(); ++y) {
      worst = std::max(
          worst, std::abs(tool_distance(a, s[x], s[y]) - tool_distance(b, sigma[x], sigma[y])));
    }
  }
  return worst;
}

// Every k-subset of A (a bit mask) and every ordered k-tuple of distinct markers of B (every
// permutation of every k-subset of B); `self` skips sigma equal to the inclusion.
double brute_mismatch(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, int k, bool self) {
  const int na = static_cast<int>(a.cols());
  const int nb = static_cast<int>(b.cols());
  double best = std::numeric_limits<double>::infinity();
  long tried = 0;
  for (int mask = 0; mask < (1 << na); ++mask) {
    if (__builtin_popcount(static_cast<unsigned>(mask)) != k) continue;
    std::vector<int> s;
    for (int i = 0; i < na; ++i) {
      if (mask & (1 << i)) s.push_back(i);
    }
    for (int image = 0; image < (1 << nb); ++image) {
      if (__builtin_popcount(static_cast<unsigned>(image)) != k) continue;
      std::vector<int> sigma;
      for (int j = 0; j < nb; ++j) {
        if (image & (1 << j)) sigma.push_back(j);
      }
      do {
        if (self && sigma == s) continue;
        best = std::min(best, mismatch_of(a, b, s, sigma));
        ++tried;
      } while (std::next_permutation(sigma.begin(), sigma.end()));
    }
  }
  EXPECT_GT(tried, 0);
  return best;
}

TEST(MatchTools, EqualsEverySubsetAndAssignment) {
  std::mt19937 rng(kSeed + 10);
  for (int trial = 0; trial < 6; ++trial) {
    const int na = 4 + trial % 3;
    const int nb = 3 + (trial * 2) % 4;
    const Eigen::Matrix3Xd a = random_points(rng, na, 50.0);
    const Eigen::Matrix3Xd b = random_points(rng, nb, 50.0);
    for (int k = 2; k <= std::min(na, nb); ++k) {
      ToolMatchOptions options;
      options.min_visible = k;
      const ToolMatch got = match_tools(a, b, options);
      EXPECT_TRUE(got.certified);
      EXPECT_EQ(got.mismatch, brute_mismatch(a, b, k, false)) << "trial " << trial << " k " << k;
      EXPECT_EQ(got.mismatch_lower, got.mismatch);
      ASSERT_EQ(got.subset.size(), static_cast<std::size_t>(k));
      EXPECT_TRUE(std::is_sorted(got.subset.begin(), got.subset.end()));
      EXPECT_EQ(mismatch_of(a, b, got.subset, got.assignment), got.mismatch);
      // m(A, B) = m(B, A).
      EXPECT_EQ(match_tools(b, a, options).mismatch, got.mismatch);
    }
  }
}

TEST(SelfAmbiguity, EqualsEveryNonIdentityAssignment) {
  std::mt19937 rng(kSeed + 11);
  for (int n = 3; n <= 6; ++n) {
    const Eigen::Matrix3Xd a = random_points(rng, n, 50.0);
    for (int k = 2; k <= n; ++k) {
      ToolMatchOptions options;
      options.min_visible = k;
      const ToolMatch got = self_ambiguity(a, options);
      EXPECT_EQ(got.mismatch, brute_mismatch(a, a, k, true)) << "n " << n << " k " << k;
      EXPECT_NE(got.subset, got.assignment);
      // Two markers always pass for each other (the pair reversed); three or more do not.
      if (k >= 3) {
        EXPECT_GT(got.mismatch, 0.0);
      }
    }
  }
}

TEST(MatchTools, MirrorImageMatchesExactlyAsAReflection) {
  std::mt19937 rng(kSeed + 12);
  const Eigen::Matrix3Xd a = random_points(rng, 5, 40.0);
  // B: A mirrored, turned, moved and relabelled.
  Eigen::Matrix3Xd mirror = a;
  mirror.row(0) = -mirror.row(0);
  mirror = (random_rotation(rng) * mirror).colwise() + Eigen::Vector3d(100.0, -20.0, 5.0);
  const std::vector<int> labels = {3, 0, 4, 1, 2};
  Eigen::Matrix3Xd b(3, 5);
  for (int i = 0; i < 5; ++i) b.col(labels[static_cast<std::size_t>(i)]) = mirror.col(i);

  ToolMatchOptions options;
  options.min_visible = 4;
  const ToolMatch four = match_tools(a, b, options);
  EXPECT_LT(four.mismatch, kZeroMismatch * 40.0);
  EXPECT_EQ(four.transform, ToolMatch::Transform::kReflection);
  EXPECT_LT(four.improper_rms, kZeroMismatch * 40.0);
  EXPECT_GT(four.proper_rms, 1.0);
  for (std::size_t s = 0; s < four.subset.size(); ++s) {
    EXPECT_EQ(four.assignment[s], labels[static_cast<std::size_t>(four.subset[s])]);
  }

  // Three markers are coplanar: a rotation fits as well as a reflection.
  options.min_visible = 3;
  const ToolMatch three = match_tools(a, b, options);
  EXPECT_LT(three.mismatch, kZeroMismatch * 40.0);
  EXPECT_EQ(three.transform, ToolMatch::Transform::kEither);
  EXPECT_STREQ(to_string(three.transform), "either");

  // A turned copy matches by a rotation.
  const Eigen::Matrix3Xd turned = random_rotation(rng) * a;
  options.min_visible = 4;
  const ToolMatch rotated = match_tools(a, turned, options);
  EXPECT_LT(rotated.mismatch, kZeroMismatch * 40.0);
  EXPECT_EQ(rotated.transform, ToolMatch::Transform::kRotation);
}

TEST(MatchTools, OutOfBudgetBracketsTheTruth) {
  std::mt19937 rng(kSeed + 13);
  const Eigen::Matrix3Xd a = random_points(rng, 7, 50.0);
  const Eigen::Matrix3Xd b = random_points(rng, 7, 50.0);
  ToolMatchOptions options;
  options.min_visible = 4;
  const double truth = brute_mismatch(a, b, 4, false);
  options.max_comparisons = 20;
  const ToolMatch got = match_tools(a, b, options);
  EXPECT_FALSE(got.certified);
  EXPECT_GE(got.mismatch, truth);
  EXPECT_LE(got.mismatch_lower, truth);
}

TEST(MatchTools, RejectsToolsSmallerThanTheView) {
  ToolMatchOptions options;
  options.min_visible = 4;
  const Eigen::Matrix3Xd three = Eigen::Matrix3Xd::Identity(3, 3);
  const Eigen::Matrix3Xd four = Eigen::Matrix3Xd::Random(3, 4);
  EXPECT_THAT(message_of([&] { match_tools(four, three, options); }), HasSubstr("b"));
  EXPECT_THAT(message_of([&] { self_ambiguity(three, options); }), HasSubstr("a"));
  options.min_visible = 1;
  EXPECT_THAT(message_of([&] { match_tools(four, four, options); }),
              HasSubstr("options.min_visible"));
}

TEST(MatchToolLibrary, EveryPairOnceEachAsItsOwnSearch) {
  std::mt19937 rng(kSeed + 14);
  const std::vector<Eigen::Matrix3Xd> tools = {
      random_points(rng, 4, 50.0), random_points(rng, 5, 50.0), random_points(rng, 4, 50.0)};
  ToolMatchOptions options;
  const ToolLibraryMatches got = match_tool_library(tools, options);
  ASSERT_EQ(got.pairs.size(), 6u);
  EXPECT_TRUE(got.certified);
  double smallest = std::numeric_limits<double>::infinity();
  std::size_t k = 0;
  for (int a = 0; a < 3; ++a) {
    for (int b = a; b < 3; ++b, ++k) {
      const ToolPairMatch& p = got.pairs[k];
      EXPECT_EQ(p.a, a);
      EXPECT_EQ(p.b, b);
      const double truth = brute_mismatch(tools[static_cast<std::size_t>(a)],
                                          tools[static_cast<std::size_t>(b)], 3, a == b);
      EXPECT_EQ(p.match.mismatch, truth) << a << " " << b;
      smallest = std::min(smallest, truth);
    }
  }
  ASSERT_GE(got.closest, 0);
  EXPECT_EQ(got.pairs[static_cast<std::size_t>(got.closest)].match.mismatch, smallest);
  EXPECT_THAT(message_of([] { match_tool_library({}); }), HasSubstr("tools"));
  options.min_visible = 5;
  EXPECT_THAT(message_of([&] { match_tool_library(tools, options); }), HasSubstr("tools[0]"));
}

// Each tool is seen in views of its own k, a pair in views of the smaller of its two; the matrix
// holds every pair's mismatch both ways; each mismatch is the enumeration's at that k.
TEST(MatchToolLibrary, EachToolsOwnMinimumAndTheMatrix) {
  std::mt19937 rng(kSeed + 15);
  const std::vector<Eigen::Matrix3Xd> tools = {
      random_points(rng, 4, 50.0), random_points(rng, 5, 50.0), random_points(rng, 4, 50.0)};
  const std::vector<int> own = {4, 3, 4};
  const ToolLibraryMatches got = match_tool_library(tools, {}, own);
  EXPECT_EQ(got.min_visible, own);
  const Eigen::MatrixXd matrix = got.mismatch_matrix();
  for (const ToolPairMatch& p : got.pairs) {
    const int k = std::min(own[static_cast<std::size_t>(p.a)], own[static_cast<std::size_t>(p.b)]);
    EXPECT_EQ(p.min_visible, k);
    const double truth = brute_mismatch(tools[static_cast<std::size_t>(p.a)],
                                        tools[static_cast<std::size_t>(p.b)], k, p.a == p.b);
    EXPECT_EQ(p.match.mismatch, truth) << p.a << " " << p.b;
    EXPECT_EQ(matrix(p.a, p.b), truth);
    EXPECT_EQ(matrix(p.b, p.a), truth);
  }
  EXPECT_THAT(message_of([&] {
                match_tool_library(tools, {}, {4, 3});
              }),
              HasSubstr("min_visible: one per tool: 2 for 3 tools"));
  EXPECT_THAT(message_of([&] { match_tool_library(tools, {}, {5, 3, 4}); }), HasSubstr("tools[0]"));
}

// A copy moved rigidly and relabelled is the same tool; its mirror image is a mirror; a copy
// with one marker moved by 0.1 is distinct; so is a tool with another marker count. A tool with
// a mirror plane is the same tool as its reflection (a relabelling makes it a rotation).
TEST(MatchToolLibrary, VerdictsSameToolMirrorAndDistinct) {
  std::mt19937 rng(kSeed + 16);
  const Eigen::Matrix3Xd a = random_points(rng, 5, 50.0);
  const Eigen::Matrix3d r = random_rotation(rng);
  Eigen::Matrix3Xd moved = (r * a).colwise() + Eigen::Vector3d(10, -20, 300);
  moved.col(0).swap(moved.col(3));
  Eigen::Matrix3Xd mirror = a;
  mirror.row(0) *= -1.0;
  Eigen::Matrix3Xd bent = moved;
  bent(2, 1) += 0.1;
  const Eigen::Matrix3Xd more = random_points(rng, 6, 50.0);
  const ToolLibraryMatches got = match_tool_library({a, moved, mirror, bent, more});
  auto verdict = [&](int x, int y) {
    for (const ToolPairMatch& p : got.pairs) {
      if (p.a == x && p.b == y) return p.verdict;
    }
    return ToolPairMatch::Verdict::kSelf;
  };
  EXPECT_EQ(verdict(0, 0), ToolPairMatch::Verdict::kSelf);
  EXPECT_EQ(verdict(0, 1), ToolPairMatch::Verdict::kSameTool);
  EXPECT_EQ(verdict(0, 2), ToolPairMatch::Verdict::kMirror);
  EXPECT_EQ(verdict(1, 2), ToolPairMatch::Verdict::kMirror);
  EXPECT_EQ(verdict(0, 3), ToolPairMatch::Verdict::kDistinct);
  EXPECT_EQ(verdict(0, 4), ToolPairMatch::Verdict::kDistinct);
  EXPECT_STREQ(to_string(verdict(0, 1)), "same_tool");
  // The closest distinct pair is the bent copy (3) against the tool (0) or the moved copy (1).
  ASSERT_GE(got.closest_distinct, 0);
  const ToolPairMatch& closest = got.pairs[static_cast<std::size_t>(got.closest_distinct)];
  EXPECT_EQ(closest.verdict, ToolPairMatch::Verdict::kDistinct);
  EXPECT_EQ(closest.b, 3);
  EXPECT_LE(closest.a, 1);
  // A wider tolerance takes the bent copy for the tool.
  ToolMatchOptions loose;
  loose.same_tolerance = 0.2;
  EXPECT_EQ(match_tool_library({a, bent}, loose).pairs[1].verdict,
            ToolPairMatch::Verdict::kSameTool);
  // Mirror-symmetric: (x, y, z) -> (-x, y, z) maps the set onto itself.
  Eigen::Matrix3Xd symmetric(3, 5);
  symmetric << -20, 20, 0, 0, 0,  //
      0, 0, 35, -10, 5,           //
      0, 0, 0, 15, 40;
  Eigen::Matrix3Xd reflected = r * symmetric;
  reflected.row(1) *= -1.0;
  EXPECT_EQ(match_tool_library({symmetric, reflected}).pairs[1].verdict,
            ToolPairMatch::Verdict::kSameTool);
  // Nearly planar (5e-4 off its plane, as a real .rom): a rotation fits its mirror image within
  // the tolerance, so the two are one tool, whatever the labelling the search finds first.
  Eigen::Matrix3Xd flat = random_points(rng, 4, 50.0);
  flat.row(2) = 5e-4 * Eigen::RowVector4d(1, -1, 1, -1);
  Eigen::Matrix3Xd flat_mirror = flat;
  flat_mirror.row(0) *= -1.0;
  EXPECT_EQ(match_tool_library({flat, flat_mirror}).pairs[1].verdict,
            ToolPairMatch::Verdict::kSameTool);
  // S4 symmetry (a quarter turn about z with z -> -z) and no mirror plane: two generic orbits of
  // 4. Its proper symmetries (the half turn) and improper ones are both labellings onto itself;
  // its reflection is a rotation of it under an improper one, so one tool.
  Eigen::Matrix3Xd s4(3, 8);
  for (int orbit = 0; orbit < 2; ++orbit) {
    Eigen::Vector3d p = orbit == 0 ? Eigen::Vector3d(30, 11, 7) : Eigen::Vector3d(13, -41, 22);
    for (int k = 0; k < 4; ++k) {
      s4.col(4 * orbit + k) = p;
      p = Eigen::Vector3d(-p.y(), p.x(), -p.z());
    }
  }
  Eigen::Matrix3Xd s4_mirror = r * s4;
  s4_mirror.row(0) *= -1.0;
  EXPECT_EQ(match_tool_library({s4, s4_mirror}).pairs[1].verdict,
            ToolPairMatch::Verdict::kSameTool);
  EXPECT_THAT(message_of([&] {
                ToolMatchOptions bad;
                bad.same_tolerance = -1.0;
                match_tool_library({a}, bad);
              }),
              HasSubstr("options.same_tolerance"));
}

}  // namespace
}  // namespace vantage::tracker

#include "vantage/sdp/worst_viewpoint.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "support/nlopt_build.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// The branch and bound's certificate and the exact vertex enumeration agree to rounding.
constexpr double kExact = 1e-9;
// The acceptance threshold against brute force and the NLopt cross-check.
constexpr double kBruteForce = 1e-6;
// CSDP's relative accuracy 1e-8 gives t to about 1e-7.
constexpr double kSdp = 1e-6;
// The paper's Fig. 3 / docs/math.md §13 value is printed to three decimals.
constexpr double kPrinted = 5e-4;

// The same quantity reported twice, or the same deterministic call repeated: bit for bit.
constexpr double kIdentical = 0.0;
// t is recomputed from the reported viewpoint, or from a layout with repeats removed: the rounding
// of one dot product.
constexpr double kRounding = 1e-15;
// The viewpoint is normalised: its norm is 1 to rounding.
constexpr double kUnitRounding = 1e-12;
// t or an angle evaluated at a polished point, or by another formula: rounding of a few dot
// products, asin or sqrt of unit vectors.
constexpr double kEvaluationRounding = 1e-12;
// WorstViewpointOptions::certificate_tolerance's default: certified means t_upper - t_lower <= it.
constexpr double kCertificateTolerance = 1e-9;
// docs/math.md prints p-bar = 0.8165 to four decimals.
constexpr double kFourDecimals = 1e-4;
// p-bar = sqrt(1 - t^2) at t = 1: a t certified to 1e-9 gives p-bar up to sqrt(2e-9) = 4.5e-5.
constexpr double kSqrtOfCertified = 1e-4;

const double kInvSqrt3 = 1.0 / std::sqrt(3.0);

Eigen::Matrix3Xd columns(std::initializer_list<Eigen::Vector3d> list) {
  Eigen::Matrix3Xd m(3, list.size());
  int i = 0;
  for (const Eigen::Vector3d& v : list) m.col(i++) = v;
  return m;
}

// Exact t* by enumerating every candidate optimum (docs/math.md §13: a cell optimum is the
// minimum-norm point of conv{s_i n_i}, supported by 1, 2 or 3 points): a = n_i, a ~ n_i +- n_j,
// a ~ (n_i - s_j n_j) x (n_i - s_k n_k). Independent of the library's algorithm.
double brute_force_t(const Eigen::Matrix3Xd& vectors) {
  const Eigen::Matrix3Xd n = vectors.colwise().normalized();
  const int m = static_cast<int>(n.cols());
  double best = 0.0;
  auto consider = [&](const Eigen::Vector3d& a) {
    if (a.norm() < 1e-12) return;
    best = std::max(best, min_abs_projection(n, a.normalized()));
  };
  for (int i = 0; i < m; ++i) {
    consider(n.col(i));
    for (int j = i + 1; j < m; ++j) {
      for (double sj : {-1.0, 1.0}) {
        consider(n.col(i) + sj * n.col(j));
        for (int k = j + 1; k < m; ++k) {
          for (double sk : {-1.0, 1.0}) {
            consider((n.col(i) - sj * n.col(j)).cross(n.col(i) - sk * n.col(k)));
          }
        }
      }
    }
  }
  return best;
}

Eigen::Matrix3Xd random_unit_columns(std::mt19937& rng, int m) {
  Eigen::Matrix3Xd z(3, m);
  for (int i = 0; i < m; ++i) z.col(i) = testing::random_unit_vector(rng);
  return z;
}

void expect_consistent(const WorstViewpoint& w, const Eigen::Matrix3Xd& vectors) {
  const Eigen::Matrix3Xd n = vectors.colwise().normalized();
  EXPECT_EQ(w.status, WorstViewpoint::Status::kCertified) << w.message;
  EXPECT_LE(w.t_upper - w.t_lower, kCertificateTolerance);
  EXPECT_NEAR(w.t, w.t_lower, kIdentical);
  EXPECT_NEAR(min_abs_projection(n, w.viewpoint), w.t, kRounding) << "the viewpoint attains t";
  EXPECT_NEAR(w.viewpoint.norm(), 1.0, kUnitRounding);
  // sqrt(1 - t^2) loses digits near t = 1 (narrow cones): its rounding is ~1e-16 / p-bar.
  EXPECT_NEAR(w.pbar_min, std::sqrt(1.0 - w.t * w.t), kRounding * (1.0 + 1.0 / w.pbar_min));
  ASSERT_FALSE(w.viewpoints.empty());
  EXPECT_EIGEN_NEAR(w.viewpoints.front(), w.viewpoint, kIdentical);
  for (const Eigen::Vector3d& a : w.viewpoints) {
    EXPECT_NEAR(min_abs_projection(n, a), w.t, kExact) << "every reported optimum attains t";
    EXPECT_EQ(upper_hemisphere(a), a);
  }
  EXPECT_TRUE(std::isfinite(w.t) && std::isfinite(w.pbar_min));
}

TEST(PaperSigns, UpperHemisphereWithTieBreaks) {
  const Eigen::Matrix3Xd z = columns(
      {{0, 0, 1}, {0, 0, -1}, {1, 1, 0}, {1, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0.3, 0.2, -0.1}});
  Eigen::VectorXd expected(7);
  expected << 1, -1, 1, -1, 1, -1, -1;
  EXPECT_EIGEN_NEAR(upper_hemisphere_signs(z), expected, kIdentical);
}

TEST(PaperSigns, KeepsVectorsThatShareAHemisphereAndNegatesOtherwise) {
  const Eigen::Matrix3Xd shared = columns({{1, 0, 0}, {0, 1, 0}, {0.5, 0.5, -2}});
  EXPECT_EIGEN_NEAR(paper_signs(shared), Eigen::Vector3d::Ones(), kIdentical);
  const Eigen::Matrix3Xd opposite = columns({{0, 0, 1}, {0, 0, -1}, {1, 0, 0}});
  EXPECT_EIGEN_NEAR(paper_signs(opposite), upper_hemisphere_signs(opposite), kIdentical);
}

TEST(CellLmi, OrthogonalTriadMatchesPaper) {
  // Fig. 2: Z = I gives a = (1, 1, 1)/sqrt(3), t = 1/sqrt(3), p-bar = sqrt(2/3) = 0.8165.
  const CellViewpoint paper = paper_worst_viewpoint(Eigen::Matrix3d::Identity());
  ASSERT_EQ(paper.status, CellViewpoint::Status::kOk) << paper.message;
  EXPECT_NEAR(paper.t, kInvSqrt3, kSdp);
  EXPECT_NEAR(paper.pbar_at, std::sqrt(2.0 / 3.0), kSdp);
  EXPECT_EIGEN_NEAR(paper.viewpoint, Eigen::Vector3d::Constant(kInvSqrt3), kSdp);
  EXPECT_EQ(paper.sdp.backend, "csdp");
  EXPECT_NEAR(paper.sdp.gap, 0.0, kSdp);
}

TEST(CellLmi, EmptyCellIsReported) {
  // n and -n with equal signs: 0 is in the hull, no viewpoint sees both positively.
  const Eigen::Matrix3Xd z = columns({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}});
  const CellViewpoint cell = solve_cell_lmi(z, Eigen::Vector3d(1, 1, 1));
  EXPECT_NE(cell.status, CellViewpoint::Status::kOk);
  EXPECT_LE(cell.t, kSdp);
}

TEST(CellLmi, RejectsBadSigns) {
  EXPECT_THROW(solve_cell_lmi(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 1)),
               InvalidArgument);
  EXPECT_THROW(solve_cell_lmi(Eigen::Matrix3d::Identity(), Eigen::Vector2d(1, 1)), InvalidArgument);
}

TEST(GlobalWorstViewpoint, OrthogonalTriadHasFourOptima) {
  WorstViewpointOptions options;
  options.confirm_with_sdp = true;
  const WorstViewpoint w = global_worst_viewpoint(Eigen::Matrix3d::Identity(), options);
  expect_consistent(w, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(w.t, kInvSqrt3, kExact);
  EXPECT_NEAR(w.pbar_min, 0.8165, kFourDecimals);
  ASSERT_EQ(w.viewpoints.size(), 4u);
  for (double sx : {-1.0, 1.0}) {
    for (double sy : {-1.0, 1.0}) {
      const Eigen::Vector3d expected = Eigen::Vector3d(sx, sy, 1.0) * kInvSqrt3;
      int found = 0;
      for (const Eigen::Vector3d& a : w.viewpoints) found += (a - expected).norm() < 1e-9;
      EXPECT_EQ(found, 1) << expected.transpose();
    }
  }
  EXPECT_TRUE(w.sdp_confirmed);
  EXPECT_NEAR(w.confirmation.t, w.t, kSdp);
}

TEST(GlobalWorstViewpoint, NoteThreeLayoutGlobalVersusPaper) {
  // docs/math.md §13: adding (1, 1, -2)/sqrt(6) moves the paper's single LMI to p-bar = 0.953
  // but (1, 1, -1)/sqrt(3) still has p-bar = 0.8165.
  Eigen::Matrix3Xd z(3, 4);
  z << Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 1, -2) / std::sqrt(6.0);
  const WorstViewpoint w = global_worst_viewpoint(z);
  expect_consistent(w, z);
  EXPECT_NEAR(w.t, kInvSqrt3, kExact);
  EXPECT_NEAR(w.pbar_min, std::sqrt(2.0 / 3.0), kExact);
  bool has_111 = false;
  for (const Eigen::Vector3d& a : w.viewpoints) {
    has_111 = has_111 || (a - Eigen::Vector3d(-1, -1, 1) * kInvSqrt3).norm() < 1e-9;
  }
  EXPECT_TRUE(has_111) << "(1, 1, -1)/sqrt(3) up to sign is a worst viewpoint";
  // The 0.953 of docs/math.md §13 (the paper's "0.95") is the all-positive cell: with a = (u, u, v)
  // the active constraints give t^2 = 1 / (2 (1 + sqrt(6)/2)^2 + 1).
  const double k = 1.0 + std::sqrt(6.0) / 2.0;
  const CellViewpoint all_positive = solve_cell_lmi(z, Eigen::Vector4d::Ones());
  ASSERT_EQ(all_positive.status, CellViewpoint::Status::kOk);
  EXPECT_NEAR(all_positive.t, 1.0 / std::sqrt(2.0 * k * k + 1.0), kSdp);
  EXPECT_NEAR(all_positive.pbar_at, 0.953, kPrinted);
  // The four vectors as given lie in one open hemisphere, so the paper keeps their signs and
  // its single LMI is the all-positive cell: the paper's 0.95.
  EXPECT_EIGEN_NEAR(paper_signs(z), Eigen::Vector4d::Ones(), kIdentical);
  const CellViewpoint paper = paper_worst_viewpoint(z);
  ASSERT_EQ(paper.status, CellViewpoint::Status::kOk);
  EXPECT_NEAR(paper.t, all_positive.t, kSdp);
  EXPECT_NEAR(paper.pbar_at, 0.953, kPrinted);
  EXPECT_GE(paper.pbar_at, w.pbar_min);
  // Negating by the z > 0 rule alone would flip (1, 1, -2)/sqrt(6) into another cell:
  // t^2 = 1 / (2 + (1 + sqrt(6)/2)^2), p-bar = 0.9253.
  const CellViewpoint z_rule = solve_cell_lmi(z, upper_hemisphere_signs(z));
  ASSERT_EQ(z_rule.status, CellViewpoint::Status::kOk);
  EXPECT_NEAR(z_rule.t, 1.0 / std::sqrt(2.0 + k * k), kSdp);
  EXPECT_NEAR(z_rule.pbar_at, 0.9253, kPrinted);
  EXPECT_GE(all_positive.pbar_at, w.pbar_min);
}

TEST(GlobalWorstViewpoint, RandomLayoutsMatchBruteForce) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 24; ++trial) {
    const int m = 3 + trial % 10 + (trial >= 20 ? 20 : 0);
    const Eigen::Matrix3Xd z = random_unit_columns(rng, m) * (1.0 + trial);
    WorstViewpointOptions options;
    options.confirm_with_sdp = true;
    const WorstViewpoint w = global_worst_viewpoint(z, options);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << ", m = " << m);
    expect_consistent(w, z);
    EXPECT_NEAR(w.t, brute_force_t(z), kExact);
    EXPECT_NEAR(w.confirmation.t, w.t, kSdp) << "CSDP cell LMI confirms the exact cell optimum";
    const CellViewpoint paper = paper_worst_viewpoint(z);
    ASSERT_EQ(paper.status, CellViewpoint::Status::kOk);
    EXPECT_LE(paper.t, w.t + kSdp) << "the paper's single cell cannot beat the global optimum";
    EXPECT_GE(paper.pbar_at, w.pbar_min - kSdp);
    if (!built_with_nlopt()) continue;
    const CrossCheck check = crosscheck_worst_viewpoint(z, w.t);
    EXPECT_TRUE(check.agrees) << check.message;
    EXPECT_NEAR(check.t, w.t, kBruteForce);
  }
}

TEST(GlobalWorstViewpoint, LargeRandomLayoutAgreesWithCrossCheck) {
  std::mt19937 rng(kSeed + 1);
  const Eigen::Matrix3Xd z = random_unit_columns(rng, 200);
  WorstViewpointOptions options;
  options.confirm_with_sdp = true;
  const WorstViewpoint w = global_worst_viewpoint(z, options);
  expect_consistent(w, z);
  VANTAGE_SKIP_WITHOUT_NLOPT();
  CrossCheckOptions check_options;
  check_options.samples = 100000;  // spacing ~0.01 rad, well inside cells of inradius ~0.03
  const CrossCheck check = crosscheck_worst_viewpoint(z, w.t, check_options);
  EXPECT_TRUE(check.agrees) << check.message;
  EXPECT_LE(check.t, w.t_upper + kEvaluationRounding) << "nothing beats the certified upper bound";
}

TEST(GlobalWorstViewpoint, CoplanarFanReachesTheZoneCeiling) {
  // docs/math.md §15: m coplanar vectors at equal angles reach p-bar = cos(pi / (2m)); the m
  // in-plane bisectors are the worst viewpoints.
  for (int m : {3, 4, 6}) {
    Eigen::Matrix3Xd z(3, m);
    for (int i = 0; i < m; ++i) z.col(i) << std::cos(kPi * i / m), std::sin(kPi * i / m), 0.0;
    const WorstViewpoint w = global_worst_viewpoint(z);
    expect_consistent(w, z);
    EXPECT_NEAR(w.pbar_min, std::cos(kPi / (2 * m)), kExact);
    EXPECT_EQ(static_cast<int>(w.viewpoints.size()), m);
  }
}

// Symmetric layouts with several tied optima (the regression of near-tie certificates).
struct TiedLayout {
  const char* name;
  Eigen::Matrix3Xd vectors;
  int optima;  // global optima up to sign of the unperturbed layout
  double t;    // its t*
};

std::vector<TiedLayout> tied_layouts() {
  const double s = std::sqrt(3.0) / 2.0;
  std::vector<TiedLayout> layouts;
  layouts.push_back({"triad Z = I", Eigen::Matrix3d::Identity(), 4, kInvSqrt3});
  layouts.push_back({"fan plus (0, 0, 1)",
                     columns({{1, 0, 0}, {0.5, s, 0}, {-0.5, s, 0}, {0, 0, 1}}), 6,
                     1.0 / std::sqrt(5.0)});
  // The cube's three face normals and four body diagonals (octahedral symmetry): t* = 1/3 at the
  // four diagonals.
  layouts.push_back(
      {"cube axes and diagonals",
       columns({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}}), 4,
       1.0 / 3.0});
  return layouts;
}

TEST(GlobalWorstViewpoint, NearTiePerturbationsAreCertifiedAtTheBestTie) {
  // Tiny tie-breaking perturbations split the tied optima by ~the perturbation size. The
  // reported viewpoint must attain the best of them: t_upper is certified against the best
  // attained value, so the gap is bounded by the exact-cell test (1e-12, a subset-cell optimum
  // attained to that accuracy closes its patch) plus the rounding tie of the final choice
  // (1e-14), independent of the perturbation and of tie_tolerance (1e-9, which once widened it).
  constexpr double kNearTieGap = 2e-12;
  // The brute force evaluates cross products of near-equal differences: accurate to ~1e-12.
  constexpr double kUpperBoundSlack = 1e-12;
  // Ties equal to the best up to rounding are ordered lexicographically (kSameValue = 1e-14).
  constexpr double kRoundingTie = 1e-14;
  std::mt19937 rng(kSeed + 2);
  std::uniform_real_distribution<double> log_size(-12.0, -7.0);
  for (const TiedLayout& layout : tied_layouts()) {
    const WorstViewpoint exact = global_worst_viewpoint(layout.vectors);
    expect_consistent(exact, layout.vectors);
    EXPECT_EQ(static_cast<int>(exact.viewpoints.size()), layout.optima) << layout.name;
    EXPECT_NEAR(exact.t, layout.t, kExact) << layout.name;
    for (int trial = 0; trial < 40; ++trial) {
      Eigen::Matrix3Xd z = layout.vectors;
      for (Eigen::Index i = 0; i < z.cols(); ++i) {
        z.col(i) += std::pow(10.0, log_size(rng)) * testing::random_unit_vector(rng);
      }
      const WorstViewpoint w = global_worst_viewpoint(z);
      SCOPED_TRACE(::testing::Message() << layout.name << ", trial " << trial);
      expect_consistent(w, z);
      EXPECT_LE(w.t_upper - w.t_lower, kNearTieGap);
      const double brute = brute_force_t(z);
      EXPECT_NEAR(w.t, brute, kExact);
      EXPECT_LE(brute, w.t_upper + kUpperBoundSlack) << "t_upper bounds every candidate optimum";
      const Eigen::Matrix3Xd n = z.colwise().normalized();
      for (const Eigen::Vector3d& a : w.viewpoints) {
        EXPECT_LE(min_abs_projection(n, a), w.t + kRoundingTie) << "no tie beats the viewpoint";
      }
    }
  }
}

TEST(GlobalWorstViewpoint, DegenerateLayouts) {
  // All parallel (with antiparallel and scaled copies): t = 1, p-bar = 0, a = the direction.
  const Eigen::Vector3d d = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Matrix3Xd parallel = columns({d, -2.0 * d, 0.5 * d});
  const WorstViewpoint wp = global_worst_viewpoint(parallel);
  expect_consistent(wp, parallel);
  EXPECT_NEAR(wp.t, 1.0, kExact);
  EXPECT_NEAR(wp.pbar_min, 0.0, kSqrtOfCertified);
  EXPECT_EIGEN_NEAR(wp.viewpoint, d, kExact);
  EXPECT_EQ(wp.viewpoints.size(), 1u);

  // Two vectors at angle theta: t* = max(cos(theta/2), sin(theta/2)).
  for (double theta : {0.3, 1.0, kPi / 2, 2.5}) {
    const Eigen::Matrix3Xd two = columns({{1, 0, 0}, {std::cos(theta), std::sin(theta), 0}});
    const WorstViewpoint w2 = global_worst_viewpoint(two);
    expect_consistent(w2, two);
    EXPECT_NEAR(w2.t, std::max(std::cos(theta / 2), std::sin(theta / 2)), kExact);
  }

  // Duplicated and antiparallel copies of Z = I change nothing.
  Eigen::Matrix3Xd copies(3, 7);
  copies << Eigen::Matrix3d::Identity(), -Eigen::Matrix3d::Identity(), Eigen::Vector3d(3, 0, 0);
  const WorstViewpoint wc = global_worst_viewpoint(copies);
  expect_consistent(wc, copies);
  EXPECT_NEAR(wc.t, kInvSqrt3, kExact);
  EXPECT_EQ(wc.viewpoints.size(), 4u);
}

// Free vectors z_j - z_i (i < j) of a point layout, as the analysis builds them (Prop. 8).
Eigen::Matrix3Xd free_vectors(const Eigen::Matrix3Xd& points) {
  const int n = static_cast<int>(points.cols());
  Eigen::Matrix3Xd z(3, n * (n - 1) / 2);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) z.col(k++) = points.col(j) - points.col(i);
  }
  return z;
}

TEST(GlobalWorstViewpoint, RandomMarkerLayoutsMatchBruteForce) {
  std::mt19937 rng(kSeed + 3);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int trials = 0;
  for (int points = 4; points <= 9; ++points) {
    for (int repeat = 0; repeat < 3; ++repeat) {
      Eigen::Matrix3Xd p(3, points);
      for (int i = 0; i < points; ++i) {
        p.col(i) << coordinate(rng), coordinate(rng), coordinate(rng);
      }
      const Eigen::Matrix3Xd z = free_vectors(p);
      SCOPED_TRACE(::testing::Message() << points << " points, repeat " << repeat);
      const WorstViewpoint w = global_worst_viewpoint(z);
      expect_consistent(w, z);
      EXPECT_NEAR(w.t, brute_force_t(z), kExact);
      ++trials;
    }
  }
  EXPECT_EQ(trials, 18);
}

TEST(GlobalWorstViewpoint, ParallelAndAntiparallelRepeatsChangeNothing) {
  // A 3 x 2 x 2 grid: its 66 free vectors repeat a few directions many times (z and k z, and
  // their negatives). The search runs on the distinct directions: the same answer, certificate,
  // ties and work as the layout of distinct directions alone, and the exact enumeration agrees.
  Eigen::Matrix3Xd grid(3, 12);
  int k = 0;
  for (int x = 0; x < 3; ++x) {
    for (int y = 0; y < 2; ++y) {
      for (int z = 0; z < 2; ++z) grid.col(k++) << x, y, 0.7 * z;
    }
  }
  const Eigen::Matrix3Xd repeated = free_vectors(grid);
  // The distinct directions, found independently of the library (by exact integer multiples).
  std::vector<Eigen::Vector3d> distinct;
  for (Eigen::Index i = 0; i < repeated.cols(); ++i) {
    const Eigen::Vector3d d = repeated.col(i).normalized();
    bool seen = false;
    for (const Eigen::Vector3d& e : distinct)
      seen = seen || std::abs(std::abs(d.dot(e)) - 1) < 1e-12;
    if (!seen) distinct.push_back(d);
  }
  ASSERT_LT(distinct.size(), static_cast<std::size_t>(repeated.cols()) / 2) << "the grid repeats";
  Eigen::Matrix3Xd unique(3, distinct.size());
  for (std::size_t i = 0; i < distinct.size(); ++i) unique.col(i) = distinct[i];

  const WorstViewpoint w = global_worst_viewpoint(repeated);
  const WorstViewpoint u = global_worst_viewpoint(unique);
  expect_consistent(w, repeated);
  expect_consistent(u, unique);
  EXPECT_NEAR(w.t, brute_force_t(repeated), kExact);
  EXPECT_NEAR(w.t, u.t, kRounding);
  EXPECT_NEAR(w.t_upper, u.t_upper, kRounding);
  EXPECT_EIGEN_NEAR(w.viewpoint, u.viewpoint, kRounding);
  ASSERT_EQ(w.viewpoints.size(), u.viewpoints.size());
  EXPECT_EQ(w.patches, u.patches) << "the repeats cost no work";
  EXPECT_EQ(w.cells_solved, u.cells_solved);
}

TEST(GlobalWorstViewpoint, SameAnswerOnEveryCall) {
  // The search is deterministic: repeated calls return bit-identical results.
  std::mt19937 rng(kSeed + 4);
  const Eigen::Matrix3Xd z = random_unit_columns(rng, 300);
  const WorstViewpoint first = global_worst_viewpoint(z);
  expect_consistent(first, z);
  for (int call = 0; call < 3; ++call) {
    const WorstViewpoint again = global_worst_viewpoint(z);
    EXPECT_EQ(again.t, first.t);
    EXPECT_EQ(again.t_upper, first.t_upper);
    EXPECT_EIGEN_NEAR(again.viewpoint, first.viewpoint, kIdentical);
    EXPECT_EQ(again.patches, first.patches);
  }
}

// m unit vectors within `radius` rad of a random axis.
Eigen::Matrix3Xd narrow_cone(std::mt19937& rng, int m, double radius) {
  const Eigen::Vector3d axis = testing::random_unit_vector(rng);
  const Eigen::Vector3d e1 = axis.unitOrthogonal();
  const Eigen::Vector3d e2 = axis.cross(e1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::Matrix3Xd z(3, m);
  for (int i = 0; i < m; ++i) {
    const double angle = radius * std::sqrt(unit(rng));
    const double phi = 2.0 * kPi * unit(rng);
    z.col(i) = std::cos(angle) * axis + std::sin(angle) * (std::cos(phi) * e1 + std::sin(phi) * e2);
  }
  return z;
}

TEST(CrossCheck, NarrowConeHasNoFalseDisagreement) {
  VANTAGE_SKIP_WITHOUT_NLOPT();
  // 20 vectors in a 1e-3 rad cone: t* is within ~1e-6 of 1 and the cell constraints differ by
  // ~1e-6. The polish once stopped ~1e-6 short here and reported a false disagreement.
  std::mt19937 rng(kSeed + 5);
  for (int trial = 0; trial < 8; ++trial) {
    const Eigen::Matrix3Xd z = narrow_cone(rng, 20, 1e-3);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    const WorstViewpoint w = global_worst_viewpoint(z);
    expect_consistent(w, z);
    EXPECT_GT(w.t, 1.0 - 1e-5);
    EXPECT_NEAR(w.t, brute_force_t(z), kExact);
    const CrossCheck alone = crosscheck_worst_viewpoint(z, w.t);
    EXPECT_TRUE(alone.agrees) << alone.message;
    const CrossCheck seeded = crosscheck_worst_viewpoint(z, w.t, {}, w.viewpoints);
    EXPECT_TRUE(seeded.agrees) << seeded.message;
    EXPECT_LE(seeded.t, w.t_upper + kRounding) << "nothing beats the certified upper bound";
  }
}

TEST(CrossCheck, LargeLayoutIsBoundedAndConfirmsTheReference) {
  VANTAGE_SKIP_WITHOUT_NLOPT();
  // m = 3000: the cells are far smaller than any affordable sample spacing, so the samples are
  // capped by max_sample_products, and the reference's cell is re-solved by the polish.
  std::mt19937 rng(kSeed + 6);
  const Eigen::Matrix3Xd z = random_unit_columns(rng, 3000);
  const WorstViewpoint w = global_worst_viewpoint(z);
  expect_consistent(w, z);
  const CrossCheckOptions options;
  const CrossCheck check = crosscheck_worst_viewpoint(z, w.t, options, w.viewpoints);
  EXPECT_TRUE(check.agrees) << check.message;
  EXPECT_LE(static_cast<double>(check.samples) * z.cols(), options.max_sample_products);
  EXPECT_GT(check.sample_spacing, std::asin(w.t)) << "the samples alone cannot resolve the cells";
  EXPECT_GE(check.polished, 1 + static_cast<int>(w.viewpoints.size()));
  EXPECT_LE(check.t, w.t_upper + kRounding);
  // A wrong reference is caught: the polish of the true optimum's cell exceeds it.
  const CrossCheck low = crosscheck_worst_viewpoint(z, w.t - 1e-4, options, w.viewpoints);
  EXPECT_FALSE(low.agrees);
  EXPECT_FALSE(low.message.empty());
}

TEST(CrossCheck, AutomaticSamplesResolveTheOptimalCell) {
  VANTAGE_SKIP_WITHOUT_NLOPT();
  // m = 60: half the optimal inradius is affordable, so the samples alone find the optimum.
  std::mt19937 rng(kSeed + 7);
  const Eigen::Matrix3Xd z = random_unit_columns(rng, 60);
  const WorstViewpoint w = global_worst_viewpoint(z);
  const CrossCheck check = crosscheck_worst_viewpoint(z, w.t);
  EXPECT_LE(check.sample_spacing, 0.5 * std::asin(w.t) + kEvaluationRounding);
  EXPECT_TRUE(check.agrees) << check.message;
}

TEST(GlobalWorstViewpoint, RejectsBadInput) {
  EXPECT_THROW(global_worst_viewpoint(Eigen::Matrix3Xd(3, 1)), InvalidArgument);
  EXPECT_THROW(global_worst_viewpoint(Eigen::Matrix3Xd(3, 0)), InvalidArgument);
  EXPECT_THROW(global_worst_viewpoint(columns({{1, 0, 0}, {0, 0, 0}})), InvalidArgument);
  EXPECT_THROW(global_worst_viewpoint(columns({{1, 0, 0}, {0, NAN, 0}})), InvalidArgument);
  WorstViewpointOptions bad;
  bad.certificate_tolerance = 0.0;
  EXPECT_THROW(global_worst_viewpoint(Eigen::Matrix3d::Identity(), bad), InvalidArgument);
  EXPECT_THROW(crosscheck_worst_viewpoint(Eigen::Matrix3Xd(3, 1), 0.0), InvalidArgument);
  EXPECT_THROW(
      crosscheck_worst_viewpoint(Eigen::Matrix3d::Identity(), 0.5, {}, {Eigen::Vector3d::Zero()}),
      InvalidArgument);
  CrossCheckOptions few;
  few.max_sample_products = 10.0;
  EXPECT_THROW(crosscheck_worst_viewpoint(Eigen::Matrix3d::Identity(), 0.5, few), InvalidArgument);
}

}  // namespace
}  // namespace vantage::sdp

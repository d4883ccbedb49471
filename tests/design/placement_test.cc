#include "vantage/design/placement.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "support/message_of.h"
#include "support/placement_sites.h"
#include "support/sanitized.h"
#include "vantage/analysis/common.h"

namespace vantage::design {
namespace {

using ::testing::HasSubstr;
using testing::message_of;

constexpr unsigned kSeed = 20261202;
// Truth and answer are certified to this (t_upper - t_lower), and place tells apart two subsets
// only when their t_upper differ by more: the answer must tie the optimum within kTie.
constexpr double kTruthTolerance = 1e-9;
constexpr double kTie = 1e-9;
// Coverage fractions of one lattice, compared as counts over the same directions.
constexpr double kSameLattice = 1e-12;
// A lattice small enough for the enumeration of every subset to stay quick.
constexpr int kLattice = 4000;

// n sites on the unit sphere (seeded), radial normals, every cone `cone_deg`.
visibility::VisibilityProblem sphere_sites(int n, double cone_deg, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<double> gauss;
  visibility::VisibilityProblem out;
  out.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d v(gauss(engine), gauss(engine), gauss(engine));
    out.points.col(i) = v.normalized();
  }
  out.normals = out.points;
  out.cos_cone = Eigen::VectorXd::Constant(n, std::cos(cone_deg * kPi / 180.0));
  return out;
}

visibility::VisibilityProblem subset(const visibility::VisibilityProblem& all,
                                     const std::vector<int>& chosen) {
  visibility::VisibilityProblem out = all;
  const Eigen::Index n = static_cast<Eigen::Index>(chosen.size());
  out.points.resize(3, n);
  out.normals.resize(3, n);
  out.cos_cone.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    out.points.col(k) = all.points.col(chosen[static_cast<std::size_t>(k)]);
    out.normals.col(k) = all.normals.col(chosen[static_cast<std::size_t>(k)]);
    out.cos_cone(k) = all.cos_cone(chosen[static_cast<std::size_t>(k)]);
  }
  return out;
}

struct Truth {
  double coverage = -1.0;
  double t = 2.0;
  std::vector<int> chosen;
};

// Every K-subset, scored by sdp's own coverage and certified search (not place's code): first
// at a coarse tolerance, then again at kTruthTolerance for the subsets that may be optimal
// (t_lower at or below the least t_upper).
Truth enumerate(const visibility::VisibilityProblem& all, int k) {
  struct Candidate {
    std::vector<int> chosen;
    double coverage;
    visibility::VisibilityWorstViewpoint coarse;
  };
  std::vector<Candidate> candidates;
  double top = -1.0;
  testing::enumerate_subsets(
      static_cast<int>(all.points.cols()), k, [&](const std::vector<int>& idx) {
        const visibility::VisibilityProblem p = subset(all, idx);
        const double coverage = visibility::visibility_coverage(p, kLattice).trackable_fraction;
        top = std::max(top, coverage);
        candidates.push_back({idx, coverage, visibility::visibility_worst_viewpoint(p)});
        return 0.0;
      });
  using Status = visibility::VisibilityWorstViewpoint::Status;
  double least_upper = 1.0;
  for (const Candidate& c : candidates) {
    if (c.coverage > top - kSameLattice && c.coarse.status == Status::kCertified) {
      least_upper = std::min(least_upper, c.coarse.t_upper);
    }
  }
  visibility::VisibilitySearchOptions tight;
  tight.certificate_tolerance = kTruthTolerance;
  Truth best;
  best.coverage = top;
  for (const Candidate& c : candidates) {
    if (c.coverage < top - kSameLattice || c.coarse.status == Status::kUntrackable) continue;
    if (c.coarse.status == Status::kCertified && c.coarse.t_lower > least_upper) continue;
    const visibility::VisibilityWorstViewpoint w =
        visibility::visibility_worst_viewpoint(subset(all, c.chosen), tight);
    if (w.t_upper < best.t) {
      best.t = w.t_upper;
      best.chosen = c.chosen;
    }
  }
  return best;
}

// The exhaustive comparisons certify at kTruthTolerance; the other tests at the default.
PlaceOptions small_options(double tolerance = 1e-7) {
  PlaceOptions options;
  options.coverage_samples = kLattice;
  options.search.certificate_tolerance = tolerance;
  options.random_trials = 200;
  return options;
}

struct Instance {
  const char* name;
  visibility::VisibilityProblem sites;
};

struct Solved {
  Instance instance;
  Truth truth;
};

// N = 10, K = 4 (210 subsets; under the sanitizers N = 8, 70 subsets): the whole sphere, which
// some subsets cover, and a cone, which none covers whole (the best coverage, then the least t).
const std::vector<Solved>& small_instances() {
  static const std::vector<Solved> solved = [] {
    const int n = testing::kUnderSanitizer ? 8 : 10;
    std::vector<Instance> cases;
    cases.push_back({"whole sphere, 150 deg cones", sphere_sites(n, 150.0, kSeed)});
    Instance cone{"workspace cone of 50 deg, 120 deg cones", sphere_sites(n, 120.0, kSeed + 1)};
    cone.sites.workspace =
        visibility::Workspace{Eigen::Vector3d::UnitZ(), std::cos(50.0 * kPi / 180.0)};
    cases.push_back(cone);
    std::vector<Solved> out;
    for (const Instance& c : cases) out.push_back({c, enumerate(c.sites, 4)});
    return out;
  }();
  return solved;
}

TEST(PlaceMarkers, FindsTheExhaustiveOptimumOfEverySubset) {
  for (const Solved& s : small_instances()) {
    SCOPED_TRACE(s.instance.name);
    PlacementProblem problem;
    problem.sites = s.instance.sites;
    problem.markers = 4;
    ASSERT_FALSE(s.truth.chosen.empty());
    const PlacementResult result = place_markers(problem, small_options(kTruthTolerance));
    EXPECT_EQ(result.search, "exhaustive");
    EXPECT_EQ(result.status == PlacementResult::Status::kComplete,
              s.truth.coverage > 1.0 - kSameLattice);
    EXPECT_NEAR(result.value.coverage, s.truth.coverage, kSameLattice);
    EXPECT_LE(result.value.t_upper, s.truth.t + kTie);
    // The truth's subset is certified; the answer cannot beat it by more than the tolerances.
    EXPECT_GE(result.value.t_upper, s.truth.t - kTie);
  }
}

TEST(PlaceMarkers, GreedyWithSwapsOnTheSmallInstances) {
  // The same instances with the exhaustive search turned off: the gap to the optimum that the
  // closing note of issue 19 reports. Greedy with single swaps is not exact; here it covers the
  // workspace and stays within kGreedyGap of the optimal t.
  constexpr double kGreedyGap = 0.05;
  for (const Solved& s : small_instances()) {
    SCOPED_TRACE(s.instance.name);
    PlacementProblem problem;
    problem.sites = s.instance.sites;
    problem.markers = 4;
    PlaceOptions options = small_options(kTruthTolerance);
    options.exhaustive_limit = 0;
    const PlacementResult result = place_markers(problem, options);
    EXPECT_EQ(result.search, "greedy+swap");
    EXPECT_NEAR(result.value.coverage, s.truth.coverage, kSameLattice);
    EXPECT_GE(result.value.t_upper, s.truth.t - kTie);
    EXPECT_LE(result.value.t_upper, s.truth.t + kGreedyGap);
    std::cout << "[ gap      ] " << s.instance.name << ": greedy+swap t " << result.value.t_upper
              << ", optimum " << s.truth.t << "\n";
  }
}

// Iterated local search (docs/math.md §21, "Perturbations") on instances of 12 sites, K = 5,
// against the brute force over every 5-subset: never worse than greedy with swaps, never better
// than the optimum, and at the optimum more often. Seeded; when written, of these four instances
// greedy with swaps found 1 optimum and 20 perturbation rounds 3 (of the 12 instances from kSeed,
// at a 1e-9 certificate and 30 rounds: 4 and 10); under the sanitizers the first (0 and 1).
TEST(PlaceMarkers, PerturbationsReachTheOptimumWhereSwapsStop) {
  // 108 s under the sanitizers for one instance (the search's certified analyses, not memory
  // work): the sanitizers run the perturbations in PlaceCli.PerturbationsAreReportedAndNeverWorse.
  if (testing::kUnderSanitizer) GTEST_SKIP() << "the same code as PlaceCli's perturbations";
  constexpr int kRounds = 20;
  // Placements at the default certificate tolerance, told apart from the truth by it.
  constexpr double kPlaceTie = 1e-7;
  constexpr unsigned instances = 4;
  unsigned plain_optimal = 0;
  unsigned perturbed_optimal = 0;
  for (unsigned seed = kSeed + 1; seed < kSeed + 1 + instances; ++seed) {
    SCOPED_TRACE(seed);
    const visibility::VisibilityProblem sites = sphere_sites(12, 150.0, seed);
    const Truth truth = enumerate(sites, 5);
    PlacementProblem problem;
    problem.sites = sites;
    problem.markers = 5;
    PlaceOptions options = small_options();
    options.exhaustive_limit = 0;
    const PlacementResult plain = place_markers(problem, options);
    options.perturbations = kRounds;
    const PlacementResult perturbed = place_markers(problem, options);
    EXPECT_EQ(perturbed.search, "greedy+swap");
    EXPECT_LE(perturbed.value.t_upper, plain.value.t_upper + kPlaceTie);
    EXPECT_GE(perturbed.value.t_upper, truth.t - kPlaceTie);
    EXPECT_EQ(perturbed.improving_perturbations > 0,
              perturbed.value.t_upper < plain.value.t_upper - kPlaceTie);
    plain_optimal += plain.value.t_upper <= truth.t + kPlaceTie;
    perturbed_optimal += perturbed.value.t_upper <= truth.t + kPlaceTie;
  }
  std::cout << "[ optimum  ] greedy+swap " << plain_optimal << " of " << instances << ", with "
            << kRounds << " perturbations " << perturbed_optimal << "\n";
  EXPECT_GT(perturbed_optimal, plain_optimal);
}

// Five sites facing +z in the plane z = 0 and two facing -z below: every 5-subset that holds
// sites 0, 1, 2 covers the same +z cap, and [0, 1, 2, 5, 6] also brings the -z directions two
// markers closer to being seen. Coverage ties; only t may rank them (issue 35: place chose
// [0, 1, 2, 5, 6] by that progress, with a worse t).
TEST(PlaceMarkers, RanksEqualCoverageByTheObjectiveAlone) {
  visibility::VisibilityProblem sites;
  sites.points.resize(3, 7);
  sites.points << 0.0, 1.0, 0.2, 0.9, 0.4, 0.3, 0.7,  //
      0.0, 0.1, 1.0, 0.8, 0.5, 0.2, 0.6,              //
      0.0, 0.0, 0.0, 0.0, 0.0, -1.0, -1.0;
  sites.normals.resize(3, 7);
  for (int i = 0; i < 7; ++i) sites.normals.col(i) = Eigen::Vector3d(0, 0, i < 5 ? 1.0 : -1.0);
  sites.cos_cone = Eigen::VectorXd::Constant(7, std::cos(60.0 * kPi / 180.0));
  const Truth truth = enumerate(sites, 5);
  PlacementProblem problem;
  problem.sites = sites;
  problem.markers = 5;
  PlaceOptions options = small_options(kTruthTolerance);
  options.min_coverage = 1.0;
  const PlacementResult result = place_markers(problem, options);
  EXPECT_EQ(result.search, "exhaustive");
  EXPECT_EQ(result.chosen, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(result.chosen, truth.chosen);
  EXPECT_NEAR(result.value.coverage, truth.coverage, kSameLattice);
  EXPECT_NEAR(result.value.t_upper, truth.t, kTie);
}

TEST(PlaceMarkers, MinCoverageMakesAPlacementComplete) {
  // The cone instance: the best 4 of 10 covers part of the workspace. A min_coverage at that
  // fraction makes it complete; above it, incomplete.
  const Solved& cone = small_instances()[1];
  PlacementProblem problem;
  problem.sites = cone.instance.sites;
  problem.markers = 4;
  PlaceOptions options = small_options(kTruthTolerance);
  options.min_coverage = 1.0;
  const PlacementResult strict = place_markers(problem, options);
  ASSERT_LT(strict.value.coverage, 1.0);
  EXPECT_EQ(strict.status, PlacementResult::Status::kIncomplete);
  options.min_coverage = strict.value.coverage;
  const PlacementResult loose = place_markers(problem, options);
  EXPECT_EQ(loose.status, PlacementResult::Status::kComplete);
  EXPECT_GE(loose.value.coverage, strict.value.coverage - kSameLattice);
  EXPECT_LE(loose.value.t_upper, strict.value.t_upper + kTie);
  options.min_coverage = 0.0;
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }), HasSubstr("min_coverage"));
}

PlacementProblem larger_problem() {
  PlacementProblem problem;
  problem.sites = sphere_sites(60, 100.0, kSeed + 2);
  problem.markers = 7;
  return problem;
}

TEST(PlaceMarkers, IsTheSameForEveryThreadCount) {
  const PlacementProblem problem = larger_problem();
  PlaceOptions one = small_options();
  one.threads = 1;
  PlaceOptions two = one;
  two.threads = 2;
  const PlacementResult a = place_markers(problem, one);
  const PlacementResult b = place_markers(problem, two);
  EXPECT_EQ(a.search, "greedy+swap");
  EXPECT_EQ(a.chosen, b.chosen);
  EXPECT_EQ(a.value.t_upper, b.value.t_upper);
  EXPECT_EQ(a.random_baseline.best, b.random_baseline.best);
  EXPECT_EQ(a.random_baseline.median_pbar_min, b.random_baseline.median_pbar_min);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) EXPECT_EQ(a.steps[i].added, b.steps[i].added);
}

TEST(PlaceMarkers, IsNeverWorseThanTheRandomBaselineItReports) {
  const PlacementResult result = place_markers(larger_problem(), small_options());
  ASSERT_EQ(result.status, PlacementResult::Status::kComplete);
  EXPECT_GE(result.random_baseline.trials, 1);
  EXPECT_GE(result.value.coverage, result.random_baseline.best_coverage);
  EXPECT_GE(result.value.pbar_min, result.random_baseline.best_pbar_min);
  EXPECT_GE(result.random_baseline.best_pbar_min, result.random_baseline.median_pbar_min);
}

TEST(PlaceMarkers, KeepsTheKeptMarkersAndTheSeparation) {
  PlacementProblem problem = larger_problem();
  problem.keep = {5, 17};
  problem.min_separation = 0.6;
  const PlacementResult result = place_markers(problem, small_options());
  ASSERT_EQ(result.chosen.size(), 7u);
  for (int k : problem.keep) {
    EXPECT_TRUE(std::find(result.chosen.begin(), result.chosen.end(), k) != result.chosen.end());
  }
  const Eigen::Matrix3Xd& p = problem.sites.points;
  for (std::size_t i = 0; i < result.chosen.size(); ++i) {
    for (std::size_t j = i + 1; j < result.chosen.size(); ++j) {
      EXPECT_GE((p.col(result.chosen[i]) - p.col(result.chosen[j])).norm(), problem.min_separation);
    }
  }
}

TEST(PlaceMarkers, HoldsTheDistanceDifference) {
  PlacementProblem problem = larger_problem();
  problem.min_distance_difference = 0.02;
  const PlacementResult result = place_markers(problem, small_options());
  Eigen::Matrix3Xd chosen(3, static_cast<Eigen::Index>(result.chosen.size()));
  for (std::size_t i = 0; i < result.chosen.size(); ++i) {
    chosen.col(static_cast<Eigen::Index>(i)) = problem.sites.points.col(result.chosen[i]);
  }
  EXPECT_GE(tracker::min_distance_difference(chosen).value, problem.min_distance_difference);
}

TEST(PlaceMarkers, RobustValueIsTheWorstSingleLoss) {
  PlacementProblem problem;
  problem.sites = sphere_sites(14, 120.0, kSeed + 3);
  problem.markers = 5;
  PlaceOptions options = small_options();
  options.robust_dropout = true;
  const PlacementResult result = place_markers(problem, options);
  ASSERT_TRUE(result.robust.has_value());
  visibility::VisibilitySearchOptions tight;
  tight.certificate_tolerance = kTruthTolerance;
  double worst_t = 0.0;
  for (std::size_t m = 0; m < result.chosen.size(); ++m) {
    std::vector<int> rest = result.chosen;
    rest.erase(rest.begin() + static_cast<long>(m));
    const visibility::VisibilityWorstViewpoint w =
        visibility::visibility_worst_viewpoint(subset(problem.sites, rest), tight);
    worst_t = std::max(worst_t, w.t_upper);
  }
  // place certifies at the default 1e-7 in t; at these t, p-bar moves by less than 1e-6.
  constexpr double kDefaultCertificate = 1e-6;
  EXPECT_NEAR(result.robust->pbar_min, std::sqrt(1.0 - worst_t * worst_t), kDefaultCertificate);
}

TEST(PlaceMarkers, RobustGreedyStartsFromTooFewMarkersToLoseOne) {
  // The greedy's first steps hold fewer than min_visible + 1 markers: every loss leaves an
  // untrackable layout, which must score as such rather than fail.
  PlacementProblem problem;
  problem.sites = sphere_sites(12, 120.0, kSeed + 4);
  problem.markers = 5;
  PlaceOptions options = small_options();
  options.robust_dropout = true;
  options.exhaustive_limit = 0;
  options.random_trials = 20;
  const PlacementResult result = place_markers(problem, options);
  EXPECT_EQ(result.search, "greedy+swap");
  ASSERT_TRUE(result.robust.has_value());
  EXPECT_EQ(result.chosen.size(), 5u);
}

// Every site twice (the same point and normal): a layout file refuses two markers at one point,
// so no answer holds both copies, exhaustive or greedy, and keeping both is refused.
TEST(PlaceMarkers, NeverChoosesCoincidentSites) {
  const visibility::VisibilityProblem once = sphere_sites(8, 100.0, kSeed + 5);
  PlacementProblem problem;
  problem.sites = once;
  problem.sites.points = Eigen::Matrix3Xd(3, 16);
  problem.sites.normals = Eigen::Matrix3Xd(3, 16);
  problem.sites.points << once.points, once.points;
  problem.sites.normals << once.normals, once.normals;
  problem.sites.cos_cone = Eigen::VectorXd::Constant(16, once.cos_cone(0));
  problem.markers = 5;
  for (const int exhaustive_limit : {100000, 0}) {
    PlaceOptions options = small_options();
    options.exhaustive_limit = exhaustive_limit;
    options.random_trials = 20;
    const PlacementResult result = place_markers(problem, options);
    ASSERT_EQ(result.chosen.size(), 5u) << exhaustive_limit;
    std::vector<int> points;
    for (int c : result.chosen) points.push_back(c % 8);
    std::sort(points.begin(), points.end());
    EXPECT_TRUE(std::adjacent_find(points.begin(), points.end()) == points.end())
        << "search " << result.search;
  }
  problem.keep = {2, 10};
  EXPECT_THAT(message_of([&] { place_markers(problem); }),
              HasSubstr("kept sites 2 and 10 coincide"));
}

TEST(PlaceMarkers, RejectsBadProblemsNamingTheField) {
  PlacementProblem problem = larger_problem();
  problem.markers = 61;
  EXPECT_THAT(message_of([&] { place_markers(problem); }), HasSubstr("markers"));
  problem.markers = 2;
  EXPECT_THAT(message_of([&] { place_markers(problem); }), HasSubstr("markers"));
  problem.markers = 5;
  problem.keep = {3, 3};
  EXPECT_THAT(message_of([&] { place_markers(problem); }), HasSubstr("keep"));
  problem.keep = {};
  problem.min_separation = -1.0;
  EXPECT_THAT(message_of([&] { place_markers(problem); }), HasSubstr("min_separation"));
}

// Two triangles of areas 1/2 and 3 in the plane z = 0, wound so that their normals are -z.
Mesh two_triangles() {
  Mesh mesh;
  mesh.vertices.resize(3, 6);
  mesh.vertices << 0, 0, 1, 5, 5, 8,  //
      0, 1, 0, 0, 2, 0,               //
      0, 0, 0, 0, 0, 0;
  mesh.triangles.resize(3, 2);
  mesh.triangles << 0, 3, 1, 4, 2, 5;
  return mesh;
}

TEST(SampleSurfaceSites, IsAreaUniform) {
  const int n = 40000;
  const SurfaceSites sites = sample_surface_sites(two_triangles(), n, 0.0, kSeed);
  ASSERT_EQ(sites.points.cols(), n);
  int first = 0;
  for (int t : sites.triangles) first += t == 0 ? 1 : 0;
  // Areas 1/2 and 3: Binomial(n, 1/7), five standard deviations.
  const double p = 1.0 / 7.0;
  const double sd = std::sqrt(n * p * (1.0 - p));
  EXPECT_NEAR(first, n * p, 5.0 * sd);
  // Inside its triangle: x, y >= 0 and below the hypotenuse.
  for (Eigen::Index i = 0; i < sites.points.cols(); ++i) {
    const Eigen::Vector3d p = sites.points.col(i);
    if (sites.triangles[static_cast<std::size_t>(i)] == 0) {
      EXPECT_LE(p.x() + p.y(), 1.0 + 1e-12);
    } else {
      EXPECT_LE((p.x() - 5.0) / 3.0 + p.y() / 2.0, 1.0 + 1e-12);
    }
  }
}

// A unit cube centred at the origin, wound inward when `inward`.
Mesh cube(bool inward) {
  Mesh mesh;
  mesh.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.col(i) =
        Eigen::Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  mesh.triangles.resize(3, 12);
  for (int q = 0; q < 6; ++q) {
    const int* v = quads[q];
    mesh.triangles.col(2 * q) << v[0], v[1], v[2];
    mesh.triangles.col(2 * q + 1) << v[0], v[2], v[3];
    if (inward) {
      mesh.triangles.col(2 * q).reverseInPlace();
      mesh.triangles.col(2 * q + 1).reverseInPlace();
    }
  }
  return mesh;
}

TEST(SampleSurfaceSites, NormalsPointOutwardWhicheverTheWinding) {
  for (bool inward : {false, true}) {
    const SurfaceSites sites = sample_surface_sites(cube(inward), 300, 0.0, kSeed);
    for (Eigen::Index i = 0; i < sites.points.cols(); ++i) {
      // On a centred cube the outward normal is the axis of the largest coordinate.
      const Eigen::Vector3d p = sites.points.col(i);
      Eigen::Index axis = 0;
      p.cwiseAbs().maxCoeff(&axis);
      EXPECT_NEAR(sites.normals(axis, i), p(axis) > 0 ? 1.0 : -1.0, 1e-12) << "inward " << inward;
    }
  }
}

TEST(SampleSurfaceSites, ThinsToTheSeparation) {
  const double d = 0.2;
  const SurfaceSites sites = sample_surface_sites(cube(false), 2000, d, kSeed);
  EXPECT_EQ(sites.drawn, 2000);
  EXPECT_LT(sites.points.cols(), 2000);
  for (Eigen::Index i = 0; i < sites.points.cols(); ++i) {
    for (Eigen::Index j = i + 1; j < sites.points.cols(); ++j) {
      ASSERT_GE((sites.points.col(i) - sites.points.col(j)).norm(), d);
    }
  }
}

TEST(SampleSurfaceSites, RejectsAMeshWithoutFaces) {
  Mesh mesh;
  mesh.vertices = Eigen::Matrix3Xd::Zero(3, 3);
  mesh.triangles.resize(3, 0);
  EXPECT_THAT(message_of([&] { sample_surface_sites(mesh, 10, 0.0, kSeed); }), HasSubstr("body"));
}

}  // namespace
}  // namespace vantage::design

// Prop. 8 (pose from image points through free vectors) and the two baselines of Sec. IV.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "affine_testing.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::IsRotation;
using testing::kSeed;

// Noise-free recovery: Theorem 1 on the exact pattern, rounding of O(n^2) unit-size sums.
constexpr double kNoiseFreeRadians = 1e-9;
constexpr double kNoiseFreeRelative = 1e-9;

struct Scene {
  Eigen::Matrix3Xd model;
  Eigen::Matrix2Xd image;
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  double alpha;
};

/// n random points, a rotation that puts the farthest pair in the image plane (so the LUB of
/// the free vectors is exact and that pair is in the maximum spanning tree), affine image.
Scene make_scene(std::mt19937& rng, int n, double alpha) {
  Scene s;
  s.model = testing::random_points(rng, n);
  const auto [i, j] = testing::farthest_pair(s.model);
  s.R = testing::rotation_with_in_plane(rng, s.model.col(i) - s.model.col(j));
  s.p = testing::random_points(rng, 1, 3.0).col(0);
  s.p.z() = 50.0;
  s.alpha = alpha;
  s.image = ((s.R * s.model).colwise() + s.p).topRows<2>() / alpha;
  return s;
}

void expect_pose(const AffinePoseResult& result, const Scene& s, int n) {
  EXPECT_EQ(result.status, PoseStatus::kOk) << result.message;
  EXPECT_FALSE(result.ambiguous);
  EXPECT_THAT(result.R_camera_object, IsRotation());
  EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kNoiseFreeRadians) << n;
  EXPECT_NEAR(result.alpha, s.alpha, kNoiseFreeRelative * s.alpha);
  EXPECT_LT((result.p_camera_object.head<2>() - s.p.head<2>()).norm(),
            kNoiseFreeRelative * s.p.head<2>().norm());
}

TEST(AffinePose, NoiseFreePointsReturnPoseWithAllPairs) {
  // Prop. 8 as in the paper; all pairs limits n (n = 6 gives 15 free vectors).
  std::mt19937 rng(kSeed + 20);
  for (int trial = 0; trial < 9; ++trial) {
    const int n = 4 + trial % 3;
    const Scene s = make_scene(rng, n, 0.5 + 0.2 * trial);
    AffinePoseOptions options;
    options.free_vectors = FreeVectorSet::kAllPairs;
    options.camera.focal_length = 2.0;
    options.pair_weighting =
        trial % 2 == 0 ? PairWeighting::kGeometricMean : PairWeighting::kArithmeticMean;
    const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    const AffinePoseResult result = affine_pose(s.model, s.image, w, options);
    expect_pose(result, s, n);
    EXPECT_EQ(result.pairs.cols(), n * (n - 1) / 2);
    EXPECT_TRUE(result.depth_known);
    EXPECT_NEAR(result.p_camera_object.z(), result.alpha * options.camera.focal_length,
                0.0);  // Eq. 37
    EXPECT_LT(result.objective, 1e-18 * n);
    EXPECT_LT(result.reprojection_rms_px, 1e-8);
  }
}

TEST(AffinePose, NoiseFreePointsReturnPoseWithSpanningTree) {
  std::mt19937 rng(kSeed + 21);
  for (int trial = 0; trial < 18; ++trial) {
    const int n = 4 + trial % 9;  // 4..12 points, 3..11 free vectors
    const Scene s = make_scene(rng, n, 0.7 + 0.1 * trial);
    AffinePoseOptions options;
    options.free_vectors = FreeVectorSet::kMaxSpanningTree;
    const AffinePoseResult result = affine_pose(s.model, s.image, {}, options);
    expect_pose(result, s, n);
    EXPECT_EQ(result.pairs.cols(), n - 1);
    EXPECT_FALSE(result.depth_known);
    EXPECT_TRUE(std::isnan(result.p_camera_object.z()));
    EXPECT_EQ(result.orientation.sign_patterns, std::uint64_t{1} << (n - 2));  // one in plane
  }
}

TEST(AffinePose, SpanningTreeConnectsEveryPointWithTheLongestVectors) {
  std::mt19937 rng(kSeed + 22);
  const int n = 9;
  const Eigen::Matrix3Xd model = testing::random_points(rng, n);
  const Eigen::Matrix2Xd image = model.topRows<2>();
  AffinePoseOptions options;
  options.free_vectors = FreeVectorSet::kMaxSpanningTree;
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 1.0, 4.0);
  const FreeVectors tree = affine_free_vectors(model, image, w, options);
  ASSERT_EQ(tree.pairs.cols(), n - 1);
  // Connected: union-find over the pairs joins all n points.
  std::vector<int> root(n);
  for (int i = 0; i < n; ++i) root[i] = i;
  std::function<int(int)> find = [&](int i) { return root[i] == i ? i : root[i] = find(root[i]); };
  for (int k = 0; k < n - 1; ++k) root[find(tree.pairs(0, k))] = find(tree.pairs(1, k));
  std::set<int> roots;
  for (int i = 0; i < n; ++i) roots.insert(find(i));
  EXPECT_EQ(roots.size(), 1u);
  // The farthest pair is in the maximum spanning tree; weights are geometric means.
  const auto [fi, fj] = testing::farthest_pair(model);
  bool has_farthest = false;
  for (int k = 0; k < n - 1; ++k) {
    const int i = tree.pairs(0, k), j = tree.pairs(1, k);
    has_farthest |= (i == fi && j == fj);
    EXPECT_NEAR(tree.weights(k), std::sqrt(w(i) * w(j)), 1e-15);
    EXPECT_EIGEN_NEAR(tree.z_object.col(k), model.col(j) - model.col(i), 0.0);  // z_j - z_i
  }
  EXPECT_TRUE(has_farthest);
  options.pair_weighting = PairWeighting::kArithmeticMean;
  options.free_vectors = FreeVectorSet::kAllPairs;
  const FreeVectors all = affine_free_vectors(model, image, w, options);
  EXPECT_EQ(all.pairs.cols(), n * (n - 1) / 2);
  EXPECT_NEAR(all.weights(0), 0.5 * (w(all.pairs(0, 0)) + w(all.pairs(1, 0))), 1e-15);
}

TEST(AffinePose, ThreePointsGiveTheTwoFoldAmbiguity) {
  // Three points are coplanar: affine imaging cannot tell the pose from its mirror.
  std::mt19937 rng(kSeed + 23);
  for (int trial = 0; trial < 5; ++trial) {
    const Scene s = make_scene(rng, 3, 1.0);
    const AffinePoseResult result = affine_pose(s.model, s.image);
    EXPECT_EQ(result.status, PoseStatus::kOk);
    EXPECT_TRUE(result.ambiguous);
    ASSERT_TRUE(result.alternative.has_value());
    const double best = std::min(rotation_angle_between(result.R_camera_object, s.R),
                                 rotation_angle_between(result.alternative->R_camera_object, s.R));
    EXPECT_LT(best, kNoiseFreeRadians);
  }
}

TEST(AffinePose, AutoFreeVectorsNeverThrowAndStayBounded) {
  // kAuto: all pairs up to 5 points (10 vectors), then a budget of kAutoBudget vectors: no
  // cost cliff and no throw at any n.
  std::mt19937 rng(kSeed + 27);
  for (const int n : {3, 5, 6, 8, 13, 14, 30}) {
    const Scene s = make_scene(rng, n, 1.0);
    const AffinePoseResult result = affine_pose(s.model, s.image);
    const Eigen::Index expected = n <= 5 ? n * (n - 1) / 2 : kAutoBudget;
    EXPECT_EQ(result.pairs.cols(), expected) << n;
    EXPECT_EQ(free_vector_count(n, FreeVectorSet::kAuto), expected);
    EXPECT_LE(result.orientation.sign_patterns, std::uint64_t{1} << kAutoBudget);
    if (n > 3) expect_pose(result, s, n);  // the farthest pair is kept: exact LUB scale
  }
}

TEST(AffinePose, AutoFreeVectorsKeepThePairInTheImagePlane) {
  // Lemma 7's LUB scale is exact when the free vector of largest image-to-object ratio lies in
  // the image plane. Here that pair is the shortest of all: never an edge of the maximum
  // spanning tree (it is the shortest edge of every triangle it is in), nor one of the longest
  // further pairs. kAuto must still hold it, and so return the truth as all pairs do.
  std::mt19937 rng(kSeed + 40);
  for (const int n : {6, 7, 9, 14, 20}) {
    const Eigen::Matrix3Xd model = testing::random_points(rng, n);
    int short_i = 0;
    int short_j = 1;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if ((model.col(j) - model.col(i)).norm() <
            (model.col(short_j) - model.col(short_i)).norm()) {
          short_i = i;
          short_j = j;
        }
      }
    }
    const Eigen::Matrix3d R =
        testing::rotation_with_in_plane(rng, model.col(short_j) - model.col(short_i));
    const Eigen::Matrix2Xd image = testing::affine_image(R, model, 1.0);

    const AffinePoseResult result = affine_pose(model, image);
    EXPECT_EQ(result.pairs.cols(), kAutoBudget) << n;
    bool holds_pair = false;
    for (Eigen::Index k = 0; k < result.pairs.cols(); ++k) {
      holds_pair |= result.pairs(0, k) == short_i && result.pairs(1, k) == short_j;
    }
    EXPECT_TRUE(holds_pair) << n;
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians) << n;
    EXPECT_NEAR(result.alpha, 1.0, kNoiseFreeRelative) << n;

    // Control: the spanning tree alone lacks the pair, so its LUB scale is off and the pose is
    // not exact (the defect kAuto had at 6+ points).
    AffinePoseOptions spanning;
    spanning.free_vectors = FreeVectorSet::kMaxSpanningTree;
    EXPECT_GT(rotation_angle_between(affine_pose(model, image, {}, spanning).R_camera_object, R),
              1e3 * kNoiseFreeRadians)
        << n;
  }
}

TEST(FreeVectors, AutoIsTheTreeThenTheLongestOtherPairs) {
  // Independent truth: every pair sorted by length; the tree edges are checked to be a
  // spanning tree of maximum total length by comparing with the greedy (Kruskal) total.
  std::mt19937 rng(kSeed + 41);
  for (const int n : {6, 8, 12, 13}) {
    const Eigen::Matrix3Xd points = testing::random_points(rng, n);
    const Eigen::Matrix2Xi pairs = free_vector_pairs(points, FreeVectorSet::kAuto);
    ASSERT_EQ(pairs.cols(), kAutoBudget);
    std::set<std::pair<int, int>> chosen;
    for (Eigen::Index k = 0; k < pairs.cols(); ++k) chosen.insert({pairs(0, k), pairs(1, k)});
    EXPECT_EQ(chosen.size(), static_cast<std::size_t>(kAutoBudget)) << "repeated pairs";
    const Eigen::Matrix2Xi tree = free_vector_pairs(points, FreeVectorSet::kMaxSpanningTree);
    for (Eigen::Index k = 0; k < tree.cols(); ++k) {
      EXPECT_EQ(chosen.count({tree(0, k), tree(1, k)}), 1u) << "tree edge missing, n " << n;
    }
    // The further pairs are the longest non-tree pairs.
    std::vector<double> further_lengths;
    std::vector<double> other_lengths;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        bool in_tree = false;
        for (Eigen::Index k = 0; k < tree.cols(); ++k) {
          in_tree |= tree(0, k) == i && tree(1, k) == j;
        }
        if (in_tree) continue;
        const double length = (points.col(j) - points.col(i)).norm();
        (chosen.count({i, j}) ? further_lengths : other_lengths).push_back(length);
      }
    }
    ASSERT_EQ(further_lengths.size(), static_cast<std::size_t>(kAutoBudget - (n - 1)));
    for (double kept : further_lengths) {
      for (double left : other_lengths) EXPECT_GE(kept, left) << n;
    }
  }
}

TEST(AffinePose, PrincipalPointShiftsOnlyTheTranslation) {
  std::mt19937 rng(kSeed + 28);
  const Scene s = make_scene(rng, 6, 0.8);
  AffinePoseOptions options;
  options.camera.principal_point = Eigen::Vector2d(320.0, 240.0);
  const Eigen::Matrix2Xd shifted = s.image.colwise() + options.camera.principal_point;
  const AffinePoseResult result = affine_pose(s.model, shifted, {}, options);
  expect_pose(result, s, 6);
}

TEST(StandardApproach, ExactOnlyWhenTheDepthsVanish) {
  // Theorem 1 with v_z = 0 is exact when the free vectors lie in the image plane and biased
  // otherwise; Prop. 8 is exact in both cases.
  std::mt19937 rng(kSeed + 24);
  const int n = 5;
  Scene s = make_scene(rng, n, 1.0);
  const AffinePoseResult standard = standard_affine_pose(s.model, s.image);
  const AffinePoseResult prop8 = affine_pose(s.model, s.image);
  EXPECT_THAT(standard.R_camera_object, IsRotation());
  EXPECT_EQ(standard.orientation.sign_patterns, 1u);
  EXPECT_TRUE(std::isinf(standard.orientation.ambiguity_margin));
  EXPECT_GT(rotation_angle_between(standard.R_camera_object, s.R), 1e-3);
  EXPECT_GT(standard.objective, prop8.objective);
  EXPECT_FALSE(standard.ambiguous);
  EXPECT_FALSE(standard.alternative.has_value());
  // A planar model parallel to the image plane: the standard approach is exact.
  Eigen::Matrix3Xd planar = testing::random_points(rng, n);
  planar.row(2).setZero();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix2Xd image = ((R * planar).colwise() + s.p).topRows<2>() / 2.0;
  const AffinePoseResult exact = standard_affine_pose(planar, image);
  EXPECT_LT(rotation_angle_between(exact.R_camera_object, R), kNoiseFreeRadians);
  EXPECT_NEAR(exact.alpha, 2.0, kNoiseFreeRelative * 2.0);
}

TEST(Full3dPose, NoiseFreeMeasurementsReturnPose) {
  std::mt19937 rng(kSeed + 25);
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 3 + trial % 8;
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Matrix3Xd model = testing::random_points(rng, n);
    const Eigen::Vector3d p = testing::random_points(rng, 1, 5.0).col(0);
    const double alpha = 0.5 + 0.3 * trial;
    const Eigen::Matrix3Xd measured = ((R * model).colwise() + p) / alpha;
    AffinePoseOptions options;
    options.free_vectors =
        trial % 2 == 0 ? FreeVectorSet::kAllPairs : FreeVectorSet::kMaxSpanningTree;
    const PoseResult result = full_3d_pose(model, measured, {}, options);
    EXPECT_EQ(result.status, OrientationStatus::kOk) << result.message;
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians);
    EXPECT_NEAR(result.alpha, alpha, kNoiseFreeRelative * alpha);
    EXPECT_LT((result.p_camera_object - p).norm(), kNoiseFreeRelative * p.norm());
  }
}

std::string message_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(AffinePose, BadInputThrowsNamingTheArgument) {
  std::mt19937 rng(kSeed + 26);
  const Scene s = make_scene(rng, 8, 1.0);
  using ::testing::HasSubstr;
  // 8 points, all pairs: 28 free vectors exceed the limit of 24 (the default kAuto never does).
  AffinePoseOptions all_pairs;
  all_pairs.free_vectors = FreeVectorSet::kAllPairs;
  EXPECT_THAT(message_of([&] { affine_pose(s.model, s.image, {}, all_pairs); }),
              HasSubstr("max_vectors"));
  EXPECT_THAT(message_of([&] { affine_pose(s.model, s.image.leftCols(7)); }),
              HasSubstr("image: has 7"));
  EXPECT_THAT(message_of([&] { affine_pose(s.model.leftCols(2), s.image.leftCols(2)); }),
              HasSubstr("at least 3"));
  Eigen::Matrix3Xd coincident = s.model;
  coincident.col(5) = coincident.col(2);
  EXPECT_THAT(message_of([&] { affine_pose(coincident, s.image); }),
              HasSubstr("points 2 and 5 coincide"));
  Eigen::Matrix2Xd nan = s.image;
  nan(1, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message_of([&] { standard_affine_pose(s.model, nan); }), HasSubstr("image[4]"));
  EXPECT_THAT(message_of([&] { affine_pose(s.model, s.image, -Eigen::VectorXd::Ones(8)); }),
              HasSubstr("weights[0]"));
  AffinePoseOptions bad;
  bad.camera.focal_length = -1.0;
  EXPECT_THAT(message_of([&] { affine_pose(s.model, s.image, {}, bad); }),
              HasSubstr("camera.focal_length"));
  EXPECT_THAT(message_of([&] { full_3d_pose(s.model, Eigen::Matrix3Xd::Zero(3, 8)); }),
              HasSubstr("measured"));
}

}  // namespace
}  // namespace vantage

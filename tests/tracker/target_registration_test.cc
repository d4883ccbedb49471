// The first-order TRE of docs/math.md §23 against independent truth: Fitzpatrick's formula
// (Eq. 23.3) from the principal axes, a finite-difference linearisation of the actual
// registration (SVD fit, not the q-method), and Monte Carlo.

#include "vantage/tracker/target_registration.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "vantage/analysis/absolute_orientation.h"

namespace vantage::tracker {
namespace {

// Eq. (23.3) and the library's trace differ by the roundings of two 3x3 inversions.
constexpr double kFormulaTolerance = 1e-9;
// Central differences of step 1e-5 on a fit of size ~50: truncation ~1e-10, rounding ~1e-11,
// relative to the covariance's norm.
constexpr double kLinearisationTolerance = 1e-6;
constexpr double kStep = 1e-5;
// The Monte Carlo requirement at 1e5 trials (sampling error about 0.2 %).
constexpr double kMonteCarloTolerance = 0.02;

Eigen::Matrix3Xd random_tool(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  Eigen::Matrix3Xd p(3, n);
  for (int i = 0; i < n; ++i) p.col(i) = Eigen::Vector3d(u(rng), u(rng), 0.4 * u(rng));
  return p;
}

std::vector<int> all_of(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = i;
  return v;
}

// Fitzpatrick, West & Maurer 1998 Eq. (46) from the principal axes of the centred markers.
double fitzpatrick_rms(const Eigen::Matrix3Xd& p, const Eigen::Vector3d& r, double fle) {
  const Eigen::Vector3d centroid = p.rowwise().mean();
  const Eigen::Matrix3Xd q = p.colwise() - centroid;
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(q, Eigen::ComputeFullU);
  const Eigen::Vector3d d = r - centroid;
  const double n = static_cast<double>(p.cols());
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = svd.matrixU().col(k);
    double f2 = 0.0;
    for (Eigen::Index i = 0; i < q.cols(); ++i) {
      f2 += q.col(i).squaredNorm() - std::pow(q.col(i).dot(axis), 2);
    }
    f2 /= n;
    sum += (d.squaredNorm() - std::pow(d.dot(axis), 2)) / f2;
  }
  return std::sqrt(fle * fle / n * (1.0 + sum / 3.0));
}

// The registered target for markers measured at `y` (tool frame, true pose identity): the
// rigid least-squares fit by Haralick's SVD solution.
Eigen::Vector3d registered_target(const Eigen::Matrix3Xd& p, const Eigen::Matrix3Xd& y,
                                  const Eigen::Vector3d& r) {
  const Eigen::Vector3d pc = p.rowwise().mean();
  const Eigen::Vector3d yc = y.rowwise().mean();
  const Eigen::Matrix3d H = (p.colwise() - pc) * (y.colwise() - yc).transpose();
  OrientationOptions svd;
  svd.method = OrientationMethod::kSvd;
  const Eigen::Matrix3d R = optimal_rotation(H, svd);
  return R * r + yc - R * pc;
}

TEST(TargetRegistration, IsotropicRmsIsFitzpatricksFormula) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> u(-200.0, 200.0);
  int cases = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Matrix3Xd p = random_tool(rng, 3 + trial % 8);
    const Eigen::Vector3d r(u(rng), u(rng), u(rng));
    const double expected = fitzpatrick_rms(p, r, 0.25);
    EXPECT_NEAR(tre_rms_isotropic(p, r, 0.25), expected, kFormulaTolerance * expected);
    ++cases;
  }
  EXPECT_EQ(cases, 50);
}

TEST(TargetRegistration, CovarianceIsTheLinearisedRegistration) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-150.0, 150.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const FleModel fle{0.0995, 0.2985};
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 4 + trial % 5;
    const Eigen::Matrix3Xd p = random_tool(rng, n);
    const Eigen::Vector3d r(u(rng), u(rng), u(rng));
    const Eigen::Vector3d a = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    Eigen::MatrixXd J(3, 3 * n);
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        Eigen::Matrix3Xd plus = p, minus = p;
        plus(k, i) += kStep;
        minus(k, i) -= kStep;
        J.col(3 * i + k) =
            (registered_target(p, plus, r) - registered_target(p, minus, r)) / (2.0 * kStep);
      }
    }
    const Eigen::Matrix3d sigma =
        fle.sigma_perp * fle.sigma_perp * (Eigen::Matrix3d::Identity() - a * a.transpose()) +
        fle.sigma_axial * fle.sigma_axial * a * a.transpose();
    Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i) {
      expected += J.middleCols(3 * i, 3) * sigma * J.middleCols(3 * i, 3).transpose();
    }
    const Eigen::Matrix3d cov = tre_covariance(p, all_of(n), r, fle, a);
    EXPECT_LE((cov - expected).norm(), kLinearisationTolerance * expected.norm()) << trial;
    const TreQuadratic q = tre_quadratic(p, all_of(n), r, fle);
    EXPECT_NEAR(q.rms_squared(a), expected.trace(), kLinearisationTolerance * expected.trace());
  }
}

TEST(TargetRegistration, CollinearMarkersAreNotRegistrable) {
  Eigen::Matrix3Xd p(3, 3);
  p << 0, 1, 2, 0, 1, 2, 0, 1, 2;
  EXPECT_FALSE(tre_quadratic(p, all_of(3), Eigen::Vector3d::Zero(), FleModel{1, 1}).registrable);
  EXPECT_TRUE(tre_covariance(p, all_of(3), Eigen::Vector3d::Zero(), FleModel{1, 1},
                             Eigen::Vector3d::UnitZ())
                  .isZero(0.0));
}

TEST(TargetRegistration, MonteCarloAgreesIsotropicAndAnisotropic) {
  std::mt19937 rng(22);
  const Eigen::Matrix3Xd p = random_tool(rng, 5);
  const Eigen::Vector3d r(10.0, -20.0, -150.0);
  const Eigen::Vector3d a = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  for (const FleModel& fle : {FleModel::isotropic(0.25), FleModel{0.0995, 0.2985}}) {
    const TreMonteCarlo mc = tre_monte_carlo(p, all_of(5), r, fle, a, 100000, 7);
    const double formula = std::sqrt(tre_covariance(p, all_of(5), r, fle, a).trace());
    EXPECT_DOUBLE_EQ(mc.formula_rms, formula);
    EXPECT_LE(std::abs(mc.rms / formula - 1.0), kMonteCarloTolerance) << mc.rms << " " << formula;
    EXPECT_EQ(mc.trials, 100000);
  }
}

TEST(TargetRegistration, MonteCarloDoesNotDependOnThreads) {
  std::mt19937 rng(23);
  const Eigen::Matrix3Xd p = random_tool(rng, 4);
  const FleModel fle{0.1, 0.3};
  const Eigen::Vector3d a = Eigen::Vector3d::UnitX();
  const TreMonteCarlo one =
      tre_monte_carlo(p, all_of(4), Eigen::Vector3d::Zero(), fle, a, 5000, 3, 1);
  const TreMonteCarlo two =
      tre_monte_carlo(p, all_of(4), Eigen::Vector3d::Zero(), fle, a, 5000, 3, 2);
  EXPECT_EQ(one.rms, two.rms);
  const TreMonteCarlo other =
      tre_monte_carlo(p, all_of(4), Eigen::Vector3d::Zero(), fle, a, 5000, 4, 2);
  EXPECT_NE(one.rms, other.rms);
}

}  // namespace
}  // namespace vantage::tracker

// The first-order TRE of docs/math.md §23 against independent truth: Fitzpatrick's formula
// (Eq. 23.3) from the principal axes, a finite-difference linearisation of the actual
// registration (SVD fit, not the q-method), and Monte Carlo.

#include "vantage/tracker/target_registration.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"

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

// A 5-DoF tool (three markers on a line, as NDI's 8700248 stylus) registers a target on its
// line: the rotation about the line is not measured and does not move the target, so the TRE is
// the translation's plus the two rotations across the line, TRE^2 = F^2/N + (2/3) F^2 D^2 / S
// (D the target's distance from the centroid, S = sum of the markers' squared distances from
// it; derived here from the two across-line rotations, docs/math.md §23), and a Monte Carlo run
// of the actual registration agrees. Off the line the error is unbounded: refused.
TEST(TargetRegistration, AFiveDofToolRegistersTargetsOnItsLineOnly) {
  const Eigen::Vector3d u = Eigen::Vector3d(1.0, -2.0, 2.0).normalized();
  const Eigen::Vector3d origin(5.0, 3.0, -1.0);
  const double along[3] = {0.0, 50.0, 105.0};
  Eigen::Matrix3Xd p(3, 3);
  for (int i = 0; i < 3; ++i) p.col(i) = origin + along[i] * u;
  const double centroid = (0.0 + 50.0 + 105.0) / 3.0;
  double S = 0.0;
  for (double t : along) S += (t - centroid) * (t - centroid);
  const Eigen::Vector3d tip = origin - 100.0 * u;
  const double D = 100.0 + centroid;
  constexpr double kFle = 0.25;
  EXPECT_EQ(registration_of(p, all_of(3), tip), Registration::kOnAxis);
  const double expected = std::sqrt(kFle * kFle / 3.0 + (2.0 / 3.0) * kFle * kFle * D * D / S);
  EXPECT_NEAR(tre_rms_isotropic(p, tip, kFle), expected, kFormulaTolerance * expected);
  const FleModel anisotropic{0.0995, 0.2985};
  const Eigen::Vector3d a = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  const TreMonteCarlo mc = tre_monte_carlo(p, all_of(3), tip, anisotropic, a, 100000, 7);
  EXPECT_LE(std::abs(mc.rms / mc.formula_rms - 1.0), kMonteCarloTolerance)
      << mc.rms << " " << mc.formula_rms;
  // 1 mm off the line: no bounded error, refused with the nearest target on the line.
  const Eigen::Vector3d off = tip + u.unitOrthogonal();
  EXPECT_EQ(registration_of(p, all_of(3), off), Registration::kOffAxis);
  EXPECT_FALSE(tre_quadratic(p, all_of(3), off, anisotropic).registrable);
  std::string message;
  try {
    check_on_axis(p, off, 1);
  } catch (const InvalidArgument& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("target: target 1: 1 from the line of the tool's collinear markers: a "
                         "5-DoF tool"),
            std::string::npos)
      << message;
  EXPECT_NO_THROW(check_on_axis(p, tip, -1));
  Eigen::Vector3d point;
  Eigen::Vector3d axis;
  ASSERT_TRUE(tool_axis(p, &point, &axis));
  EXPECT_NEAR(std::abs(axis.dot(u)), 1.0, 1e-12);
  EXPECT_GT(axis.z(), 0.0);
}

// A tilted stylus stored as float32 (as a .rom stores it) is collinear only to ~1e-6 mm: a tip
// on the intended line is on the fitted line as far as the markers can tell, and the nearest
// point a refusal prints is accepted when given back.
TEST(TargetRegistration, AFloat32StylusTakesTipsOnItsLine) {
  std::mt19937 rng(23);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d u = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Eigen::Vector3d origin(g(rng), g(rng), g(rng));
    Eigen::Matrix3Xd p(3, 3);
    const double along[3] = {0.0, 50.0, 105.0};
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d exact = origin + along[i] * u;
      p.col(i) = exact.cast<float>().cast<double>();
    }
    const Eigen::Vector3d tip = origin - 100.0 * u;
    EXPECT_EQ(registration_of(p, all_of(3), tip), Registration::kOnAxis) << trial;
    const Eigen::Vector3d off = tip + 0.5 * u.unitOrthogonal();
    std::string message;
    try {
      check_on_axis(p, off, -1);
    } catch (const InvalidArgument& e) {
      message = e.what();
    }
    const std::size_t at = message.find("the nearest target on the line is ");
    ASSERT_NE(at, std::string::npos) << message;
    std::istringstream text(message.substr(at + 34));
    Eigen::Vector3d nearest;
    char comma = 0;
    text >> nearest.x() >> comma >> nearest.y() >> comma >> nearest.z();
    EXPECT_EQ(registration_of(p, all_of(3), nearest), Registration::kOnAxis) << message;
  }
}

// A 6-DoF tool of which only collinear markers are seen gives no pose, even for a target on
// their line; fewer than three markers never do.
TEST(TargetRegistration, CollinearViewsOfASixDofToolAreNotRegistrable) {
  Eigen::Matrix3Xd p(3, 4);
  p << 0, 1, 2, 0,  //
      0, 1, 2, 1,   //
      0, 1, 2, 0;
  const std::vector<int> line = {0, 1, 2};
  EXPECT_EQ(registration_of(p, line, Eigen::Vector3d(3, 3, 3)), Registration::kOffAxis);
  EXPECT_FALSE(tre_quadratic(p, line, Eigen::Vector3d(3, 3, 3), FleModel{1, 1}).registrable);
  EXPECT_TRUE(
      tre_covariance(p, line, Eigen::Vector3d(3, 3, 3), FleModel{1, 1}, Eigen::Vector3d::UnitZ())
          .isZero(0.0));
  EXPECT_EQ(registration_of(p, {0, 1}, Eigen::Vector3d::Zero()), Registration::kTooFew);
  EXPECT_EQ(registration_of(p, all_of(4), Eigen::Vector3d(3, 3, 3)), Registration::kFull);
  EXPECT_STREQ(to_string(Registration::kOnAxis), "on_axis");
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

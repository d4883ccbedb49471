// The one validation grammar (analysis/include/vantage/analysis/internal/checks.h): every
// message reads "<arg>: <problem>" or "<arg>[<i>]: <problem>", and passing checks allocate
// nothing.

#include "vantage/analysis/internal/checks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/allocation_counter.h"
#include "support/message_of.h"

namespace vantage {
namespace {

using testing::message_of;
using ::testing::StrEq;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct ToyOptions {
  double tolerance = 1e-6;
  bool is_valid(std::string* why = nullptr) const {
    if (!(tolerance > 0.0)) return internal::invalid_option(why, "tolerance", "must be > 0");
    return true;
  }
};

TEST(Checks, MessagesFollowTheGrammar) {
  EXPECT_THAT(message_of([] { internal::fail("alpha", "must be positive"); }),
              StrEq("alpha: must be positive"));
  EXPECT_THAT(message_of([] { internal::fail_at("image", 3, "not finite"); }),
              StrEq("image[3]: not finite"));
  ToyOptions bad;
  bad.tolerance = -1.0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_EQ(why, "tolerance: must be > 0");
  EXPECT_FALSE(bad.is_valid()) << "a null why is allowed";
  EXPECT_THAT(message_of([&] { internal::check_options("options", bad); }),
              StrEq("options.tolerance: must be > 0"));
  EXPECT_THAT(message_of([] { internal::check_min_count("from", 0, 1, "correspondence"); }),
              StrEq("from: need at least 1 correspondence, got 0"));
  EXPECT_THAT(message_of([] { internal::check_count_matches("to", 3, 4, "from"); }),
              StrEq("to: has 3 columns, expected 4 (one per column of from)"));
  EXPECT_THAT(message_of([] { internal::check_positive_finite("alpha", 0.0); }),
              StrEq("alpha: must be positive and finite, got 0"));
  EXPECT_THAT(message_of([] { internal::check_unit_vector("a", Eigen::Vector3d(0, 0, 2)); }),
              StrEq("a: must be a finite unit vector"));
}

TEST(Checks, WeightsEmptyMeansAllOne) {
  EXPECT_THAT(message_of([] { internal::check_weights("weights", {}, 5, "z"); }),
              StrEq("no exception"));
  EXPECT_THAT(
      message_of([] { internal::check_weights("weights", Eigen::VectorXd::Ones(3), 4, "z"); }),
      StrEq("weights: has 3 entries, expected 4 (one per column of z)"));
  Eigen::VectorXd w = Eigen::VectorXd::Ones(4);
  for (double bad : {0.0, -1.0, kNaN, kInf}) {
    w(2) = bad;
    EXPECT_THAT(message_of([&] { internal::check_weights("weights", w, 4, "z"); }),
                StrEq("weights[2]: must be positive and finite"))
        << bad;
  }
  w(2) = 0.0;
  EXPECT_THAT(message_of([&] {
                internal::check_weights("weights", w, 4, "z", internal::WeightRule::kNonNegative);
              }),
              StrEq("no exception"))
      << "a zero weight ignores a point";
  w(2) = -1.0;
  EXPECT_THAT(message_of([&] {
                internal::check_weights("weights", w, 4, "z", internal::WeightRule::kNonNegative);
              }),
              StrEq("weights[2]: must be >= 0 and finite"));
  EXPECT_THAT(message_of([] {
                internal::check_weights("weights", Eigen::VectorXd::Zero(4), 4, "z",
                                        internal::WeightRule::kNonNegative);
              }),
              StrEq("weights: all zero, at least one must be positive"));
}

TEST(Checks, ColumnsNameTheFirstBadOne) {
  Eigen::Matrix3Xd z = Eigen::Matrix3Xd::Ones(3, 5);
  z(1, 3) = kNaN;
  z(0, 4) = kInf;
  EXPECT_THAT(message_of([&] { internal::check_finite_columns("z", z); }),
              StrEq("z[3]: not finite"));
  z = Eigen::Matrix3Xd::Ones(3, 5);
  z.col(2).setZero();
  EXPECT_THAT(message_of([&] { internal::check_finite_columns("z", z); }), StrEq("no exception"));
  EXPECT_THAT(message_of([&] { internal::check_nonzero_finite_columns("z", z); }),
              StrEq("z[2]: zero length"));
  Eigen::Matrix3Xd a = Eigen::Matrix3Xd::Zero(3, 2);
  a(2, 0) = 1.0;
  a(0, 1) = 1.1;
  EXPECT_THAT(message_of([&] { internal::check_unit_columns("viewpoints", a); }),
              StrEq("viewpoints[1]: must be a finite unit vector"));
  const Eigen::Matrix2Xd image = Eigen::Matrix2Xd::Constant(2, 3, kNaN);
  EXPECT_THAT(message_of([&] { internal::check_finite_columns("image", image); }),
              StrEq("image[0]: not finite"));
}

TEST(Checks, PassingChecksAllocateNothing) {
  const Eigen::Matrix3Xd z = Eigen::Matrix3Xd::Ones(3, 50);
  const Eigen::VectorXd w = Eigen::VectorXd::Ones(50);
  const ToyOptions options;
  testing::CountAllocations counter;
  internal::check_options("options", options);
  internal::check_min_count("z", z.cols(), 1, "column");
  internal::check_count_matches("v", z.cols(), 50, "z");
  internal::check_weights("weights", w, 50, "z");
  internal::check_finite_columns("z", z);
  internal::check_nonzero_finite_columns("z", z);
  internal::check_positive_finite("alpha", 2.0);
  internal::check_unit_vector("a", Eigen::Vector3d::UnitZ());
  EXPECT_EQ(counter.count(), 0);
}

}  // namespace
}  // namespace vantage

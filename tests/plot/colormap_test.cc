#include "vantage/plot/colormap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vantage::plot {
namespace {

// Luminance (Rec. 709 weights) of a colour, in [0, 255].
double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Smallest per-channel distance that keeps a marked item apart from the value map.
constexpr int kMinChannelGap = 40;

int channel_distance(const Rgb& a, const Rgb& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

TEST(Colormap, ValueColourIsMonotoneInLuminanceAndClamped) {
  double previous = -1.0;
  for (int k = 0; k <= 100; ++k) {
    const double l = luminance(value_colour(k / 100.0));
    EXPECT_GT(l, previous) << "fraction " << k / 100.0;
    previous = l;
  }
  EXPECT_EQ(value_colour(-3.0), value_colour(0.0));
  EXPECT_EQ(value_colour(7.0), value_colour(1.0));
  EXPECT_EQ(value_colour(std::numeric_limits<double>::quiet_NaN()), value_colour(0.0));
  EXPECT_EQ(value_colour(15.0, 10.0, 20.0), value_colour(0.5));
  EXPECT_EQ(value_colour(15.0, 20.0, 20.0), value_colour(0.0)) << "empty range";
}

TEST(Colormap, MarkedItemsStayApartFromTheValueMap) {
  for (const Rgb& marked : {kWorstViewpointColour, kPaperLmiColour}) {
    for (int k = 0; k <= 1000; ++k) {
      EXPECT_GT(channel_distance(marked, value_colour(k / 1000.0)), kMinChannelGap);
    }
  }
}

}  // namespace
}  // namespace vantage::plot

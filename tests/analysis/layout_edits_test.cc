// Removing and adding a marker keeps every per-marker field one per marker (docs/math.md §20):
// checked against the layout rebuilt by hand.

#include <gtest/gtest.h>

#include "vantage/analysis/layout.h"

namespace vantage {
namespace {

Layout on_body() {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 4);
  layout.entries << 1, -1, 0, 0,  //
      0, 0, 1, -1,                //
      0, 0, 0, 1;
  layout.weights = Eigen::Vector4d(1, 2, 3, 4);
  MarkerVisibility v;
  v.normals = Eigen::Matrix3Xd::Identity(3, 4);
  v.normals.col(3) = Eigen::Vector3d(0, 0, -1);
  v.cone_half_angle_deg = Eigen::Vector4d(10, 20, 30, 40);
  v.min_visible = 4;
  layout.visibility = v;
  return layout;
}

TEST(LayoutEdits, WithoutEntryTakesItsWeightNameNormalAndCone) {
  const Layout layout = on_body();
  const Layout out = without_entry(layout, 1);
  out.validate();
  ASSERT_EQ(out.entries.cols(), 3);
  for (int i : {0, 2, 3}) {
    const int k = i == 0 ? 0 : i - 1;
    EXPECT_EQ(out.entries.col(k), layout.entries.col(i));
    EXPECT_EQ(out.weights(k), layout.weights(i));
    EXPECT_EQ(out.names[static_cast<std::size_t>(k)], layout.entry_name(i));
    EXPECT_EQ(out.visibility->normals.col(k), layout.visibility->normals.col(i));
    EXPECT_EQ(out.visibility->cone_half_angle_deg(k), layout.visibility->cone_half_angle_deg(i));
  }
  EXPECT_EQ(out.visibility->min_visible, 3) << "at most the markers left";
}

TEST(LayoutEdits, AppendedMarkerLooksOutFromTheCentroidWithTheWidestCone) {
  Layout layout = on_body();
  const Eigen::Vector3d centroid = layout.entries.rowwise().mean();
  const Eigen::Vector3d x(2, 2, 0.25);
  append_entry(&layout, x, "added");
  layout.validate();
  ASSERT_EQ(layout.entries.cols(), 5);
  EXPECT_EQ(layout.entries.col(4), x);
  EXPECT_EQ(layout.weights(4), 1.0);
  EXPECT_TRUE(layout.names.empty()) << "an unnamed layout stays unnamed";
  EXPECT_NEAR((layout.visibility->normals.col(4) - (x - centroid).normalized()).norm(), 0.0, 1e-15);
  EXPECT_EQ(layout.visibility->cone_half_angle_deg(4), 40.0);
  Layout named = on_body();
  named.names = {"a", "b", "added1", "d"};
  append_entry(&named, x, "added");
  EXPECT_EQ(named.names.back(), "added2");
}

}  // namespace
}  // namespace vantage

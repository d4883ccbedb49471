#include "vantage/viewer/layout_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"

namespace vantage::viewer {
namespace {

const std::string kSatellite = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/satellite.json";

// Exact equality of everything a layout file holds.
void expect_same_layout(const Layout& a, const Layout& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.mode, b.mode);
  ASSERT_EQ(a.entries.cols(), b.entries.cols());
  EXPECT_TRUE((a.entries.array() == b.entries.array()).all());
  ASSERT_EQ(a.weights.size(), b.weights.size());
  EXPECT_TRUE((a.weights.array() == b.weights.array()).all());
  ASSERT_EQ(a.candidates.cols(), b.candidates.cols());
  EXPECT_TRUE((a.candidates.array() == b.candidates.array()).all());
  EXPECT_EQ(a.names, b.names);
}

std::filesystem::path scratch_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("vantage_viewer_doc_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

TEST(LayoutDocument, EveryEditIsUndoneExactly) {
  LayoutDocument doc(io::read_layout(kSatellite), kSatellite);
  const Layout original = doc.layout();
  const std::uint64_t r0 = doc.revision();
  EXPECT_FALSE(doc.modified());

  doc.set_entry(3, Eigen::Vector3d(0.1, -0.2, 0.3));
  doc.remove_entry(0);
  Layout grown = doc.layout();
  grown.entries.conservativeResize(3, grown.entries.cols() + 1);
  grown.entries.col(grown.entries.cols() - 1) = Eigen::Vector3d(0.0, 0.0, 1.5);
  grown.weights.conservativeResize(grown.weights.size() + 1);
  grown.weights(grown.weights.size() - 1) = 1.0;
  // The removal named the entries (p1, p2, ...: the names they were shown under), so an added
  // entry needs a name too.
  ASSERT_EQ(grown.names.size(), 11u);
  grown.names.push_back("new");
  MarkerVisibility& on_body = *grown.visibility;
  on_body.normals.conservativeResize(3, on_body.normals.cols() + 1);
  on_body.normals.col(on_body.normals.cols() - 1) = Eigen::Vector3d::UnitZ();
  on_body.cone_half_angle_deg.conservativeResize(on_body.normals.cols());
  on_body.cone_half_angle_deg(on_body.normals.cols() - 1) = 80.0;
  doc.replace(grown);
  EXPECT_EQ(doc.undo_depth(), 3u);
  EXPECT_TRUE(doc.modified());
  EXPECT_EQ(doc.layout().entries.cols(), original.entries.cols());

  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.layout().entries.col(3), Eigen::Vector3d(0.1, -0.2, 0.3));
  ASSERT_TRUE(doc.undo());
  expect_same_layout(doc.layout(), original);
  EXPECT_FALSE(doc.undo());
  EXPECT_EQ(doc.revision(), r0 + 6);  // three edits and three undos, each a new revision
}

TEST(LayoutDocument, RemovingAMarkerRemovesItsNormalAndCone) {
  Layout layout = io::read_layout(kSatellite);
  ASSERT_TRUE(layout.visibility);
  layout.visibility->cone_half_angle_deg(5) = 30.0;  // one marker's cone differs
  LayoutDocument doc(layout, kSatellite);
  doc.remove_entry(4);
  const MarkerVisibility& left = *doc.layout().visibility;
  ASSERT_EQ(left.normals.cols(), 11);
  ASSERT_EQ(left.cone_half_angle_deg.size(), 11);
  for (Eigen::Index i = 0; i < 11; ++i) {
    const Eigen::Index from = i < 4 ? i : i + 1;
    EXPECT_EQ(left.normals.col(i), layout.visibility->normals.col(from)) << i;
    EXPECT_EQ(left.cone_half_angle_deg(i), layout.visibility->cone_half_angle_deg(from)) << i;
  }
  EXPECT_EQ(left.cone_half_angle_deg(4), 30.0);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.layout().visibility->normals, layout.visibility->normals);
}

TEST(LayoutDocument, ConeAndMinVisibleEditsAreUndoableAndBadOnesThrow) {
  LayoutDocument doc(io::read_layout(kSatellite), kSatellite);
  const Layout original = doc.layout();
  std::uint64_t revision = doc.revision();
  doc.set_cone_half_angle_deg(45.0);
  EXPECT_EQ(doc.revision(), ++revision);
  EXPECT_TRUE((doc.layout().visibility->cone_half_angle_deg.array() == 45.0).all());
  doc.set_cone_half_angle_deg(180.0);  // the closed end of [0.001, 180]
  doc.set_min_visible(12);             // every marker
  EXPECT_EQ(doc.layout().visibility->min_visible, 12);
  revision += 2;
  auto expect_refused = [&](auto edit, const std::string& field) {
    const Layout before = doc.layout();
    try {
      edit();
      FAIL() << field << ": accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
    EXPECT_EQ(doc.revision(), revision);
    EXPECT_EQ(doc.layout().visibility->cone_half_angle_deg, before.visibility->cone_half_angle_deg);
    EXPECT_EQ(doc.layout().visibility->min_visible, before.visibility->min_visible);
  };
  const std::string cone = "visibility.cone_half_angle_deg";
  expect_refused([&] { doc.set_cone_half_angle_deg(0.0); }, cone);
  expect_refused([&] { doc.set_cone_half_angle_deg(180.000001); }, cone);
  expect_refused([&] { doc.set_cone_half_angle_deg(std::nan("")); }, cone);
  expect_refused([&] { doc.set_cone_half_angle_deg(INFINITY); }, cone);
  expect_refused([&] { doc.set_min_visible(2); }, "visibility.min_visible");
  expect_refused([&] { doc.set_min_visible(13); }, "visibility.min_visible");
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.layout().visibility->cone_half_angle_deg, original.visibility->cone_half_angle_deg);
  EXPECT_EQ(doc.layout().visibility->min_visible, original.visibility->min_visible);

  LayoutDocument whole(LayoutDocument::default_layout());
  EXPECT_THROW(whole.set_cone_half_angle_deg(45.0), InvalidArgument);
  EXPECT_THROW(whole.set_min_visible(3), InvalidArgument);
}

TEST(LayoutDocument, ADragIsOneUndoStep) {
  LayoutDocument doc(LayoutDocument::default_layout());
  const Layout original = doc.layout();
  doc.set_entry(0, Eigen::Vector3d(1.0, 0.1, 0.0));
  for (int k = 2; k <= 10; ++k) doc.set_entry(0, Eigen::Vector3d(1.0, 0.1 * k, 0.0), true);
  EXPECT_EQ(doc.undo_depth(), 1u);
  EXPECT_EQ(doc.layout().entries.col(0), Eigen::Vector3d(1.0, 1.0, 0.0));
  ASSERT_TRUE(doc.undo());
  expect_same_layout(doc.layout(), original);
}

TEST(LayoutDocument, InvalidEditsThrowAndChangeNothing) {
  LayoutDocument doc(LayoutDocument::default_layout());
  const Layout original = doc.layout();
  const std::uint64_t revision = doc.revision();
  EXPECT_THROW(doc.set_entry(1, Eigen::Vector3d::Zero()), InvalidArgument);   // zero vector
  EXPECT_THROW(doc.set_entry(7, Eigen::Vector3d::UnitX()), InvalidArgument);  // no entry 7
  doc.remove_entry(2);
  EXPECT_THROW(doc.remove_entry(1), InvalidArgument);  // would leave 1 vector
  ASSERT_TRUE(doc.undo());
  expect_same_layout(doc.layout(), original);
  EXPECT_EQ(doc.revision(), revision + 2);
  try {
    doc.set_entry(1, Eigen::Vector3d(0.0, std::nan(""), 0.0));
    FAIL() << "a NaN entry was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("vectors[1]"), std::string::npos) << e.what();
  }
}

TEST(LayoutDocument, BadFileKeepsTheLayoutAndSaysWhy) {
  LayoutDocument doc(io::read_layout(kSatellite), kSatellite);
  doc.set_entry(0, Eigen::Vector3d(0.5, 0.5, 0.5));
  const Layout before = doc.layout();
  const std::filesystem::path bad = scratch_file("bad.json");
  std::ofstream(bad) << R"({"vectors": [[1, 0, 0], [0, 0, 0]]})";
  try {
    doc.load(bad.string());
    FAIL() << "a zero vector was loaded";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(bad.string()), std::string::npos) << what;
    EXPECT_NE(what.find("vectors[1]"), std::string::npos) << what;
  }
  EXPECT_THROW(doc.load((bad.string() + ".missing")), InvalidArgument);
  expect_same_layout(doc.layout(), before);
  EXPECT_EQ(doc.path(), kSatellite);
  EXPECT_EQ(doc.undo_depth(), 1u);
  std::filesystem::remove(bad);
}

TEST(LayoutDocument, ALoadIsUndoneBackToTheEditsItReplaced) {
  LayoutDocument doc(io::read_layout(kSatellite), kSatellite);
  doc.set_entry(0, Eigen::Vector3d(0.5, 0.5, 0.5));
  const Layout edited = doc.layout();
  const std::string csv =
      std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/mocap_rigid_body.csv";
  doc.load(csv);
  EXPECT_EQ(doc.layout().entries.cols(), 5);
  EXPECT_EQ(doc.path(), csv);
  EXPECT_FALSE(doc.modified());
  EXPECT_EQ(doc.undo_depth(), 2u) << "the edit and the load";
  ASSERT_TRUE(doc.undo());
  expect_same_layout(doc.layout(), edited);
  EXPECT_EQ(doc.path(), kSatellite);
  EXPECT_TRUE(doc.modified()) << "the edits are unsaved again";
}

TEST(LayoutDocument, EveryFormatLoadsAndMarkersKeepTheirNames) {
  LayoutDocument doc(LayoutDocument::default_layout());
  const std::string dir = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";
  doc.load(dir + "apriltag_cube.yaml");
  EXPECT_EQ(doc.layout().entries.cols(), 12);
  doc.load(dir + "mocap_rigid_body.csv");
  ASSERT_EQ(doc.layout().entry_name(2), "arm_short");
  doc.remove_entry(1);
  EXPECT_EQ(doc.layout().names, (std::vector<std::string>{"hub", "arm_short", "arm_side", "mast"}));
  // An unnamed layout: the entries keep the names they were shown under (p0, p1, ...).
  LayoutDocument satellite(io::read_layout(kSatellite), kSatellite);
  ASSERT_TRUE(satellite.layout().names.empty());
  satellite.remove_entry(0);
  EXPECT_EQ(satellite.layout().entry_name(0), "p1");
  EXPECT_EQ(satellite.layout().entry_name(10), "p11");
  ASSERT_TRUE(satellite.undo());
  EXPECT_TRUE(satellite.layout().names.empty()) << "undo restores the layout exactly";
}

TEST(LayoutDocument, SaveWritesTheFormatOfTheExtension) {
  LayoutDocument doc(LayoutDocument::default_layout());
  doc.load(std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/mocap_rigid_body.csv");
  doc.remove_entry(0);
  const std::filesystem::path file = scratch_file("saved.csv");
  std::filesystem::remove(file);
  doc.save(file.string(), false);
  const Layout again = io::load_layout(file.string());
  EXPECT_EQ(again.names, doc.layout().names);
  EXPECT_TRUE((again.entries.array() == doc.layout().entries.array()).all());
  EXPECT_THROW(io::read_layout(file.string()), InvalidArgument) << "CSV, not JSON";
  EXPECT_THROW(doc.save(scratch_file("saved.yaml").string(), false), InvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(scratch_file("saved.yaml")));
  std::filesystem::remove(file);
}

TEST(LayoutDocument, SaveNeverOverwritesUnlessAsked) {
  LayoutDocument doc(LayoutDocument::default_layout());
  const std::filesystem::path file = scratch_file("saved.json");
  std::filesystem::remove(file);
  doc.set_entry(2, Eigen::Vector3d(0.0, 0.6, 0.8));
  doc.save(file.string(), false);
  EXPECT_FALSE(doc.modified());
  EXPECT_EQ(doc.path(), file.string());
  expect_same_layout(io::read_layout(file.string()), doc.layout());

  doc.set_entry(2, Eigen::Vector3d(0.0, 0.0, 2.0));
  EXPECT_THROW(doc.save(file.string(), false), InvalidArgument);
  EXPECT_TRUE(doc.modified());
  EXPECT_EQ(io::read_layout(file.string()).entries.col(2), Eigen::Vector3d(0.0, 0.6, 0.8));
  doc.save(file.string(), true);
  EXPECT_EQ(io::read_layout(file.string()).entries.col(2), Eigen::Vector3d(0.0, 0.0, 2.0));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace vantage::viewer

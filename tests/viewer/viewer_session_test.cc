#include "vantage/viewer/viewer_session.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/visibility/visibility_report.h"
#include "viewer/viewer_runner.h"

namespace vantage::viewer {
namespace {

using std::chrono::seconds;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";
constexpr auto kAnalysisWait = seconds(300);  // generous: the machine is shared
// The worker and a fresh analyze_vectors run the same deterministic code on the same doubles
// (the JSON file round-trips them exactly); allow only rounding-level differences.
constexpr double kSameRun = 1e-12;
// pbar_min is the certified global minimum of p_bar(a): no sphere vertex may beat it by more than
// the certificate tolerance.
constexpr double kCertificateSlack = 1e-7;

// The readout's largest error is recomputed from the data at the certified viewpoint: arccos of a
// p-bar within rounding of the report's, in degrees.
constexpr double kReadoutDeg = 1e-6;
// p-bar is the maximum of the p_i: the limiting p_i is the same double.
constexpr double kExact = 0.0;
// The camera keeps a view direction as yaw and pitch: trigonometric rounding, far below this.
constexpr double kCameraRounding = 1e-9;

ViewerSession open(const std::string& file) {
  return ViewerSession(LayoutDocument(io::read_layout(kLayouts + file), kLayouts + file));
}

void expect_same_analysis(const sdp::LayoutAnalysis& got, const sdp::LayoutAnalysis& want) {
  EXPECT_NEAR(got.t, want.t, kSameRun);
  EXPECT_NEAR(got.pbar_min, want.pbar_min, kSameRun);
  EXPECT_EIGEN_NEAR(got.worst_viewpoint, want.worst_viewpoint, kSameRun);
  EXPECT_EQ(got.worst_viewpoints.size(), want.worst_viewpoints.size());
  EXPECT_EIGEN_NEAR(got.worst_case_errors_deg, want.worst_case_errors_deg, kSameRun);
  EXPECT_NEAR(got.certificate.t_upper, want.certificate.t_upper, kSameRun);
  EXPECT_EQ(got.certificate.certified, want.certificate.certified);
  EXPECT_NEAR(got.paper_lmi.pbar_at, want.paper_lmi.pbar_at, kSameRun);
  EXPECT_EQ(got.solver.status, want.solver.status);
}

// Drags entry `index` through a few positions (one undo step), waits for the worker, saves, and
// compares the worker's analysis with analyze_vectors on the saved file (what `vantage analyze`
// runs).
void drag_and_compare(const std::string& file, int index) {
  ViewerSession session = open(file);
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  const double before = session.analysis()->analysis.pbar_min;
  const Eigen::Vector3d start = session.layout().entries.col(index);
  for (int k = 1; k <= 4; ++k) {
    ASSERT_TRUE(
        session.set_entry(index, start + Eigen::Vector3d(0.05 * k, -0.03 * k, 0.02 * k), k > 1));
  }
  EXPECT_EQ(session.document().undo_depth(), 1u);
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  ASSERT_TRUE(session.analysis_current());
  ASSERT_EQ(session.analysis()->error, "");

  testing::ViewerScratch scratch;
  const std::string saved = scratch.path("dragged.json");
  ASSERT_EQ(session.save(saved, false), SaveOutcome::kSaved);
  const DataVectors data = data_vectors(io::read_layout(saved));
  expect_same_analysis(session.analysis()->analysis,
                       sdp::analyze_vectors(data.vectors, data.weights));
  EXPECT_NE(session.analysis()->analysis.pbar_min, before);  // the drag changed the answer
}

TEST(ViewerSession, DraggedVectorIsReanalysedAsAnalyzeOnTheSavedFile) {
  drag_and_compare("note3_four_vectors.json", 0);
}

TEST(ViewerSession, DraggedMarkerIsReanalysedAsAnalyzeOnTheSavedFile) {
  drag_and_compare("satellite.json", 0);
}

TEST(ViewerSession, OnlyTheNewestRevisionIsShown) {
  ViewerSession session = open("triad.json");
  for (int k = 1; k <= 6; ++k) {
    ASSERT_TRUE(session.set_entry(0, Eigen::Vector3d(1.0, 0.1 * k, 0.0)));
  }
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_EQ(session.analysis()->revision, session.document().revision());
  EXPECT_TRUE(
      (session.analysis()->layout.entries.array() == session.layout().entries.array()).all());
}

TEST(ViewerSession, AugmenterStepThenUndoRestoresExactly) {
  ViewerSession session = open("note3_four_vectors.json");
  const Layout original = session.layout();
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  const double pbar_before = session.analysis()->analysis.pbar_min;
  session.step_augmenter();
  EXPECT_TRUE(session.augmenting());
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_FALSE(session.message_is_error()) << session.message();
  ASSERT_EQ(session.layout().entries.cols(), original.entries.cols() + 1);
  EXPECT_GE(session.analysis()->analysis.pbar_min, pbar_before - kSameRun);  // never worse

  ASSERT_TRUE(session.undo());
  EXPECT_TRUE((session.layout().entries.array() == original.entries.array()).all());
  EXPECT_TRUE((session.layout().weights.array() == original.weights.array()).all());
  EXPECT_EQ(session.layout().name, original.name);
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_NEAR(session.analysis()->analysis.pbar_min, pbar_before, kSameRun);
}

TEST(ViewerSession, AugmenterStepForAnOlderLayoutIsDiscarded) {
  ViewerSession session = open("triad.json");
  session.step_augmenter();
  ASSERT_TRUE(session.set_entry(2, Eigen::Vector3d(0.0, 0.3, 1.0)));
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_EQ(session.layout().entries.cols(), 3);
  EXPECT_TRUE(session.message_is_error());
  EXPECT_NE(session.message().find("discarded"), std::string::npos) << session.message();
}

TEST(ViewerSession, BadFileInTheLoadDialogKeepsEverything) {
  ViewerSession session = open("satellite.json");
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  const std::uint64_t revision = session.document().revision();
  testing::ViewerScratch scratch;
  const std::string bad =
      scratch.write("bad.json", R"({"points": [[0, 0, 0], [0, 0, 0], [1, 2]]})");
  EXPECT_EQ(session.load(bad), LoadOutcome::kFailed);
  EXPECT_TRUE(session.message_is_error());
  EXPECT_NE(session.message().find(bad), std::string::npos) << session.message();
  EXPECT_EQ(session.document().revision(), revision);
  EXPECT_EQ(session.document().path(), kLayouts + "satellite.json");
  EXPECT_TRUE(session.analysis_current());
  EXPECT_EQ(session.layout().entries.cols(), 12);
}

TEST(ViewerSession, LoadAsksBeforeDroppingUnsavedEditsAndUndoBringsThemBack) {
  ViewerSession session = open("triad.json");
  const std::string csv = kLayouts + "mocap_rigid_body.csv";
  ASSERT_TRUE(session.set_entry(2, Eigen::Vector3d(0.0, 0.3, 1.0)));
  const Layout edited = session.layout();
  const std::uint64_t revision = session.document().revision();
  EXPECT_EQ(session.load(csv), LoadOutcome::kNeedsDiscardOk);
  EXPECT_EQ(session.document().revision(), revision) << "nothing read";
  EXPECT_TRUE((session.layout().entries.array() == edited.entries.array()).all());
  EXPECT_EQ(session.load(csv, true), LoadOutcome::kLoaded);
  EXPECT_EQ(session.layout().entries.cols(), 5);
  EXPECT_GT(session.document().undo_depth(), 0u) << "Undo is available after a load";
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE((session.layout().entries.array() == edited.entries.array()).all());
  EXPECT_TRUE(session.document().modified());
  EXPECT_EQ(session.document().path(), kLayouts + "triad.json");
  // Without edits a load needs no confirmation.
  ViewerSession fresh = open("triad.json");
  EXPECT_EQ(fresh.load(csv), LoadOutcome::kLoaded);
}

TEST(ViewerSession, DraggingAVectorTipMovesItUnderTheMouse) {
  // The scene draws vector i's tip at 1.45 |v_i|-normalised (viewer/app/scene_view.cc).
  constexpr double kTipRadius = 1.45;
  constexpr double kPixel = 1e-6;  // closed-form projections
  ViewerSession session = open("triad.json");
  const Viewport viewport = scene_viewport(1400, 900);
  const Eigen::Vector3d start = session.layout().entries.col(0);
  const std::optional<Eigen::Vector2d> grabbed =
      session.camera.project(kTipRadius * start.normalized(), viewport);
  ASSERT_TRUE(grabbed);
  // What the drag used before: the unit sphere under the tip, which is not there.
  EXPECT_FALSE(session.camera.pick_sphere(*grabbed, viewport));
  Eigen::Vector2d mouse = *grabbed;
  for (int k = 1; k <= 5; ++k) {
    mouse += Eigen::Vector2d(9.0, -5.0);
    ASSERT_TRUE(session.drag_vector_tip(0, mouse, viewport, kTipRadius, k > 1));
  }
  const Eigen::Vector3d moved = session.layout().entries.col(0);
  EXPECT_NEAR(moved.norm(), start.norm(), 1e-12) << "the length is kept";
  const std::optional<Eigen::Vector2d> drawn =
      session.camera.project(kTipRadius * moved.normalized(), viewport);
  ASSERT_TRUE(drawn);
  EXPECT_NEAR((*drawn - mouse).norm(), 0.0, kPixel) << "the tip is under the mouse";
  EXPECT_GT((moved - start).norm(), 0.05);
  EXPECT_EQ(session.document().undo_depth(), 1u) << "one drag, one undo step";
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE((session.layout().entries.col(0).array() == start.array()).all());
  ViewerSession points = open("satellite.json");
  EXPECT_FALSE(points.drag_vector_tip(0, mouse, viewport, kTipRadius, false));
}

TEST(ViewerSession, SaveAsksBeforeOverwriting) {
  ViewerSession session = open("triad.json");
  testing::ViewerScratch scratch;
  const std::string file = scratch.write("exists.json", "keep me");
  EXPECT_EQ(session.save(file, false), SaveOutcome::kNeedsOverwriteOk);
  EXPECT_EQ(testing::slurp(file), "keep me");
  EXPECT_EQ(session.save(file, true), SaveOutcome::kSaved);
  EXPECT_EQ(io::read_layout(file).entries.cols(), 3);
  EXPECT_EQ(session.save(scratch.path("no/such/dir.json"), false), SaveOutcome::kFailed);
  EXPECT_TRUE(session.message_is_error());
}

TEST(ViewerSession, ShadingAndReadoutAgreeWithTheCertifiedWorstCase) {
  for (const char* file : {"triad.json", "satellite.json", "coplanar_fan.json"}) {
    SCOPED_TRACE(file);
    ViewerSession session = open(file);
    ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
    const sdp::LayoutAnalysis& report = session.analysis()->analysis;
    const double top_deg = kDegreesPerRadian * std::acos(report.pbar_min);
    EXPECT_LE(session.shading().error_deg.maxCoeff(), top_deg + kCertificateSlack * 180.0);
    const ViewpointReadout r = read_viewpoint(session.data().vectors, report.worst_viewpoint);
    EXPECT_NEAR(r.pbar_at, report.pbar_min, kCertificateSlack);
    EXPECT_NEAR(r.max_error_deg, report.max_worst_case_error_deg, kReadoutDeg);
    EXPECT_NEAR(r.p(r.limiting), r.pbar_at, kExact);
  }
}

// The satellite on its body (io::load_layout reads the mesh the file names).
ViewerSession open_on_body() {
  return ViewerSession(
      LayoutDocument(io::load_layout(kLayouts + "satellite.json"), kLayouts + "satellite.json"));
}

TEST(ViewerSession, ConeEditIsReanalysedThroughTheWorkerAsAnalyze) {
  ViewerSession session = open_on_body();
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  ASSERT_TRUE(session.analysis()->visibility);
  const visibility::VisibilityReport before = *session.analysis()->visibility;
  const std::uint64_t revision = session.document().revision();
  ASSERT_TRUE(session.set_cone_half_angle_deg(60.0));
  EXPECT_EQ(session.document().revision(), revision + 1);
  EXPECT_FALSE(session.analysis_current()) << "the edit asks for a new analysis";
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  ASSERT_EQ(session.analysis()->error, "");
  const visibility::VisibilityReport& after = *session.analysis()->visibility;

  // What `vantage analyze --cone-deg 60` computes: the file with every cone set to 60 degrees.
  Layout edited = io::load_layout(kLayouts + "satellite.json");
  edited.visibility->cone_half_angle_deg.setConstant(60.0);
  const visibility::VisibilityReport want = visibility::analyze_visibility(edited);
  EXPECT_NEAR(after.worst.t, want.worst.t, kSameRun);
  EXPECT_NEAR(after.worst.t_upper, want.worst.t_upper, kSameRun);
  EXPECT_EQ(after.worst.visible_markers, want.worst.visible_markers);
  EXPECT_EQ(after.coverage.trackable_fraction, want.coverage.trackable_fraction);
  // A narrower cone sees a subset of the markers from every direction: nothing becomes
  // trackable (the coverage samples the same directions).
  EXPECT_LE(after.coverage.trackable_fraction, before.coverage.trackable_fraction);
  EXPECT_NE(after.worst.t, before.worst.t);
  // The viewer's own model follows the edit too.
  ASSERT_NE(session.visibility(), nullptr);
  EXPECT_NEAR(session.visibility()->problem().cos_cone(0), std::cos(60.0 / kDegreesPerRadian),
              kSameRun);

  ASSERT_TRUE(session.set_min_visible(5));
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_EQ(session.analysis()->visibility->min_visible, 5);
  EXPECT_LE(session.analysis()->visibility->coverage.trackable_fraction,
            after.coverage.trackable_fraction);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_EQ(session.analysis()->visibility->worst.t, before.worst.t) << "undo: the same answer";
}

TEST(ViewerSession, BadVisibilityEditsAreRefusedAndChangeNothing) {
  ViewerSession session = open_on_body();
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  const std::uint64_t revision = session.document().revision();
  for (const double cone : {0.0, -10.0, 180.5, std::nan("")}) {
    EXPECT_FALSE(session.set_cone_half_angle_deg(cone)) << cone;
    EXPECT_TRUE(session.message_is_error());
    EXPECT_NE(session.message().find("visibility.cone_half_angle_deg"), std::string::npos)
        << session.message();
  }
  for (const int k : {2, 13}) {
    EXPECT_FALSE(session.set_min_visible(k)) << k;
    EXPECT_NE(session.message().find("visibility.min_visible"), std::string::npos)
        << session.message();
  }
  EXPECT_EQ(session.document().revision(), revision);
  EXPECT_TRUE(session.analysis_current()) << "no analysis was asked for";
  EXPECT_FALSE(session.working());
  EXPECT_EQ(session.layout().visibility->cone_half_angle_deg(0), 80.0);

  // The augmenter's marker comes with a normal and a cone (analysis' append_entry).
  const Eigen::Index before = session.layout().entries.cols();
  session.step_augmenter();
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  EXPECT_FALSE(session.message_is_error()) << session.message();
  ASSERT_EQ(session.layout().entries.cols(), before + 1);
  EXPECT_EQ(session.layout().visibility->normals.cols(), before + 1);
  EXPECT_EQ(session.layout().visibility->cone_half_angle_deg.size(), before + 1);

  ViewerSession whole = open("triad.json");
  EXPECT_FALSE(whole.set_cone_half_angle_deg(45.0));
  EXPECT_NE(whole.message().find("visibility.cone_half_angle_deg"), std::string::npos)
      << whole.message();
}

TEST(ViewerSession, ViewPresetsUseTheAnalysis) {
  ViewerSession session = open("note3_four_vectors.json");
  ASSERT_TRUE(session.wait_until_current(kAnalysisWait));
  ASSERT_TRUE(session.apply_view(ViewPreset::kWorst));
  EXPECT_EIGEN_NEAR(session.camera.back(), session.analysis()->analysis.worst_viewpoint,
                    kCameraRounding);
  ASSERT_TRUE(session.apply_view(ViewPreset::kPaper));
  EXPECT_EIGEN_NEAR(session.camera.back(), session.analysis()->analysis.paper_lmi.viewpoint,
                    kCameraRounding);
}

}  // namespace
}  // namespace vantage::viewer

// Bad input on vantage-viewer's command line: exit status 2 and one line on stderr naming the
// file, field or option, before any window opens (so these run without a display).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "viewer/viewer_runner.h"

namespace vantage::testing {
namespace {

using ::testing::HasSubstr;

void expect_refused(const ViewerRun& run, const std::string& fragment) {
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage-viewer: "));
  EXPECT_THAT(run.err, HasSubstr(fragment));
}

TEST(ViewerCli, BadLayoutFileNamesFileFieldAndIndex) {
  ViewerScratch scratch;
  const std::string bad = scratch.write("bad.json", R"({"vectors": [[1, 0, 0], [0, 1]]})");
  const ViewerRun run = run_viewer("env -u DISPLAY", "'" + bad + "'", scratch);
  expect_refused(run, bad);
  EXPECT_THAT(run.err, HasSubstr("vectors[1]"));
}

TEST(ViewerCli, MissingAndNonJsonFiles) {
  ViewerScratch scratch;
  expect_refused(run_viewer("env -u DISPLAY", "'" + scratch.path("none.json") + "'", scratch),
                 "none.json");
  const std::string text = scratch.write("text.json", "not json at all");
  expect_refused(run_viewer("env -u DISPLAY", "'" + text + "'", scratch), "text.json");
}

TEST(ViewerCli, BadOptionsNameTheOption) {
  ViewerScratch scratch;
  expect_refused(run_viewer("env -u DISPLAY", "--size 12x", scratch), "--size");
  expect_refused(run_viewer("env -u DISPLAY", "--size 100000x900", scratch), "--size");
  expect_refused(run_viewer("env -u DISPLAY", "--view bottom", scratch), "--view");
  expect_refused(run_viewer("env -u DISPLAY", "--frames 0", scratch), "--frames");
  expect_refused(run_viewer("env -u DISPLAY", "--pin 0,0,0", scratch), "--pin");
  expect_refused(run_viewer("env -u DISPLAY", "--pin 1,2", scratch), "--pin");
  expect_refused(run_viewer("env -u DISPLAY", "--pin 1,2,nan", scratch), "--pin");
  expect_refused(run_viewer("env -u DISPLAY", "--place 2", scratch), "--place");
  // The default layout (the triad) has no body to place markers on.
  expect_refused(run_viewer("env -u DISPLAY", "--place 4", scratch), "--place");
  expect_refused(run_viewer("env -u DISPLAY", "--candidates 0", scratch), "--candidates");
}

TEST(ViewerCli, NoDisplayIsAFailureNotACrash) {
  ViewerScratch scratch;
  const ViewerRun run = run_viewer("env -u DISPLAY -u WAYLAND_DISPLAY",
                                   "--screenshot '" + scratch.path("x.png") + "'", scratch);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("xvfb-run"));
}

}  // namespace
}  // namespace vantage::testing

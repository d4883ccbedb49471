// `vantage plot`, `vantage analyze --dropout` and `vantage design --plot`: the JSON contracts,
// the files written, and the bad-input contract (one line, exit 2, nothing written).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

// Two global solves of the same vectors agree to rounding.
constexpr double kExact = 1e-12;

// arccos of p-bars kExact apart, in degrees: 57 x 1e-12 / sin(theta).
constexpr double kExactDeg = 1e-9;

std::string layout(const char* name) {
  return "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json'";
}

// A `vantage design --json` output with the fields `plot --design` reads.
constexpr const char* kDesignJson = R"({
  "name": "triad grown",
  "initial": {"n_vectors": 3, "pbar_min": 0.816496580927726},
  "steps": [{"n_vectors": 4, "pbar_min": 0.816496580927726},
            {"n_vectors": 5, "pbar_min": 0.9}],
  "direct": {"pbar_min": 0.92}
})";

std::size_t entries_in(const std::filesystem::path& dir) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++count;
  return count;
}

TEST(PlotCli, WritesEveryFigureAndListsTheFiles) {
  ScratchDir scratch;
  scratch.write("design.json", kDesignJson);
  const auto json = testing::run_json(
      "plot " + layout("note3_four_vectors") + " --out figs --design design.json --size 800x600",
      scratch);
  for (const char* field : {"layout", "name", "out", "format", "size", "threshold_deg", "pbar_min",
                            "max_worst_case_error_deg", "status", "figures"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  EXPECT_EQ(json["format"], "png");
  EXPECT_EQ(json["size"], nlohmann::json::array({800, 600}));
  EXPECT_EQ(json["status"], "certified");
  ASSERT_EQ(json["figures"].size(), 5u);
  const char* names[] = {"viewpoint_map", "dropout", "error_surface", "vectors", "design"};
  for (std::size_t k = 0; k < 5; ++k) {
    const auto& figure = json["figures"][k];
    EXPECT_EQ(figure["name"], names[k]);
    EXPECT_EQ(figure["image"], std::string("figs/") + names[k] + ".png");
    EXPECT_TRUE(std::filesystem::exists(scratch.dir() / figure["image"].get<std::string>()));
    EXPECT_TRUE(std::filesystem::exists(scratch.dir() / figure["csv"].get<std::string>()));
  }
  EXPECT_EQ(entries_in(scratch.dir() / "figs"), 10u);
}

TEST(PlotCli, OnlyAndFormatPickTheFiles) {
  ScratchDir scratch;
  const auto json = testing::run_json(
      "plot " + layout("triad") + " --out figs --only vectors,error_surface --format svg", scratch);
  ASSERT_EQ(json["figures"].size(), 2u);
  EXPECT_EQ(json["figures"][0]["name"], "error_surface");
  EXPECT_EQ(json["figures"][1]["image"], "figs/vectors.svg");
  EXPECT_EQ(entries_in(scratch.dir() / "figs"), 4u);
}

TEST(PlotCli, ReadableReportListsTheFiles) {
  ScratchDir scratch;
  const auto run = run_vantage("plot " + layout("triad") + " --out figs --only dropout", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_THAT(run.out, HasSubstr("figs/dropout.png"));
  EXPECT_THAT(run.out, HasSubstr("figs/dropout.csv"));
}

TEST(PlotCli, BadInputIsOneLineExitTwoAndWritesNothing) {
  const testing::BadCall calls[] = {
      {"unknown figure", nullptr, "LAYOUT --out figs --only vectors,histogram", "--only"},
      {"design figure without a design", nullptr, "LAYOUT --out figs --only design", "--design"},
      {"size not WxH", nullptr, "LAYOUT --out figs --size big", "--size"},
      {"size too small", nullptr, "LAYOUT --out figs --size 10x10", "--size"},
      {"unknown format", nullptr, "LAYOUT --out figs --format gif", "--format"},
      {"threshold out of range", nullptr, "LAYOUT --out figs --threshold-deg 95",
       "--threshold-deg"},
      {"out is a file", nullptr, "LAYOUT --out in.txt", "--out"},
      {"out cannot be created", nullptr, "LAYOUT --out /proc/vantage_figures", "--out"},
      {"bad layout", R"({"vectors": [[1, 0, 0], [0, 0, 0]]})", "in.json --out figs", "in.json"},
      {"design file not JSON", nullptr, "LAYOUT --out figs --design in.txt", "in.txt"},
      {"visibility figure without normals", nullptr, "LAYOUT --out figs --only visibility",
       "--only"},
  };
  for (const testing::BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    ScratchDir scratch;
    scratch.write("in.txt", "not json");
    std::string args = call.args;
    const auto at = args.find("LAYOUT");
    if (at != std::string::npos) args.replace(at, 6, layout("triad"));
    testing::run_bad_call("plot", {call.name, call.file_text, args.c_str(), call.expected},
                          scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.dir() / "figs"));
    EXPECT_FALSE(std::filesystem::exists("/proc/vantage_figures"));
  }
}

TEST(PlotCli, OnABodyTheVisibilityFigureAndBothAnswers) {
  ScratchDir scratch;
  const auto json =
      testing::run_json("plot " + layout("satellite") + " --out figs --only visibility", scratch);
  ASSERT_EQ(json["figures"].size(), 1u);
  EXPECT_EQ(json["figures"][0]["image"], "figs/visibility.png");
  const auto analysis = testing::run_json("analyze " + layout("satellite") + " --json", scratch);
  EXPECT_EQ(json["visibility"]["max_worst_case_error_deg"],
            analysis["visibility"]["max_worst_case_error_deg"]);
  EXPECT_EQ(json["visibility"]["trackable_fraction"], analysis["visibility"]["trackable_fraction"]);
  EXPECT_EQ(json["max_worst_case_error_deg"], analysis["max_worst_case_error_deg"]) << "seen whole";
}

TEST(AnalyzeDropoutCli, EntriesEqualTheAnalysisOfTheLayoutWithoutThatVector) {
  ScratchDir scratch;
  const auto json =
      testing::run_json("analyze " + layout("note3_four_vectors") + " --dropout", scratch);
  ASSERT_TRUE(json.contains("dropout"));
  const double intact = json["pbar_min"].get<double>();
  const char* vectors[] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]",
                           "[0.4082482904638631, 0.4082482904638631, -0.8164965809277261]"};
  ASSERT_EQ(json["dropout"].size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const auto& entry = json["dropout"][k];
    EXPECT_EQ(entry["index"], k);
    for (const char* field : {"pbar_min", "max_worst_case_error_deg", "worst_viewpoint"}) {
      EXPECT_TRUE(entry.contains(field)) << field;
    }
    EXPECT_LE(entry["pbar_min"].get<double>(), intact + kExact);
    std::string text = R"({"vectors": [)";
    bool first = true;
    for (int i = 0; i < 4; ++i) {
      if (i == k) continue;
      text += (first ? "" : ", ") + std::string(vectors[i]);
      first = false;
    }
    scratch.write("without.json", text + "]}");
    const auto reduced = testing::run_json("analyze without.json", scratch);
    EXPECT_NEAR(entry["pbar_min"].get<double>(), reduced["pbar_min"].get<double>(), kExact);
    EXPECT_NEAR(entry["max_worst_case_error_deg"].get<double>(),
                reduced["max_worst_case_error_deg"].get<double>(), kExactDeg);
  }
}

TEST(AnalyzeDropoutCli, WithoutTheFlagThereIsNoDropoutField) {
  ScratchDir scratch;
  const auto json = testing::run_json("analyze " + layout("triad"), scratch);
  EXPECT_FALSE(json.contains("dropout"));
}

TEST(DesignPlotCli, WritesTheDesignFigure) {
  ScratchDir scratch;
  const auto json =
      testing::run_json("design " + layout("triad") + " --add 1 --no-direct --plot figs", scratch);
  ASSERT_TRUE(json.contains("figures"));
  ASSERT_EQ(json["figures"].size(), 1u);
  EXPECT_EQ(json["figures"][0]["image"], "figs/design.png");
  EXPECT_TRUE(std::filesystem::exists(scratch.dir() / "figs" / "design.png"));
  EXPECT_TRUE(std::filesystem::exists(scratch.dir() / "figs" / "design.csv"));
}

TEST(DesignPlotCli, PlotThatIsAFileIsRefusedBeforeTheSearch) {
  ScratchDir scratch;
  scratch.write("in.txt", "x");
  const auto run =
      run_vantage("design " + layout("triad") + " --add 1 --no-direct --plot in.txt", scratch);
  testing::expect_bad_input(run, "--plot");
}

}  // namespace
}  // namespace vantage

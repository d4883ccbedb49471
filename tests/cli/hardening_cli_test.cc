// The contract under hostile input (issue 13): bounded resources, all-or-nothing writes,
// diagnostics in the user's words, reports that cannot mislead.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>

#include "support/cli_runner.h"
#include "support/sanitized.h"

namespace vantage {
namespace {

// The same correspondences in other units give R and alpha that differ by rounding only.
constexpr double kScaleInvariance = 1e-12;

namespace fs = std::filesystem;
using testing::expect_bad_input;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";
const std::string kTriad = kLayouts + "triad.json";
const std::string kSatellite = kLayouts + "satellite.json";
const std::string kCube = std::string(VANTAGE_SOURCE_DIR) + "/examples/correspondences/cube.json";
const char* kTriadText = R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})";

// Runs `<prefix> vantage <args>` in `scratch` (prefix: a shell command that wraps the run).
testing::CliRun run_wrapped(const std::string& prefix, const std::string& args,
                            const ScratchDir& scratch) {
  const std::string out = scratch.path("stdout.txt"), err = scratch.path("stderr.txt");
  const std::string command = "cd '" + scratch.dir().string() + "' && " + prefix + " '" +
                              VANTAGE_CLI + "' " + args + " > '" + out + "' 2> '" + err +
                              "' < /dev/null";
  const int raw = std::system(command.c_str());
  testing::CliRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = testing::read_file(out);
  run.err = testing::read_file(err);
  fs::remove(out);
  fs::remove(err);
  return run;
}

// Every entry of the scratch directory except the given input files.
std::vector<std::string> outputs(const ScratchDir& scratch, std::vector<std::string> inputs) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(scratch.dir())) {
    const std::string name = e.path().filename().string();
    if (std::find(inputs.begin(), inputs.end(), name) == inputs.end()) names.push_back(name);
  }
  return names;
}

// ---- Diagnostics: the user's words --------------------------------------------------------

TEST(HardeningCli, UnknownSubcommandIsNamed) {
  ScratchDir scratch;
  const auto run = run_vantage("frob", scratch);
  expect_bad_input(run, "unknown subcommand \"frob\"");
  EXPECT_THAT(run.err, HasSubstr("analyze"));
}

// Issue 36, item 6: "Could not convert: --monte-carlo = 1e15" (CLI11's words) named the option
// but not what it takes; a whole-number option written as 1e5 or 2.5 now says so.
TEST(HardeningCli, ANumberOfTheWrongKindNamesWhatTheOptionTakes) {
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  const std::string whole = "is not a whole number (write its digits: 100000, not 1e5)";
  expect_bad_input(run_vantage("simulate in.json --trials 1e5", scratch),
                   "--trials: \"1e5\" " + whole);
  expect_bad_input(run_vantage("design in.json --add 2.5", scratch), "--add: \"2.5\" " + whole);
  expect_bad_input(run_vantage("layout board --type chessboard --rows 2e1 --cols 3 --square 1 "
                               "--out b.json",
                               scratch),
                   "--rows: \"2e1\" " + whole);
  expect_bad_input(run_vantage("crb in.json --distance x --focal 900 --noise-px 0.3", scratch),
                   "--distance: \"x\" is not a number");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("b.json")));
  // Issue 36, item 6: a comma list took C's hexadecimal floats ("0x1p3" as 8); decimals only.
  const std::string tool = std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/ndi_like.json";
  expect_bad_input(run_vantage("tre " + tool + " --target 0x1p3,0,0 --fle-rms 0.25", scratch),
                   "--target: expected X,Y,Z, three finite numbers, got \"0x1p3,0,0\"");
  expect_bad_input(run_vantage("analyze in.json --workspace 0,0,1,0x3c", scratch), "--workspace");
}

TEST(HardeningCli, FileNameTooLongIsBadInput) {
  ScratchDir scratch;
  const std::string name = std::string(300, 'n') + ".json";
  expect_bad_input(run_vantage("analyze " + name, scratch), "File name too long");
  expect_bad_input(run_vantage("weights " + name, scratch), "File name too long");
  scratch.write("in.json", kTriadText);
  expect_bad_input(run_vantage("design in.json --add 1 --write " + name, scratch),
                   "File name too long");
}

TEST(HardeningCli, JsonReaderNamesFieldAndIndex) {
  ScratchDir scratch;
  scratch.write("dup.json", R"({"vectors": [[1,0,0],[0,1,0]], "vectors": [[0,0,1],[1,0,0]]})");
  expect_bad_input(run_vantage("analyze dup.json", scratch), "dup.json: vectors: duplicate key");
  scratch.write("nan.json", R"({"vectors": [[1,0,0],[0,1,NaN]]})");
  expect_bad_input(run_vantage("weights nan.json", scratch),
                   "nan.json: vectors[1][2]: not a finite number");
  scratch.write("big.json", R"({"vectors": [[1,0,0],[0,1,1e999]]})");
  expect_bad_input(run_vantage("design big.json --add 1", scratch),
                   "big.json: vectors[1][2]: number out of range");
}

TEST(HardeningCli, OrientNamesTheFileFields) {
  ScratchDir scratch;
  scratch.write("empty.json", R"({"model": [], "measured": []})");
  const auto run = run_vantage("orient empty.json", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_THAT(run.err, HasSubstr("model"));
  EXPECT_THAT(run.err, Not(HasSubstr("z_object")));
}

TEST(HardeningCli, OrientIsScaleInvariant) {
  // The cube example in units of 1e-200 and 1e200, and with a point moved to 1e308 (which
  // stays an outlier, not "coincident points"): the same rotation as the original units.
  ScratchDir scratch;
  const nlohmann::json cube = nlohmann::json::parse(testing::read_file(kCube));
  const nlohmann::json reference = testing::run_json("orient '" + kCube + "'", scratch);
  for (const double scale : {1e-200, 1e200}) {
    nlohmann::json scaled = cube;
    for (const char* field : {"model", "measured"}) {
      for (auto& point : scaled[field]) {
        for (auto& x : point) x = x.get<double>() * scale;
      }
    }
    scratch.write("scaled.json", scaled.dump());
    const nlohmann::json json = testing::run_json("orient scaled.json", scratch);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(json["R"][i][j].get<double>(), reference["R"][i][j].get<double>(),
                    kScaleInvariance)
            << scale;
      }
    }
    EXPECT_NEAR(json["alpha"].get<double>(), reference["alpha"].get<double>(), kScaleInvariance)
        << scale;
  }
  nlohmann::json outlier = cube;
  outlier["measured"][0][0] = 1e308;
  scratch.write("outlier.json", outlier.dump());
  const auto run = run_vantage("orient outlier.json --json", scratch);
  EXPECT_THAT(run.err, Not(HasSubstr("coincide")));
  EXPECT_NE(run.status, 2) << run.err;
}

TEST(HardeningCli, MarginOutOfRangeIsRejectedAsSuch) {
  ScratchDir scratch;
  const auto run = run_vantage("design '" + kSatellite + "' --add 1 --margin 1e8", scratch);
  expect_bad_input(run, "--margin: must be in [0, 100]");
  EXPECT_THAT(run.err, Not(HasSubstr("coincides")));
}

// ---- Resources ------------------------------------------------------------------------------

TEST(HardeningCli, LimitsAreCheckedBeforeAnyWork) {
  ScratchDir scratch;
  expect_bad_input(run_vantage("design '" + kTriad + "' --add 1000000", scratch),
                   "--add 1000000 on 1000003 data vectors: about 500001500 s of CPU exceeds the "
                   "budget of 30 s for `vantage design`");
  // /dev/zero as a layout: the read stops at the file size bound.
  expect_bad_input(run_vantage("analyze /dev/zero", scratch), "/dev/zero: larger than 67108864");
  // 201 points give 20 100 free vectors, beyond analyze's 20 000.
  nlohmann::json many;
  for (int k = 0; k < 201; ++k) many["points"].push_back({k, k * k % 17, k % 5});
  scratch.write("many.json", many.dump());
  expect_bad_input(run_vantage("analyze many.json", scratch),
                   "many.json: data vectors: 20100 exceeds the limit of 20000");
  // --dropout runs one search per entry: 46 points (1035 free vectors) are beyond its 1000.
  nlohmann::json dropout;
  for (int k = 0; k < 46; ++k) dropout["points"].push_back({k, k * k % 17, k % 5});
  scratch.write("dropout.json", dropout.dump());
  expect_bad_input(run_vantage("analyze dropout.json --dropout", scratch),
                   "dropout.json: data vectors with --dropout: 1035 exceeds the limit of 1000");
  // 50 000 points: an int would overflow in 49 999 * 50 000; now a clear bound, exit 2.
  std::ostringstream huge;
  huge << "{\"points\": [";
  for (int k = 0; k < 50000; ++k) huge << (k ? "," : "") << "[" << k << ",0,0]";
  huge << "]}";
  scratch.write("huge.json", huge.str());
  expect_bad_input(run_vantage("analyze huge.json", scratch), "1249975000 exceeds the limit");
  expect_bad_input(run_vantage("design huge.json --add 1", scratch), "exceeds the budget");
}

TEST(HardeningCli, WeightsOnAHundredThousandVectors) {
  ScratchDir scratch;
  std::mt19937 rng(20261126);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::ostringstream text;
  text.precision(17);
  text << "{\"vectors\": [";
  for (int k = 0; k < 100000; ++k) {
    text << (k ? "," : "") << "[" << gauss(rng) + 0.2 << "," << gauss(rng) << "," << gauss(rng)
         << "]";
  }
  text << "]}";
  scratch.write("large.json", text.str());
  const nlohmann::json json = testing::run_json("weights large.json", scratch);
  EXPECT_EQ(json["status"], "positive");
  EXPECT_EQ(json["weights"].size(), 100000u);
  EXPECT_GT(json["min_weight"].get<double>(), 0.0);
}

// Runs `vantage <args>` under script(1), which gives it a terminal; returns what the terminal
// showed (stdout and stderr together).
std::string run_on_terminal(const std::string& args, const ScratchDir& scratch) {
  const std::string out = scratch.path("terminal.txt");
  const std::string command = "cd '" + scratch.dir().string() + "' && script -qec \"'" +
                              VANTAGE_CLI + "' " + args + "\" /dev/null > '" + out +
                              "' 2>&1 < /dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0);
  const std::string text = testing::read_file(out);
  fs::remove(out);
  return text;
}

TEST(HardeningCli, ProgressOnlyOnATerminal) {
  // Six point-mode steps and the direct optimiser run for seconds (two steps, under the
  // sanitizers, for as long), so a progress line appears on a terminal; --quiet silences it (and
  // without a terminal stderr stays empty: run_json checks that everywhere). Under the
  // sanitizers the quiet run adds one marker: its single step runs for seconds there too.
  ScratchDir scratch;
  const std::string steps = testing::kUnderSanitizer ? "2" : "6";
  const std::string quiet_steps = testing::kUnderSanitizer ? "1" : "6";
  const std::string design = "design '" + kSatellite + "' --add ";
  const std::regex progress(
      "vantage design: (step [0-9]/[0-9]|direct optimiser(, start [0-9]+/[0-9]+)?), [0-9]+ s");
  const std::string shown = run_on_terminal(design + steps, scratch);
  EXPECT_TRUE(std::regex_search(shown, progress)) << shown;
  const std::string quiet = run_on_terminal(design + quiet_steps + " --quiet", scratch);
  EXPECT_THAT(quiet, HasSubstr("final p-bar_min"));
  EXPECT_FALSE(std::regex_search(quiet, progress)) << quiet;
}

// Issue 36, item 6: long runs show progress. crb's distance sweep (up to 1000 maps, about 28 s)
// says which distance it is at; --quiet silences it.
TEST(HardeningCli, CrbSweepShowsItsProgressOnATerminal) {
  ScratchDir scratch;
  const std::string count = testing::kUnderSanitizer ? "20" : "60";  // over a second either way
  const std::string crb = "crb '" + kLayouts + "apriltag_cube.yaml' --distance 2 --focal 1000 " +
                          "--noise-px 0.3 --sweep-distance 1:3:" + count;
  const std::regex progress("vantage crb: distance [0-9]+/" + count + ", [0-9]+ s");
  const std::string shown = run_on_terminal(crb, scratch);
  EXPECT_TRUE(std::regex_search(shown, progress)) << shown;
  EXPECT_THAT(shown, HasSubstr("worst direction"));
  const std::string quiet = run_on_terminal(crb + " --quiet", scratch);
  EXPECT_THAT(quiet, HasSubstr("worst direction"));
  EXPECT_FALSE(std::regex_search(quiet, progress)) << quiet;
}

// `vantage plot --crb` shows the same progress during its distance sweep, and --quiet drops it;
// the figures are written either way.
TEST(HardeningCli, PlotCrbSweepShowsItsProgressOnATerminal) {
  ScratchDir scratch;
  const std::string count = testing::kUnderSanitizer ? "30" : "100";  // over a second either way
  const std::string plot = "plot '" + kLayouts + "apriltag_cube.yaml' --crb --distance 2 " +
                           "--focal 1000 --noise-px 0.3 --sweep-distance 1:3:" + count;
  const std::regex progress("vantage plot: distance [0-9]+/" + count + ", [0-9]+ s");
  const std::string shown = run_on_terminal(plot + " --out shown", scratch);
  EXPECT_TRUE(std::regex_search(shown, progress)) << shown;
  EXPECT_TRUE(fs::exists(scratch.dir() / "shown" / "crb_sweep.png"));
  const std::string quiet = run_on_terminal(plot + " --out quiet --quiet", scratch);
  EXPECT_FALSE(std::regex_search(quiet, progress)) << quiet;
  EXPECT_TRUE(fs::exists(scratch.dir() / "quiet" / "crb_sweep.png"));
}

// Issue 36, item 8: a user's word quoted in an error is an excerpt (its first 60 bytes and its
// size), so that a 5 000-byte figure or marker name does not become a 5 000-byte line.
TEST(HardeningCli, LongWordsInErrorsAreExcerpts) {
  constexpr std::size_t kShortLine = 600;
  ScratchDir scratch;
  const std::string word(5000, 'q');
  scratch.write("in.json", kTriadText);
  const testing::CliRun only = run_vantage("plot in.json --out figs --only " + word, scratch);
  expect_bad_input(only, "--only: unknown figure \"" + word.substr(0, 60) + "... (5000 bytes)\"");
  EXPECT_LT(only.err.size(), kShortLine);
  scratch.write("named.json", R"({"points": [[0,0,0],[1,0,0],[0,1,0]], "names": ["a", "b", ")" +
                                  word + R"(,c"]})");
  const testing::CliRun csv = run_vantage("layout convert named.json --out named.csv", scratch);
  expect_bad_input(csv, "names[2]: \"" + word.substr(0, 60) + "... (5002 bytes)\"");
  EXPECT_LT(csv.err.size(), kShortLine);
}

TEST(HardeningCli, ControlCharactersInAFileNameAreEscaped) {
  // An escape sequence in a file name must not reach the terminal raw: written \x1b.
  ScratchDir scratch;
  expect_bad_input(run_vantage("analyze \"$(printf 'no\\033[2Jsuch.json')\"", scratch),
                   "no\\x1b[2Jsuch.json");
}

// ---- Writes: all or nothing -----------------------------------------------------------------

TEST(HardeningCli, WriteTargetsAreCheckedFirst) {
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  expect_bad_input(run_vantage("design in.json --add 1 --write ''", scratch),
                   "--write: empty file name");
  fs::create_symlink(scratch.path("elsewhere.json"), scratch.path("dangling.json"));
  expect_bad_input(run_vantage("design in.json --add 1 --write dangling.json --overwrite", scratch),
                   "symbolic link");
  EXPECT_FALSE(fs::exists(scratch.path("elsewhere.json")));
  expect_bad_input(
      run_vantage("design in.json --add 1 --write \"$(printf 'bad\\377.json')\"", scratch),
      "not valid UTF-8");
  EXPECT_EQ(outputs(scratch, {"in.json", "dangling.json"}), std::vector<std::string>{});
}

TEST(HardeningCli, ConcurrentWriterFailsFast) {
  // flock(1) holds the target's lock while vantage runs: it must give up at once, exit 2.
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  const auto run = run_wrapped("flock .out.json.lock",
                               "design in.json --add 1 --no-direct --write out.json", scratch);
  expect_bad_input(run, "out.json: another process is writing it");
  EXPECT_FALSE(fs::exists(scratch.path("out.json")));
}

TEST(HardeningCli, FailedWriteLeavesNothing) {
  // A file size limit (4 KiB in dash's 512-byte blocks) makes the write of a large layout fail
  // part-way, as a full disk does: exit 1, no target, no temporary; the report is small enough.
  ScratchDir scratch;
  nlohmann::json layout = nlohmann::json::parse(kTriadText);
  for (int k = 0; k < 400; ++k) layout["candidates"].push_back({1.0 + k, 0.5, 0.25});
  scratch.write("in.json", layout.dump());
  const auto run = run_wrapped("ulimit -f 8; trap '' XFSZ;",
                               "design in.json --add 1 --no-direct --write out.json", scratch);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("out.json: write failed"));
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_EQ(outputs(scratch, {"in.json"}), std::vector<std::string>{});
}

// ---- Reports that cannot mislead ------------------------------------------------------------

TEST(HardeningCli, CollinearPointsAreDegenerate) {
  ScratchDir scratch;
  scratch.write("line.json", R"({"points": [[0,0,0],[1,1,1],[3,3,3],[-2,-2,-2]]})");
  auto run = run_vantage("analyze line.json --json", scratch);
  EXPECT_EQ(run.status, 1);
  EXPECT_THAT(run.err, HasSubstr("degenerate"));
  EXPECT_EQ(testing::line_count(run.err), 1);
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_TRUE(json["degenerate"].get<bool>());
  EXPECT_EQ(json["max_worst_case_error_deg"].get<double>(), 90.0);
  run = run_vantage("analyze line.json", scratch);
  // Collinear markers are a 5-DoF tool (issue 37, item 3); collinear vectors are degenerate.
  EXPECT_THAT(run.out, HasSubstr("5-DOF TOOL             every marker is on one line"));
  EXPECT_THAT(run.out, Not(HasSubstr("max worst-case error   0 deg")));
  scratch.write("parallel.json", R"({"vectors": [[1,1,1],[2,2,2],[-1,-1,-1]]})");
  run = run_vantage("analyze parallel.json", scratch);
  EXPECT_THAT(run.out, HasSubstr("DEGENERATE             every data vector is parallel"));
}

TEST(HardeningCli, SkippedCrossCheckClaimsNothing) {
  ScratchDir scratch;
  const nlohmann::json json =
      testing::run_json("analyze '" + kTriad + "' --no-crosscheck", scratch);
  EXPECT_EQ(json["crosscheck"],
            nlohmann::json({{"method", "skipped"}, {"skipped", "not requested"}}));
  EXPECT_FALSE(json["degenerate"].get<bool>());
  const auto run = run_vantage("analyze '" + kTriad + "' --no-crosscheck", scratch);
  EXPECT_THAT(run.out, HasSubstr("cross-check            skipped"));
  EXPECT_THAT(run.out, Not(HasSubstr("agrees")));
}

// Issue 36, item 8: valid tiny and huge directions were refused by the command (std::stod
// throws on a subnormal; |a|^2 of a 1e200 direction overflows) although files and Python take
// them. Each now gives what the unit direction gives, byte for byte.
TEST(HardeningCli, TinyAndHugeDirectionsAreTheUnitDirection) {
  ScratchDir scratch;
  const std::string drone = "analyze '" + kLayouts + "drone.json' --json --workspace ";
  const std::string crb = "crb '" + kSatellite + "' --focal 1000 --noise-px 0.2 --distance 10 " +
                          "--samples 500 --json --direction ";
  const std::string tre = "tre '" + std::string(VANTAGE_SOURCE_DIR) +
                          "/examples/tools/ndi_like.json' --target 0,0,-150 --fle-rms 0.25 " +
                          "--json --direction ";
  const std::pair<std::string, std::string> same[] = {
      {drone + "5e-324,0,0,30", drone + "1,0,0,30"},
      {drone + "0,1e300,0,30", drone + "0,1,0,30"},
      {crb + "1e200,0,0", crb + "1,0,0"},
      {crb + "0,0,-1e-310", crb + "0,0,-1"},
      {crb + "'0, 0 ,1'", crb + "0,0,1"},
      {tre + "1e200,0,0", tre + "1,0,0"},
      {tre + "0,-1e-200,0", tre + "0,-1,0"},
  };
  for (const auto& [odd, unit] : same) {
    const auto a = run_vantage(odd, scratch);
    const auto b = run_vantage(unit, scratch);
    EXPECT_EQ(a.status, 0) << odd << ": " << a.err;
    EXPECT_EQ(a.out, b.out) << odd;
  }
  for (const char* bad : {"0,0,0", "1e400,0,0", "1,2", "1,2,3,4", "1,,2", "nan,0,1"}) {
    expect_bad_input(run_vantage(crb + bad, scratch), "--direction: expected AX,AY,AZ");
  }
}

TEST(HardeningCli, NoNegativeZeroInViewpoints) {
  // The fan's worst viewpoints lie in its plane: their z components are zero up to rounding
  // (of either sign) and must print as 0.000000.
  ScratchDir scratch;
  const auto run = run_vantage("analyze '" + kLayouts + "coplanar_fan.json'", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr(" 0.000000 ]"));
  EXPECT_THAT(run.out, Not(HasSubstr("-0.000000")));
}

TEST(HardeningCli, EmptyPaperCellPrintsItsStatus) {
  ScratchDir scratch;
  scratch.write("cell.json", R"({"vectors": [[1,0,0],[-1,1e-9,0],[0,0,1]]})");
  const auto run = run_vantage("analyze cell.json", scratch);
  EXPECT_THAT(run.out, HasSubstr("paper's single LMI     empty_cell"));
  EXPECT_THAT(run.out, Not(HasSubstr("pbar 1 at")));
}

TEST(HardeningCli, SatelliteReportLeadsWithTheVerdict) {
  ScratchDir scratch;
  const auto run = run_vantage("analyze '" + kSatellite + "'", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  std::istringstream lines(run.out);
  std::string line;
  std::vector<std::string> all;
  while (std::getline(lines, line)) all.push_back(line);
  ASSERT_GT(all.size(), 12u);
  // The satellite has normals: what its body lets a camera see comes first, then the layout
  // seen whole, each with its verdict in its first two lines.
  EXPECT_EQ(all[3].rfind("on its body", 0), 0u) << run.out;
  EXPECT_EQ(all[4].rfind("  pbar_min", 0), 0u) << run.out;
  EXPECT_EQ(all[5].rfind("  max worst-case error", 0), 0u) << run.out;
  EXPECT_EQ(all[9].rfind("seen whole", 0), 0u) << run.out;
  EXPECT_EQ(all[10].rfind("pbar_min", 0), 0u) << run.out;
  EXPECT_EQ(all[11].rfind("max worst-case error", 0), 0u) << run.out;
  EXPECT_THAT(run.out, HasSubstr("5 of 66 (--verbose or --json for all)"));
  EXPECT_LT(all.size(), 36u) << "the default report stays short";
  EXPECT_THAT(run.out, Not(HasSubstr("-0.000000")));
  // Noise-free swaps of the satellite's free vectors never move the rotation: said plainly.
  EXPECT_THAT(run.out, HasSubstr("0 deg for every one of the 2145 pairs"));
  const auto verbose = run_vantage("analyze '" + kSatellite + "' --verbose", scratch);
  EXPECT_THAT(verbose.out, Not(HasSubstr("--verbose or --json for all")));
  EXPECT_GT(testing::line_count(verbose.out), testing::line_count(run.out) + 60);
}

}  // namespace
}  // namespace vantage

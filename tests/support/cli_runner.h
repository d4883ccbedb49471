#pragma once

/// Runs the built `vantage` binary (path in VANTAGE_CLI, set by CMake) and captures its exit
/// status, stdout and stderr, for end-to-end tests of the command-line contract.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <unistd.h>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace vantage::testing {

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A scratch directory, removed with the object; unique per process and instance.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("vantage_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::ofstream(file) << text;
    return file.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& dir() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// Runs `vantage <args>` (args are passed to the shell as written) in `scratch`.
inline CliRun run_vantage(const std::string& args, const ScratchDir& scratch) {
  const std::string out = scratch.path("stdout.txt");
  const std::string err = scratch.path("stderr.txt");
  const std::string command = "cd '" + scratch.dir().string() + "' && '" VANTAGE_CLI "' " + args +
                              " > '" + out + "' 2> '" + err + "' < /dev/null";
  const int raw = std::system(command.c_str());
  CliRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = read_file(out);
  run.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

/// Number of lines in `text` (a last line without '\n' counts).
inline int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines + (!text.empty() && text.back() != '\n');
}

/// Runs `vantage <args> --json`, expects success with nothing on stderr, and parses stdout.
inline nlohmann::json run_json(const std::string& args, const ScratchDir& scratch) {
  const CliRun run = run_vantage(args + " --json", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  return nlohmann::json::parse(run.out);
}

/// A call that must be refused as bad input or usage.
struct BadCall {
  const char* name;
  const char* file_text;  ///< written to in.json first; nullptr: no file
  const char* args;       ///< after the subcommand
  const char* expected;   ///< a fragment the one error line must contain
};

/// The bad-input contract (README.md, "The `vantage` command"): exit status 2, nothing on stdout,
/// exactly one line on stderr, "vantage: error: ..." containing `expected`.
inline void expect_bad_input(const CliRun& run, const std::string& expected) {
  EXPECT_EQ(run.status, 2) << run.out;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, ::testing::HasSubstr("vantage: error: "));
  EXPECT_THAT(run.err, ::testing::HasSubstr(expected));
}

/// Writes call.file_text to in.json (when given), runs `vantage <subcommand> <call.args>` and
/// checks the bad-input contract.
inline CliRun run_bad_call(const std::string& subcommand, const BadCall& call,
                           const ScratchDir& scratch) {
  if (call.file_text) scratch.write("in.json", call.file_text);
  CliRun run = run_vantage(subcommand + " " + call.args, scratch);
  expect_bad_input(run, call.expected);
  return run;
}

}  // namespace vantage::testing

// Issue 36, item 7: SIGINT and SIGTERM left `.OUT.lock` beside place and design targets, and an
// interrupted `simulate --csv` left its hidden `.vantage-write-*` temporary (3.6 GB in the
// audit). vantage removes both when it is interrupted and ends by the same signal; a lock file
// left by SIGKILL (which no handler sees) is taken over by the next run without a word.

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_runner.h"

namespace vantage {
namespace {

namespace fs = std::filesystem;
using testing::run_vantage;
using testing::ScratchDir;

// How long a test waits for the command to reach its write, and for it to end after a signal.
constexpr auto kPatience = std::chrono::seconds(60);
constexpr auto kPoll = std::chrono::milliseconds(10);

const std::string kExamples = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";

// `vantage ARGS...` started in `dir` with no output, not waited for.
pid_t start_vantage(const ScratchDir& dir, const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.dir().c_str()) != 0) ::_exit(127);
    // As from an interactive shell: a runner may start the tests with SIGINT ignored, which
    // vantage (rightly) keeps.
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv;
    std::string program = VANTAGE_CLI;
    argv.push_back(program.data());
    std::vector<std::string> copies = args;
    for (std::string& arg : copies) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// The names in `dir` that start with `prefix`.
std::vector<std::string> names_starting(const ScratchDir& dir, const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.dir())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) names.push_back(name);
  }
  return names;
}

// Waits until `dir` holds a name starting with `prefix` (true) or the command ended (false).
bool wait_for_file(const ScratchDir& dir, const std::string& prefix, pid_t pid) {
  const auto until = std::chrono::steady_clock::now() + kPatience;
  while (std::chrono::steady_clock::now() < until) {
    if (!names_starting(dir, prefix).empty()) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(kPoll);
  }
  return false;
}

// The wait status of `pid`, killed with SIGKILL when it does not end in time (-1 then).
int wait_status(pid_t pid) {
  const auto until = std::chrono::steady_clock::now() + kPatience;
  while (std::chrono::steady_clock::now() < until) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(kPoll);
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  return -1;
}

TEST(SignalCleanupCli, InterruptedSimulateLeavesNoTemporary) {
  ScratchDir scratch;
  const pid_t pid =
      start_vantage(scratch, {"simulate", kExamples + "triad.json", "--trials", "9000000",
                              "--threads", "1", "--csv", "out.csv", "--quiet"});
  ASSERT_TRUE(wait_for_file(scratch, ".vantage-write-", pid)) << "the run never began its CSV";
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const int status = wait_status(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_THAT(names_starting(scratch, ".vantage-write-"), ::testing::IsEmpty());
  EXPECT_FALSE(fs::exists(scratch.path("out.csv")));
}

// Starts `design drone.json --add 6 --write out.json` in `scratch`, sends `signal` once it holds
// its lock, and returns the wait status (-1 when it never took the lock).
int design_signalled(const ScratchDir& scratch, int signal) {
  const pid_t pid = start_vantage(
      scratch, {"design", kExamples + "drone.json", "--add", "6", "--write", "out.json"});
  if (!wait_for_file(scratch, ".out.json.lock", pid)) return -1;
  if (::kill(pid, signal) != 0) return -1;
  return wait_status(pid);
}

TEST(SignalCleanupCli, TerminatedDesignLeavesNoLock) {
  ScratchDir scratch;
  const int status = design_signalled(scratch, SIGTERM);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(scratch.path(".out.json.lock")));
  EXPECT_THAT(names_starting(scratch, ".vantage-write-"), ::testing::IsEmpty());
  EXPECT_FALSE(fs::exists(scratch.path("out.json")));
}

TEST(SignalCleanupCli, LockLeftByKillIsTakenOverSilently) {
  ScratchDir scratch;
  const int status = design_signalled(scratch, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  ASSERT_TRUE(fs::exists(scratch.path(".out.json.lock"))) << "SIGKILL leaves the lock file";

  const testing::CliRun run = run_vantage(
      "design '" + kExamples + "triad.json' --add 1 --no-direct --write out.json", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_TRUE(fs::exists(scratch.path("out.json")));
  EXPECT_FALSE(fs::exists(scratch.path(".out.json.lock")));
}

}  // namespace
}  // namespace vantage

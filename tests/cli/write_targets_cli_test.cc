// Issue 22: `design --write /dev/full --overwrite` replaced the device node with a JSON file (as
// root, as CI runs). Writes may only ever replace a regular file; a full disk is an environment
// failure (exit 1) for every command that writes.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "support/cli_runner.h"

namespace vantage {
namespace {

namespace fs = std::filesystem;
using testing::expect_bad_input;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const char* kTriadText = R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})";
const std::string kBoard = "layout board --type chessboard --rows 4 --cols 5 --square 0.03";

// The kind (S_IFMT bits) and device number of what is at `path`, without following links.
struct Node {
  mode_t type = 0;
  dev_t rdev = 0;
};
Node node_at(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) return {};
  return {static_cast<mode_t>(info.st_mode & S_IFMT), info.st_rdev};
}

// The two commands that write a layout, each told to replace `target`.
std::vector<std::string> writes_to(const std::string& target) {
  return {"design in.json --add 1 --no-direct --write " + target + " --overwrite",
          kBoard + " --out " + target + " --overwrite"};
}

TEST(WriteTargetsCli, FifoIsRefusedAndStaysAFifo) {
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  const std::string pipe = scratch.path("pipe.json");
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0) << std::strerror(errno);
  for (const std::string& call : writes_to("pipe.json")) {
    expect_bad_input(run_vantage(call, scratch),
                     "pipe.json: is a FIFO (named pipe), not a regular file; refusing to replace");
    EXPECT_EQ(node_at(pipe).type, S_IFIFO) << call;
  }
  EXPECT_EQ(testing::read_file(scratch.path("in.json")), kTriadText);
}

TEST(WriteTargetsCli, CharacterDevicesAreRefusedAndStayDevices) {
  if (::geteuid() != 0) {
    std::printf("skipped: creating character devices (mknod) needs root\n");
    GTEST_SKIP() << "mknod of a character device needs root";
  }
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  // Private copies of /dev/full (1, 7) and /dev/null (1, 3): the real ones are never named.
  for (const auto& [name, minor] : {std::pair<const char*, unsigned>{"full.json", 7},
                                    std::pair<const char*, unsigned>{"null.json", 3}}) {
    const std::string device = scratch.path(name);
    ASSERT_EQ(::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, minor)), 0)
        << std::strerror(errno);
    for (const std::string& call : writes_to(name)) {
      expect_bad_input(run_vantage(call, scratch),
                       std::string(name) + ": is a character device, not a regular file");
      const Node node = node_at(device);
      EXPECT_EQ(node.type, S_IFCHR) << call;
      EXPECT_EQ(node.rdev, makedev(1, minor)) << call;
    }
  }
}

TEST(WriteTargetsCli, RegularFileIsStillReplaced) {
  // The control: the same calls replace a regular file.
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  for (const std::string& call : writes_to("out.json")) {
    scratch.write("out.json", "old");
    const testing::CliRun run = run_vantage(call, scratch);
    EXPECT_EQ(run.status, 0) << call << ": " << run.err;
    EXPECT_NE(testing::read_file(scratch.path("out.json")), "old") << call;
  }
}

// Issue 36, item 1: `simulate k14.csv --trials 10 --csv k14.csv` replaced the layout with trial
// rows. --csv follows the write rule (a new name, or an existing regular file with --overwrite)
// and never replaces one of the run's own inputs, with --overwrite or without.
TEST(WriteTargetsCli, SimulateCsvReplacesNothingUnasked) {
  ScratchDir scratch;
  const std::string layout = "name,x,y,z\nm0,0,0,0\nm1,1,0,0\nm2,0,1,0\nm3,0,0,1\n";
  scratch.write("k4.csv", layout);
  scratch.write("old.csv", "old");
  const std::string simulate = "simulate k4.csv --trials 10 --seed 3 --quiet";

  expect_bad_input(run_vantage(simulate + " --csv old.csv", scratch),
                   "--csv: old.csv: exists already");
  EXPECT_EQ(testing::read_file(scratch.path("old.csv")), "old");
  for (const char* overwrite : {"", " --overwrite"}) {
    expect_bad_input(run_vantage(simulate + " --csv k4.csv" + overwrite, scratch),
                     "--csv: k4.csv is an input of this run");
    // The same file by another name is the same input.
    expect_bad_input(run_vantage(simulate + " --csv ./k4.csv" + overwrite, scratch),
                     "is an input of this run");
    EXPECT_EQ(testing::read_file(scratch.path("k4.csv")), layout);
  }

  const testing::CliRun run = run_vantage(simulate + " --csv old.csv --overwrite", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(testing::read_file(scratch.path("old.csv")), HasSubstr("trial,"));
}

// A shard file given to --merge is an input too.
TEST(WriteTargetsCli, SimulateMergeCsvKeepsItsShards) {
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  const testing::CliRun shard =
      run_vantage("simulate in.json --trials 20 --shard 1/1 --json --quiet", scratch);
  ASSERT_EQ(shard.status, 0) << shard.err;
  scratch.write("shard.json", shard.out);
  expect_bad_input(run_vantage("simulate --merge shard.json --csv shard.json --overwrite", scratch),
                   "--csv: shard.json is an input of this run");
  EXPECT_EQ(testing::read_file(scratch.path("shard.json")), shard.out);
}

// A tmpfs of 64 KiB, filled: where vantage must fail to write. Needs root and a kernel that lets
// this process mount; otherwise the test is skipped with the reason printed.
class FullDisk {
 public:
  // blocks: fill the data blocks; otherwise use up the inodes (the blocks stay free).
  FullDisk(const ScratchDir& scratch, const char* options, bool blocks)
      : dir_(scratch.path("full_fs")) {
    fs::create_directories(dir_);
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", 0, options) != 0) {
      reason_ = std::string("cannot mount a tmpfs: ") + std::strerror(errno);
      return;
    }
    mounted_ = true;
    if (blocks) {
      std::ofstream fill(dir_ + "/fill", std::ios::binary);
      const std::string block(4096, 'x');
      while (fill.write(block.data(), static_cast<std::streamsize>(block.size()))) fill.flush();
    } else {
      for (int k = 0; k < 1000; ++k) {
        if (!std::ofstream(dir_ + "/inode" + std::to_string(k))) break;
      }
    }
  }
  ~FullDisk() {
    if (mounted_) ::umount(dir_.c_str());
  }
  bool mounted() const { return mounted_; }
  const std::string& reason() const { return reason_; }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  bool mounted_ = false;
  std::string reason_;
};

TEST(WriteTargetsCli, FullDiskIsExitOneForEveryWriteWithNothingWritten) {
  // Blocks full, and inodes full: the first fails the write, the second already the lock file
  // or the temporary. Both are the environment's failure: exit 1, one line, nothing written.
  ScratchDir scratch;
  scratch.write("in.json", kTriadText);
  for (const auto& [options, blocks] :
       {std::pair<const char*, bool>{"size=64k", true},
        std::pair<const char*, bool>{"size=1m,nr_inodes=16", false}}) {
    FullDisk disk(scratch, options, blocks);
    if (!disk.mounted()) {
      std::printf("skipped: %s\n", disk.reason().c_str());
      GTEST_SKIP() << disk.reason();
    }
    for (const std::string& call : writes_to(disk.dir() + "/out.json")) {
      const testing::CliRun run = run_vantage(call, scratch);
      EXPECT_EQ(run.status, 1) << options << ": " << call << ": " << run.err;
      EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
      EXPECT_THAT(run.err, HasSubstr("No space left on device")) << options;
      EXPECT_THAT(run.err, HasSubstr("nothing written"));
      EXPECT_FALSE(fs::exists(disk.dir() + "/out.json")) << options << ": " << call;
    }
  }
}

}  // namespace
}  // namespace vantage

#include "vantage/io/text_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "vantage/analysis/common.h"

namespace vantage::io {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A fresh directory per test, removed afterwards.
class TextFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vantage_text_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string content(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // Every entry of the directory: nothing temporary may be left behind.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }
  static std::string message_of(const std::function<void()>& call) {
    try {
      call();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(TextFile, WritesAndRefusesToReplaceWithoutOverwrite) {
  write_text_file(path("a.json"), "first\n", false);
  EXPECT_EQ(content(path("a.json")), "first\n");
  EXPECT_THAT(message_of([&] { write_text_file(path("a.json"), "second\n", false); }),
              HasSubstr("exists already"));
  EXPECT_EQ(content(path("a.json")), "first\n");
  write_text_file(path("a.json"), "second\n", true);
  EXPECT_EQ(content(path("a.json")), "second\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.json"});
  // The file gets ordinary permissions (umask), not mkstemp's 0600.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(static_cast<mode_t>(fs::status(path("a.json")).permissions()) & 0777, 0666 & ~mask);
}

TEST_F(TextFile, BadTargetsAreRejectedBeforeAnyWrite) {
  EXPECT_THAT(message_of([&] { write_text_file("", "x", false); }), HasSubstr("empty file name"));
  EXPECT_THAT(message_of([&] { write_text_file(dir_.string(), "x", true); }),
              HasSubstr("is a directory"));
  EXPECT_THAT(message_of([&] { write_text_file(path("no/such/dir/a.json"), "x", false); }),
              HasSubstr("does not exist"));
  // A dangling symbolic link: its target must not be created.
  fs::create_symlink(path("target.json"), path("link.json"));
  EXPECT_THAT(message_of([&] { write_text_file(path("link.json"), "x", true); }),
              HasSubstr("symbolic link"));
  EXPECT_FALSE(fs::exists(path("target.json")));
  // A file name longer than the OS allows is bad input, not an internal error.
  const std::string long_name = path(std::string(300, 'x') + ".json");
  EXPECT_THROW(write_text_file(long_name, "x", false), InvalidArgument);
  EXPECT_THROW(read_text_file(long_name), InvalidArgument);
  EXPECT_EQ(entries(), std::vector<std::string>{"link.json"});
}

// What is at `p`, without following a symbolic link: type bits and device number.
struct Node {
  mode_t type = 0;
  dev_t rdev = 0;
  bool operator==(const Node& other) const { return type == other.type && rdev == other.rdev; }
};
Node node_at(const std::string& p) {
  struct stat info {};
  if (::lstat(p.c_str(), &info) != 0) return {};
  return {static_cast<mode_t>(info.st_mode & S_IFMT), info.st_rdev};
}

// Issue 22: `--write /dev/full --overwrite` replaced the device node with a JSON file. Only a
// regular file may ever be replaced, with or without `overwrite`.
TEST_F(TextFile, FifoIsRefusedAndStaysAFifo) {
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0) << std::strerror(errno);
  const Node before = node_at(path("pipe"));
  ASSERT_EQ(before.type, S_IFIFO);
  for (const bool overwrite : {true, false}) {
    EXPECT_THAT(message_of([&] { check_write_target(path("pipe"), overwrite); }),
                HasSubstr("pipe: is a FIFO (named pipe), not a regular file; refusing to replace"));
    EXPECT_THAT(message_of([&] { write_text_file(path("pipe"), "{}\n", overwrite); }),
                HasSubstr("not a regular file"));
    EXPECT_TRUE(node_at(path("pipe")) == before);
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"pipe"});
}

TEST_F(TextFile, CharacterDeviceIsRefusedAndStaysADevice) {
  if (::geteuid() != 0) {
    std::printf("skipped: creating a character device (mknod) needs root\n");
    GTEST_SKIP() << "mknod of a character device needs root";
  }
  // A private copy of /dev/full (major 1, minor 7) in the test's own directory.
  ASSERT_EQ(::mknod(path("full").c_str(), S_IFCHR | 0666, makedev(1, 7)), 0)
      << std::strerror(errno);
  const Node before = node_at(path("full"));
  ASSERT_EQ(before.type, S_IFCHR);
  for (const bool overwrite : {true, false}) {
    EXPECT_THAT(message_of([&] { write_text_file(path("full"), "{}\n", overwrite); }),
                HasSubstr("full: is a character device, not a regular file; refusing to replace"));
    EXPECT_TRUE(node_at(path("full")) == before);
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"full"});
}

TEST_F(TextFile, RegularFileStillReplacedWithOverwrite) {
  // The control of the two tests above: the same calls on a regular file do replace it.
  write_text_file(path("plain"), "old\n", false);
  write_text_file(path("plain"), "new\n", true);
  EXPECT_EQ(content(path("plain")), "new\n");
  EXPECT_EQ(node_at(path("plain")).type, S_IFREG);
}

TEST_F(TextFile, FailedWriteLeavesTargetAndDirectoryUntouched) {
  // A file size limit of 1 KiB makes write(2) fail part-way (EFBIG), as a full disk does
  // (ENOSPC): the temporary must go and the existing target keep its content.
  write_text_file(path("kept.json"), "old content\n", false);
  const std::string big(64 * 1024, 'x');
  struct rlimit saved {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = saved;
  small.rlim_cur = 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  // Both failures must be WriteError (an environment failure), not bad input.
  auto write_error = [](const std::function<void()>& call) -> std::string {
    try {
      call();
    } catch (const WriteError& e) {
      return e.what();
    } catch (const std::exception& e) {
      return std::string("wrong exception type: ") + e.what();
    }
    return "no error";
  };
  const std::string replace_error =
      write_error([&] { write_text_file(path("kept.json"), big, true); });
  const std::string create_error =
      write_error([&] { write_text_file(path("new.json"), big, false); });
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &saved), 0);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_THAT(replace_error, HasSubstr("kept.json: write failed"));
  EXPECT_THAT(create_error, HasSubstr("new.json: write failed"));
  EXPECT_EQ(content(path("kept.json")), "old content\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"kept.json"});
}

TEST_F(TextFile, ReadsAreBounded) {
  write_text_file(path("small.json"), std::string(100, 'a'), false);
  EXPECT_EQ(read_text_file(path("small.json"), 100).size(), 100u);
  EXPECT_THROW(read_text_file(path("small.json"), 99), FileTooLarge);
  // /dev/zero never ends: the read stops at the bound.
  EXPECT_THAT(message_of([] { read_text_file("/dev/zero", 1 << 20); }),
              HasSubstr("/dev/zero: larger than 1048576 bytes"));
  EXPECT_THAT(message_of([&] { read_text_file(dir_.string()); }), HasSubstr("is a directory"));
  EXPECT_THAT(message_of([&] { read_text_file(path("missing.json")); }),
              HasSubstr("missing.json: cannot open file"));
}

TEST_F(TextFile, SecondWriterOfTheSameTargetFailsAtOnce) {
  {
    WriteLock first(path("out.json"));
    EXPECT_THAT(message_of([&] { WriteLock second(path("out.json")); }),
                HasSubstr("another process is writing it"));
    WriteLock other(path("other.json"));  // a different target is independent
  }
  EXPECT_TRUE(entries().empty()) << "lock files are removed on release";
  WriteLock again(path("out.json"));
}

}  // namespace
}  // namespace vantage::io

#include "quiet_stdio.h"

#include <fcntl.h>
#include <plplot.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace vantage::plot::internal {
namespace {

std::string g_aborts;    // messages of plabort() while a QuietStdio exists
int g_real_stderr = -1;  // the caller's stderr while redirected

void on_abort(PLCHAR_VECTOR message) {
  if (!g_aborts.empty()) g_aborts += "; ";
  g_aborts += message ? message : "unknown error";
}

// plexit() ends the process whatever the handler returns (exit(status) for status != 0). It is
// reached only for failures vantage checks before calling PLplot (missing driver, out of
// memory); say so in one line on the caller's stderr and exit with the failure status.
int on_exit(PLCHAR_VECTOR message) {
  const std::string line =
      std::string("vantage: internal error: PLplot: ") + (message ? message : "fatal error") + "\n";
  const int fd = g_real_stderr >= 0 ? g_real_stderr : STDERR_FILENO;
  if (::write(fd, line.data(), line.size()) < 0) return 1;
  return 1;
}

int scratch_file() {
  std::error_code ec;
  std::string pattern = (std::filesystem::temp_directory_path(ec) / "vantage-plot-XXXXXX").string();
  if (ec) pattern = "/tmp/vantage-plot-XXXXXX";
  const int fd = ::mkstemp(pattern.data());
  if (fd >= 0) {
    ::unlink(pattern.c_str());
    return fd;
  }
  return ::open("/dev/null", O_WRONLY);
}

}  // namespace

QuietStdio::QuietStdio() {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  g_aborts.clear();
  scratch_ = scratch_file();
  if (scratch_ >= 0) {
    saved_out_ = ::dup(STDOUT_FILENO);
    saved_err_ = ::dup(STDERR_FILENO);
    ::dup2(scratch_, STDOUT_FILENO);
    ::dup2(scratch_, STDERR_FILENO);
  }
  g_real_stderr = saved_err_;
  plsabort(on_abort);
  plsexit(on_exit);
}

QuietStdio::~QuietStdio() {
  std::fflush(nullptr);
  if (saved_out_ >= 0) {
    ::dup2(saved_out_, STDOUT_FILENO);
    ::close(saved_out_);
  }
  if (saved_err_ >= 0) {
    ::dup2(saved_err_, STDERR_FILENO);
    ::close(saved_err_);
  }
  if (scratch_ >= 0) ::close(scratch_);
  g_real_stderr = -1;
  plsabort(nullptr);
  plsexit(nullptr);
}

std::string QuietStdio::aborts() const { return g_aborts; }

std::string QuietStdio::captured() const {
  std::fflush(nullptr);
  struct stat info {};
  if (scratch_ < 0 || ::fstat(scratch_, &info) != 0 || info.st_size <= 0) return {};
  constexpr off_t kTail = 4096;
  const off_t start = info.st_size > kTail ? info.st_size - kTail : 0;
  std::string text(static_cast<std::size_t>(info.st_size - start), '\0');
  const ssize_t got = ::pread(scratch_, text.data(), text.size(), start);
  text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  return text;
}

}  // namespace vantage::plot::internal

#pragma once

// Keeps PLplot, cairo and fontconfig quiet: while a QuietStdio exists, the process's stdout and
// stderr file descriptors point at a scratch file, and PLplot's abort and exit handlers are ours.
// Private to vantage::plot.

#include <string>

namespace vantage::plot::internal {

class QuietStdio {
 public:
  QuietStdio();
  ~QuietStdio();
  QuietStdio(const QuietStdio&) = delete;
  QuietStdio& operator=(const QuietStdio&) = delete;

  /// The messages PLplot passed to its abort handler (plabort) since construction, joined by
  /// "; ". Empty when none.
  std::string aborts() const;

  /// Text written to stdout/stderr by the libraries since construction (last 4 kB).
  std::string captured() const;

 private:
  int saved_out_ = -1;
  int saved_err_ = -1;
  int scratch_ = -1;
};

}  // namespace vantage::plot::internal

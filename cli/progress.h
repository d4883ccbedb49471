#pragma once

// Progress of a long command on stderr: one line rewritten in place ("vantage design: step 3/10,
// 12 s"), shown only when stderr is a terminal, the command was not asked for --json or
// --quiet, and it has run for more than a second; cleared when the command ends.

#include <chrono>
#include <functional>
#include <string>

namespace vantage::cli {

class Progress {
 public:
  /// Enabled when `wanted` (not --json, not --quiet) and stderr is a terminal.
  Progress(const std::string& command, bool wanted);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Shows `stage` (after the first second).
  void update(const std::string& stage);

  /// A callback for library options (AugmentOptions::progress, ...), or empty when disabled.
  std::function<void(const std::string&)> callback();

 private:
  std::string command_;
  bool enabled_ = false;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace vantage::cli

#pragma once

/// A one-line progress bar on stderr for long runs. Debian packages no progress-bar library for
/// C++ that vantage already depends on, so this is a small one: "\r[=====     ]  50%  500/1000".

#include <chrono>
#include <string>

namespace vantage::simulate {

/// Draws on stderr only when `enabled`, stderr is a terminal, and the run has lasted at least
/// kDelay; redraws at most every kInterval. Not thread-safe: call from one thread.
class ProgressBar {
 public:
  static constexpr std::chrono::milliseconds kDelay{1000};
  static constexpr std::chrono::milliseconds kInterval{100};

  ProgressBar(long total, bool enabled, std::string label = "trials");
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Reports `done` of `total` steps finished.
  void update(long done);
  /// Ends the line (when anything was drawn).
  void finish();

 private:
  long total_;
  bool enabled_;
  bool drawn_ = false;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

/// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace vantage::simulate

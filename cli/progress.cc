#include "progress.h"

#include <unistd.h>

#include <iostream>

namespace vantage::cli {

namespace {

// Commands shorter than this show nothing.
constexpr std::chrono::seconds kQuietPeriod{1};

}  // namespace

Progress::Progress(const std::string& command, bool wanted)
    : command_(command),
      enabled_(wanted && ::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (shown_) std::cerr << "\r\033[K" << std::flush;
}

void Progress::update(const std::string& stage) {
  if (!enabled_) return;
  const auto elapsed = std::chrono::steady_clock::now() - start_;
  if (elapsed < kQuietPeriod) return;
  const long seconds =
      static_cast<long>(std::chrono::duration_cast<std::chrono::seconds>(elapsed).count());
  std::cerr << "\r\033[K"
            << "vantage " << command_ << ": " << stage << ", " << seconds << " s" << std::flush;
  shown_ = true;
}

std::function<void(const std::string&)> Progress::callback() {
  if (!enabled_) return {};
  return [this](const std::string& stage) { update(stage); };
}

}  // namespace vantage::cli

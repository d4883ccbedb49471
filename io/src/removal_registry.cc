#include "removal_registry.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

#include "vantage/io/text_file.h"

namespace vantage::io {
namespace {

// A command holds at most a lock and a temporary or two at once; 16 slots leave room.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;

// kFree -> kFilling (one thread copies the path) -> kRegistered (the handler may remove it).
enum SlotState : int { kFree = 0, kFilling = 1, kRegistered = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes] = {};
};

Slot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slot states");

// Async-signal-safe: atomic loads of lock-free atomics and unlink(2) only. SA_RESETHAND has
// restored the default action, and the signal is blocked while this runs: raising it again ends
// the process by the same signal once the handler returns, so the exit status still says which.
extern "C" void remove_registered_files(int signal) {
  for (Slot& slot : g_slots) {
    if (slot.state.load() == kRegistered) ::unlink(slot.path);
  }
  ::raise(signal);
}

}  // namespace

namespace internal {

int register_removal(const std::string& path) {
  if (path.empty() || path.size() >= kPathBytes) return -1;
  for (int k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (g_slots[k].state.compare_exchange_strong(expected, kFilling)) {
      std::memcpy(g_slots[k].path, path.c_str(), path.size() + 1);
      g_slots[k].state.store(kRegistered);
      return k;
    }
  }
  return -1;
}

void unregister_removal(int slot) {
  if (slot >= 0 && slot < kSlots) g_slots[slot].state.store(kFree);
}

}  // namespace internal

void remove_partial_files_on_signal() {
  struct sigaction action {};
  action.sa_handler = remove_registered_files;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the parent set to be ignored stays ignored (a shell ignores SIGINT in the jobs
    // it starts in the background; nohup ignores SIGHUP).
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    ::sigaction(signal, &action, nullptr);
  }
}

}  // namespace vantage::io

#include "libemb/common/signal_cleanup.h"

#include <unistd.h>

#include <atomic>
#include <cstring>

namespace emb {
namespace {

// One slot: state 0 free, 1 being written, 2 holds a path. Lock-free atomics only, so that a
// signal handler can read the table at any moment.
struct Slot {
  std::atomic<int> state{0};
  char path[4096];
};
static_assert(std::atomic<int>::is_always_lock_free);
Slot g_slots[kMaxCleanupFiles];

}  // namespace

CleanupOnSignal::CleanupOnSignal(const std::string& path) {
  if (path.size() >= sizeof(Slot::path)) return;
  for (int i = 0; i < kMaxCleanupFiles; ++i) {
    int expected = 0;
    if (g_slots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
      g_slots[i].state.store(2);
      slot_ = i;
      return;
    }
  }
}

CleanupOnSignal& CleanupOnSignal::operator=(CleanupOnSignal&& o) noexcept {
  if (this != &o) {
    Release();
    slot_ = o.slot_;
    o.slot_ = -1;
  }
  return *this;
}

void CleanupOnSignal::Release() {
  if (slot_ >= 0) g_slots[slot_].state.store(0);
  slot_ = -1;
}

void RemoveCleanupFilesNow() {
  for (Slot& s : g_slots)
    if (s.state.load() == 2) ::unlink(s.path);
}

}  // namespace emb

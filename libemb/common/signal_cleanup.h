#pragma once
/// @file
/// Files to remove if the process is stopped by a signal before they are finished: the
/// temporaries of atomic writes (atomic_file.h) and output locks (output_lock.h). A signal
/// such as SIGINT or SIGTERM ends the process without unwinding the stack, so destructors do
/// not run; the tool's signal handler calls RemoveCleanupFilesNow(), which is
/// async-signal-safe (it only reads a fixed table and calls unlink). The library keeps the
/// table and never installs handlers itself.

#include <string>

namespace emb {

/// Slots in the table; a registration beyond them is not cleaned up on a signal.
inline constexpr int kMaxCleanupFiles = 64;

/// A file registered for removal on a signal while the object lives (or until Release()).
class CleanupOnSignal {
 public:
  CleanupOnSignal() = default;
  explicit CleanupOnSignal(const std::string& path);
  ~CleanupOnSignal() { Release(); }
  CleanupOnSignal(const CleanupOnSignal&) = delete;
  CleanupOnSignal& operator=(const CleanupOnSignal&) = delete;
  CleanupOnSignal(CleanupOnSignal&& o) noexcept : slot_(o.slot_) { o.slot_ = -1; }
  CleanupOnSignal& operator=(CleanupOnSignal&& o) noexcept;
  /// The file is finished (or already removed): no longer removed on a signal.
  void Release();

 private:
  int slot_{-1};
};

/// Removes every registered file. Async-signal-safe: call it from a signal handler.
void RemoveCleanupFilesNow();

}  // namespace emb

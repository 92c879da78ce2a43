#pragma once
/// @file
/// Keeps two emb processes from writing the same output at once (the second would truncate
/// or interleave with the first): an exclusive lock on a hidden lock file ".<name>.lock"
/// beside the output, taken before any work and held until the output is finished. The lock
/// is an flock(2), so the kernel releases it when the process dies however it dies; the lock
/// file is removed on release, on SIGINT/SIGTERM (signal_cleanup.h), and a file left by a
/// SIGKILL is simply locked again by the next run.

#include <string>

#include "libemb/common/signal_cleanup.h"

namespace emb {

class OutputLock {
 public:
  OutputLock() = default;
  /// Locks `output`. @throws InputError if another process holds the lock (naming its pid
  /// when known) or the lock file cannot be created.
  explicit OutputLock(const std::string& output);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  OutputLock(OutputLock&& o) noexcept;
  OutputLock& operator=(OutputLock&& o) noexcept;

  /// The lock file of `output`: ".<name>.lock" in the same directory.
  static std::string LockPath(const std::string& output);

 private:
  void Unlock();
  std::string lock_path_;
  int fd_{-1};
  CleanupOnSignal cleanup_;
};

}  // namespace emb

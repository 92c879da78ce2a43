#pragma once
/// @file
/// Files to remove if the process is ended by a signal before they are finished: the
/// temporaries of atomic writes (atomic_file.h), output locks (output_lock.h) and saved
/// meshes. A process ended by SIGINT or SIGTERM does not unwind its stack, so destructors do
/// not run; the tool's termination (tools/emb/interrupt.h) calls
/// RemoveCleanupFilesForever() first.
///
/// The registry is a mutex-guarded table, not something a signal handler reads: the tool
/// takes signals on a thread of its own (sigwait), so the termination is ordinary code. What
/// makes it race-free is that a registered file's *existence* changes only under the same
/// lock: a writer creates its file inside Create() and renames or removes it inside
/// Release(); RemoveCleanupFilesForever() takes the lock and never gives it back. A
/// termination therefore sees every file either not yet made, or made and registered, or
/// already in its final place, and no other thread makes or moves one afterwards (it blocks
/// until the process ends). The library keeps the table and never installs handlers itself.
///
/// fork(): the lock is taken around it (pthread_atfork), so a child never inherits it held;
/// the child starts with an empty table (its parent's files are not its to remove).

#include <mutex>
#include <string>
#include <utility>

namespace emb {

/// The registry's lock, for Create() and WithCleanupLock(); never held while registering.
std::unique_lock<std::mutex> LockCleanupRegistry();

/// Runs fn() while no termination can remove files or end the process's file work: for
/// short file-system operations that must not be cut in half (a probe file made and removed).
/// fn must not register or release files itself (the lock is not recursive).
template <class Fn>
decltype(auto) WithCleanupLock(Fn&& fn) {
  const std::unique_lock<std::mutex> lock = LockCleanupRegistry();
  return std::forward<Fn>(fn)();
}

/// A file registered for removal on a termination while the object lives (or until
/// Release()).
class CleanupOnSignal {
 public:
  CleanupOnSignal() = default;
  /// Registers `path` (the file need not exist yet; it must be made inside Create()).
  explicit CleanupOnSignal(const std::string& path);
  ~CleanupOnSignal() { Release(); }
  CleanupOnSignal(const CleanupOnSignal&) = delete;
  CleanupOnSignal& operator=(const CleanupOnSignal&) = delete;
  CleanupOnSignal(CleanupOnSignal&& o) noexcept : id_(std::exchange(o.id_, -1)) {}
  CleanupOnSignal& operator=(CleanupOnSignal&& o) noexcept;

  /// Runs make() — which creates the registered file — under the registry lock and returns
  /// its result. make must not register or release files.
  template <class Make>
  decltype(auto) Create(Make&& make) const {
    return WithCleanupLock(std::forward<Make>(make));
  }
  /// The file is finished (or removed): no longer removed on a termination.
  void Release();
  /// Runs finish() (the rename that makes the file permanent, or its removal) and ends the
  /// registration, both under the registry lock. finish may throw; the registration then
  /// stays.
  template <class Finish>
  void Release(Finish&& finish) {
    const std::unique_lock<std::mutex> lock = LockCleanupRegistry();
    std::forward<Finish>(finish)();
    ReleaseLocked();
  }
  bool registered() const { return id_ >= 0; }

 private:
  void ReleaseLocked();
  int id_{-1};
};

/// Takes the registry lock for good and removes every registered file: from here on no
/// thread of this process creates, renames or removes a registered file (those that try
/// block until the process ends). Call it only on the way to the process's end (a signal's
/// termination, a deadline's exit); not async-signal-safe.
void RemoveCleanupFilesForever();

/// The lock around calls into libraries that swap the process's signal handlers while they
/// run: METIS (GKlib's gk_sigtrap) installs its own SIGTERM and SIGABRT handlers for the
/// length of every call and long-jumps from them to a thread-local buffer, so a SIGTERM it
/// receives on another thread jumps into garbage (the crash of `emb modes` stopped during
/// the ordering thread), and two concurrent calls can leave its handler installed for good.
/// Those calls run under this lock; the tool's termination takes it before it relies on
/// the default action of a signal. Held around fork() as well.
std::mutex& SignalSwappingLibraryMutex();

}  // namespace emb

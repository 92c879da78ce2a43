#pragma once
/// @file
/// Keeps two emb processes from writing the same output at once (the second would truncate
/// or interleave with the first): an exclusive lock taken before any work and held until the
/// output is finished.
///
/// The lock is a name in Linux's abstract socket namespace, bound by the holder, derived from
/// the output's directory (device and inode) and file name. It leaves nothing on disk: the
/// kernel releases the name when the last descriptor closes, however the process ends — on
/// SIGKILL too, which mpirun sends a rank one second after SIGTERM and which no cleanup can
/// follow (issue 37: a lock *file* left by such a rank). The holder listens, so a second
/// process can name the holder's pid (SO_PEERCRED). Its reach is one machine (one network
/// namespace): two hosts writing one file over a network file system are not kept apart.

#include <string>

namespace emb {

class OutputLock {
 public:
  OutputLock() = default;
  /// Locks `output`. @throws InputError if another process holds the lock (naming its pid
  /// when known) or the output's directory cannot be examined.
  explicit OutputLock(const std::string& output);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  OutputLock(OutputLock&& o) noexcept;
  OutputLock& operator=(OutputLock&& o) noexcept;

  /// The abstract socket name (without its leading NUL) of `output`'s lock:
  /// "emb-output/<dev hex>/<inode hex>/<file name>" of the resolved path, the file name
  /// replaced by "#<FNV-1a 64 hex>" when the whole would exceed the 107 bytes Linux allows.
  static std::string LockName(const std::string& output);

 private:
  void Unlock();
  int fd_{-1};
};

}  // namespace emb

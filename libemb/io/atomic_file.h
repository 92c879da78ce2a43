#pragma once
/// @file
/// Atomic file output: write to a temporary file beside the target, then rename it over the
/// target only when everything was written and closed without error. A failure leaves the
/// previous file (if any) untouched and removes the temporary; so does an interruption by
/// SIGINT or SIGTERM, whose termination runs RemoveCleanupFilesForever() (signal_cleanup.h):
/// the temporary is made inside Create() and renamed inside Commit(), under the lock of that
/// registry, so a termination never runs between the making of a file and its registration.
/// A SIGKILL can leave the hidden temporary ".<name>.tmp.<pid>" behind, never a partial file
/// under the target's name; the next AtomicFile for the same target removes such
/// temporaries of processes that no longer run.

#include <string>
#include <utility>

#include "libemb/common/signal_cleanup.h"

namespace emb {

class AtomicFile {
 public:
  /// Prepares to write `path`. @throws InputError if the directory does not exist or the
  /// path is a directory.
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless Commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where to write now; the file must be made by Create().
  const std::string& temp_path() const { return temp_; }
  /// Runs make(temp_path()), which creates the temporary file (e.g. an HDF5 file opened for
  /// creation), under the cleanup registry's lock; returns its result. Later writes go
  /// through what make opened.
  template <class Make>
  decltype(auto) Create(Make&& make) {
    return cleanup_.Create([&]() -> decltype(auto) { return std::forward<Make>(make)(temp_); });
  }
  /// The final name.
  const std::string& path() const { return path_; }
  /// Writes `text` to the temporary file; every write and the close are checked.
  /// @throws InputError naming the target and the system's reason (e.g. no space left).
  void WriteText(const std::string& text);
  /// Renames the temporary file to the final name (atomic on POSIX file systems). The
  /// temporary must be complete and closed.
  /// @throws InputError if the rename fails.
  void Commit();

 private:
  std::string path_;
  std::string temp_;
  CleanupOnSignal cleanup_;
  bool committed_{false};
};

/// Writes `text` to `path` atomically.
void WriteTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace emb

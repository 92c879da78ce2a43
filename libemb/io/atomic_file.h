#pragma once
/// @file
/// Atomic file output: write to a temporary file beside the target, then rename it over the
/// target only when everything was written and closed without error. A failure leaves the
/// previous file (if any) untouched and removes the temporary; so does an interruption by
/// SIGINT or SIGTERM when the tool's handler runs RemoveCleanupFilesNow() (signal_cleanup.h).
/// A SIGKILL can leave the hidden temporary ".<name>.tmp.<pid>" behind, never a partial file
/// under the target's name; the next AtomicFile for the same target removes such
/// temporaries of processes that no longer run.

#include <string>

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

  /// Where to write now.
  const std::string& temp_path() const { return temp_; }
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

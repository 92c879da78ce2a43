#pragma once
/// @file
/// Atomic file output: write to a temporary file beside the target, then rename it over the
/// target only when everything was written. A failure or an interruption never leaves a
/// partial or corrupted file under the target's name.

#include <string>

namespace emb {

class AtomicFile {
 public:
  /// Prepares to write `path`. @throws InputError if the directory does not exist.
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless Commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where to write now.
  const std::string& temp_path() const { return temp_; }
  /// The final name.
  const std::string& path() const { return path_; }
  /// Renames the temporary file to the final name (atomic on POSIX file systems).
  /// @throws InputError if the rename fails.
  void Commit();

 private:
  std::string path_;
  std::string temp_;
  bool committed_{false};
};

/// Writes `text` to `path` atomically.
void WriteTextFileAtomic(const std::string& path, const std::string& text);

}  // namespace emb

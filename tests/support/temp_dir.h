#pragma once
// Unique temporary directories for tests (test support): several test processes, and the test
// suites of several checkouts on one machine, run at once, so no test may write to a fixed
// name under /tmp.

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace emb::testing {

/// A fresh directory under the system's temp directory, made by mkdtemp (unique to this call),
/// removed with its contents when the object goes away.
class ScopedTempDir {
 public:
  explicit ScopedTempDir(const std::string& prefix = "emb_test") {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "_XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~ScopedTempDir() {
    std::error_code ec;  // never throw from a destructor; a leftover dir is harmless
    std::filesystem::remove_all(path_, ec);
  }
  ScopedTempDir(const ScopedTempDir&) = delete;
  ScopedTempDir& operator=(const ScopedTempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The path of `name` inside the directory.
  std::string File(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// One directory for the whole test process (removed at exit), for files several tests share.
inline const ScopedTempDir& ProcessTempDir() {
  static const ScopedTempDir dir("emb_process");
  return dir;
}

}  // namespace emb::testing

#include "libemb/io/output_path.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "libemb/common/error.h"
#include "libemb/common/signal_cleanup.h"

namespace emb {
namespace fs = std::filesystem;

fs::path ResolvedPath(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  if (ec) p = path;
  // weakly_canonical follows every link of the existing prefix; a dangling link at the end
  // is followed here (writing through it would create its target). 40 hops as in POSIX.
  for (int hop = 0; hop < 40; ++hop) {
    fs::path q = fs::weakly_canonical(p, ec);
    if (ec) return p.lexically_normal();
    if (!fs::is_symlink(q, ec)) return q;
    const fs::path target = fs::read_symlink(q, ec);
    if (ec) return q;
    p = target.is_absolute() ? target : q.parent_path() / target;
  }
  return p.lexically_normal();
}

bool IsInside(const std::string& path, const std::string& root) {
  const fs::path p = ResolvedPath(path), r = ResolvedPath(root);
  auto pi = p.begin();
  for (auto ri = r.begin(); ri != r.end(); ++ri, ++pi) {
    if (ri->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *ri) return false;
  }
  return true;
}

void CheckConfined(const std::string& path, const std::vector<std::string>& roots,
                   const std::string& what) {
  for (const auto& root : roots)
    if (IsInside(path, root)) return;
  std::string list;
  for (const auto& root : roots)
    list += (list.empty() ? "'" : " or '") + ResolvedPath(root).string() + "'";
  EMB_THROW(InputError, what << " '" << path << "' leads to '" << ResolvedPath(path).string()
                             << "', outside " << list
                             << "; a scene may only write inside its own directory or the "
                                "working directory (give other paths on the command line: -o, "
                                "--csv)");
}

void CheckWritableOutput(const std::string& path, const std::string& what) {
  if (path.empty()) return;
  std::error_code ec;
  const fs::path target = ResolvedPath(path);
  const fs::path dir = target.parent_path();
  EMB_THROW_IF(fs::is_directory(target, ec),
               what << " '" << path << "' is a directory; expected a file name");
  EMB_THROW_IF(!fs::is_directory(dir, ec),
               what << " '" << path << "': directory '" << dir.string() << "' does not exist");
  if (fs::exists(target, ec)) {
    EMB_THROW_IF(!fs::is_regular_file(target, ec),
                 what << " '" << path << "' exists and is not a regular file (a device, FIFO "
                      << "or socket); expected a file name to write");
    EMB_THROW_IF(::access(target.c_str(), W_OK) != 0,
                 what << " '" << path << "' exists and is write-protected: "
                      << std::strerror(errno));
  }
  // Whether a file can be created there (read-only file system, permissions, no space for
  // a directory entry) is known only by creating one.
  static std::atomic<int> counter{0};
  const fs::path probe = dir / (".emb-probe-" + std::to_string(::getpid()) + "-" +
                                std::to_string(counter++));
  // Made and removed in one step under the cleanup lock (signal_cleanup.h): a termination
  // never leaves it behind.
  const int err = WithCleanupLock([&] {
    const int fd = ::open(probe.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0600);
    if (fd < 0) return errno;
    ::close(fd);
    ::unlink(probe.c_str());
    return 0;
  });
  EMB_THROW_IF(err != 0, what << " '" << path << "': cannot create files in directory '"
                              << dir.string() << "': " << std::strerror(err));
}

void CheckDistinctFiles(const std::vector<std::string>& outputs,
                        const std::vector<std::string>& inputs) {
  auto same = [](const std::string& a, const std::string& b) {
    const fs::path ra = ResolvedPath(a), rb = ResolvedPath(b);
    if (ra == rb) return true;
    std::error_code ec;
    return fs::exists(ra, ec) && fs::exists(rb, ec) && fs::equivalent(ra, rb, ec);
  };
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].empty()) continue;
    for (const auto& in : inputs)
      EMB_THROW_IF(!in.empty() && same(outputs[i], in),
                   "output '" << outputs[i] << "' is the input '" << in
                              << "'; expected a different file name (it would be overwritten)");
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      EMB_THROW_IF(!outputs[j].empty() && same(outputs[i], outputs[j]),
                   "outputs '" << outputs[i] << "' and '" << outputs[j]
                               << "' are the same file; expected different names");
  }
}

}  // namespace emb

#include "libemb/io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "libemb/common/error.h"

namespace emb {
namespace {

// Removes ".<name>.tmp.<pid>" files in `dir` whose process is gone: temporaries of an
// earlier run of the same output that was killed outright (SIGKILL, power loss), which no
// handler could remove. A temporary of a live process (another emb writing the same name,
// which its lock refuses anyway) is left alone.
void RemoveStaleTemporaries(const std::filesystem::path& dir, const std::string& name) {
  namespace fs = std::filesystem;
  const std::string prefix = "." + name + ".tmp.";
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file.size() <= prefix.size() || file.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string pid_text = file.substr(prefix.size());
    if (pid_text.size() > 9 || pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code rm;
      fs::remove(it->path(), rm);
    }
  }
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  const fs::path p(path_);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  EMB_THROW_IF(!fs::is_directory(dir, ec),
               "output '" << path_ << "': directory '" << dir.string() << "' does not exist");
  EMB_THROW_IF(fs::is_directory(p, ec), "output '" << path_ << "' is a directory; expected a file name");
  RemoveStaleTemporaries(dir, p.filename().string());
  temp_ = (dir / ("." + p.filename().string() + ".tmp." + std::to_string(::getpid()))).string();
  cleanup_ = CleanupOnSignal(temp_);
}

AtomicFile::~AtomicFile() {
  if (!committed_) cleanup_.Release([&] { std::remove(temp_.c_str()); });
}

void AtomicFile::WriteText(const std::string& text) {
  const int fd = Create([](const std::string& temp) {
    return ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  });
  EMB_THROW_IF(fd < 0, "output '" << path_ << "': cannot create '" << temp_
                                  << "': " << std::strerror(errno));
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      EMB_THROW(InputError, "output '" << path_ << "': write failed: " << std::strerror(err));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  EMB_THROW_IF(::close(fd) != 0,
               "output '" << path_ << "': write failed on close: " << std::strerror(errno));
}

void AtomicFile::Commit() {
  // The data must be on the disk before the rename makes it the file (after a crash in
  // between, some file systems would show an empty file under the target's name).
  const int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
  EMB_THROW_IF(fd < 0, "output '" << path_ << "': the finished file '" << temp_
                                  << "' cannot be opened: " << std::strerror(errno));
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: cannot be synced
  const int sync_err = errno;
  ::close(fd);
  EMB_THROW_IF(!synced, "output '" << path_ << "': writing to the disk failed: "
                                   << std::strerror(sync_err));
  cleanup_.Release([&] {
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
      EMB_THROW(InputError, "output '" << path_
                                       << "': could not move the finished file into place: "
                                       << std::strerror(errno));
  });
  committed_ = true;
}

void WriteTextFileAtomic(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.WriteText(text);
  file.Commit();
}

}  // namespace emb

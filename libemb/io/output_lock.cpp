#include "libemb/io/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "libemb/common/error.h"
#include "libemb/io/output_path.h"

namespace emb {

std::string OutputLock::LockPath(const std::string& output) {
  // Beside the file the name leads to, so that two names of one file share the lock.
  const std::filesystem::path p = ResolvedPath(output);
  return (p.parent_path() / ("." + p.filename().string() + ".lock")).string();
}

OutputLock::OutputLock(const std::string& output) : lock_path_(LockPath(output)) {
  // Retry when the lock file was removed between our open and our flock by the process
  // that held it: then we hold a lock on a file nobody else will open.
  for (int attempt = 0; attempt < 100; ++attempt) {
    // Registered before it is made, made under the registry's lock (signal_cleanup.h): a
    // termination finds it either absent or registered.
    CleanupOnSignal cleanup(lock_path_);
    const int fd = cleanup.Create(
        [&] { return ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644); });
    EMB_THROW_IF(fd < 0, "output '" << output << "': cannot create the lock file '" << lock_path_
                                    << "': " << std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char pid[32] = {0};
      const ssize_t n = ::read(fd, pid, sizeof pid - 1);
      ::close(fd);
      cleanup.Release();  // the file is the other process's
      EMB_THROW(InputError, "output '" << output << "' is being written by another emb process"
                                       << (n > 0 ? " (pid " + std::string(pid, n) + ")" : "")
                                       << "; wait for it to finish or choose another output");
    }
    struct stat by_fd {}, by_name {};
    if (::fstat(fd, &by_fd) == 0 && ::stat(lock_path_.c_str(), &by_name) == 0 &&
        by_fd.st_ino == by_name.st_ino && by_fd.st_dev == by_name.st_dev) {
      const std::string pid = std::to_string(::getpid());
      if (::ftruncate(fd, 0) == 0 && ::write(fd, pid.data(), pid.size()) < 0) {
        // The pid is only a courtesy for the message of a second process.
      }
      fd_ = fd;
      cleanup_ = std::move(cleanup);
      return;
    }
    ::close(fd);
    cleanup.Release();  // a name the previous holder removed: not ours
  }
  EMB_THROW(InputError, "output '" << output << "': could not lock '" << lock_path_ << "'");
}

OutputLock::~OutputLock() { Unlock(); }

OutputLock::OutputLock(OutputLock&& o) noexcept
    : lock_path_(std::move(o.lock_path_)), fd_(o.fd_), cleanup_(std::move(o.cleanup_)) {
  o.fd_ = -1;
}

OutputLock& OutputLock::operator=(OutputLock&& o) noexcept {
  if (this != &o) {
    Unlock();
    lock_path_ = std::move(o.lock_path_);
    fd_ = o.fd_;
    cleanup_ = std::move(o.cleanup_);
    o.fd_ = -1;
  }
  return *this;
}

void OutputLock::Unlock() {
  if (fd_ < 0) return;
  // Remove the name while still holding the lock: a process that opened it meanwhile sees
  // the inode change and retries on a fresh file.
  cleanup_.Release([&] { ::unlink(lock_path_.c_str()); });
  ::close(fd_);
  fd_ = -1;
}

}  // namespace emb

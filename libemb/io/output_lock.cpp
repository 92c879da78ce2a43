#include "libemb/io/output_lock.h"

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>

#include "libemb/common/error.h"
#include "libemb/io/output_path.h"

namespace emb {
namespace {

// The longest abstract name: sun_path less its leading NUL.
constexpr std::size_t kMaxName = sizeof(sockaddr_un::sun_path) - 1;

std::uint64_t Fnv1a64(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

sockaddr_un AbstractAddress(const std::string& name, socklen_t* length) {
  sockaddr_un a{};
  a.sun_family = AF_UNIX;
  a.sun_path[0] = '\0';
  std::memcpy(a.sun_path + 1, name.data(), name.size());
  *length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size());
  return a;
}

// The pid of the process listening on `name`, or -1 (a full backlog, a holder gone meanwhile).
long HolderPid(const sockaddr_un& address, socklen_t length) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return -1;
  long pid = -1;
  ucred cred{};
  socklen_t size = sizeof cred;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), length) == 0 &&
      ::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &size) == 0)
    pid = cred.pid;
  ::close(fd);
  return pid;
}

}  // namespace

std::string OutputLock::LockName(const std::string& output) {
  // The directory by identity, so that two names of one file (links, "..") share the lock.
  const std::filesystem::path p = ResolvedPath(output);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0)
    EMB_THROW(InputError, "output '" << output << "': cannot examine its directory '"
                                     << dir.string() << "': " << std::strerror(errno));
  std::ostringstream o;
  o << "emb-output/" << std::hex << static_cast<unsigned long long>(st.st_dev) << "/"
    << static_cast<unsigned long long>(st.st_ino) << "/";
  const std::string file = p.filename().string();
  if (o.str().size() + file.size() <= kMaxName)
    o << file;
  else
    o << "#" << Fnv1a64(file);
  return o.str();
}

OutputLock::OutputLock(const std::string& output) {
  const std::string name = LockName(output);
  socklen_t length = 0;
  const sockaddr_un address = AbstractAddress(name, &length);
  // Closed on exec, not on fork: a worker forked by `emb sweep -j` shares its parent's lock.
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  EMB_THROW_IF(fd < 0, "output '" << output << "': cannot make its lock (socket: "
                                  << std::strerror(errno) << ")");
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), length) != 0) {
    const int err = errno;
    ::close(fd);
    if (err != EADDRINUSE)
      EMB_THROW(InputError, "output '" << output << "': cannot take its lock (bind: "
                                       << std::strerror(err) << ")");
    const long pid = HolderPid(address, length);
    EMB_THROW(InputError, "output '" << output << "' is being written by another emb process"
                                     << (pid > 0 ? " (pid " + std::to_string(pid) + ")" : "")
                                     << "; wait for it to finish or choose another output");
  }
  // Listening only so that a second process can ask who holds the name.
  if (::listen(fd, 1) != 0) {
    // The lock holds without it; only the pid in a second process's message is lost.
  }
  fd_ = fd;
}

OutputLock::~OutputLock() { Unlock(); }

OutputLock::OutputLock(OutputLock&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }

OutputLock& OutputLock::operator=(OutputLock&& o) noexcept {
  if (this != &o) {
    Unlock();
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

void OutputLock::Unlock() {
  if (fd_ < 0) return;
  ::close(fd_);
  fd_ = -1;
}

}  // namespace emb

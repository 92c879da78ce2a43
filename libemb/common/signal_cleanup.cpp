#include "libemb/common/signal_cleanup.h"

#include <pthread.h>
#include <unistd.h>

#include <map>

namespace emb {
namespace {

struct Registry {
  std::mutex mutex;
  std::map<int, std::string> files;  // id -> path
  int next_id{0};
};

// Never destroyed: a termination may run while static destructors do.
Registry& TheRegistry() {
  static Registry* registry = [] {
    auto* r = new Registry;
    // Neither lock may be held by another thread at a fork: the child would inherit it
    // held for good. The order (libraries, then the registry) is the termination's.
    pthread_atfork(
        [] {
          SignalSwappingLibraryMutex().lock();
          TheRegistry().mutex.lock();
        },
        [] {
          TheRegistry().mutex.unlock();
          SignalSwappingLibraryMutex().unlock();
        },
        [] {
          TheRegistry().files.clear();  // the parent's files are not the child's to remove
          TheRegistry().mutex.unlock();
          SignalSwappingLibraryMutex().unlock();
        });
    return r;
  }();
  return *registry;
}

}  // namespace

std::mutex& SignalSwappingLibraryMutex() {
  // The registry first: its fork handlers cover this lock too.
  static std::mutex* mutex = (TheRegistry(), new std::mutex);
  return *mutex;
}

std::unique_lock<std::mutex> LockCleanupRegistry() {
  return std::unique_lock<std::mutex>(TheRegistry().mutex);
}

CleanupOnSignal::CleanupOnSignal(const std::string& path) {
  Registry& r = TheRegistry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  id_ = r.next_id++;
  r.files.emplace(id_, path);
}

CleanupOnSignal& CleanupOnSignal::operator=(CleanupOnSignal&& o) noexcept {
  if (this != &o) {
    Release();
    id_ = std::exchange(o.id_, -1);
  }
  return *this;
}

void CleanupOnSignal::Release() {
  if (id_ < 0) return;
  const std::unique_lock<std::mutex> lock = LockCleanupRegistry();
  ReleaseLocked();
}

void CleanupOnSignal::ReleaseLocked() {
  if (id_ >= 0) TheRegistry().files.erase(id_);
  id_ = -1;
}

void RemoveCleanupFilesForever() {
  Registry& r = TheRegistry();
  r.mutex.lock();  // never unlocked: the process is ending
  for (const auto& entry : r.files) ::unlink(entry.second.c_str());
}

}  // namespace emb

#include "libemb/common/script_deadline.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace emb {
namespace {

std::mutex g_mutex;
double g_seconds = 0.0;
ScriptTimeoutHandler g_handler;

}  // namespace

void SetScriptDeadlineHandler(double seconds, ScriptTimeoutHandler handler) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_seconds = seconds > 0.0 && handler ? seconds : 0.0;
  g_handler = g_seconds > 0.0 ? std::move(handler) : ScriptTimeoutHandler();
}

struct ScriptDeadline::Impl {
  std::mutex mutex;
  std::condition_variable finished;
  bool done{false};
  std::thread watchdog;
};

ScriptDeadline::ScriptDeadline(std::string what) {
  double seconds = 0.0;
  ScriptTimeoutHandler handler;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    seconds = g_seconds;
    handler = g_handler;
  }
  if (seconds <= 0.0) return;
  impl_ = std::make_unique<Impl>();
  Impl* impl = impl_.get();
  impl->watchdog = std::thread([impl, seconds, handler, what = std::move(what)] {
    std::unique_lock<std::mutex> lock(impl->mutex);
    const bool done = impl->finished.wait_for(lock, std::chrono::duration<double>(seconds),
                                              [impl] { return impl->done; });
    if (!done) {
      lock.unlock();
      handler(what, seconds);
    }
  });
}

ScriptDeadline::~ScriptDeadline() {
  if (!impl_) return;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->done = true;
  }
  impl_->finished.notify_all();
  impl_->watchdog.join();
}

}  // namespace emb

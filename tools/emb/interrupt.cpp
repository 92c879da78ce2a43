#include "tools/emb/interrupt.h"

#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <mutex>
#include <set>

#include "libemb/common/error.h"
#include "libemb/common/signal_cleanup.h"

namespace emb::cli {
namespace {

std::atomic<int> g_stop_signal{0};
std::atomic<int> g_graceful{0};
// The thread that takes the signals; written before g_have_signal_thread is set.
pthread_t g_signal_thread;
std::atomic<bool> g_have_signal_thread{false};

// Worker processes a termination must end. Its lock is held by ForkWorker across fork() and
// by a termination for good.
struct Workers {
  std::mutex mutex;
  std::set<pid_t> pids;
};
Workers& TheWorkers() {
  static Workers* workers = new Workers;  // never destroyed: a termination may come late
  return *workers;
}

sigset_t InterruptSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

void* TakeSignals(void*) {
  const sigset_t set = InterruptSignals();
  for (;;) {
    int signal = 0;
    if (sigwait(&set, &signal) != 0) continue;
    if (g_graceful.load() > 0 && g_stop_signal.exchange(signal) == 0) continue;  // at a sample
    EndBySignal(signal);
  }
  return nullptr;
}

// A thread that unblocked the signals itself got one: hand it to the thread that takes them
// (pthread_kill is async-signal-safe; that thread has them blocked and waits for them).
extern "C" void ForwardToSignalThread(int signal) {
  if (g_have_signal_thread.load()) pthread_kill(g_signal_thread, signal);
}

void StartSignalThread() {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
  pthread_t thread;
  const int err = pthread_create(&thread, &attr, TakeSignals, nullptr);
  pthread_attr_destroy(&attr);
  if (err != 0)
    EMB_THROW(InternalError, "cannot start the thread that takes SIGINT and SIGTERM (error "
                                 << err << ")");
  g_signal_thread = thread;
  g_have_signal_thread.store(true);
}

// Ends every recorded worker by `signal`: forwarded at once, waited for at most
// kWorkerGraceSeconds, then killed. Called with the workers' lock held for good.
void EndWorkers(const std::set<pid_t>& pids, int signal) {
  for (const pid_t pid : pids) ::kill(pid, signal);
  std::set<pid_t> left = pids;
  const timespec tick{0, 10'000'000};  // 10 ms
  for (int k = 0; !left.empty() && k < static_cast<int>(kWorkerGraceSeconds * 100); ++k) {
    for (auto it = left.begin(); it != left.end();) {
      int status = 0;
      const pid_t r = ::waitpid(*it, &status, WNOHANG);
      // Ended, or already waited for by the main thread (ECHILD).
      it = r == *it || (r < 0 && errno == ECHILD) ? left.erase(it) : std::next(it);
    }
    if (!left.empty()) nanosleep(&tick, nullptr);
  }
  for (const pid_t pid : left) {
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
  }
}

}  // namespace

void BlockInterrupts() {
  const sigset_t set = InterruptSignals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void InstallInterruptHandlers() {
  BlockInterrupts();  // already, from main.cpp's pre-initialisation; harmless twice
  struct sigaction sa {};
  sa.sa_handler = ForwardToSignalThread;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  StartSignalThread();
}

GracefulStop::GracefulStop() { ++g_graceful; }
GracefulStop::~GracefulStop() { --g_graceful; }

int StopSignal() { return g_stop_signal.load(); }

std::string SignalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

void EndBySignal(int signal) {
  static std::atomic<bool> ending{false};
  if (ending.exchange(true))
    for (;;) pause();  // the first caller ends the process
  Workers& workers = TheWorkers();
  workers.mutex.lock();  // never unlocked: no worker starts from here on
  RemoveCleanupFilesForever();
  EndWorkers(workers.pids, signal);
  // The default action, without a library swapping the handler in between.
  SignalSwappingLibraryMutex().lock();  // never unlocked
  struct sigaction sa {};
  sa.sa_handler = SIG_DFL;
  sigemptyset(&sa.sa_mask);
  sigaction(signal, &sa, nullptr);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, signal);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  raise(signal);
  _exit(128 + signal);  // if the default action did not end the process
}

pid_t ForkWorker() {
  Workers& workers = TheWorkers();
  std::unique_lock<std::mutex> lock(workers.mutex);
  const pid_t pid = fork();
  if (pid == 0) {
    // The child: one thread (this one), the signals still blocked; its own signal thread.
    workers.pids.clear();
    lock.unlock();
    g_stop_signal.store(0);
    g_have_signal_thread.store(false);
    StartSignalThread();
  } else if (pid > 0) {
    workers.pids.insert(pid);
  }
  return pid;
}

void ForgetWorker(pid_t pid) {
  Workers& workers = TheWorkers();
  const std::lock_guard<std::mutex> lock(workers.mutex);
  workers.pids.erase(pid);
}

}  // namespace emb::cli

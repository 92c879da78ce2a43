#include "tools/emb/interrupt.h"

#include <csignal>

#include <atomic>

#include "libemb/common/signal_cleanup.h"

namespace emb::cli {
namespace {

std::atomic<int> g_stop_signal{0};
std::atomic<int> g_graceful{0};

extern "C" void OnSignal(int signal) {
  if (g_graceful.load() > 0 && g_stop_signal.exchange(signal) == 0) return;  // stop at a sample
  EndBySignal(signal);
}

}  // namespace

void InstallInterruptHandlers() {
  struct sigaction sa {};
  sa.sa_handler = OnSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
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
  // Async-signal-safe only: unlink, signal, raise.
  RemoveCleanupFilesNow();
  std::signal(signal, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal);
  sigprocmask(SIG_UNBLOCK, &set, nullptr);  // blocked while its handler runs
  std::raise(signal);
  std::_Exit(128 + signal);  // if the default action did not end the process
}

}  // namespace emb::cli

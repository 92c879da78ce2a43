#pragma once
/// @file
/// SIGINT and SIGTERM in emb. By default a signal removes the temporaries and lock files the
/// library registered (libemb/common/signal_cleanup.h) and ends the process by the same signal
/// (the shell sees 130 or 143): `emb modes`/`reduce` leave no hidden files behind. Where a
/// command can stop cleanly — `emb run` between two samples — it asks for a graceful stop:
/// the first signal only sets a flag (StopSignal()), the run ends at the next sample and
/// marks its results "interrupted"; a second signal ends the process at once.

#include <stdexcept>
#include <string>

namespace emb::cli {

/// Installs the handlers (once, at start-up).
void InstallInterruptHandlers();

/// While an object lives, the first SIGINT/SIGTERM asks for a stop instead of ending the
/// process.
class GracefulStop {
 public:
  GracefulStop();
  ~GracefulStop();
  GracefulStop(const GracefulStop&) = delete;
  GracefulStop& operator=(const GracefulStop&) = delete;
};

/// The signal that asked for a stop (SIGINT, SIGTERM), 0 if none.
int StopSignal();
/// "SIGINT", "SIGTERM" or "signal N".
std::string SignalName(int signal);

/// Thrown where the work stops after a signal; main() ends the process by that signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Removes the registered files and ends the process by `signal` (default action).
[[noreturn]] void EndBySignal(int signal);

}  // namespace emb::cli

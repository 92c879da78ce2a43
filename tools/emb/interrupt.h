#pragma once
/// @file
/// SIGINT and SIGTERM in emb.
///
/// How a signal is taken. Both signals are blocked in every thread from before the first
/// library constructor runs (main.cpp's pre-initialisation; threads inherit the mask, so the
/// OpenBLAS, OpenMP, CHOLMOD, METIS and assembly threads never run a handler) and taken by
/// one thread of emb's own with sigwait(). No handler runs inside foreign code: a library
/// that swaps the process's handlers (METIS does, for every call) never sees a signal meant
/// for emb, and the termination is ordinary code on an ordinary thread. A thread that
/// unblocks the signals itself only forwards them to that thread.
///
/// What a signal does. By default it ends the process (Terminate()): the temporaries and
/// probe files the library registered are removed (libemb/common/signal_cleanup.h; output
/// locks leave no file, libemb/io/output_lock.h; a file
/// being made or moved into place finishes first, none is made afterwards), worker
/// processes (`emb sweep -j`) get the same signal and are waited for (at most
/// kWorkerGraceSeconds, then SIGKILL), and the process dies by the signal (the shell sees
/// 130 or 143). Where a command can stop cleanly — `emb run` between two samples — it asks
/// for a graceful stop: the first signal only sets a flag (StopSignal()), the run ends at the
/// next sample or before IDA's next step, whichever comes first, marks its results
/// "interrupted" and then ends by the signal; a second signal ends the process at once.

#include <sys/types.h>

#include <stdexcept>
#include <string>

namespace emb::cli {

/// How long a terminating emb waits for its worker processes to end by the signal it
/// forwarded before it kills them [s].
inline constexpr double kWorkerGraceSeconds = 10.0;

/// Blocks SIGINT and SIGTERM in the calling thread (main.cpp calls it before any library
/// constructor can start a thread).
void BlockInterrupts();

/// Starts the thread that takes the signals (once, at start-up, in main()).
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

/// Ends the process by `signal` (see the file comment): registered files removed, worker
/// processes ended, death by the signal's default action. From any thread; a second caller
/// waits for the first to end the process.
[[noreturn]] void EndBySignal(int signal);

/// fork() for a worker process whose end a termination must see to: the child is recorded
/// (a termination forwards its signal to it and waits for it) before any termination can
/// look, and no worker is started once a termination has begun (this call then blocks until
/// the process ends). In the child: its own signal thread, no workers of its parent's.
/// @returns fork()'s result.
pid_t ForkWorker();
/// The worker `pid` has been waited for (its pid may be reused): forget it.
void ForgetWorker(pid_t pid);

}  // namespace emb::cli

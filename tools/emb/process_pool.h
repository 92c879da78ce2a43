#pragma once
/// @file
/// Independent jobs as child processes on one machine (`emb sweep -j N`). emb forbids
/// starting programs (no_exec.h), so the children are fork()s of the running emb, each with
/// its own copy of everything (no solver state is shared between threads); a job reports
/// through the files it writes and its exit code.

#include <functional>
#include <string>
#include <vector>

namespace emb::cli {

/// Runs job(j) for every j of `jobs`, each in a child process, at most `processes` at a
/// time, in the order given. In the parent, done(j, outcome) is called as each child ends:
/// outcome is "" for exit code 0, else "exit code N" or "ended by signal N (NAME)". A job
/// that throws ends its child with exit code 4. Flushes stdout/stderr before each fork.
/// @throws InternalError if fork() or waitpid() fails.
void RunInChildProcesses(const std::vector<int>& jobs, int processes,
                         const std::function<int(int)>& job,
                         const std::function<void(int, const std::string&)>& done);

}  // namespace emb::cli

#include "tools/emb/process_pool.h"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>

#include "libemb/common/error.h"
#include "tools/emb/interrupt.h"

namespace emb::cli {

void RunInChildProcesses(const std::vector<int>& jobs, int processes,
                         const std::function<int(int)>& job,
                         const std::function<void(int, const std::string&)>& done) {
  EMB_THROW_IF(processes < 1, "process pool: expected at least one process, got " << processes);
  std::map<pid_t, int> running;  // child -> job
  std::size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < processes) {
      std::cout.flush();
      std::cerr.flush();
      std::fflush(nullptr);
      const pid_t pid = ForkWorker();  // a termination forwards its signal to it
      if (pid < 0) EMB_THROW(InternalError, "fork failed: " << std::strerror(errno));
      if (pid == 0) {
        int code = 4;
        try {
          code = job(jobs[next]);
        } catch (...) {
          code = 4;
        }
        std::fflush(nullptr);
        _exit(code);
      }
      running[pid] = jobs[next++];
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0 && errno == EINTR) continue;
    if (pid < 0) EMB_THROW(InternalError, "waitpid failed: " << std::strerror(errno));
    ForgetWorker(pid);
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const int j = it->second;
    running.erase(it);
    std::string outcome;
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
      outcome = "exit code " + std::to_string(WEXITSTATUS(status));
    else if (WIFSIGNALED(status))
      outcome = "ended by signal " + std::to_string(WTERMSIG(status)) + " (" +
                strsignal(WTERMSIG(status)) + ")";
    done(j, outcome);
  }
}

}  // namespace emb::cli

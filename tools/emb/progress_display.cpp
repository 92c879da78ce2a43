#include "tools/emb/progress_display.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace emb::cli {
namespace {
bool g_line_open = false;
}

ProgressFn MakeProgressDisplay(bool quiet) {
  if (quiet) return {};
  struct State {
    std::string phase;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    bool tty = isatty(fileno(stderr));
  };
  auto state = std::make_shared<State>();
  return [state](std::string_view phase, double fraction) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
    if (state->tty) {
      std::fprintf(stderr, "\r\033[K[%7.1f s] %-14.*s %5.1f %%", t, static_cast<int>(phase.size()),
                   phase.data(), 100.0 * fraction);
      g_line_open = true;
      if (fraction >= 1.0) {
        std::fputc('\n', stderr);
        g_line_open = false;
      }
    } else if (phase != state->phase) {
      std::fprintf(stderr, "[%7.1f s] %.*s\n", t, static_cast<int>(phase.size()), phase.data());
    }
    state->phase = std::string(phase);
    std::fflush(stderr);
  };
}

void FinishProgressLine() {
  if (g_line_open) std::fputc('\n', stderr);
  g_line_open = false;
}

}  // namespace emb::cli

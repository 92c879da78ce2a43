#pragma once
// Shared by the numbered examples: main() runs the example's steps and turns their verdict
// (or an exception: bad input, a missing file) into the printed result and the exit code.

#include <cstdio>
#include <exception>

namespace emb::examples {

/// Runs `run(argc, argv)`, which returns whether all of the example's checks held; prints
/// "all checks PASSED" (exit code 0) or "a check FAILED" (1); an exception is printed as
/// "NAME: message" on stderr (1).
inline int Main(const char* name, bool (*run)(int, char**), int argc, char** argv) {
  try {
    const bool ok = run(argc, argv);
    std::printf("%s\n", ok ? "all checks PASSED" : "a check FAILED");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

/// "ok" or "WRONG", for a check's printed line.
inline const char* Verdict(bool ok) { return ok ? "ok" : "WRONG"; }

}  // namespace emb::examples

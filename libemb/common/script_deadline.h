#pragma once
/// @file
/// A time limit on untrusted scripts that a library runs with no way to stop it: gmsh reading
/// a .geo file runs its loops and macros, and a file from someone else may loop 10^12 times
/// or call a macro from itself (issue 14: a hang, not an error). The library marks where such
/// a script runs with a ScriptDeadline; the tool says how long it may take and what happens
/// then (SetScriptDeadlineHandler: the emb command prints the file and exits with 1). The
/// library itself never prints or exits: without a handler a ScriptDeadline does nothing.

#include <functional>
#include <memory>
#include <string>

namespace emb {

/// Called from a watchdog thread when a marked script has run for `seconds`; `what` names
/// it (the file). It should not return (the script cannot be stopped otherwise); if it does,
/// the script runs on.
using ScriptTimeoutHandler = std::function<void(const std::string& what, double seconds)>;

/// Sets the limit [s] (> 0) and the handler for every later ScriptDeadline of the process;
/// seconds <= 0 or an empty handler removes it.
void SetScriptDeadlineHandler(double seconds, ScriptTimeoutHandler handler);

/// Marks a script run: from construction to destruction the handler's clock runs (one
/// watchdog thread while it lives).
class ScriptDeadline {
 public:
  explicit ScriptDeadline(std::string what);
  ~ScriptDeadline();
  ScriptDeadline(const ScriptDeadline&) = delete;
  ScriptDeadline& operator=(const ScriptDeadline&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace emb

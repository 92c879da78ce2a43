#pragma once
/// @file
/// The gmsh SDK session used by emb's gmsh-based readers and generators (mesh reading in
/// gmsh_reader.cpp, beam-model generation in libemb/beam): one RAII session at a time, errors
/// turned into InputError naming the file, and the `-setnumber` arguments that set a .geo
/// file's `DefineConstant` parameters. Include only where gmsh.h is linked (Gmsh::Gmsh).

#include <string>
#include <utility>
#include <vector>

namespace emb {

/// gmsh is a process-wide singleton: one session at a time, always finalized. Starts gmsh
/// with `args` (e.g. {"-setnumber", "h", "0.01"}), quiet, one thread, errors logged (not
/// thrown, see GmshCall).
class GmshSession {
 public:
  explicit GmshSession(const std::vector<std::string>& args);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// The last error gmsh logged, or the last few messages if it logged no error.
  static std::string LastError();
  /// The last error gmsh logged, empty if none.
  static std::string LoggedError();
};

namespace internal {
[[noreturn]] void ThrowGmshError(const std::string& what, const std::string& path,
                                 const std::string& error);
}  // namespace internal

/// Runs a gmsh call and turns an exception or a logged error into an InputError
/// "gmsh failed to <what> '<path>': <gmsh's message>".
template <typename F>
void GmshCall(const std::string& what, const std::string& path, F&& f) {
  std::string error;
  try {
    f();
    error = GmshSession::LoggedError();
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = GmshSession::LastError();
  }
  if (!error.empty()) internal::ThrowGmshError(what, path, error);
}

/// Opens `path` in the current session (gmsh::open). Unless `trusted`, the file and everything
/// gmsh would read with it are audited first (AuditGmshInput): gmsh never sees a file that
/// would run a command, write or delete files or stop the process.
/// @throws InputError for a refused file or when gmsh fails (GmshCall).
/// `time_limited`: a script (GmshReadsAsScript) is read under a ScriptDeadline
/// (common/script_deadline.h): the tool's limit on untrusted scripts applies.
void GmshOpen(const std::string& path, bool trusted, bool time_limited = false);

/// The gmsh arguments {"-setnumber", name, value, ...} that set the `DefineConstant`
/// parameters `overrides` of the .geo file `path`.
/// @throws InputError naming the parameter and listing the file's parameters when a name is
///         not declared by the file, or for a value that is not finite.
std::vector<std::string> GeoParameterArgs(
    const std::string& path, const std::vector<std::pair<std::string, double>>& overrides);

}  // namespace emb

#include "libemb/mesh/gmsh_session.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/script_deadline.h"
#include "libemb/mesh/gmsh_input_audit.h"
#include "libemb/mesh/gmsh_reader.h"

namespace emb {

GmshSession::GmshSession(const std::vector<std::string>& args) {
  std::vector<std::string> all{"emb"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  gmsh::initialize(static_cast<int>(argv.size()), argv.data(), /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 0);
  // Errors are logged, not thrown: gmsh 4.8 throwing from inside its .geo parser leaves the
  // lexer's state behind, and every later file in the process then misparses. We check the
  // log after each call instead (GmshCall).
  gmsh::option::setNumber("General.AbortOnError", 0);
  // One thread, so that meshing is as reproducible as gmsh allows (the same geometry and
  // parameters should give the same mesh: its hash is provenance). Known exception in 4.8:
  // Mesh.HighOrderOptimize moves curved high-order nodes differently from run to run.
  gmsh::option::setNumber("General.NumThreads", 1);
  // Never ask on stdin (gmsh's GetValue/GetString, "uncompress this file?"): the default.
  gmsh::option::setNumber("General.NoPopup", 1);
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::finalize();
  } catch (...) {
  }
}

std::string GmshSession::LoggedError() {
  std::string err;
  gmsh::logger::getLastError(err);
  return err;
}

std::string GmshSession::LastError() {
  std::string err;
  try {
    gmsh::logger::getLastError(err);
  } catch (...) {
  }
  if (!err.empty()) return err;
  std::vector<std::string> log;
  try {
    gmsh::logger::get(log);
  } catch (...) {
  }
  std::string tail;
  for (size_t i = log.size() > 3 ? log.size() - 3 : 0; i < log.size(); ++i) tail += log[i] + "; ";
  return tail.empty() ? "(gmsh gave no message)" : tail;
}

namespace internal {
void ThrowGmshError(const std::string& what, const std::string& path, const std::string& error) {
  EMB_THROW(InputError, "gmsh failed to " << what << " '" << path << "': " << error);
}
}  // namespace internal

void GmshOpen(const std::string& path, bool trusted, bool time_limited) {
  if (!trusted) AuditGmshInput(path);
  // A script's loops and macros run while gmsh reads it: bounded by the tool's deadline.
  std::optional<ScriptDeadline> deadline;
  if (time_limited && GmshReadsAsScript(path)) deadline.emplace(path);
  GmshCall("open", path, [&] { gmsh::open(path); });
}

std::vector<std::string> GeoParameterArgs(
    const std::string& path, const std::vector<std::pair<std::string, double>>& overrides) {
  const auto known = GeoParameters(path);
  auto is_known = [&](const std::string& name) {
    return std::any_of(known.begin(), known.end(), [&](const auto& k) { return k.first == name; });
  };
  std::vector<std::string> args;
  for (const auto& [name, value] : overrides) {
    if (!is_known(name)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k.first;
      EMB_THROW(InputError, "geometry '" << path << "' has no parameter '" << name
                                         << "'; expected one of: "
                                         << (list.empty() ? "(none)" : list));
    }
    // gmsh aborts the process on a non-finite -setnumber value.
    EMB_THROW_IF(!std::isfinite(value), "geometry '" << path << "': parameter " << name
                                                     << ": expected a finite number, got "
                                                     << value);
    std::ostringstream v;
    v.precision(17);
    v << value;
    args.insert(args.end(), {"-setnumber", name, v.str()});
  }
  return args;
}

}  // namespace emb

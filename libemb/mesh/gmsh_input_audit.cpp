#include "libemb/mesh/gmsh_input_audit.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>

#include "libemb/common/error.h"
#include "libemb/mesh/geo_lexer.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

// Names gmsh 4.8 acts on while reading a script, and what they do (Parser/Gmsh.y).
struct Refused {
  std::string_view name;
  std::string_view reason;
};
constexpr Refused kRefused[] = {
    {"SystemCall", "runs a shell command"},
    {"System", "runs a shell command"},
    {"NonBlockingSystemCall", "runs a shell command"},
    {"OnelabRun", "runs a program (ONELAB client)"},
    {"SendToServer", "talks to an ONELAB server"},
    {"Save", "writes a file"},
    {"Print", "writes a file (image export)"},
    {"CreateDir", "creates a directory"},
    {"Exit", "ends the process (emb would stop without a word)"},
    {"Sleep", "stalls the process"},
    {"StringToName", "builds a name from a string, which can spell any command"},
    {"S2N", "builds a name from a string, which can spell any command"},
    {"Plugin", "runs a post-processing plugin (not needed for a solid, not audited)"},
};

// The General options a script may set: they only change what gmsh prints.
constexpr std::string_view kHarmlessGeneralOptions[] = {"Terminal", "Verbosity", "ExpertMode"};

// Extensions MergeFile reads with a mesh, CAD or data reader in every gmsh 4.8 build
// (Common/OpenFile.cpp); the comparison is case-exact as gmsh's is.
constexpr std::string_view kNonScriptExtensions[] = {
    ".stl",  ".STL",  ".brep", ".rle",  ".brp",     ".BRP",  ".iges", ".IGES", ".igs",
    ".IGS",  ".step", ".STEP", ".stp",  ".STP",     ".sat",  ".SAT",  ".x_t",  ".xmt_txt",
    ".x_b",  ".xmt_bin", ".unv", ".UNV", ".vtk",    ".VTK",  ".wrl",  ".WRL",  ".vrml",
    ".VRML", ".iv",   ".IV",   ".mesh", ".MESH",    ".diff", ".DIFF", ".med",  ".MED",
    ".mmed", ".MMED", ".rmed", ".RMED", ".bdf",     ".BDF",  ".nas",  ".NAS",  ".dat",
    ".DAT",  ".p3d",  ".P3D",  ".ply2", ".PLY2",    ".ply",  ".PLY",  ".geom", ".GEOM",
    ".pch"};
// Extensions MergeFile turns into a solver program definition (ONELAB), and compressed files,
// for which it offers to run gunzip.
constexpr std::string_view kProgramExtensions[] = {".py", ".PY", ".m", ".M", ".exe", ".EXE",
                                                   ".pro"};
// First-line prefixes with which MergeFile reads a file of unknown extension as a mesh or a
// post-processing view rather than a script.
constexpr std::string_view kDataHeaders[] = {"$PTS",      "$NO",       "$PARA",      "$ELM",
                                             "$MeshFormat", "$Comments", "$PostFormat", "$View"};

template <std::size_t N>
bool Contains(const std::string_view (&list)[N], std::string_view s) {
  return std::find(std::begin(list), std::end(list), s) != std::end(list);
}

// gmsh's SplitFileName: the extension is from the last '.' of the last path component.
std::string GmshExtension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t base = slash == std::string::npos ? 0 : slash + 1;
  const std::size_t dot = path.find_last_of('.');
  return dot == std::string::npos || dot < base ? "" : path.substr(dot);
}

// gmsh's FixRelativePath: a relative name is relative to the directory of the file naming it.
std::string Resolve(const std::string& from_file, const std::string& name) {
  if (!name.empty() && name[0] == '/') return name;
  return (fs::path(from_file).parent_path() / name).string();
}

class Auditor {
 public:
  std::vector<ScriptFinding> findings;

  // What gmsh's MergeFile does with `path` (also what gmsh::open does).
  void Merged(const std::string& path, const std::string& from, int line) {
    if (!Readable(path, from, line)) return;
    const std::string ext = GmshExtension(path);
    if (ext == ".gz" || ext == ".GZ") {
      Add(from.empty() ? path : from, line, "compressed file '" + path + "'",
          "gmsh offers to run gunzip on it");
    } else if (Contains(kProgramExtensions, ext)) {
      Add(from.empty() ? path : from, line, "'" + path + "'",
          "gmsh defines it as a solver program (ONELAB)");
    } else if (GmshReadsAsScript(path)) {
      Script(path, from, line);
    }
    // After any file, MergeFile also merges "<file>.opt" when it exists.
    std::error_code ec;
    if (fs::exists(path + ".opt", ec)) Merged(path + ".opt", "", 0);
  }

  // What gmsh's ParseFile does: read `path` as a script, whatever its extension.
  void Script(const std::string& path, const std::string& from, int line) {
    if (!Readable(path, from, line)) return;
    std::error_code ec;
    const std::string key = fs::weakly_canonical(path, ec).string();
    if (std::find(stack_.begin(), stack_.end(), key) != stack_.end()) {
      Add(from, line, "Include of '" + path + "'",
          "includes a file that includes it (gmsh would recurse until it crashes)");
      return;
    }
    if (!done_.insert(key).second) return;
    if (++files_ > kMaxScriptFiles) {
      Add(path, 0, "'" + path + "'",
          "more than " + std::to_string(kMaxScriptFiles) + " script files to check");
      return;
    }
    const auto size = fs::file_size(path, ec);
    bytes_ += ec ? 0 : size;
    if (bytes_ > kMaxScriptBytes) {
      Add(path, 0, "'" + path + "'",
          "more than " + std::to_string(kMaxScriptBytes >> 20) + " MiB of script to check");
      return;
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::vector<GeoToken> tokens;
    try {
      tokens = LexGeoScript(text.str(), path);
    } catch (const InputError& e) {
      Add(path, 0, "text", e.what());
      return;
    }
    stack_.push_back(key);
    Scan(path, tokens);
    stack_.pop_back();
  }

 private:
  std::set<std::string> done_;
  std::vector<std::string> stack_;
  int files_{0};
  std::uintmax_t bytes_{0};

  void Add(const std::string& file, int line, std::string construct, std::string reason) {
    findings.push_back({file, line, std::move(construct), std::move(reason)});
  }

  bool Readable(const std::string& path, const std::string& from, int line) {
    std::error_code ec;
    const std::string where = from.empty() ? path : from;
    if (!fs::exists(path, ec)) {
      Add(where, line, "'" + path + "'", "not found");
      return false;
    }
    if (!fs::is_regular_file(path, ec)) {
      Add(where, line, "'" + path + "'", "not a regular file (a FIFO or device would stall gmsh)");
      return false;
    }
    return true;
  }

  void Scan(const std::string& path, const std::vector<GeoToken>& t) {
    const std::size_t n = t.size();
    auto symbol = [&](std::size_t k, std::string_view s) {
      return k < n && t[k].kind == GeoToken::Kind::kSymbol && t[k].text == s;
    };
    // `Command "literal";` -> the literal, or nullptr for a computed argument.
    auto literal_arg = [&](std::size_t k) -> const GeoToken* {
      if (k + 1 < n && t[k + 1].kind == GeoToken::Kind::kString && symbol(k + 2, ";"))
        return &t[k + 1];
      return nullptr;
    };
    // `Function("literal")` -> the literal, or nullptr.
    auto literal_call = [&](std::size_t k) -> const GeoToken* {
      if (symbol(k + 1, "(") && k + 2 < n && t[k + 2].kind == GeoToken::Kind::kString &&
          symbol(k + 3, ")"))
        return &t[k + 2];
      return nullptr;
    };
    for (std::size_t k = 0; k < n; ++k) {
      if (t[k].kind != GeoToken::Kind::kName) continue;
      const std::string& name = t[k].text;
      const int line = t[k].line;
      for (const Refused& r : kRefused)
        if (name == r.name) Add(path, line, name, std::string(r.reason));
      if (name == "Printf" && symbol(k + 1, "(")) {
        std::size_t p = k + 2;
        for (int depth = 1; p < n && depth > 0; ++p) {
          if (symbol(p, "(")) ++depth;
          if (symbol(p, ")")) --depth;
        }
        if (symbol(p, ">") || symbol(p, ">>"))
          Add(path, line, "Printf(...) " + t[p].text + " file", "writes a file");
      } else if (name == "Include" || name == "Merge" || name == "MergeWithBoundingBox") {
        const GeoToken* arg = literal_arg(k);
        if (arg == nullptr) {
          Add(path, line, name + " of a computed path", "cannot be checked before gmsh runs it");
        } else if (name == "Include") {
          Script(Resolve(path, arg->text), path, line);
        } else {
          Merged(Resolve(path, arg->text), path, line);
        }
      } else if (name == "ShapeFromFile" || name == "ListFromFile") {
        const GeoToken* arg = literal_call(k);
        if (arg == nullptr)
          Add(path, line, name + " of a computed path", "cannot be checked before gmsh runs it");
        else
          Readable(Resolve(path, arg->text), path, line);
      } else if ((name == "General" || name == "Solver") && (symbol(k + 1, ".") || symbol(k + 1, "["))) {
        const bool harmless = name == "General" && symbol(k + 1, ".") && k + 2 < n &&
                              Contains(kHarmlessGeneralOptions, t[k + 2].text) &&
                              !symbol(k + 3, ".");
        if (!harmless)
          Add(path, line, name + (symbol(k + 1, ".") && k + 2 < n ? "." + t[k + 2].text : ""),
              name == "Solver" ? "names programs gmsh runs"
                               : "application option (General.TmpFileName names a file gmsh "
                                 "deletes; others name files it writes or stop the process)");
      }
    }
  }
};

}  // namespace

bool GmshReadsAsScript(const std::string& path) {
  const std::string ext = GmshExtension(path);
  if (Contains(kNonScriptExtensions, ext) || Contains(kProgramExtensions, ext) || ext == ".gz")
    return false;
  // MergeFile reads the first line (fgets, at most 255 characters) to tell meshes and views.
  std::ifstream in(path, std::ios::binary);
  char header[256] = {0};
  in.getline(header, sizeof header);
  for (std::string_view h : kDataHeaders)
    if (std::strncmp(header, h.data(), h.size()) == 0) return false;
  return true;
}

std::vector<ScriptFinding> FindUnsafeGmshInput(const std::string& path) {
  Auditor a;
  a.Merged(path, "", 0);
  return a.findings;
}

void AuditGmshInput(const std::string& path) {
  const std::vector<ScriptFinding> f = FindUnsafeGmshInput(path);
  if (f.empty()) return;
  std::ostringstream m;
  m << "refusing to give '" << path << "' to gmsh: it holds what gmsh would act on while "
    << "reading it, outside the model: ";
  constexpr std::size_t kShown = 12;
  for (std::size_t i = 0; i < std::min(f.size(), kShown); ++i)
    m << (i ? "; " : "") << f[i].file << (f[i].line > 0 ? ":" + std::to_string(f[i].line) : "")
      << ": " << f[i].construct << " (" << f[i].reason << ")";
  if (f.size() > kShown) m << "; and " << f.size() - kShown << " more";
  m << ". Read the file; if you trust it, run again with --trust-geo (README: Files from others)";
  throw InputError(m.str());
}

}  // namespace emb

#pragma once
/// @file
/// Checks a file before gmsh reads it, because gmsh's .geo language can do more than describe
/// geometry: `SystemCall "…"` runs a shell command while the file is read. emb opens files
/// from others (a supplier's geometry, a colleague's mesh), so it reads them only when no
/// command with an effect outside the model is found — unless the user says the file is
/// trusted (`--trust-geo`, MeshingOptions::trust_scripts).
///
/// Which files gmsh 4.8 reads as a script (Common/OpenFile.cpp, MergeFile): every file whose
/// extension is not one of its mesh or CAD formats — so also a `.msh` file that does not start
/// with `$MeshFormat` (or another mesh/post-processing header), and any unknown extension;
/// after reading any file F gmsh also reads `F.opt` if it exists; `Include` reads any file as
/// a script; `Merge` reads by the same rules. The audit follows all of them (paths relative
/// to the including file, as gmsh resolves them).
///
/// Refused, with the reason (each is something gmsh 4.8 does while reading, Parser/Gmsh.y):
///   runs a program       SystemCall, System, NonBlockingSystemCall, OnelabRun, SendToServer;
///                        Merge of .py/.m/.exe/.pro (defines a solver program) or .gz
///                        (gmsh offers to run gunzip on the name)
///   writes files         Save, Print, CreateDir, Printf(…) > "file" / >> "file"
///   deletes files        options of the General category (General.TmpFileName names a file
///                        gmsh deletes when it finishes) except Terminal, Verbosity,
///                        ExpertMode; the Solver category (program paths)
///   stops or stalls emb  Exit (ends the process), Sleep
///   cannot be checked    StringToName / S2N (builds any command or category name from a
///                        string), Include / Merge / ShapeFromFile / ListFromFile of a computed
///                        path (not a string literal), Plugin (post-processing plugins, not
///                        needed for a solid and not audited)
///   not readable safely  a missing file or one that is not a regular file (a FIFO or device
///                        would stall gmsh), an Include cycle, NUL bytes or over-long strings
///                        (gmsh's lexer would read part of them as script).
/// The check is conservative: it looks at every token, also in macros and branches that never
/// run, and at names that happen to equal a command. It does not bound what a script may
/// compute (a loop may run long): GmshOpen reads an untrusted script under the tool's time
/// limit (common/script_deadline.h); the element-count estimate covers --size.

#include <string>
#include <vector>

namespace emb {

/// One refused construct: where it is and why.
struct ScriptFinding {
  std::string file;
  int line{0};
  std::string construct;  ///< e.g. "SystemCall"
  std::string reason;     ///< e.g. "runs a shell command"
};

/// Limits of the audit (a script that needs more is refused).
inline constexpr int kMaxScriptFiles = 256;          ///< files read by one audit
inline constexpr std::size_t kMaxScriptBytes = 64u << 20;  ///< bytes read by one audit

/// True when gmsh 4.8 would read `path` as a .geo script (by extension and first line, as
/// MergeFile does). Does not check that the file exists.
bool GmshReadsAsScript(const std::string& path);

/// Everything that makes `path` unsafe to give to gmsh (empty: safe), following the files it
/// includes or merges and the `.opt` companions gmsh reads.
std::vector<ScriptFinding> FindUnsafeGmshInput(const std::string& path);

/// @throws InputError listing the findings of FindUnsafeGmshInput(path) (file:line, construct,
///         reason) and how to trust the file, if there are any.
void AuditGmshInput(const std::string& path);

}  // namespace emb

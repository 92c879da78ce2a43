#pragma once
/// @file
/// Checks of output paths, all made before any work starts (a run must not compute for
/// minutes and then find that it cannot write, or write over its own input):
///  - where a file name actually leads (symbolic links followed, also a dangling last one);
///  - that outputs named by a scene stay inside the scene's directory tree or the working
///    directory (a scene from elsewhere must not write over the user's files);
///  - that the directory exists and can be written, the name is not a directory, an existing
///    file can be replaced;
///  - that no output is an input or another output.

#include <filesystem>
#include <string>
#include <vector>

namespace emb {

/// The absolute path `path` leads to: every symbolic link followed (a link at the end too,
/// even if its target does not exist yet), "." and ".." removed. Relative paths are relative
/// to the working directory. Never throws; a link loop gives the path as far as it resolved.
std::filesystem::path ResolvedPath(const std::string& path);

/// True if `path` (resolved) is `root` (resolved) or inside it.
bool IsInside(const std::string& path, const std::string& root);

/// @throws InputError "<what> '<path>' leads to <resolved>, outside <roots...>; ..." when the
///         resolved `path` is inside none of `roots`.
void CheckConfined(const std::string& path, const std::vector<std::string>& roots,
                   const std::string& what);

/// Checks that `path` can be written as an output: its directory exists and a file can be
/// created in it (a probe file is created and removed), the name is not a directory, and an
/// existing file there is writable.
/// @throws InputError naming `what` ("-o", "output.file", ...) and the path.
void CheckWritableOutput(const std::string& path, const std::string& what);

/// @throws InputError when two of `outputs` lead to the same file, or an output leads to the
///         same file as one of `inputs` (compared by resolved path and, for existing files,
///         by device and inode). Empty names are ignored.
void CheckDistinctFiles(const std::vector<std::string>& outputs,
                        const std::vector<std::string>& inputs);

}  // namespace emb

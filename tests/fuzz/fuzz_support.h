#pragma once
/// @file
/// Shared pieces of emb's libFuzzer targets (issue 14). A target hands the fuzzer's bytes to
/// one reader and lets through only what emb promises for bad input: emb::InputError (a
/// message for the user) or emb::NumericalError (a status). Anything else — another
/// exception, a crash, a sanitizer report, a hang — is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "libemb/common/error.h"

namespace emb::fuzz {

/// Writes the input to a new file `name` in a directory of this process (the readers under
/// test take paths); returns the path. The directory is the same for every input of a run.
inline std::string WriteInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("emb_fuzz_" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::string path = (dir / name).string();
  // A new file (inode) per input: HDF5 recognises a file it still has open by its inode and
  // would serve the previous input's cached metadata with this input's bytes.
  std::remove(path.c_str());
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) __builtin_trap();  // the harness itself is broken
  if (size > 0 && std::fwrite(data, 1, size, f) != size) __builtin_trap();
  std::fclose(f);
  return path;
}

/// Runs `read`, accepting the two errors emb gives for bad input.
template <class Read>
void Expect(Read&& read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const NumericalError&) {
  }
}

}  // namespace emb::fuzz

#pragma once
/// @file
/// The supports options of `emb modes` (--fixed, --symmetry, --rbe2, --rbe3, --equation,
/// --equations; syntax in libemb/cms/support_spec.h) and their parsing into SupportSpecs.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "libemb/cms/support_spec.h"

namespace emb::cli {

struct SupportOptions {
  std::vector<std::string> fixed, symmetry, rbe2, rbe3, equations;
  std::string equation_file;

  void Register(CLI::App& cmd);
  /// Parses every option (and reads the equation file). @throws InputError naming the option.
  SupportSpecs Specs() const;
};

}  // namespace emb::cli

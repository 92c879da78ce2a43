#pragma once
/// @file
/// A second line of defence behind the .geo audit (libemb/mesh/gmsh_input_audit.h): emb
/// never starts a program, so it can ask the kernel to refuse it (seccomp: execve and
/// execveat fail with EPERM, for this process and its children). A `SystemCall` the audit
/// missed then fails inside gmsh instead of running. Not installed with --trust-geo.

namespace emb::cli {

/// Installs the filter. @returns false if the kernel refused it (the audit still applies).
bool ForbidProgramExecution();

}  // namespace emb::cli

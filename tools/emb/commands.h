#pragma once
/// @file
/// The subcommands of `emb`. Each adds itself to the app; its callback does the work and
/// throws emb exceptions on failure (main turns them into messages and exit codes).

#include <CLI/CLI.hpp>

namespace emb::cli {

/// Exit codes: 0 success, 1 bad input, 2 usage error, 3 numerical failure, 4 internal error.
inline constexpr int kExitInput = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitNumerical = 3;
inline constexpr int kExitInternal = 4;

void RegisterMeshCommand(CLI::App& app);
void RegisterModesCommand(CLI::App& app);
/// `emb reduce PART` (Craig–Bampton body file) and `emb inspect FILE`.
void RegisterReduceCommand(CLI::App& app);
void RegisterInspectCommand(CLI::App& app);
/// `emb dof SCENE` and `emb run SCENE` (multibody scenes).
void RegisterDofCommand(CLI::App& app);
void RegisterRunCommand(CLI::App& app);
/// `emb spectrum RESULTS --channel NAME` (engine-order spectrum of a results channel).
void RegisterSpectrumCommand(CLI::App& app);
/// `emb campbell SCENE --rpm ...` (Campbell diagram) and `emb tvd-tune SCENE` (issue 17).
void RegisterCampbellCommand(CLI::App& app);
void RegisterTvdTuneCommand(CLI::App& app);
/// `emb sweep SCENE --rpm LIST` (speed sweep to steady state, orders) and `emb runup RESULTS`
/// (order tracking of a speed ramp), issue 17.
void RegisterSweepCommand(CLI::App& app);
void RegisterRunUpCommand(CLI::App& app);
/// `emb compare PART` (beam vs CMS vs 3-D FE, issue 6).
void RegisterCompareCommand(CLI::App& app);

}  // namespace emb::cli

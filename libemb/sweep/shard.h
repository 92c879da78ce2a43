#pragma once
/// @file
/// A share of a sweep's operating points for one process of a parallel engine that already
/// exists (MPI ranks under mpirun, a batch scheduler's job array): shard K of N holds the
/// points i with i mod N = K (0 <= K < N), so that the shards together hold every point once
/// and speeds spread evenly over them. The shards' files are merged afterwards
/// (sweep_file.h MergeSweeps). emb itself sends no messages between the shards.

#include <functional>
#include <string>

namespace emb::sweep {

struct Shard {
  int index{0};  ///< K
  int count{1};  ///< N
  bool Holds(int point) const { return point % count == index; }
};

/// Reads an environment variable (nullptr if unset); std::getenv by default.
using EnvironmentFn = std::function<const char*(const char*)>;

/// "K/N" with 0 <= K < N, or "auto" (ShardFromEnvironment).
/// @throws InputError for anything else, naming `what` (e.g. "--shard").
Shard ParseShard(const std::string& text, const std::string& what, const EnvironmentFn& env = {});

/// The shard of this process from the first of: Open MPI (OMPI_COMM_WORLD_RANK,
/// OMPI_COMM_WORLD_SIZE), MPICH/Hydra and Intel MPI (PMI_RANK, PMI_SIZE), Slurm job arrays
/// (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of SLURM_ARRAY_TASK_COUNT), PBS/Torque job
/// arrays via EMB_SHARD_INDEX/EMB_SHARD_COUNT (set them in the job script from
/// PBS_ARRAY_INDEX or any scheduler's index).
/// @throws InputError if none is set or a value is not a whole number in range.
Shard ShardFromEnvironment(const EnvironmentFn& env = {});

}  // namespace emb::sweep

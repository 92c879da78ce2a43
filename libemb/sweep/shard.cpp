#include "libemb/sweep/shard.h"

#include <cstdlib>

#include "libemb/common/error.h"

namespace emb::sweep {
namespace {

// A whole number >= 0 in `text`, or -1.
long Whole(const std::string& text) {
  if (text.empty() || text.size() > 9) return -1;
  for (char c : text)
    if (c < '0' || c > '9') return -1;
  return std::strtol(text.c_str(), nullptr, 10);
}

Shard Checked(long index, long count, const std::string& what, const std::string& text) {
  EMB_THROW_IF(index < 0 || count < 1 || index >= count,
               what << ": expected K/N with whole numbers 0 <= K < N, got '" << text << "'");
  return {static_cast<int>(index), static_cast<int>(count)};
}

}  // namespace

Shard ParseShard(const std::string& text, const std::string& what, const EnvironmentFn& env) {
  if (text == "auto") return ShardFromEnvironment(env);
  const std::size_t slash = text.find('/');
  EMB_THROW_IF(slash == std::string::npos,
               what << ": expected K/N (shard K of N, 0 <= K < N) or 'auto', got '" << text << "'");
  return Checked(Whole(text.substr(0, slash)), Whole(text.substr(slash + 1)), what, text);
}

Shard ShardFromEnvironment(const EnvironmentFn& env_in) {
  const EnvironmentFn env = env_in ? env_in : [](const char* name) { return std::getenv(name); };
  auto get = [&](const char* name) -> std::string {
    const char* v = env(name);
    return v ? v : "";
  };
  struct Pair {
    const char *index, *count;
  };
  for (const Pair& p : {Pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                        Pair{"PMI_RANK", "PMI_SIZE"}, Pair{"EMB_SHARD_INDEX", "EMB_SHARD_COUNT"}}) {
    if (get(p.index).empty()) continue;
    const std::string text = get(p.index) + "/" + get(p.count);
    return Checked(Whole(get(p.index)), Whole(get(p.count)),
                   std::string("--shard auto (") + p.index + ", " + p.count + ")", text);
  }
  if (!get("SLURM_ARRAY_TASK_ID").empty()) {
    const std::string min = get("SLURM_ARRAY_TASK_MIN").empty() ? "0" : get("SLURM_ARRAY_TASK_MIN");
    const long id = Whole(get("SLURM_ARRAY_TASK_ID")), lo = Whole(min);
    const long count = Whole(get("SLURM_ARRAY_TASK_COUNT"));
    const std::string text = get("SLURM_ARRAY_TASK_ID") + " - " + min + " / " +
                             get("SLURM_ARRAY_TASK_COUNT");
    EMB_THROW_IF(id < 0 || lo < 0, "--shard auto (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN): "
                                   "expected whole numbers, got '" << text << "'");
    return Checked(id - lo, count, "--shard auto (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of "
                                   "SLURM_ARRAY_TASK_COUNT)", text);
  }
  EMB_THROW(InputError, "--shard auto: no shard in the environment; expected an MPI rank "
                        "(OMPI_COMM_WORLD_RANK/SIZE, PMI_RANK/SIZE), a Slurm job array "
                        "(SLURM_ARRAY_TASK_ID/COUNT) or EMB_SHARD_INDEX/EMB_SHARD_COUNT");
}

}  // namespace emb::sweep

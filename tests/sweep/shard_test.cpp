// Shards of a sweep (sweep/shard.h) from the command line and from the environment of MPI
// ranks and job arrays, and the lists of speeds and orders (sweep/value_list.h).

#include "libemb/sweep/shard.h"

#include <gtest/gtest.h>

#include <map>

#include "libemb/common/error.h"
#include "libemb/sweep/value_list.h"

namespace emb::sweep {
namespace {

EnvironmentFn Env(std::map<std::string, std::string> vars) {
  return [vars = std::move(vars)](const char* name) -> const char* {
    const auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  };
}

TEST(Shard, ShardsTogetherHoldEveryPointOnce) {
  constexpr int kPoints = 23, kShards = 4;
  std::vector<int> held(kPoints, 0);
  for (int k = 0; k < kShards; ++k) {
    const Shard s = ParseShard(std::to_string(k) + "/" + std::to_string(kShards), "--shard");
    for (int i = 0; i < kPoints; ++i) held[static_cast<std::size_t>(i)] += s.Holds(i) ? 1 : 0;
  }
  for (int h : held) EXPECT_EQ(h, 1);
}

TEST(Shard, AutoReadsMpiRanksAndJobArrays) {
  auto shard = [](std::map<std::string, std::string> vars) {
    const Shard s = ParseShard("auto", "--shard", Env(std::move(vars)));
    return std::pair{s.index, s.count};
  };
  EXPECT_EQ(shard({{"OMPI_COMM_WORLD_RANK", "2"}, {"OMPI_COMM_WORLD_SIZE", "4"}}), std::pair(2, 4));
  EXPECT_EQ(shard({{"PMI_RANK", "0"}, {"PMI_SIZE", "3"}}), std::pair(0, 3));
  EXPECT_EQ(shard({{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                   {"SLURM_ARRAY_TASK_COUNT", "8"}}),
            std::pair(4, 8));
  EXPECT_EQ(shard({{"EMB_SHARD_INDEX", "1"}, {"EMB_SHARD_COUNT", "2"}}), std::pair(1, 2));
  EXPECT_THROW(shard({}), InputError);
  EXPECT_THROW(shard({{"OMPI_COMM_WORLD_RANK", "4"}, {"OMPI_COMM_WORLD_SIZE", "4"}}), InputError);
  EXPECT_THROW(shard({{"PMI_RANK", "x"}, {"PMI_SIZE", "2"}}), InputError);
}

TEST(Shard, RefusesMalformedShards) {
  for (const char* bad : {"", "1", "2/2", "-1/2", "a/b", "1/0", "1/2/3", " 1/2"})
    EXPECT_THROW(ParseShard(bad, "--shard"), InputError) << bad;
}

TEST(ValueList, RangesAndLists) {
  EXPECT_EQ(ParseValueList("1000:6500:250", "--rpm").size(), 23u);
  EXPECT_EQ(ParseValueList("1000:6500:250", "--rpm").back(), 6500.0);
  EXPECT_EQ(ParseValueList("0.5:12:0.5", "--orders").size(), 24u);
  EXPECT_EQ(ParseValueList("3000,1000", "--rpm"), (std::vector<double>{3000, 1000}));
  for (const char* bad : {"", "1000:", "1:2:3:4", "1000:abc:1", "5:1:1", "1:5:0", "1:5:-1",
                          "1,,2", "1,1", "1e400", "nan", "0:1e9:1"})
    EXPECT_THROW(ParseValueList(bad, "--rpm"), InputError) << bad;
}

}  // namespace
}  // namespace emb::sweep

// What makes two sweeps the same (sweep/sweep_file.h): resume and merge reuse point files only
// of the same definition, which includes the bytes of every file the scene reads.

#include <gtest/gtest.h>

#include <fstream>

#include "libemb/common/error.h"
#include "libemb/sweep/sweep_file.h"
#include "tests/support/temp_dir.h"

namespace emb::sweep {
namespace {

TEST(SweepDigest, ChangesWithEveryPartOfTheDefinitionAndTheBodyFilesItReads) {
  const auto body = testing::ProcessTempDir().path() / "digest_body.h5";
  std::ofstream(body, std::ios::binary) << "reduced crank, 108 coordinates";
  OrderSettings settings;
  settings.orders = {1.0, 2.0};
  settings.channels = {"nose_torsion"};
  const std::vector<double> rpm{2000, 3000};
  const std::vector<std::string> inputs{body.string()};
  const std::string base = SweepDigest("scene text", inputs, rpm, settings);
  EXPECT_EQ(base, SweepDigest("scene text", inputs, rpm, settings));
  EXPECT_NE(base, SweepDigest("scene text ", inputs, rpm, settings));
  EXPECT_NE(base, SweepDigest("scene text", {}, rpm, settings));
  EXPECT_NE(base, SweepDigest("scene text", inputs, {2000, 3001}, settings));
  OrderSettings other = settings;
  other.samples_per_cycle += 1;
  EXPECT_NE(base, SweepDigest("scene text", inputs, rpm, other));
  // The same body file path re-reduced (other bytes) is another sweep.
  std::ofstream(body, std::ios::binary) << "reduced crank, 110 coordinates";
  EXPECT_NE(base, SweepDigest("scene text", inputs, rpm, settings));
  std::filesystem::remove(body);
  EXPECT_THROW(SweepDigest("scene text", inputs, rpm, settings), InputError);
}

}  // namespace
}  // namespace emb::sweep

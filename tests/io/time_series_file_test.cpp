// Appendable HDF5 series: rows written one at a time are all there, including zero-width
// rows and scalars, and the file reads back with H5File (as h5py would).

#include "libemb/io/time_series_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "libemb/common/error.h"
#include "libemb/io/hdf5_file.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

TEST(TimeSeriesFile, AppendsRowsScalarsAndEmptyRows) {
  const testing::ScopedTempDir dir("emb_time_series");
  const std::string path = dir.File("series.h5");
  {
    TimeSeriesFile f(path);
    const int t = f.AddScalarSeries("/time");
    const int x = f.AddSeries("/state/x", 3, 2);  // chunks of 2 rows: forces several extends
    const int none = f.AddSeries("/empty", 0);
    f.SetAttribute("/", "format", std::string("test"));
    for (int k = 0; k < 5; ++k) {
      const double tk = 0.1 * k;
      const double row[3] = {1.0 * k, 2.0 * k, 3.0 * k};
      f.Append(t, &tk);
      f.Append(x, row);
      f.Append(none, nullptr);
      f.Flush();
    }
    EXPECT_EQ(f.rows(x), 5u);
  }
  H5File r(path, H5File::Mode::kRead);
  EXPECT_EQ(r.Shape("/time"), (std::vector<std::uint64_t>{5}));
  EXPECT_EQ(r.Shape("/state/x"), (std::vector<std::uint64_t>{5, 3}));
  EXPECT_EQ(r.Shape("/empty"), (std::vector<std::uint64_t>{5, 0}));
  const auto x = r.ReadDoubles("/state/x");
  EXPECT_DOUBLE_EQ(x[3 * 4 + 2], 12.0);
  EXPECT_DOUBLE_EQ(r.ReadDoubles("/time")[4], 0.4);
  EXPECT_EQ(r.ReadStringAttribute("/", "format"), "test");
  std::filesystem::remove(path);
}

TEST(TimeSeriesFile, UncreatableFileThrows) {
  EXPECT_THROW(TimeSeriesFile("/nonexistent-dir/x.h5"), InputError);
}

}  // namespace
}  // namespace emb

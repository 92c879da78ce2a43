// HDF5 layer: bit-for-bit round trips, attributes, listing, and errors naming the object.

#include "libemb/io/hdf5_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/io/atomic_file.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

fs::path TempPath(const std::string& name) {
  return testing::ProcessTempDir().path() / ("h5_" + name);
}

TEST(H5File, RoundTripIsBitForBit) {
  const fs::path p = TempPath("roundtrip.h5");
  std::vector<double> d(5000);
  for (size_t i = 0; i < d.size(); ++i) d[i] = std::sin(1.0 + i) * std::pow(10.0, double(i % 40) - 20);
  d[7] = std::numeric_limits<double>::denorm_min();
  d[8] = -0.0;
  const std::vector<int> ints{-3, 0, 7, 2147483647};
  {
    H5File f(p.string(), H5File::Mode::kCreate);
    f.Write("/a/b/values", d.data(), {1000, 5});
    f.Write("/ints", ints.data(), {2, 2});
    f.Write("/names", std::vector<std::string>{"main_journal_1", "flange", ""});
    f.SetAttribute("/", "format", std::string("emb.test"));
    f.SetAttribute("/a", "pi", M_PI);
    f.SetAttribute("/a/b/values", "count", 5000LL);
  }
  H5File f(p.string(), H5File::Mode::kRead);
  EXPECT_EQ(f.Shape("/a/b/values"), (std::vector<std::uint64_t>{1000, 5}));
  const std::vector<double> back = f.ReadDoubles("/a/b/values");
  ASSERT_EQ(back.size(), d.size());
  EXPECT_EQ(std::memcmp(back.data(), d.data(), sizeof(double) * d.size()), 0);
  EXPECT_EQ(f.ReadInts("/ints"), ints);
  EXPECT_EQ(f.ReadStrings("/names"), (std::vector<std::string>{"main_journal_1", "flange", ""}));
  EXPECT_EQ(f.ReadStringAttribute("/", "format"), "emb.test");
  EXPECT_EQ(f.ReadDoubleAttribute("/a", "pi"), M_PI);
  EXPECT_EQ(f.ReadIntAttribute("/a/b/values", "count"), 5000);
  EXPECT_EQ(f.List("/"), (std::vector<std::string>{"a", "ints", "names"}));
  EXPECT_TRUE(f.Exists("/a/b"));
  EXPECT_FALSE(f.Exists("/a/c/d"));
  fs::remove(p);
}

TEST(H5File, ErrorsNameTheFileAndObject) {
  const fs::path p = TempPath("errors.h5");
  { H5File f(p.string(), H5File::Mode::kCreate); }
  H5File f(p.string(), H5File::Mode::kRead);
  try {
    f.ReadDoubles("/modes/shapes");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/modes/shapes"), std::string::npos) << e.what();
  }
  EXPECT_THROW(f.ReadStringAttribute("/", "format"), InputError);
  fs::remove(p);

  const fs::path text = TempPath("not_hdf5.h5");
  std::ofstream(text) << "hello";
  EXPECT_THROW(H5File(text.string(), H5File::Mode::kRead), InputError);
  fs::remove(text);
  EXPECT_THROW(H5File(TempPath("missing.h5").string(), H5File::Mode::kRead), InputError);
}

// Strings are stored fixed-length: any content (UTF-8, long, empty) comes back unchanged.
TEST(H5File, StringsOfAnyLengthRoundTrip) {
  const fs::path p = TempPath("strings.h5");
  const std::string long_text(100000, 'k');
  const std::vector<std::string> names{"", "Kurbelwelle_\xC3\xBC", long_text, "a"};
  {
    H5File f(p.string(), H5File::Mode::kCreate);
    f.Write("/names", names);
    f.Write("/none", std::vector<std::string>{});
    f.SetAttribute("/", "empty", std::string());
    f.SetAttribute("/", "long", long_text);
  }
  H5File f(p.string(), H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStrings("/names"), names);
  EXPECT_TRUE(f.ReadStrings("/none").empty());
  EXPECT_EQ(f.ReadStringAttribute("/", "empty"), "");
  EXPECT_EQ(f.ReadStringAttribute("/", "long"), long_text);
  fs::remove(p);
}

// Variable-length strings (h5py's default) are refused by name, before HDF5's global-heap
// reader runs: a damaged heap drove that reader into an endless loop (fuzz_body_file).
TEST(H5File, VariableLengthStringsAreRefusedByName) {
  const fs::path p = TempPath("vlen.h5");
  {
    const hid_t file = H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const char* text = "emb.body";
    const hid_t attr = H5Acreate2(file, "format", type, scalar, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(H5Awrite(attr, type, &text), 0);
    const hsize_t two = 2;
    const hid_t space = H5Screate_simple(1, &two, nullptr);
    const char* names[] = {"x0", "x1"};
    const hid_t ds = H5Dcreate2(file, "names", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, names), 0);
    for (hid_t id : {ds, space, attr, scalar}) H5Idec_ref(id);
    H5Tclose(type);
    H5Fclose(file);
  }
  H5File f(p.string(), H5File::Mode::kRead);
  for (const auto& read : std::vector<std::function<void()>>{
           [&] { f.ReadStringAttribute("/", "format"); }, [&] { f.ReadStrings("/names"); }}) {
    try {
      read();
      FAIL() << "a variable-length string was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("variable-length string"), std::string::npos)
          << e.what();
    }
  }
  fs::remove(p);
}

TEST(AtomicFile, NothingAppearsUnlessCommitted) {
  const fs::path p = TempPath("atomic.txt");
  {
    AtomicFile f(p.string());
    std::ofstream(f.temp_path()) << "partial";
    // no Commit(): e.g. an exception unwound the writer
  }
  EXPECT_FALSE(fs::exists(p));
  WriteTextFileAtomic(p.string(), "complete");
  std::ifstream in(p);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "complete");
  fs::remove(p);
  EXPECT_THROW(AtomicFile("/nonexistent_dir_emb/x.h5"), InputError);
}

}  // namespace
}  // namespace emb

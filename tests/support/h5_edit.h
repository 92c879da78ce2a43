#pragma once
// Edits an HDF5 file in place as an editor (or a disk error) would, for the tests that a
// reader refuses a modified file (test support).

#include <gtest/gtest.h>
#include <hdf5.h>

#include <string>
#include <vector>

namespace emb {

// Changes entry `index` of dataset `name` in place, as an editor (or a disk error) would: scales
// it by `factor` (a float32 dataset needs a change larger than its rounding, 2^-24).
inline void ChangeOneEntry(const std::string& path, const char* name, std::size_t index,
                           double factor = 1.0 + 1e-12) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t ds = H5Dopen2(file, name, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  const hid_t space = H5Dget_space(ds);
  std::vector<double> v(H5Sget_simple_extent_npoints(space));
  H5Sclose(space);
  ASSERT_LT(index, v.size());
  ASSERT_GE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  v[index] *= factor;
  ASSERT_GE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  H5Dclose(ds);
  H5Fclose(file);
}

}  // namespace emb

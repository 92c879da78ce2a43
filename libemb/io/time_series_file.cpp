#include "libemb/io/time_series_file.h"

#include <hdf5.h>

#include "libemb/common/error.h"
#include "libemb/io/h5_strings.h"

namespace emb {
namespace {

void Check(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0)
    EMB_THROW(InputError, "HDF5 file '" << file << "': " << what
                                        << " failed (disk full, I/O error or file removed?)");
}

hid_t CheckId(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) EMB_THROW(InputError, "HDF5 file '" << file << "': " << what << " failed");
  return id;
}

// Closes an HDF5 id at scope exit.
struct Closer {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Closer() {
    if (id >= 0) close(id);
  }
};

hid_t LinkProps() {
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  return lcpl;
}

}  // namespace

TimeSeriesFile::TimeSeriesFile(const std::string& path) : path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Closer fapl{h5::NewFileAccessProps(), H5Pclose};
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.id);
  EMB_THROW_IF(file_ < 0, "HDF5 file '" << path << "' cannot be created (directory? permissions?)");
}

TimeSeriesFile::~TimeSeriesFile() {
  // An error path (Close() was not reached): close without reporting, the failure that led
  // here was reported already.
  for (auto& s : series_)
    if (s.dataset >= 0) H5Dclose(s.dataset);
  if (file_ >= 0) H5Fclose(file_);
}

void TimeSeriesFile::Close() {
  bool ok = true;
  for (auto& s : series_) {
    if (s.dataset >= 0) ok = H5Dclose(s.dataset) >= 0 && ok;
    s.dataset = -1;
  }
  const hid_t f = file_;
  file_ = -1;
  if (f >= 0) ok = H5Fclose(f) >= 0 && ok;
  EMB_THROW_IF(!ok, "HDF5 file '" << path_ << "': closing failed (disk full or I/O error?)");
}

int TimeSeriesFile::AddSeries(const std::string& path, int width, int chunk_rows) {
  return Create(path, width, false, chunk_rows);
}

int TimeSeriesFile::AddScalarSeries(const std::string& path, int chunk_rows) {
  return Create(path, 1, true, chunk_rows);
}

int TimeSeriesFile::Create(const std::string& path, int width, bool scalar, int chunk_rows) {
  EMB_CHECK(width >= 0 && chunk_rows > 0);
  const int rank = scalar ? 1 : 2;
  const hsize_t dims[2] = {0, static_cast<hsize_t>(width)};
  // A zero-width row set still gets a chunkable (unlimited) second dimension.
  const hsize_t maxdims[2] = {H5S_UNLIMITED,
                              width > 0 ? static_cast<hsize_t>(width) : H5S_UNLIMITED};
  const hsize_t chunk[2] = {static_cast<hsize_t>(chunk_rows),
                            static_cast<hsize_t>(std::max(width, 1))};
  Closer space{CheckId(H5Screate_simple(rank, dims, maxdims), path_, "dataspace " + path),
               H5Sclose};
  Closer dcpl{H5Pcreate(H5P_DATASET_CREATE), H5Pclose};
  Check(H5Pset_chunk(dcpl.id, rank, chunk), path_, "chunking " + path);
  H5Pset_obj_track_times(dcpl.id, 0);
  Closer lcpl{LinkProps(), H5Pclose};
  Series s;
  s.path = path;
  s.width = width;
  s.scalar = scalar;
  s.dataset = CheckId(
      H5Dcreate2(file_, path.c_str(), H5T_IEEE_F64LE, space.id, lcpl.id, dcpl.id, H5P_DEFAULT),
      path_, "creating dataset " + path);
  series_.push_back(s);
  return static_cast<int>(series_.size()) - 1;
}

void TimeSeriesFile::Append(int handle, const double* row) {
  EMB_CHECK(handle >= 0 && handle < static_cast<int>(series_.size()) && file_ >= 0);
  Series& s = series_[handle];
  const int rank = s.scalar ? 1 : 2;
  const hsize_t new_dims[2] = {s.rows + 1, static_cast<hsize_t>(s.width)};
  Check(H5Dset_extent(s.dataset, new_dims), path_, "extending " + s.path);
  if (s.width == 0) {
    ++s.rows;
    return;
  }
  Closer fspace{CheckId(H5Dget_space(s.dataset), path_, "dataspace of " + s.path), H5Sclose};
  const hsize_t start[2] = {s.rows, 0};
  const hsize_t count[2] = {1, static_cast<hsize_t>(s.width)};
  Check(H5Sselect_hyperslab(fspace.id, H5S_SELECT_SET, start, nullptr, count, nullptr), path_,
        "selecting a row of " + s.path);
  Closer mspace{CheckId(H5Screate_simple(rank, count, nullptr), path_, "row dataspace"), H5Sclose};
  Check(H5Dwrite(s.dataset, H5T_NATIVE_DOUBLE, mspace.id, fspace.id, H5P_DEFAULT, row), path_,
        "appending to " + s.path);
  ++s.rows;
}

void TimeSeriesFile::Flush() {
  EMB_CHECK(file_ >= 0);
  Check(H5Fflush(file_, H5F_SCOPE_GLOBAL), path_, "flush");
}

void TimeSeriesFile::EnsureGroup(const std::string& object) {
  if (object == "/" || H5Lexists(file_, object.c_str(), H5P_DEFAULT) > 0) return;
  Closer lcpl{LinkProps(), H5Pclose};
  Closer g{CheckId(H5Gcreate2(file_, object.c_str(), lcpl.id, H5P_DEFAULT, H5P_DEFAULT), path_,
                   "creating group " + object),
           H5Gclose};
}

void TimeSeriesFile::WriteDoubles(const std::string& path, const std::vector<double>& data,
                                  const std::vector<std::uint64_t>& dims) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  Closer space{CheckId(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), path_,
                       "dataspace " + path),
               H5Sclose};
  Closer lcpl{LinkProps(), H5Pclose};
  Closer ds{CheckId(H5Dcreate2(file_, path.c_str(), H5T_IEEE_F64LE, space.id, lcpl.id, H5P_DEFAULT,
                               H5P_DEFAULT),
                    path_, "creating dataset " + path),
            H5Dclose};
  if (!data.empty())
    Check(H5Dwrite(ds.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), path_,
          "writing " + path);
}

void TimeSeriesFile::WriteStrings(const std::string& path,
                                  const std::vector<std::string>& strings) {
  std::size_t width = 0;
  const std::vector<char> packed = h5::PackFixed(strings, &width);
  Closer type{h5::NewFixedStringType(width), H5Tclose};
  const hsize_t n = strings.size();
  Closer space{CheckId(H5Screate_simple(1, &n, nullptr), path_, "dataspace " + path), H5Sclose};
  Closer lcpl{LinkProps(), H5Pclose};
  Closer ds{
      CheckId(H5Dcreate2(file_, path.c_str(), type.id, space.id, lcpl.id, H5P_DEFAULT, H5P_DEFAULT),
              path_, "creating dataset " + path),
      H5Dclose};
  if (!strings.empty())
    Check(H5Dwrite(ds.id, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()), path_,
          "writing " + path);
}

namespace {
void WriteAttr(hid_t file, const std::string& fname, const std::string& object,
               const std::string& name, hid_t type, const void* value) {
  Closer obj{CheckId(H5Oopen(file, object.c_str(), H5P_DEFAULT), fname, "opening " + object),
             H5Oclose};
  if (H5Aexists(obj.id, name.c_str()) > 0) H5Adelete(obj.id, name.c_str());
  Closer space{H5Screate(H5S_SCALAR), H5Sclose};
  Closer attr{CheckId(H5Acreate2(obj.id, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT),
                      fname, "attribute " + name + " on " + object),
              H5Aclose};
  Check(H5Awrite(attr.id, type, value), fname, "writing attribute " + name);
}
}  // namespace

void TimeSeriesFile::SetAttribute(const std::string& object, const std::string& name,
                                  const std::string& value) {
  EnsureGroup(object);
  std::size_t width = 0;
  const std::vector<char> packed = h5::PackFixed({value}, &width);
  Closer type{h5::NewFixedStringType(width), H5Tclose};
  WriteAttr(file_, path_, object, name, type.id, packed.data());
}

void TimeSeriesFile::SetAttribute(const std::string& object, const std::string& name,
                                  double value) {
  EnsureGroup(object);
  WriteAttr(file_, path_, object, name, H5T_NATIVE_DOUBLE, &value);
}

void TimeSeriesFile::SetAttribute(const std::string& object, const std::string& name,
                                  long long value) {
  EnsureGroup(object);
  WriteAttr(file_, path_, object, name, H5T_NATIVE_LLONG, &value);
}

std::uint64_t TimeSeriesFile::rows(int handle) const {
  EMB_CHECK(handle >= 0 && handle < static_cast<int>(series_.size()));
  return series_[handle].rows;
}

}  // namespace emb

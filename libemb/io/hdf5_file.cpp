#include "libemb/io/hdf5_file.h"

#include <H5PLpublic.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "libemb/common/error.h"
#include "libemb/io/h5_strings.h"

namespace emb {
namespace {

// Owns one HDF5 identifier and closes it with the matching function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void SilenceHdf5() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

void Check(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0)
    EMB_THROW(InputError, "HDF5 file '" << file << "': " << what
                                        << " failed (disk full, I/O error or a damaged file?)");
}

hid_t CheckId(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) EMB_THROW(InputError, "HDF5 file '" << file << "': " << what << " failed");
  return id;
}

Handle LinkCreateProps() {
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.get(), 1);
  H5Pset_char_encoding(lcpl.get(), H5T_CSET_UTF8);
  return lcpl;
}

// A fixed-length string type (libemb/io/h5_strings.h says why never variable-length).
Handle FixedString(std::size_t bytes) { return Handle(h5::NewFixedStringType(bytes), H5Tclose); }

}  // namespace

H5File::H5File(const std::string& path, Mode mode) : path_(path) {
  SilenceHdf5();
  if (mode == Mode::kCreate) {
    Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    Handle fapl(h5::NewFileAccessProps(), H5Pclose);
    id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
    EMB_THROW_IF(id_ < 0, "HDF5 file '" << path << "' cannot be created (directory? permissions?)");
  } else {
    std::error_code ec;
    EMB_THROW_IF(!std::filesystem::exists(path, ec), "file '" << path << "' does not exist");
    // A FIFO or device would stall or never end.
    EMB_THROW_IF(!std::filesystem::is_regular_file(path, ec),
                 "file '" << path << "' is not a regular file; expected an HDF5 file");
    EMB_THROW_IF(H5Fis_hdf5(path.c_str()) <= 0, "file '" << path << "' is not an HDF5 file");
    // Filters are decoded only by what HDF5 has built in: a dataset must not make emb load
    // a shared library from HDF5_PLUGIN_PATH.
    H5PLset_loading_state(0);
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EMB_THROW_IF(id_ < 0, "HDF5 file '" << path << "' cannot be opened");
    file_size_ = std::filesystem::file_size(path, ec);
    RefuseForeignStorage();
  }
}

namespace {

// What H5File refuses in a file it reads: links to other files, and datasets whose data
// live in other files (external storage, virtual datasets). Through them a crafted file
// would make emb read files it was not given.
struct ForeignStorage {
  std::string found;  // "<path>: <what>", empty if none
};

herr_t VisitLink(hid_t, const char* name, const H5L_info_t* info, void* data) {
  auto* f = static_cast<ForeignStorage*>(data);
  if (info->type == H5L_TYPE_EXTERNAL) {
    f->found = std::string("/") + name + ": an external link (to another file)";
    return 1;
  }
  if (info->type != H5L_TYPE_HARD && info->type != H5L_TYPE_SOFT) {
    f->found = std::string("/") + name + ": a user-defined link";
    return 1;
  }
  return 0;
}

herr_t VisitObject(hid_t loc, const char* name, const H5O_info_t* info, void* data) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  auto* f = static_cast<ForeignStorage*>(data);
  const hid_t ds = H5Dopen2(loc, name, H5P_DEFAULT);
  if (ds < 0) {
    f->found = std::string("/") + name + ": a dataset that cannot be opened";
    return 1;
  }
  const hid_t dcpl = H5Dget_create_plist(ds);
  const H5D_layout_t layout = dcpl >= 0 ? H5Pget_layout(dcpl) : H5D_LAYOUT_ERROR;
  const int external = dcpl >= 0 ? H5Pget_external_count(dcpl) : -1;
  if (dcpl >= 0) H5Pclose(dcpl);
  H5Dclose(ds);
  if (layout == H5D_VIRTUAL)
    f->found = std::string("/") + name + ": a virtual dataset (data mapped from other files)";
  else if (external != 0)
    f->found = std::string("/") + name + ": a dataset stored in external files";
  else if (layout == H5D_LAYOUT_ERROR)
    f->found = std::string("/") + name + ": a dataset of unknown layout";
  return f->found.empty() ? 0 : 1;
}

}  // namespace

void H5File::RefuseForeignStorage() const {
  ForeignStorage f;
  const herr_t links = H5Lvisit(id_, H5_INDEX_NAME, H5_ITER_NATIVE, VisitLink, &f);
  if (f.found.empty() && links >= 0)
    H5Ovisit2(id_, H5_INDEX_NAME, H5_ITER_NATIVE, VisitObject, &f, H5O_INFO_BASIC);
  EMB_THROW_IF(!f.found.empty(), "HDF5 file '" << path_ << "': " << f.found
                                                << "; emb reads only data stored in the file "
                                                   "itself (README: Files from others)");
  EMB_THROW_IF(links < 0, "HDF5 file '" << path_ << "': its links cannot be listed (damaged?)");
}

H5File::~H5File() {
  if (id_ >= 0) H5Fclose(id_);  // an error path: the failure was reported already
}

void H5File::Close() {
  const hid_t id = id_;
  id_ = -1;
  if (id >= 0) Check(H5Fclose(id), path_, "closing (data may not have reached the disk)");
}

void DisableHdf5ExitCleanup() { H5dont_atexit(); }

namespace {

void WriteRaw(hid_t file, const std::string& fname, const std::string& path, hid_t file_type,
              hid_t mem_type, const void* data, const std::vector<std::uint64_t>& dims,
              bool compress) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  Handle space(CheckId(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), fname,
                       "dataspace for " + path),
               H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(dcpl.get(), 0);  // reproducible files: no time stamps
  const hsize_t total = std::accumulate(d.begin(), d.end(), hsize_t{1}, std::multiplies<>());
  if (compress && total >= 4096 && !d.empty()) {
    // Chunks of whole trailing rows, about 1 MiB each.
    std::vector<hsize_t> chunk = d;
    const hsize_t row = total / std::max<hsize_t>(d[0], 1);
    chunk[0] = std::clamp<hsize_t>((1 << 17) / std::max<hsize_t>(row, 1), 1, d[0]);
    Check(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()), fname,
          "chunking " + path);
    Check(H5Pset_deflate(dcpl.get(), 4), fname, "compression of " + path);
  }
  Handle lcpl = LinkCreateProps();
  Handle ds(CheckId(H5Dcreate2(file, path.c_str(), file_type, space.get(), lcpl.get(), dcpl.get(),
                               H5P_DEFAULT),
                    fname, "creating dataset " + path),
            H5Dclose);
  if (total > 0)
    Check(H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), fname,
          "writing dataset " + path);
}

}  // namespace

void H5File::Write(const std::string& path, const double* data,
                   const std::vector<std::uint64_t>& dims) {
  WriteRaw(id_, path_, path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, dims, false);
}
void H5File::Write(const std::string& path, const float* data,
                   const std::vector<std::uint64_t>& dims) {
  WriteRaw(id_, path_, path, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, data, dims, false);
}
void H5File::Write(const std::string& path, const int* data,
                   const std::vector<std::uint64_t>& dims) {
  WriteRaw(id_, path_, path, H5T_STD_I32LE, H5T_NATIVE_INT, data, dims, true);
}
void H5File::Write(const std::string& path, const std::uint64_t* data,
                   const std::vector<std::uint64_t>& dims) {
  WriteRaw(id_, path_, path, H5T_STD_U64LE, H5T_NATIVE_UINT64, data, dims, true);
}
void H5File::Write(const std::string& path, const std::vector<std::string>& strings) {
  std::size_t width = 0;
  const std::vector<char> packed = h5::PackFixed(strings, &width);
  Handle t = FixedString(width);
  WriteRaw(id_, path_, path, t.get(), t.get(), packed.data(), {strings.size()}, true);
}

namespace {

// Opens an object, creating it as a group (with parents) if it does not exist.
Handle OpenOrCreateObject(hid_t file, const std::string& fname, const std::string& object) {
  if (object != "/" && H5Lexists(file, object.c_str(), H5P_DEFAULT) <= 0) {
    Handle lcpl = LinkCreateProps();
    Handle g(CheckId(H5Gcreate2(file, object.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
                     fname, "creating group " + object),
             H5Gclose);
  }
  return Handle(CheckId(H5Oopen(file, object.c_str(), H5P_DEFAULT), fname, "opening " + object),
                H5Oclose);
}

void WriteAttribute(hid_t file, const std::string& fname, const std::string& object,
                    const std::string& name, hid_t type, const void* value) {
  Handle obj = OpenOrCreateObject(file, fname, object);
  if (H5Aexists(obj.get(), name.c_str()) > 0) H5Adelete(obj.get(), name.c_str());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(CheckId(H5Acreate2(obj.get(), name.c_str(), type, space.get(), H5P_DEFAULT,
                                 H5P_DEFAULT),
                      fname, "creating attribute " + object + "@" + name),
              H5Aclose);
  Check(H5Awrite(attr.get(), type, value), fname, "writing attribute " + object + "@" + name);
}

Handle OpenAttribute(hid_t file, const std::string& fname, const std::string& object,
                     const std::string& name) {
  EMB_THROW_IF(object != "/" && H5Lexists(file, object.c_str(), H5P_DEFAULT) <= 0,
               "HDF5 file '" << fname << "': expected object '" << object << "', not found");
  Handle obj(CheckId(H5Oopen(file, object.c_str(), H5P_DEFAULT), fname, "opening " + object),
             H5Oclose);
  EMB_THROW_IF(H5Aexists(obj.get(), name.c_str()) <= 0,
               "HDF5 file '" << fname << "': expected attribute '" << name << "' on '" << object
                             << "', not found");
  Handle attr(CheckId(H5Aopen(obj.get(), name.c_str(), H5P_DEFAULT), fname,
                      "opening attribute " + object + "@" + name),
              H5Aclose);
  // Every attribute emb reads is one value: reading an array into one would overrun it.
  Handle space(H5Aget_space(attr.get()), H5Sclose);
  EMB_THROW_IF(H5Sget_simple_extent_npoints(space.get()) != 1,
               "HDF5 file '" << fname << "': attribute " << object << "@" << name
                             << ": expected a single value, got "
                             << H5Sget_simple_extent_npoints(space.get()));
  return attr;
}

}  // namespace

void H5File::SetAttribute(const std::string& object, const std::string& name,
                          const std::string& value) {
  std::size_t width = 0;
  const std::vector<char> packed = h5::PackFixed({value}, &width);
  Handle t = FixedString(width);
  WriteAttribute(id_, path_, object, name, t.get(), packed.data());
}
void H5File::SetAttribute(const std::string& object, const std::string& name, double value) {
  WriteAttribute(id_, path_, object, name, H5T_NATIVE_DOUBLE, &value);
}
void H5File::SetAttribute(const std::string& object, const std::string& name, long long value) {
  WriteAttribute(id_, path_, object, name, H5T_NATIVE_LLONG, &value);
}

bool H5File::Exists(const std::string& path) const {
  // Check each prefix: H5Lexists fails on a missing intermediate group.
  std::string prefix;
  size_t pos = 1;
  while (pos <= path.size()) {
    const size_t next = path.find('/', pos);
    prefix = path.substr(0, next);
    if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return true;
}

bool H5File::HasAttribute(const std::string& object, const std::string& name) const {
  if (object != "/" && !Exists(object)) return false;
  return H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::uint64_t> H5File::Shape(const std::string& path) const {
  EMB_THROW_IF(!Exists(path), "HDF5 file '" << path_ << "': expected dataset '" << path
                                            << "', not found");
  Handle ds(CheckId(H5Dopen2(id_, path.c_str(), H5P_DEFAULT), path_, "opening " + path), H5Dclose);
  Handle space(H5Dget_space(ds.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> d(std::max(rank, 0));
  H5Sget_simple_extent_dims(space.get(), d.data(), nullptr);
  return {d.begin(), d.end()};
}

namespace {
// A dataset may be compressed, so its size is not bounded by the file's; a crafted file could
// claim any size. Reads are limited to the larger of 1 GiB and 64 times the file's size.
constexpr std::uint64_t kMinReadLimitBytes = std::uint64_t{1} << 30;
constexpr std::uint64_t kReadLimitPerFileByte = 64;

template <typename T>
std::vector<T> ReadAll(hid_t file, const std::string& fname, const std::string& path,
                       hid_t mem_type, const std::vector<std::uint64_t>& shape,
                       std::uintmax_t file_size) {
  const std::uint64_t limit =
      std::max<std::uint64_t>(kMinReadLimitBytes, kReadLimitPerFileByte * file_size) / sizeof(T);
  std::uint64_t total = 1;
  for (std::uint64_t d : shape) {
    EMB_THROW_IF(d != 0 && total > limit / d,
                 "HDF5 file '" << fname << "': dataset " << path << " claims more than " << limit
                               << " values, more than the file can hold; the file is damaged");
    total *= d;
  }
  std::vector<T> out(total);
  Handle ds(CheckId(H5Dopen2(file, path.c_str(), H5P_DEFAULT), fname, "opening " + path),
            H5Dclose);
  if (total > 0)
    Check(H5Dread(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), fname,
          "reading " + path);
  return out;
}
}  // namespace

std::vector<double> H5File::ReadDoubles(const std::string& path) const {
  return ReadAll<double>(id_, path_, path, H5T_NATIVE_DOUBLE, Shape(path), file_size_);
}
std::vector<float> H5File::ReadFloats(const std::string& path) const {
  return ReadAll<float>(id_, path_, path, H5T_NATIVE_FLOAT, Shape(path), file_size_);
}
std::vector<int> H5File::ReadInts(const std::string& path) const {
  return ReadAll<int>(id_, path_, path, H5T_NATIVE_INT, Shape(path), file_size_);
}
std::vector<std::string> H5File::ReadStrings(const std::string& path) const {
  const auto shape = Shape(path);
  Handle ds(CheckId(H5Dopen2(id_, path.c_str(), H5P_DEFAULT), path_, "opening " + path),
            H5Dclose);
  Handle ftype(H5Dget_type(ds.get()), H5Tclose);
  const std::size_t n = h5::FixedStringWidth(ftype.get(), path_, "dataset " + path);
  std::vector<std::uint64_t> bytes_shape = shape;
  bytes_shape.push_back(n);  // ReadAll bounds the total against the file's size
  Handle t(h5::NewReadStringType(ftype.get()), H5Tclose);
  return h5::UnpackFixed(ReadAll<char>(id_, path_, path, t.get(), bytes_shape, file_size_), n);
}

std::string H5File::ReadStringAttribute(const std::string& object, const std::string& name) const {
  Handle attr = OpenAttribute(id_, path_, object, name);
  Handle ftype(H5Aget_type(attr.get()), H5Tclose);
  const std::size_t n = h5::FixedStringWidth(ftype.get(), path_, "attribute " + object + "@" + name);
  Handle t(h5::NewReadStringType(ftype.get()), H5Tclose);
  std::vector<char> bytes(n, '\0');
  Check(H5Aread(attr.get(), t.get(), bytes.data()), path_, "reading attribute " + name);
  return h5::UnpackFixed(bytes, n).front();
}

double H5File::ReadDoubleAttribute(const std::string& object, const std::string& name) const {
  Handle attr = OpenAttribute(id_, path_, object, name);
  double v = 0.0;
  Check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v), path_, "reading attribute " + name);
  return v;
}

long long H5File::ReadIntAttribute(const std::string& object, const std::string& name) const {
  Handle attr = OpenAttribute(id_, path_, object, name);
  long long v = 0;
  Check(H5Aread(attr.get(), H5T_NATIVE_LLONG, &v), path_, "reading attribute " + name);
  return v;
}

std::vector<std::string> H5File::List(const std::string& group) const {
  std::vector<std::string> names;
  EMB_THROW_IF(group != "/" && !Exists(group),
               "HDF5 file '" << path_ << "': expected group '" << group << "', not found");
  Handle g(CheckId(H5Gopen2(id_, group.c_str(), H5P_DEFAULT), path_, "opening group " + group),
           H5Gclose);
  H5G_info_t info;
  Check(H5Gget_info(g.get(), &info), path_, "listing " + group);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0,
                                           H5P_DEFAULT);
    std::string name(static_cast<size_t>(std::max<ssize_t>(len, 0)), '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size() + 1,
                       H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

void H5File::Flush() { Check(H5Fflush(id_, H5F_SCOPE_GLOBAL), path_, "flush"); }

}  // namespace emb

#pragma once
/// @file
/// A small RAII layer over the HDF5 C API: files, groups (created on demand from '/'-paths),
/// datasets of doubles/ints/strings with their shapes, and attributes.
/// Every HDF5 return code is checked; a failure throws InputError naming the file and object.
/// Datasets are C-ordered (row-major) as h5py/numpy see them.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace emb {

/// Keeps HDF5 from closing files itself at process exit. Call first thing in main(), before
/// any other HDF5 call. emb closes every file it opens and checks the result; HDF5 1.10's
/// exit-time clean-up of a file whose close failed (a full disk) crashes the process.
void DisableHdf5ExitCleanup();

class H5File {
 public:
  enum class Mode { kCreate, kRead };
  /// kCreate truncates/creates `path`; kRead opens it read-only, refusing a file that links
  /// to other files: external links, user-defined links, datasets with external storage and
  /// virtual datasets (a crafted file would make emb read files it was not given). Dynamic
  /// filter plugins are not loaded.
  /// @throws InputError if the file cannot be created, is not an HDF5 file, or holds any of
  ///         the above (naming the object).
  H5File(const std::string& path, Mode mode);
  ~H5File();
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  /// Writes a dataset at `path` (e.g. "/modes/shapes"), creating parent groups.
  /// `dims` is the C-order shape; data holds prod(dims) values. Large integer datasets
  /// (connectivity, tags) are chunked and compressed (deflate level 4); floating-point ones are
  /// stored plain: deflate shrank the inline-4 crank's 120 MB of mode shapes by 4 % at the
  /// cost of ~4 s of the reduction's write (and the same again to read them back).
  void Write(const std::string& path, const double* data, const std::vector<std::uint64_t>& dims);
  /// Single precision (IEEE binary32): for large data whose precision needs are far below a
  /// double's (e.g. the whole-surface modal stresses, cms/surface_stress.h).
  void Write(const std::string& path, const float* data, const std::vector<std::uint64_t>& dims);
  void Write(const std::string& path, const int* data, const std::vector<std::uint64_t>& dims);
  void Write(const std::string& path, const std::uint64_t* data,
             const std::vector<std::uint64_t>& dims);
  void Write(const std::string& path, const std::vector<std::string>& strings);

  /// Attributes on an object (group or dataset; "/" is the root), created on demand for groups.
  void SetAttribute(const std::string& object, const std::string& name, const std::string& value);
  void SetAttribute(const std::string& object, const std::string& name, double value);
  void SetAttribute(const std::string& object, const std::string& name, long long value);

  bool Exists(const std::string& path) const;
  /// True if `object` exists and has the attribute `name`.
  bool HasAttribute(const std::string& object, const std::string& name) const;
  /// Shape of a dataset. @throws InputError if missing.
  std::vector<std::uint64_t> Shape(const std::string& path) const;
  std::vector<double> ReadDoubles(const std::string& path) const;
  std::vector<int> ReadInts(const std::string& path) const;
  /// The values as floats (a double dataset is rounded by HDF5's conversion).
  std::vector<float> ReadFloats(const std::string& path) const;
  std::vector<std::string> ReadStrings(const std::string& path) const;
  std::string ReadStringAttribute(const std::string& object, const std::string& name) const;
  double ReadDoubleAttribute(const std::string& object, const std::string& name) const;
  long long ReadIntAttribute(const std::string& object, const std::string& name) const;
  /// Names of the members of a group.
  std::vector<std::string> List(const std::string& group) const;

  /// Flushes buffers to disk (for long runs that append as they go).
  void Flush();
  /// Closes the file, writing what HDF5 still buffers. Call it before using a written file
  /// (e.g. before AtomicFile::Commit): the destructor closes too but cannot report a failure.
  /// @throws InputError if the close fails (disk full, I/O error); the file is then invalid.
  void Close();
  const std::string& path() const { return path_; }

 private:
  void RefuseForeignStorage() const;
  std::string path_;
  std::int64_t id_{-1};
  std::uintmax_t file_size_{0};  ///< of a file opened for reading
};

}  // namespace emb

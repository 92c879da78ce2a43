#pragma once
/// @file
/// An HDF5 file that grows as a run goes: fixed-width rows appended to chunked, extendable
/// datasets, flushed after every append so an interrupted or failed run keeps every row
/// written before. Static datasets and attributes go through the same file (H5File-like
/// calls). Every HDF5 return code is checked; failures throw InputError naming the file and
/// dataset.

#include <cstdint>
#include <string>
#include <vector>

namespace emb {

class TimeSeriesFile {
 public:
  /// Creates (truncates) `path`. @throws InputError if it cannot be created.
  explicit TimeSeriesFile(const std::string& path);
  ~TimeSeriesFile();
  TimeSeriesFile(const TimeSeriesFile&) = delete;
  TimeSeriesFile& operator=(const TimeSeriesFile&) = delete;

  /// Declares an extendable dataset of rows of `width` >= 0 doubles (shape [0, width]),
  /// chunked by `chunk_rows` rows. Parent groups are created. Returns a handle for Append.
  int AddSeries(const std::string& path, int width, int chunk_rows = 256);
  /// Declares an extendable dataset of scalars (shape [0]).
  int AddScalarSeries(const std::string& path, int chunk_rows = 256);
  /// Appends one row (width values; one value for a scalar series; nothing is read for
  /// width 0) to series `handle`.
  void Append(int handle, const double* row);
  /// Writes everything buffered by HDF5 to disk.
  void Flush();
  /// Closes the file (datasets first). The destructor closes too but cannot report a
  /// failure; call Close() at the end of a run. @throws InputError if a close fails.
  void Close();

  /// Static content.
  void WriteDoubles(const std::string& path, const std::vector<double>& data,
                    const std::vector<std::uint64_t>& dims);
  void WriteStrings(const std::string& path, const std::vector<std::string>& strings);
  void SetAttribute(const std::string& object, const std::string& name, const std::string& value);
  void SetAttribute(const std::string& object, const std::string& name, double value);
  void SetAttribute(const std::string& object, const std::string& name, long long value);

  /// Rows appended so far to a series.
  std::uint64_t rows(int handle) const;
  const std::string& path() const { return path_; }

 private:
  struct Series {
    std::string path;
    std::int64_t dataset{-1};
    int width{0};
    bool scalar{false};
    std::uint64_t rows{0};
  };
  void EnsureGroup(const std::string& object);
  int Create(const std::string& path, int width, bool scalar, int chunk_rows);
  std::string path_;
  std::int64_t file_{-1};
  std::vector<Series> series_;
};

}  // namespace emb

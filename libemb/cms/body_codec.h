#pragma once
/// @file
/// Internal to the body file (body_file.cpp and the optional groups it writes through other
/// files, e.g. modal_stress.cpp): one code path that writes or reads the numeric datasets of a
/// body and digests their bytes, so that writer and reader cover the same bytes in the same
/// order (the @content_digest of body_file.h).

#include <array>
#include <cstdio>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "libemb/common/error.h"
#include "libemb/common/fnv1a.h"
#include "libemb/io/hdf5_file.h"

namespace emb::body_codec {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;


// FNV-1a over the bytes of the datasets, in the order they are written/read.
using Digest = Fnv1a;

// Writes/reads the numeric datasets of a body through one code path, so the digest of the
// writer and the reader cover the same bytes in the same order.
class Codec {
 public:
  Codec(H5File& h5, bool writing) : h5_(h5), writing_(writing) {}

  // A matrix stored as `Stored` (double, or float for large data of low precision needs: the
  // digest covers the stored values); reading gives them back as doubles.
  template <typename Stored = double>
  void Matrix(const std::string& path, Eigen::MatrixXd& A) {
    using Rows = Eigen::Matrix<Stored, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    if (writing_) {
      const Rows r = A.cast<Stored>();
      h5_.Write(path, r.data(), {std::uint64_t(A.rows()), std::uint64_t(A.cols())});
      digest_.Add(r.data(), sizeof(Stored) * r.size());
      return;
    }
    const auto shape = h5_.Shape(path);
    EMB_THROW_IF(shape.size() != 2, "'" << h5_.path() << "': " << path
                                        << ": expected a 2-D dataset, got " << shape.size()
                                        << " dimensions");
    std::vector<Stored> v;
    if constexpr (std::is_same_v<Stored, float>)
      v = h5_.ReadFloats(path);
    else
      v = h5_.ReadDoubles(path);
    A = Eigen::Map<const Rows>(v.data(), shape[0], shape[1]).template cast<double>();
    digest_.Add(v.data(), sizeof(Stored) * v.size());
  }
  void Vector(const std::string& path, Eigen::VectorXd& x) {
    if (writing_) {
      h5_.Write(path, x.data(), {std::uint64_t(x.size())});
      digest_.Add(x.data(), sizeof(double) * x.size());
      return;
    }
    const std::vector<double> v = h5_.ReadDoubles(path);
    x = Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    digest_.Add(v.data(), sizeof(double) * v.size());
  }
  void Ints(const std::string& path, std::vector<int>& v) {
    if (writing_)
      h5_.Write(path, v.data(), {std::uint64_t(v.size())});
    else
      v = h5_.ReadInts(path);
    digest_.Add(v.data(), sizeof(int) * v.size());
  }
  // An integer table of `cols` columns as a (rows, cols) dataset (e.g. face connectivity).
  void IntTable(const std::string& path, std::vector<int>& v, std::uint64_t cols) {
    if (writing_) {
      EMB_CHECK(cols > 0 && v.size() % cols == 0);
      h5_.Write(path, v.data(), {std::uint64_t(v.size()) / cols, cols});
    } else {
      const auto shape = h5_.Shape(path);
      EMB_THROW_IF(shape.size() != 2 || shape[1] != cols,
                   "'" << h5_.path() << "': " << path << ": expected a (rows, " << cols
                       << ") dataset");
      v = h5_.ReadInts(path);
    }
    digest_.Add(v.data(), sizeof(int) * v.size());
  }
  // k matrices of one size as a (k, rows, cols) dataset.
  template <std::size_t k>
  void Stack(const std::string& path, std::array<Eigen::MatrixXd, k>& A) {
    if (writing_) {
      const std::uint64_t rows = A[0].rows(), cols = A[0].cols();
      std::vector<double> v;
      v.reserve(k * rows * cols);
      for (const auto& a : A) {
        EMB_CHECK(std::uint64_t(a.rows()) == rows && std::uint64_t(a.cols()) == cols);
        const RowMajor r = a;
        v.insert(v.end(), r.data(), r.data() + r.size());
      }
      h5_.Write(path, v.data(), {std::uint64_t(k), rows, cols});
      digest_.Add(v.data(), sizeof(double) * v.size());
      return;
    }
    const auto shape = h5_.Shape(path);
    EMB_THROW_IF(shape.size() != 3 || shape[0] != k,
                 "'" << h5_.path() << "': " << path << ": expected a (" << k
                     << ", rows, cols) dataset, got " << shape.size() << " dimensions");
    const std::vector<double> v = h5_.ReadDoubles(path);
    const std::size_t block = shape[1] * shape[2];
    for (std::size_t i = 0; i < k; ++i)
      A[i] = Eigen::Map<const RowMajor>(v.data() + i * block, shape[1], shape[2]);
    digest_.Add(v.data(), sizeof(double) * v.size());
  }
  void Scalar(const std::string& object, const std::string& name, double& x) {
    if (writing_)
      h5_.SetAttribute(object, name, x);
    else
      x = h5_.ReadDoubleAttribute(object, name);
    digest_.Add(&x, sizeof x);
  }
  // Metadata covered by the digest (format version 2): text and numbers, length-prefixed so
  // that "ab","c" and "a","bc" differ.
  void Text(const std::string& s) {
    const std::uint64_t n = s.size();
    digest_.Add(&n, sizeof n);
    digest_.Add(s.data(), s.size());
  }
  void Number(double x) { digest_.Add(&x, sizeof x); }
  // Reading: the dataset just read at `path` must have this shape (a damaged or crafted file
  // must not make the reader index past what it read).
  void ExpectShape(const std::string& path, const Eigen::MatrixXd& A, Eigen::Index rows,
                   Eigen::Index cols) const {
    EMB_THROW_IF(!writing_ && (A.rows() != rows || A.cols() != cols),
                 "'" << h5_.path() << "': " << path << ": expected a (" << rows << ", " << cols
                     << ") dataset, got (" << A.rows() << ", " << A.cols() << ")");
  }
  void ExpectSize(const std::string& path, Eigen::Index size, Eigen::Index expected) const {
    EMB_THROW_IF(!writing_ && size != expected, "'" << h5_.path() << "': " << path << ": expected "
                                                    << expected << " values, got " << size);
  }
  std::string Hex() const { return digest_.Hex(); }
  bool writing() const { return writing_; }
  bool Exists(const std::string& path) const { return h5_.Exists(path); }
  H5File& h5() { return h5_; }

 private:
  H5File& h5_;
  bool writing_;
  Digest digest_;
};

}  // namespace emb::body_codec

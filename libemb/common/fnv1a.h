#pragma once
/// @file
/// FNV-1a, 64 bit: a fast non-cryptographic digest of bytes fed in any number of pieces
/// (identity of files and datasets, not security).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace emb {

class Fnv1a {
 public:
  void Add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h_ ^= p[i];
      h_ *= 1099511628211ull;
    }
  }
  void Add(const std::string& text) { Add(text.data(), text.size()); }
  /// The digest as 16 hex digits.
  std::string Hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
  }

 private:
  std::uint64_t h_{14695981039346656037ull};
};

}  // namespace emb

#pragma once
/// @file
/// How emb stores strings in HDF5: fixed-length, null-padded, UTF-8. Never variable-length:
/// reading a variable-length string goes through HDF5's global-heap reader, which a damaged
/// file can drive into an endless loop (found by tests/fuzz/fuzz_body_file). Internal to
/// libemb/io; identifiers are HDF5's hid_t (64-bit since HDF5 1.10), as in hdf5_file.h.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace emb::h5 {

/// New file-access properties for files emb creates: the HDF5 1.8 format or later, whose
/// dense attribute storage holds fixed-length string attributes over 64 KiB (a scene's
/// text). The caller closes them (H5Pclose).
std::int64_t NewFileAccessProps();

/// A new fixed-length string type `bytes` wide (at least 1); the caller closes it (H5Tclose).
std::int64_t NewFixedStringType(std::size_t bytes);

/// The strings packed into records as wide as the longest (at least 1 byte), null-padded.
/// @param[out] width the record width in bytes
std::vector<char> PackFixed(const std::vector<std::string>& strings, std::size_t* width);

/// The strings held by null-padded records `width` bytes wide.
std::vector<std::string> UnpackFixed(const std::vector<char>& bytes, std::size_t width);

/// A memory type for reading strings stored as `stored`: the same width and character set
/// (HDF5 does not convert between ASCII and UTF-8), null-padded. The caller closes it.
std::int64_t NewReadStringType(std::int64_t stored);

/// The record width of a stored string type.
/// @throws InputError naming `file` and `what` if the type is not a string, is a
///   variable-length string, or is wider than 16 MiB
std::size_t FixedStringWidth(std::int64_t type, const std::string& file, const std::string& what);

}  // namespace emb::h5

#include "libemb/io/h5_strings.h"

#include <hdf5.h>

#include <algorithm>
#include <type_traits>

#include "libemb/common/error.h"

namespace emb::h5 {

static_assert(std::is_same_v<hid_t, std::int64_t>, "h5_strings.h declares hid_t as int64_t");

namespace {
// Longest string emb reads, in bytes: names, digests, a scene's text.
constexpr std::size_t kMaxStringBytes = std::size_t{1} << 24;
}  // namespace

std::int64_t NewFileAccessProps() {
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  return fapl;
}

std::int64_t NewFixedStringType(std::size_t bytes) {
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, std::max<std::size_t>(bytes, 1));
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

std::int64_t NewReadStringType(std::int64_t stored) {
  const hid_t t = H5Tcopy(stored);
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  return t;
}

std::vector<char> PackFixed(const std::vector<std::string>& strings, std::size_t* width) {
  std::size_t w = 1;
  for (const auto& s : strings) w = std::max(w, s.size());
  std::vector<char> packed(w * strings.size(), '\0');
  for (std::size_t i = 0; i < strings.size(); ++i)
    std::copy(strings[i].begin(), strings[i].end(), packed.begin() + i * w);
  *width = w;
  return packed;
}

std::vector<std::string> UnpackFixed(const std::vector<char>& bytes, std::size_t width) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + width <= bytes.size(); i += width) {
    const auto begin = bytes.begin() + i;
    out.emplace_back(begin, std::find(begin, begin + width, '\0'));
  }
  return out;
}

std::size_t FixedStringWidth(std::int64_t type, const std::string& file, const std::string& what) {
  EMB_THROW_IF(H5Tget_class(type) != H5T_STRING,
               "HDF5 file '" << file << "': " << what << ": expected a string");
  EMB_THROW_IF(H5Tis_variable_str(type) != 0,
               "HDF5 file '" << file << "': " << what
                             << " is a variable-length string; emb reads fixed-length strings "
                                "only, as it writes them. Re-create the file with this emb");
  const std::size_t n = H5Tget_size(type);
  EMB_THROW_IF(n == 0 || n > kMaxStringBytes, "HDF5 file '" << file << "': " << what
                                                            << " is a string of " << n
                                                            << " bytes; expected 1 to 16 MiB");
  return n;
}

}  // namespace emb::h5

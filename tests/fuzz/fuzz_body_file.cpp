// libFuzzer target: the body-file reader (libemb/cms/body_file.h) on any bytes written as
// an HDF5 file: shapes, attributes, links and storage of a crafted or damaged file.
#include "libemb/cms/body_file.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = emb::fuzz::WriteInput(data, size, "body.h5");
  emb::fuzz::Expect([&] { emb::ReadBodyFile(path); });
  return 0;
}

// libFuzzer target: the results reader (libemb/results/results_reader.h) on any bytes written
// as an HDF5 file: status, a body channel and a body rotation angle, as emb spectrum reads.
#include "libemb/results/results_reader.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = emb::fuzz::WriteInput(data, size, "results.h5");
  emb::fuzz::Expect([&] { emb::results::ReadResultsStatus(path); });
  emb::fuzz::Expect([&] { emb::results::ReadResultsChannel(path, "disc.omega.x"); });
  emb::fuzz::Expect([&] { emb::results::ReadBodyRotationAngle(path, "disc", "x", 0.0); });
  return 0;
}

// libFuzzer target: the scene loader (YAML text to an mbs::System, libemb/scene) on any
// bytes. Scene files may name body files and geometry: relative names resolve against the
// fuzzer's working directory, where there are none (an InputError).
#include <string>

#include "libemb/scene/scene.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  emb::fuzz::Expect([&] { emb::scene::ParseScene(text, "fuzz.yaml"); });
  return 0;
}

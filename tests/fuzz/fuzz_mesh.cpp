// libFuzzer target: the mesh reader (libemb/mesh/gmsh_reader.h, through gmsh) on any bytes
// written as a .msh file. gmsh itself is not instrumented: what is fuzzed is emb's audit
// before gmsh and its checks of what gmsh returns (node numbers, cells, groups).
#include "libemb/mesh/gmsh_reader.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = emb::fuzz::WriteInput(data, size, "part.msh");
  emb::fuzz::Expect([&] { emb::ReadMesh(path, emb::MeshingOptions{}); });
  return 0;
}

// libFuzzer target: the .geo lexer, the DefineConstant parameter scanner and the audit of
// what gmsh would execute (libemb/mesh/geo_lexer.h, gmsh_input_audit.h), on any bytes.
// The audit must end (no hang, bounded by its limits) with findings or an InputError.
#include <string_view>

#include "libemb/mesh/geo_lexer.h"
#include "libemb/mesh/gmsh_input_audit.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  emb::fuzz::Expect([&] { emb::DefineConstantParameters(emb::LexGeoScript(text, "fuzz.geo")); });
  const std::string path = emb::fuzz::WriteInput(data, size, "part.geo");
  emb::fuzz::Expect([&] { emb::FindUnsafeGmshInput(path); });
  emb::fuzz::Expect([&] { emb::GeoParameters(path); });
  return 0;
}

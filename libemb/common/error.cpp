#include "libemb/common/error.h"

namespace emb::internal {

void ThrowInternal(const char* condition, const char* file, int line, const std::string& detail) {
  std::ostringstream oss;
  oss << "emb internal error: check '" << condition << "' failed at " << file << ":" << line;
  if (!detail.empty()) oss << ": " << detail;
  throw InternalError(oss.str());
}

}  // namespace emb::internal

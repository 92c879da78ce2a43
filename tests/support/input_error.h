#pragma once
// The message of an expected InputError (test support).

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "libemb/common/error.h"

namespace emb::test {

/// The message of the InputError `f` throws, or "(no InputError)".
inline std::string InputErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// True if `message` contains every one of `words` (a gtest-friendly check of an error).
inline ::testing::AssertionResult ContainsAll(const std::string& message,
                                              const std::vector<std::string>& words) {
  for (const auto& w : words)
    if (message.find(w) == std::string::npos)
      return ::testing::AssertionFailure() << "message '" << message << "' lacks '" << w << "'";
  return ::testing::AssertionSuccess();
}

}  // namespace emb::test

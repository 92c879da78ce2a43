#pragma once
/// @file
/// Error handling for emb.
///
/// A caller's mistake (bad file, mesh, parameter) throws emb::InputError whose message
/// names the thing and says "expected X, got Y". Numerical outcomes (not converged, not
/// positive definite) are *not* exceptions: they are a status in a result struct
/// (see e.g. linalg/eigen_solver.h, EigenResult). Broken internal invariants throw emb::InternalError
/// through EMB_CHECK (always on, for cheap checks) or EMB_DEBUG_CHECK (debug builds only).

#include <sstream>
#include <stdexcept>
#include <string>

namespace emb {

/// The caller gave something emb cannot work with (file, mesh, scene, parameter).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical procedure failed in a way the caller asked to be treated as fatal.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An invariant of emb itself is broken: a bug, never the user's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace internal {
[[noreturn]] void ThrowInternal(const char* condition, const char* file, int line,
                                const std::string& detail);
}  // namespace internal

}  // namespace emb

/// Throws `ExceptionType` with a message built by streaming: EMB_THROW(InputError, "x=" << x).
#define EMB_THROW(ExceptionType, stream_expr)   \
  do {                                          \
    std::ostringstream emb_throw_oss_;          \
    emb_throw_oss_ << stream_expr;              \
    throw ::emb::ExceptionType(emb_throw_oss_.str()); \
  } while (false)

/// Throws emb::InputError when `condition` holds.
#define EMB_THROW_IF(condition, stream_expr)                 \
  do {                                                       \
    if (condition) EMB_THROW(InputError, stream_expr);       \
  } while (false)

/// Always-on check of a cheap internal invariant.
#define EMB_CHECK(condition)                                                     \
  do {                                                                           \
    if (!(condition)) ::emb::internal::ThrowInternal(#condition, __FILE__, __LINE__, ""); \
  } while (false)

/// Debug-only check of a costly internal invariant.
#ifdef NDEBUG
#define EMB_DEBUG_CHECK(condition) \
  do {                             \
  } while (false)
#else
#define EMB_DEBUG_CHECK(condition) EMB_CHECK(condition)
#endif

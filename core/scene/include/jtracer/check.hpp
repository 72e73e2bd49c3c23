#pragma once
// JT_DCHECK(condition, why): a contract the caller must keep, stated in code.
//
// Checked in debug and sanitizer builds (JT_DCHECKS is defined there by the
// top-level CMakeLists.txt); compiled out of release builds, where the
// condition is not evaluated. A broken contract prints where, what and why on
// stderr and aborts: it is a bug in the calling code. Bad input is never a
// broken contract: it gets an Error (error.hpp) or a diagnostic.
//
//   JT_DCHECK(scene != nullptr, "a frame is made of a prepared scene");

#include <cstdio>
#include <cstdlib>

namespace jt::detail {

[[noreturn]] inline void dcheck_failed(const char* condition, const char* why, const char* file,
                                       int line) {
    std::fprintf(stderr, "%s:%d: contract broken: %s (%s)\n", file, line, why, condition);
    std::abort();
}

}  // namespace jt::detail

#if defined(JT_DCHECKS)
#define JT_DCHECK(condition, why) \
    ((condition) ? void(0) : ::jt::detail::dcheck_failed(#condition, why, __FILE__, __LINE__))
#else
// Not evaluated, but still compiled: a check cannot rot in release builds.
#define JT_DCHECK(condition, why) ((void)sizeof((condition) ? 1 : 0))
#endif

// Whether this build checks contracts (for tests of the checks themselves).
namespace jt {
#if defined(JT_DCHECKS)
inline constexpr bool kContractsChecked = true;
#else
inline constexpr bool kContractsChecked = false;
#endif
}  // namespace jt

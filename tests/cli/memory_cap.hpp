#pragma once
// A shell prefix that caps a child's address space, so that a test of a read
// that must end cannot take all the memory there is should it not. The
// sanitizers reserve terabytes of address space up front, which no cap allows.

namespace jt::test {

#if JT_SANITIZED
inline constexpr const char* memory_cap = "";
#else
inline constexpr const char* memory_cap = "ulimit -v 4000000; ";
#endif

}  // namespace jt::test

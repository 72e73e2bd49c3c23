#include "io/reserve_records.hpp"

#include "io/huge_pages.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#ifndef MADV_COLLAPSE
#define MADV_COLLAPSE 25  // Linux 6.1's value; glibc 2.36 does not name it yet
#endif
#endif

namespace jt::detail {

namespace {
// A pointer this close past a 2 MiB boundary starts its own mapping: only
// malloc's header lies between.
constexpr std::uintptr_t malloc_header = 64;
}  // namespace

void advise_huge_records(const void* data, std::size_t bytes) {
    const auto start = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t boundary = start & ~(std::uintptr_t{huge_page} - 1);
    if (start - boundary > malloc_header) {
        advise_huge_pages(data, bytes);  // not a mapping of its own: its whole 2 MiB pages
        return;
    }
    advise_huge_pages(reinterpret_cast<const void*>(boundary), bytes + (start - boundary));
#if defined(__linux__) && defined(MADV_COLLAPSE)
    // malloc wrote its header into the first 2 MiB before the advice, so that
    // page was already faulted in as 4 KiB and would stay so: make it huge now
    // (one page instead of 512 faults to fill it). A failure (older kernel)
    // leaves it as it was.
    if (bytes >= huge_page) ::madvise(reinterpret_cast<void*>(boundary), huge_page, MADV_COLLAPSE);
#endif
}

}  // namespace jt::detail

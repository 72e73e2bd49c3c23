#pragma once
// Reserving large arrays (the parser's records, images) so that they fill
// without 4 KiB page faults.
//
// The parser fills a few arrays once, front to back, in memory fresh from the
// kernel; for a million spheres they are hundreds of MB, and their 4 KiB page
// faults were a quarter of a cold parse with the source map. advise_huge_pages
// covers only the whole 2 MiB pages inside an array, and an array starts
// anywhere: its first (up to) 2 MiB still took 4 KiB faults.
//
// So a large array (min_huge_page_array_bytes or more: below that the hint
// risks more than it saves, io/huge_pages.hpp) is reserved to a size that
// glibc maps afresh with mmap (above its largest adaptive threshold, 32 MiB)
// in a mapping a whole number of 2 MiB long, which Linux places on a 2 MiB
// boundary: the array then starts 16 bytes (malloc's header) past a boundary
// and every page of it can be huge. Reserved but untouched memory costs
// address space only. Elsewhere (another allocator, ASan) this is just a
// larger reservation and the same hint.

#include "io/huge_pages.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

namespace jt {

namespace detail {

constexpr std::size_t huge_page = std::size_t{2} << 20;
// Above glibc's DEFAULT_MMAP_THRESHOLD_MAX on 64-bit, so always mmap'ed.
constexpr std::size_t always_mapped_bytes = std::size_t{34} << 20;
// glibc asks mmap for request + 8 bytes of header, rounded up to 16 then to a
// page: a request of k * 2 MiB - 32 bytes maps exactly k * 2 MiB.
constexpr std::size_t malloc_overhead = 32;

// Asks for 2 MiB pages behind a freshly reserved array (reserve_records.cpp).
void advise_huge_records(const void* data, std::size_t bytes);

}  // namespace detail

// Reserves room for at least `count` records (an upper bound from a pre-count)
// in an empty array about to be filled. Never throws: when the memory cannot be
// reserved (a memory limit), the array just grows as it goes.
template <class T>
void reserve_records(std::vector<T>& records, std::size_t count) {
    using namespace detail;
    try {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < min_huge_page_array_bytes) {
            records.reserve(count);
            return;
        }
        const std::size_t mapped = std::max(
            (bytes + malloc_overhead + huge_page - 1) / huge_page * huge_page, always_mapped_bytes);
        try {
            records.reserve((mapped - malloc_overhead) / sizeof(T));
        } catch (const std::exception&) {
            records.reserve(count);  // the padding did not fit: the count may
        }
        advise_huge_records(records.data(), records.capacity() * sizeof(T));
    } catch (const std::exception&) {
    }
}

// A zero-filled array of `count` records, reserved as above: for buffers
// written once (an image, a BMP file's bytes), which for a large image are
// tens of MB.
template <class T>
std::vector<T> zeroed_records(std::size_t count) {
    std::vector<T> records;
    reserve_records(records, count);
    records.resize(count);
    return records;
}

}  // namespace jt

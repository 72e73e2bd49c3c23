#pragma once
// Asks the kernel for 2 MiB pages behind a large array about to be filled.
//
// Filling fresh memory costs a page fault for each 4 KiB page touched: a
// million spheres fill hundreds of MB (text, scene and source map), and there
// the faults once took longer than the parsing. With transparent huge pages in
// "madvise" mode (Debian's default) this hint makes it one fault per 2 MiB.
// Only a hint: a no-op for arrays spanning no whole 2 MiB page, where huge
// pages are off, and off Linux.
//
// Only arrays of min_huge_page_array_bytes or more take the hint. A huge
// page is cleared whole at its first touch, however little of it an array
// uses, and on a VM it is now and then backed by the host only then (a fresh
// 6 MB buffer: 0.3-0.8 ms in 2 MiB pages, 4-9 ms in 4 KiB pages, but once in
// a while 25 ms; 200 ms for 64 MB; bench/micro/bench_fresh_pages.cpp). For
// the arrays of a scene of a few thousand shapes that costs more than the
// faults it saves: whole renders of the race scenes ran up to 15% faster in
// the median with the hint only from 16 MiB, and their slowest tenth up to a
// third faster (docs/benchmarks.md §2.5).

#include <cstddef>
#include <string>
#include <vector>

namespace jt {

inline constexpr std::size_t min_huge_page_array_bytes = std::size_t{16} << 20;

// Advises the whole 2 MiB pages inside [data, data + bytes), when `bytes` is
// at least min_huge_page_array_bytes.
void advise_huge_pages(const void* data, std::size_t bytes);

// The array's whole capacity: call it after reserve(), before filling.
template <class T>
void advise_huge_pages(const std::vector<T>& records) {
    advise_huge_pages(records.data(), records.capacity() * sizeof(T));
}

inline void advise_huge_pages(const std::string& text) {
    advise_huge_pages(text.data(), text.capacity());
}

}  // namespace jt

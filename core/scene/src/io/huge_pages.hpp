#pragma once
// Asks the kernel for 2 MiB pages behind a large array about to be filled.
//
// Filling fresh memory costs a page fault for each 4 KiB page touched, and on
// a VM each fault costs microseconds: for a million spheres (hundreds of MB of
// text, scene and source map) the faults took longer than the parsing. With
// transparent huge pages in "madvise" mode (Debian's default) this hint makes
// it one fault per 2 MiB. Only a hint: a no-op for arrays spanning no whole
// 2 MiB page, where huge pages are off, and off Linux.

#include <cstddef>
#include <string>
#include <vector>

namespace jt {

// Advises the whole 2 MiB pages inside [data, data + bytes).
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

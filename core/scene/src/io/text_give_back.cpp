#include "io/text_give_back.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace jt {

namespace {

// A huge page: a large text is advised to take them (huge_pages.hpp), and
// giving back part of one would only split it.
constexpr std::uintptr_t give_back_unit = std::uintptr_t{2} << 20;

char* unit_down(char* p) {
    return reinterpret_cast<char*>(reinterpret_cast<std::uintptr_t>(p) & ~(give_back_unit - 1));
}

char* unit_up(char* p) {
    return reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(p) + give_back_unit - 1) &
                                   ~(give_back_unit - 1));
}

}  // namespace

// The first unit may hold the allocator's header before the text: it is kept.
TextGiveBack::TextGiveBack(std::string& text) : begin_(text.data()), next_(unit_up(text.data())) {}

void TextGiveBack::passed(std::size_t offset) {
#if defined(__linux__)
    char* const end = unit_down(begin_ + offset);
    if (end <= next_) return;
    // A failure leaves the pages as they were, but the text counts as given
    // back all the same: no reader has to ask which.
    ::madvise(next_, static_cast<std::size_t>(end - next_), MADV_DONTNEED);
    gave_back_ = true;
    next_ = end;
#else
    (void)offset;
#endif
}

}  // namespace jt

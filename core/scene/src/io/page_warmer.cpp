#include "io/page_warmer.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace jt {

namespace {

// One call faults in this much: small enough to stop soon when asked.
constexpr std::size_t warm_step = std::size_t{2} << 20;

std::uintptr_t page_size() {
#if defined(__linux__)
    static const auto size = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    return size;
#else
    return 4096;
#endif
}

std::byte* page_down(std::byte* p) {
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    return reinterpret_cast<std::byte*>(at & ~(page_size() - 1));
}

std::byte* page_up(std::byte* p) {
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    return reinterpret_cast<std::byte*>((at + page_size() - 1) & ~(page_size() - 1));
}

}  // namespace

void PageWarmer::start(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    if (thread_.joinable() || data == nullptr || bytes < smallest_warmed_bytes) return;
    begin_ = static_cast<std::byte*>(data);
    end_ = begin_ + bytes;
    // The page holding the array's first bytes may hold malloc's header: it is
    // there already, and the advice only needs whole pages.
    warmed_ = page_up(begin_);
    next_report_ = 0;
    filled_.store(0, std::memory_order_relaxed);
    stopping_.store(false, std::memory_order_relaxed);
    try {
        thread_ = std::thread([this] { run(); });
    } catch (...) {
        // No thread: the filler faults its pages in itself, as without a warmer.
    }
#else
    (void)data;
    (void)bytes;
#endif
}

void PageWarmer::report(std::size_t bytes) {
    filled_.store(bytes, std::memory_order_release);
    filled_.notify_one();
}

void PageWarmer::run() {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    std::byte* const last = page_down(end_);
    while (!stopping_.load(std::memory_order_acquire) && warmed_ < last) {
        const std::size_t filled = filled_.load(std::memory_order_acquire);
        std::byte* const limit = page_down(
            begin_ + std::min(filled + lead_bytes, static_cast<std::size_t>(end_ - begin_)));
        if (warmed_ >= limit) {
            filled_.wait(filled, std::memory_order_acquire);
            continue;
        }
        const std::size_t length = std::min(warm_step, static_cast<std::size_t>(limit - warmed_));
        // Faulting in changes no byte, so the filler may write these pages meanwhile.
        if (::madvise(warmed_, length, MADV_POPULATE_WRITE) != 0) return;  // an older kernel
        warmed_ += length;
    }
#endif
}

void PageWarmer::join() {
    if (!thread_.joinable()) return;
    stopping_.store(true, std::memory_order_release);
    filled_.store(std::numeric_limits<std::size_t>::max(), std::memory_order_release);
    filled_.notify_one();
    thread_.join();
}

void PageWarmer::finish(const void* data, std::size_t used_bytes) {
    if (!thread_.joinable()) return;
    join();
#if defined(__linux__)
    if (data == begin_) {
        // Past the last page the array uses no object lives: give those pages back.
        std::byte* const unused =
            page_up(begin_ + std::min(used_bytes, static_cast<std::size_t>(end_ - begin_)));
        if (warmed_ > unused)
            ::madvise(unused, static_cast<std::size_t>(warmed_ - unused), MADV_DONTNEED);
    }
#else
    (void)data;
    (void)used_bytes;
#endif
    begin_ = end_ = warmed_ = nullptr;
}

}  // namespace jt

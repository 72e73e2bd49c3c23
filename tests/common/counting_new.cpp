#include "common/counting_new.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include <execinfo.h>

namespace {

thread_local bool counting = false;
thread_local bool print_stacks = false;
std::atomic<long long> allocations{0};
std::atomic<long long> allocated_bytes{0};

void* counted_new(std::size_t size) {
    if (counting) {
        allocations.fetch_add(1, std::memory_order_relaxed);
        allocated_bytes.fetch_add(static_cast<long long>(size), std::memory_order_relaxed);
        if (print_stacks) {
            counting = false;  // backtrace() may allocate
            void* frames[24];
            const int n = backtrace(frames, 24);
            std::fprintf(stderr, "allocation of %zu bytes:\n", size);
            backtrace_symbols_fd(frames, n, 2);
            counting = true;
        }
    }
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) {
    return counted_new(size);
}
void* operator new[](std::size_t size) {
    return counted_new(size);
}
// The nothrow forms too: a library's nothrow new freed by the plain delete
// below must have come from malloc (AddressSanitizer checks the pairs).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return counted_new(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return counted_new(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace jt::test {

Allocated allocated_by(const std::function<void()>& work, bool print) {
    const long long count = allocations.load(), bytes = allocated_bytes.load();
    print_stacks = print;
    counting = true;
    work();
    counting = false;
    print_stacks = false;
    return {allocations.load() - count, allocated_bytes.load() - bytes};
}

}  // namespace jt::test

// io/page_warmer.hpp: pages are faulted in ahead of the filler, never far
// ahead, no byte changes, and what lies past the used part is given back.
#include "io/page_warmer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstddef>
#include <cstring>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace jt {
namespace {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)

constexpr std::size_t kMiB = std::size_t{1} << 20;

// A fresh anonymous mapping, unmapped at the end of the test.
struct Mapping {
    explicit Mapping(std::size_t size) : bytes(size) {
        void* p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        data = p == MAP_FAILED ? nullptr : static_cast<std::byte*>(p);
    }
    ~Mapping() {
        if (data) ::munmap(data, bytes);
    }
    std::byte* data = nullptr;
    std::size_t bytes = 0;
};

// How many bytes of [from, to) of the mapping are resident.
std::size_t resident(const Mapping& m, std::size_t from, std::size_t to) {
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> pages((to - from) / page);
    if (::mincore(m.data + from, to - from, pages.data()) != 0) return 0;
    std::size_t count = 0;
    for (unsigned char p : pages) count += (p & 1u) * page;
    return count;
}

// Waits (up to a minute, for a loaded machine) until the pred holds.
template <class Pred>
bool eventually(Pred pred) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!pred()) {
        if (std::chrono::steady_clock::now() > give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

bool kernel_populates() {
    Mapping probe(std::size_t{1} << 16);
    return probe.data && ::madvise(probe.data, probe.bytes, MADV_POPULATE_WRITE) == 0;
}

TEST(PageWarmer, FaultsInAheadOfTheFillerButNoFurtherThanItsLead) {
    if (!kernel_populates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE";
    const std::size_t size = PageWarmer::smallest_warmed_bytes + 2 * PageWarmer::lead_bytes;
    Mapping m(size);
    ASSERT_NE(m.data, nullptr);
    PageWarmer warmer;
    warmer.start(m.data, size);
    const std::size_t lead = PageWarmer::lead_bytes;
    // Nothing filled yet: the first `lead` bytes come in, and no more.
    ASSERT_TRUE(eventually([&] { return resident(m, 0, lead) == lead; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    // (A whole 2 MiB page past the lead may come in where the kernel backs the mapping with them.)
    EXPECT_EQ(resident(m, lead + 2 * kMiB, size), 0u);

    // The filler moves on: so does the warmer.
    std::memset(m.data, 0x5a, 8 * kMiB);
    warmer.filled(size - lead);
    ASSERT_TRUE(eventually([&] { return resident(m, 0, size) == size; }));

    // Giving back what lies past the used part keeps the used bytes.
    warmer.finish(m.data, 8 * kMiB);
    EXPECT_EQ(resident(m, 8 * kMiB, size), 0u);
    for (std::size_t i = 0; i < 8 * kMiB; i += 4093) ASSERT_EQ(m.data[i], std::byte{0x5a}) << i;
}

TEST(PageWarmer, ChangesNoByteTheFillerWritesMeanwhile) {
    if (!kernel_populates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE";
    const std::size_t size = PageWarmer::smallest_warmed_bytes + PageWarmer::lead_bytes;
    Mapping m(size);
    ASSERT_NE(m.data, nullptr);
    PageWarmer warmer;
    warmer.start(m.data, size);
    // The filler writes byte after byte, reporting as it goes, as the parser does.
    for (std::size_t i = 0; i < size; i += 64) {
        m.data[i] = static_cast<std::byte>(i / 64 % 251 + 1);
        warmer.filled(i + 64);
    }
    warmer.finish(m.data, size);
    for (std::size_t i = 0; i < size; i += 64)
        ASSERT_EQ(m.data[i], static_cast<std::byte>(i / 64 % 251 + 1)) << i;
}

TEST(PageWarmer, AnArrayThatMovedIsNotGivenBack) {
    if (!kernel_populates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE";
    const std::size_t size = PageWarmer::smallest_warmed_bytes;
    Mapping m(size);
    ASSERT_NE(m.data, nullptr);
    PageWarmer warmer;
    warmer.start(m.data, size);
    ASSERT_TRUE(eventually([&] { return resident(m, 0, PageWarmer::lead_bytes) > 0; }));
    std::memset(m.data, 0x11, size);  // someone else's bytes, once the array has moved away
    warmer.finish(m.data + 4096, 0);
    EXPECT_EQ(resident(m, 0, size), size);
    for (std::size_t i = 0; i < size; i += 4093) ASSERT_EQ(m.data[i], std::byte{0x11}) << i;
}

#endif

TEST(PageWarmer, ASmallArrayOrNoneIsLeftAlone) {
    std::vector<std::byte> small(1024);
    PageWarmer warmer;
    warmer.start(small.data(), small.size());
    warmer.filled(512);
    warmer.finish(small.data(), 512);
    warmer.start(nullptr, PageWarmer::smallest_warmed_bytes);
    warmer.finish(nullptr, 0);
    EXPECT_EQ(small[1000], std::byte{0});
}

}  // namespace
}  // namespace jt

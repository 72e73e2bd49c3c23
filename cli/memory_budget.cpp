#include "memory_budget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace jt::cli {

namespace {

// MemAvailable from /proc/meminfo, in bytes; 0 when it cannot be read.
std::uint64_t system_available_bytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    return 0;
}

std::string gib(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1ull << 30));
    return text;
}

}  // namespace

std::uint64_t render_memory_bytes(int width, int height, int samples) {
    const auto pixels = static_cast<std::uint64_t>(std::max(width, 0)) *
                        static_cast<std::uint64_t>(std::max(height, 0));
    // 3 bytes each for the job's image, the writer's copy and the encoded file;
    // with several samples a running sum of three doubles.
    const std::uint64_t per_pixel = 9 + (samples > 1 ? 24 : 0);
    return pixels * per_pixel;
}

std::uint64_t available_memory_bytes() {
    std::uint64_t available = system_available_bytes();
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const auto cap = static_cast<std::uint64_t>(limit.rlim_cur);
        available = available == 0 ? cap : std::min(available, cap);
    }
    return available;
}

std::string check_render_memory(int width, int height, int samples) {
    const std::uint64_t needed = render_memory_bytes(width, height, samples);
    const std::uint64_t available = available_memory_bytes();
    if (available == 0 || needed <= available) return {};
    std::ostringstream message;
    message << "a " << width << " x " << height << " image with " << samples
            << (samples == 1 ? " sample" : " samples") << " needs about " << gib(needed)
            << " of memory, more than the " << gib(available)
            << " available; choose a smaller --width/--height or fewer --samples";
    return message.str();
}

}  // namespace jt::cli

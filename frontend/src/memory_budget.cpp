#include "jtracer/frontend/memory_budget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace jt::frontend {

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

std::uint64_t render_memory_bytes(const RenderOptions& options, bool region_output) {
    auto pixels = [](int width, int height) {
        return static_cast<std::uint64_t>(std::max(width, 0)) *
               static_cast<std::uint64_t>(std::max(height, 0));
    };
    const std::uint64_t frame = pixels(options.width, options.height);
    const std::uint64_t rendered =
        options.region ? pixels(options.region->width(), options.region->height()) : frame;
    const std::uint64_t written = region_output ? rendered : frame;
    // 3 bytes a pixel for the job's image, with several samples a running sum
    // of three doubles; 3 each for the writer's copy and the encoded file.
    return rendered * (3 + (options.samples > 1 ? 24 : 0)) + written * 6;
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

Expected<void> check_render_memory(const RenderOptions& options, bool region_output,
                                   const ArgumentNames& names) {
    const std::uint64_t needed = render_memory_bytes(options, region_output);
    const std::uint64_t available = available_memory_bytes();
    if (available == 0 || needed <= available) return {};
    std::ostringstream message;
    message << "a " << options.width << " x " << options.height << " image with " << options.samples
            << (options.samples == 1 ? " sample" : " samples") << " needs about " << gib(needed)
            << " of memory, more than the " << gib(available) << " available; choose a smaller "
            << names.name("width") << "/" << names.name("height") << " or fewer "
            << names.name("samples");
    return Error{message.str()};
}

}  // namespace jt::frontend

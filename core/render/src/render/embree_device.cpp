#include "render/embree_device.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace jt {

namespace {

void report_embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "jtracer: embree error %d: %s\n", static_cast<int>(code),
                 message ? message : "");
}

const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error reported";
        case RTC_ERROR_UNKNOWN:
            return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "this CPU is not supported";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
    }
    return "unknown error";
}

std::atomic<std::int64_t> device_bytes{0};

// Counts, never refuses: Embree calls it before each allocation (bytes > 0)
// and after each release (bytes < 0), from whichever thread builds.
bool count_embree_bytes(void*, ssize_t bytes, bool) {
    device_bytes.fetch_add(bytes, std::memory_order_relaxed);
    return true;
}

struct Device {
    RTCDevice handle = nullptr;
    std::string failure;
};

const Device& device() {
    // Never released: scenes may outlive any owner we could name, and the
    // process exit frees it.
    static const Device d = [] {
        Device made;
        const char* config = std::getenv(kEmbreeConfigVariable);
        made.handle = rtcNewDevice(config);
        if (made.handle) {
            rtcSetDeviceErrorFunction(made.handle, report_embree_error, nullptr);
            rtcSetDeviceMemoryMonitorFunction(made.handle, count_embree_bytes, nullptr);
        } else {
            made.failure = "cannot start Embree";
            if (config)
                made.failure += std::string(" with ") + kEmbreeConfigVariable + "='" + config + "'";
            made.failure += std::string(": ") + error_name(rtcGetDeviceError(nullptr));
        }
        return made;
    }();
    return d;
}

}  // namespace

RTCDevice embree_device() {
    return device().handle;
}

std::int64_t embree_device_bytes() {
    return device_bytes.load(std::memory_order_relaxed);
}

std::string embree_device_failure() {
    return device().failure;
}

}  // namespace jt

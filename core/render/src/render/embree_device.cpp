#include "render/embree_device.hpp"

#include <cstdio>
#include <mutex>

namespace jt {

namespace {

void report_embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "jtracer: embree error %d: %s\n", static_cast<int>(code),
                 message ? message : "");
}

}  // namespace

RTCDevice embree_device() {
    // Never released: scenes may outlive any owner we could name, and the
    // process exit frees it.
    static RTCDevice device = [] {
        RTCDevice d = rtcNewDevice(nullptr);
        if (d) rtcSetDeviceErrorFunction(d, report_embree_error, nullptr);
        return d;
    }();
    return device;
}

}  // namespace jt

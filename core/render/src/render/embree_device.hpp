#pragma once
// The process's one Embree device, created on first use.
//
// Its configuration string comes from the environment variable
// JTRACER_EMBREE_CONFIG (Embree's own syntax, e.g. "isa=sse2" or
// "verbose=1"), so that a farm can check that every vector unit Embree may
// choose gives the same image (docs/distributed.md).

#include <embree3/rtcore.h>

#include <cstdint>
#include <string>

namespace jt {

inline constexpr const char* kEmbreeConfigVariable = "JTRACER_EMBREE_CONFIG";

// Null when Embree could not start; embree_device_failure() says why.
RTCDevice embree_device();

// The bytes Embree's device holds now (its acceleration structures and the
// buffers it allocated), as its memory monitor counts them; 0 before it starts.
std::int64_t embree_device_bytes();

// "cannot start Embree with JTRACER_EMBREE_CONFIG='isa=foo': ..." after a
// failed start, empty otherwise.
std::string embree_device_failure();

}  // namespace jt

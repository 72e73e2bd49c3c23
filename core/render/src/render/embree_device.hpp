#pragma once
// The process's one Embree device, created on first use.

#include <embree3/rtcore.h>

namespace jt {

RTCDevice embree_device();

}  // namespace jt

#include "render/user_geometry.hpp"

#include "render/embree_device.hpp"
#include "render/prepared_scene.hpp"

namespace jt {

unsigned attach_user_geometry(RTCScene scene, void* user_data, std::size_t count,
                              RTCBuildQuality quality, RTCBoundsFunction bounds,
                              RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded) {
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(count));
    rtcSetGeometryBuildQuality(geometry, quality);
    rtcSetGeometryUserData(geometry, user_data);
    rtcSetGeometryBoundsFunction(geometry, bounds, user_data);
    rtcSetGeometryIntersectFunction(geometry, intersect);
    rtcSetGeometryOccludedFunction(geometry, occluded);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    return id;
}

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
    *args->bounds_o = padded_sphere_bounds(*g, args->primID);
}

void shape_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
    *args->bounds_o = g->shapes[args->primID].bounds;
}

}  // namespace jt

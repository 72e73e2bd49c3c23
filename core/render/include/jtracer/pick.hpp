#pragma once
// Which primitive a pixel of a frame shows, and where a point of the scene
// appears in the image: what the viewer's click, pixel inspector and light
// markers ask.
//
// The answer is the render's own: the primary ray through the centre of the
// pixel, made as render_tile makes it (docs/language.md §7), and the nearest
// surface it meets, as the tracer finds it. With one sample a pixel, that ray
// is the one whose colour the pixel holds; with more, it is the centre of the
// pixel's samples.

#include "jtracer/render_tile.hpp"
#include "jtracer/scene.hpp"

#include <optional>

namespace jt {

// The whole image of `frame`: [0, width) x [0, height).
PixelRect frame_rect(const PreparedFrame& frame);

// A point of the image plane in pixels from the bottom left corner, so that
// the centre of pixel (i, j) is (i + 0.5, j + 0.5).
struct ImagePoint {
    double x = 0.0, y = 0.0;
};

// The primary ray through image point `at` of `frame` (inside the image or
// not), as render_tile makes it: from the camera's position along the unit
// `direction`. Nothing when the camera cannot form a frame (render_tile's
// background). At the image's centre the direction is the camera's forward.
struct CameraRay {
    Vec3 origin{0.0};
    Vec3 direction{0.0, 0.0, -1.0};
};
std::optional<CameraRay> camera_ray(const PreparedFrame& frame, const ImagePoint& at);

struct PickedPrimitive {
    int primitive = -1;     // the index in Scene::primitives
    double distance = 0.0;  // from the camera's position along the unit ray
};

// The primitive that the primary ray through pixel (x, y) of `frame` (Image8
// coordinates: y from the bottom) meets first; nothing when it meets none or
// (x, y) is outside the frame.
std::optional<PickedPrimitive> pick_primitive(const PreparedFrame& frame, int x, int y);

// Where `point` appears in the image of `frame`: (x, y) in pixels from the
// bottom left corner (ImagePoint), possibly outside the image; nothing when
// the point is not in front of the camera.
std::optional<ImagePoint> project_to_image(const PreparedFrame& frame, const Vec3& point);

}  // namespace jt

#pragma once
// The frame the image on screen is rendered from (prepared scene, camera,
// size), for picking in it; remade only when the render's prepared scene or
// view changes (picking.hpp).

#include "jtracer/pick.hpp"

#include <memory>

namespace jt::view {

struct ShownFrame {
    std::shared_ptr<const PreparedScene> scene;
    int width = 0, height = 0, camera = -1;
    std::shared_ptr<const PreparedFrame> frame;
};

}  // namespace jt::view

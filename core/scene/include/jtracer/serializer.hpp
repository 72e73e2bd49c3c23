#pragma once
// Scene -> canonical .jts text.

#include "jtracer/scene.hpp"

#include <string>

namespace jt {

// Canonical .jts text for `scene`: every block and property written out in a
// fixed order, each number in the shortest form that reads back exactly, so
// that parse_scene(serialize_scene(s)).scene == s for any scene the parser can
// produce. Strings keep only printable ASCII without '"' (others become '_'),
// since nothing else can be written in the language.
std::string serialize_scene(const Scene& scene);

}  // namespace jt

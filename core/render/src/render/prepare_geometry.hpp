#pragma once
// The geometry half of prepare_scene: every shape of a scene in world space,
// then the BVH and the lights' direction tables over them. prepare_scene.cpp
// does the rest (materials, pictures) and decides when a previous geometry
// serves again.

#include "jtracer/error.hpp"
#include "jtracer/scene.hpp"
#include "render/direction_table.hpp"
#include "render/prepared_scene.hpp"

#include <memory>
#include <vector>

namespace jt {

// Every shape of `scene` in world space, without the BVH (build_bvh_and_light_tables)
// and the digest (which the caller works out beside this). Reads no material: a
// scene handed over gives its materials up meanwhile.
Expected<std::shared_ptr<Geometry>> gather_geometry(const Scene& scene);

// The BVH and the light tables of freshly gathered shapes. The tables read
// only the finished shapes, as the BVH does, so they are built beside it: a
// table around one light is otherwise a stretch of the set-up with one busy
// core.
std::vector<DirectionTable> build_bvh_and_light_tables(Geometry& g,
                                                       const std::vector<PointLight>& lights);

}  // namespace jt

#pragma once
// What the user has selected: one primitive or one light of the scene, by its
// index in Scene::primitives or Scene::lights.

namespace jt::view {

struct Selection {
    enum class Kind { none, primitive, light };
    Kind kind = Kind::none;
    int index = -1;
    bool operator==(const Selection&) const = default;
};

}  // namespace jt::view

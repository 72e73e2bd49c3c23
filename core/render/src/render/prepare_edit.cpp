// prepare_scene_edit: a material edit patches the previous prepared scene.
//
// Each material entry of a prepared scene serves one run of consecutive
// primitives (prepare_scene merges runs of equal materials), and the tracer
// only ever reads materials[material_of[primitive]] (or materials[primitive]
// when every primitive has its own entry). So a primitive whose
// material changed either takes over its entry, when the run is itself alone,
// or gets a new entry at the end; every primitive then sees the material it
// would see in a fresh preparation, and the pixels are the same. A prepared
// scene that reads its materials where its Scene holds them is patched by
// holding the edited Scene instead, when that is shared.

#include "render/direction_table.hpp"
#include "render/pattern.hpp"
#include "render/prepared_scene.hpp"

#include <algorithm>
#include <optional>
#include <variant>

namespace jt {

namespace {

// The primitives whose material differs between `before` and `after`, or
// nothing when anything else about a primitive differs, or when the scene
// names a file (its state on disk is prepare_scene's to check).
std::optional<std::vector<std::uint32_t>> changed_materials(const Scene& before,
                                                            const Scene& after) {
    if (before.primitives.size() != after.primitives.size()) return std::nullopt;
    if (!before.settings.background_map.empty() || !after.settings.background_map.empty())
        return std::nullopt;
    std::vector<std::uint32_t> changed;
    for (std::size_t i = 0; i < after.primitives.size(); ++i) {
        const Primitive& a = before.primitives[i];
        const Primitive& b = after.primitives[i];
        if (shape_is<Mesh>(b.shape) || !b.material.finish->image_map.empty() ||
            !(a.shape == b.shape) || a.transforms != b.transforms)
            return std::nullopt;
        if (!(a.material == b.material)) changed.push_back(static_cast<std::uint32_t>(i));
    }
    return changed;
}

// Gives primitive `i` the material `m` in `prepared` (see the file comment).
void set_material(PreparedScene& prepared, std::uint32_t i, const Material& m) {
    std::vector<std::uint32_t>& of = prepared.material_of;
    if (of.empty()) {  // every primitive's entry its own, at its index
        prepared.materials[i] = m;
        return;
    }
    const std::uint32_t entry = of[i];
    const bool alone =
        (i == 0 || of[i - 1] != entry) && (std::size_t{i} + 1 == of.size() || of[i + 1] != entry);
    if (alone) {
        prepared.materials[entry] = m;
        return;
    }
    of[i] = static_cast<std::uint32_t>(prepared.materials.size());
    prepared.materials.push_back(m);
    // No material names a file here (changed_materials), so no picture; the
    // pictures are parallel to the materials only when some has a pattern.
    if (!prepared.textures.empty()) prepared.textures.emplace_back();
}

// `owned`, when given, is `scene` shared: a previous scene that reads its
// materials in place is patched by reading them in place from it.
Expected<std::shared_ptr<const PreparedScene>> edit(const Scene& before, const Scene& scene,
                                                    std::shared_ptr<const Scene> owned,
                                                    std::shared_ptr<const PreparedScene> previous) {
    std::optional<std::vector<std::uint32_t>> changed;
    // A scene that reads its materials in place (a shared one) has no list
    // to patch: only the edited scene, shared, can take its place.
    if (previous && previous->geometry && (!previous->scene || owned))
        changed = changed_materials(before, scene);
    // Patterns need each primitive's pattern space, which the previous scene
    // kept only when some material had a pattern.
    if (changed && previous->pattern_space.empty() &&
        std::any_of(changed->begin(), changed->end(),
                    [&](std::uint32_t i) { return has_pattern(scene.primitives[i].material); }))
        changed.reset();
    if (!changed)
        return owned ? prepare_scene(std::move(owned), std::move(previous))
                     : prepare_scene(scene, std::move(previous));

    auto prepared = std::make_shared<PreparedScene>(*previous);
    if (previous->scene) {
        prepared->scene = std::move(owned);  // which holds the edited materials
        // Only an edit that may have taken the last transmission away walks
        // the whole scene.
        const auto transmits = [](const Primitive& p) {
            return p.material.finish->transmission > 0.0;
        };
        prepared->has_transmission =
            std::any_of(changed->begin(), changed->end(),
                        [&](std::uint32_t i) { return transmits(scene.primitives[i]); }) ||
            (previous->has_transmission &&
             std::any_of(scene.primitives.begin(), scene.primitives.end(), transmits));
    } else {
        for (std::uint32_t i : *changed) set_material(*prepared, i, scene.primitives[i].material);
        prepared->has_transmission =
            std::any_of(prepared->materials.begin(), prepared->materials.end(),
                        [](const Material& m) { return m.finish->transmission > 0.0; });
    }
    if (!(previous->lights == scene.lights)) {
        prepared->lights = scene.lights;
        prepared->light_tables = std::make_shared<const std::vector<DirectionTable>>(
            build_light_tables(*prepared->geometry, scene.lights));
    }
    prepared->cameras = scene.cameras;
    prepared->settings = scene.settings;
    prepared->materials_gathered = changed->size();
    return std::shared_ptr<const PreparedScene>(std::move(prepared));
}

}  // namespace

Expected<std::shared_ptr<const PreparedScene>> prepare_scene_edit(
    const Scene& before, const Scene& scene, std::shared_ptr<const PreparedScene> previous) {
    return edit(before, scene, nullptr, std::move(previous));
}

Expected<std::shared_ptr<const PreparedScene>> prepare_scene_edit(
    const Scene& before, std::shared_ptr<const Scene> scene,
    std::shared_ptr<const PreparedScene> previous) {
    if (!scene) scene = std::make_shared<const Scene>();
    const Scene& held = *scene;
    return edit(before, held, std::move(scene), std::move(previous));
}

}  // namespace jt

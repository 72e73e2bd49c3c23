#include "io/huge_pages.hpp"
#include "jtracer/vector_unit.hpp"
#include "render/embree_device.hpp"
#include "render/pattern.hpp"
#include "render/prepare_geometry.hpp"
#include "render/prepared_scene.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>

namespace jt {

namespace {

// A scene shared (prepare_scene(std::shared_ptr<const Scene>)) still has its
// materials copied while the copy stays this short (512 KiB of materials;
// their finishes are shared with the scene's, not copied): a short list stays
// in the caches, where reading each primitive's own material would walk the
// whole scene. Past it, the materials are read where the scene holds them.
constexpr std::size_t max_copied_materials = 16384;

// Each primitive's shape and world-to-object map when any material has a
// pattern; a primitive the transform rule leaves out is never hit, so any map
// will do.
std::vector<PatternSpace> pattern_spaces(const std::vector<Primitive>& primitives,
                                         const std::vector<Material>& materials) {
    if (std::none_of(materials.begin(), materials.end(), has_pattern)) return {};
    std::vector<PatternSpace> spaces(primitives.size());
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        spaces[i].shape = primitives[i].shape;
        if (primitives[i].transforms.empty()) continue;
        auto placed = object_transform(primitives[i].transforms);
        if (const auto* transform = std::get_if<ObjectTransform>(&placed))
            spaces[i].to_object = transform->to_object;
    }
    return spaces;
}

// The picture read from `path` whose stamp is now `stamp`, when `in` holds it
// as it is now (or the file is gone for the moment, as while an editor saves
// it): among its first `end` textures, or as its background map.
std::shared_ptr<const Texture> held_picture(const PreparedScene& in,
                                            const std::filesystem::path& path,
                                            const FileStamp& stamp, std::size_t end) {
    auto current = [&](const std::filesystem::path& file, const FileStamp& then) {
        return file == path && (then == stamp || !stamp.exists);
    };
    for (const PreparedScene::TextureSource& held : in.texture_sources)
        if (held.material < end && current(held.file, held.stamp))
            return in.textures[held.material];
    if (in.background_map && current(in.background_map_file, in.background_map_stamp))
        return in.background_map;
    return nullptr;
}

// The picture at `path`: from this scene or the previous prepared one when
// either holds it as it is now, else from disk. Errors start with `property`.
Expected<std::shared_ptr<const Texture>> picture(const PreparedScene& prepared, std::size_t end,
                                                 const PreparedScene* previous,
                                                 const std::filesystem::path& path,
                                                 const FileStamp& stamp,
                                                 std::string_view property) {
    std::shared_ptr<const Texture> texture = held_picture(prepared, path, stamp, end);
    if (!texture && previous)
        texture = held_picture(*previous, path, stamp, previous->textures.size());
    if (texture) return texture;
    Expected<std::shared_ptr<const Texture>> read = load_texture(path);
    if (!read) return Error{std::string(property) + ": " + read.error().message};
    return read;
}

// The picture of each material's image_map and of the background map, each
// file read once.
Expected<void> load_textures(const Scene& scene, PreparedScene& prepared,
                             const PreparedScene* previous) {
    // Only a pattern reads `textures` (trace.cpp), as only it reads pattern_space.
    if (!prepared.pattern_space.empty())
        prepared.textures.assign(prepared.materials.size(), nullptr);
    for (std::size_t i = 0; i < prepared.materials.size(); ++i) {
        if (prepared.materials[i].finish->image_map.empty()) continue;
        const std::filesystem::path path =
            asset_path(scene, prepared.materials[i].finish->image_map);
        const FileStamp stamp = file_stamp(path);
        auto texture = picture(prepared, i, previous, path, stamp, "image_map");
        if (!texture) return texture.error();
        prepared.textures[i] = std::move(*texture);
        prepared.texture_sources.push_back({i, path, stamp});
    }
    if (scene.settings.background_map.empty()) return {};
    const std::filesystem::path path = asset_path(scene, scene.settings.background_map);
    const FileStamp stamp = file_stamp(path);
    auto texture =
        picture(prepared, prepared.textures.size(), previous, path, stamp, "background_map");
    if (!texture) return texture.error();
    prepared.background_map = std::move(*texture);
    prepared.background_map_file = path;
    prepared.background_map_stamp = stamp;
    return {};
}

// Each primitive's material into `prepared`, runs of equal ones as one entry;
// `most` entries at most, else none and false (the caller reads them in place).
bool gather_materials(const Scene& scene, std::size_t most, PreparedScene& prepared) {
    prepared.materials.reserve(std::min(most, scene.primitives.size()));
    prepared.material_of.reserve(scene.primitives.size());
    for (const Primitive& p : scene.primitives) {
        if (prepared.materials.empty() || !(prepared.materials.back() == p.material)) {
            if (prepared.materials.size() == most) {
                prepared.materials = std::vector<Material>();
                prepared.material_of = std::vector<std::uint32_t>();
                return false;
            }
            prepared.materials.push_back(p.material);
        }
        prepared.material_of.push_back(static_cast<std::uint32_t>(prepared.materials.size() - 1));
    }
    return true;
}

// The same for a scene handed over, whose materials are moved out, not copied:
// its primitives are freed next, and a million distinct materials take 32 MB
// here where the primitives holding them took 96. While no two neighbours are
// alike, each primitive's entry is the one at its index and `material_of`
// stays empty; the first run of equal ones lists the entries so far.
void take_materials(Scene& scene, PreparedScene& prepared) {
    // Room for every primitive's own material: pages never written cost
    // nothing, while growing by copies would hold the old and new list at once.
    // Shading reads the list at random places: on 4 KiB pages, a million
    // materials' 32 MB miss the TLB at most hits, where the parser's array
    // of primitives they were read from sat on 2 MiB pages.
    prepared.materials.reserve(scene.primitives.size());
    advise_huge_pages(prepared.materials);
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        Material& m = scene.primitives[i].material;
        const bool alike = !prepared.materials.empty() && prepared.materials.back() == m;
        if (alike && prepared.material_of.empty()) {
            prepared.material_of.reserve(scene.primitives.size());
            for (std::uint32_t j = 0; j < i; ++j) prepared.material_of.push_back(j);
        }
        if (!alike) prepared.materials.push_back(std::move(m));
        if (!prepared.material_of.empty())
            prepared.material_of.push_back(
                static_cast<std::uint32_t>(prepared.materials.size() - 1));
    }
}

// The scene's materials are read in place only from a scene the prepared one
// shares (`owned`), only when no pattern needs `textures` and `pattern_space`
// (parallel to a gathered list), and only when a copy would be large. A scene
// handed over (`handed`, the same as `scene`) has its materials moved out and
// its primitives freed before the BVH is built, the largest allocation of all.
Expected<std::shared_ptr<const PreparedScene>> prepare(
    const Scene& scene, std::shared_ptr<const Scene> owned, Scene* handed,
    std::shared_ptr<const PreparedScene> previous) {
    // Checked here, before any work: the geometry needs the device, and a
    // vector unit asked for and missing must not be passed over in silence.
    if (!embree_device()) return Error{embree_device_failure()};
    if (!vector_unit().failure.empty()) return Error{vector_unit().failure};
    auto prepared = std::make_shared<PreparedScene>();
    // The digest decides first whether a previous geometry serves again;
    // without one it is only kept for the next time, and worked out beside
    // the build (a pass over a million primitives).
    const bool may_reuse = previous && previous->geometry;
    GeometryDigest digest = may_reuse ? digest_geometry(scene) : GeometryDigest{};
    const bool reuse = may_reuse && previous->geometry->digest == digest;
    std::shared_ptr<Geometry> built_geometry;
    std::optional<std::vector<DirectionTable>> built_tables;  // with built_geometry
    std::optional<Error> build_error;
    auto build = [&] {
        if (reuse) return;
        auto gathered = gather_geometry(scene);
        if (!gathered) {
            build_error = gathered.error();
            return;
        }
        built_geometry = std::move(*gathered);
        // A scene handed over is freed first (below); one shared stays anyway.
        if (!handed) built_tables = build_bvh_and_light_tables(*built_geometry, scene.lights);
    };
    auto read_materials = [&] {
        prepared->materials_gathered = scene.primitives.size();
        if (handed) {
            take_materials(*handed, *prepared);
        } else {
            const bool may_read_in_place =
                owned && std::none_of(scene.primitives.begin(), scene.primitives.end(),
                                      [](const Primitive& p) { return has_pattern(p.material); });
            const std::size_t most =
                may_read_in_place ? max_copied_materials : scene.primitives.size();
            if (!gather_materials(scene, most, *prepared)) prepared->scene = std::move(owned);
        }
        const auto transmits = [](const Material& m) { return m.finish->transmission > 0.0; };
        prepared->has_transmission =
            prepared->scene
                ? std::any_of(scene.primitives.begin(), scene.primitives.end(),
                              [&](const Primitive& p) { return transmits(p.material); })
                : std::any_of(prepared->materials.begin(), prepared->materials.end(), transmits);
        prepared->pattern_space = pattern_spaces(scene.primitives, prepared->materials);
    };
    // The geometry reads only shapes and transforms, as the digest does, the
    // materials only materials; for a million primitives the build is worth a
    // core, the rest another.
    auto beside_build = [&] {
        if (!may_reuse) digest = digest_geometry(scene);
        read_materials();
    };
    if (scene.primitives.size() > 10000)
        tbb::parallel_invoke(build, beside_build);
    else {
        build();
        beside_build();
    }
    if (build_error) return *build_error;
    if (handed) {
        handed->primitives = std::vector<Primitive>();
        if (built_geometry)
            built_tables = build_bvh_and_light_tables(*built_geometry, scene.lights);
    }
    if (built_geometry) {
        built_geometry->digest = digest;
        prepared->geometry = std::move(built_geometry);
    } else {
        prepared->geometry = previous->geometry;
    }
    if (Expected<void> textures = load_textures(scene, *prepared, previous.get()); !textures)
        return textures.error();
    prepared->lights = scene.lights;
    if (built_tables)
        prepared->light_tables =
            std::make_shared<const std::vector<DirectionTable>>(std::move(*built_tables));
    else if (previous && previous->geometry == prepared->geometry &&
             previous->lights == scene.lights)
        prepared->light_tables = previous->light_tables;
    else
        prepared->light_tables = std::make_shared<const std::vector<DirectionTable>>(
            build_light_tables(*prepared->geometry, scene.lights));
    prepared->cameras = scene.cameras;
    prepared->settings = scene.settings;
    return std::shared_ptr<const PreparedScene>(std::move(prepared));
}

}  // namespace

Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    const Scene& scene, std::shared_ptr<const PreparedScene> previous) {
    return prepare(scene, nullptr, nullptr, std::move(previous));
}

Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    Scene&& scene, std::shared_ptr<const PreparedScene> previous) {
    // Taken over here, so that its primitives are gone once prepare frees them.
    Scene handed = std::move(scene);
    return prepare(handed, nullptr, &handed, std::move(previous));
}

Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    std::shared_ptr<const Scene> scene, std::shared_ptr<const PreparedScene> previous) {
    if (!scene) scene = std::make_shared<const Scene>();
    const Scene& held = *scene;
    return prepare(held, std::move(scene), nullptr, std::move(previous));
}

}  // namespace jt

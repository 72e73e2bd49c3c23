#include "jtracer/scene_info.hpp"

#include "jtracer/affine.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/primitive_bounds.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/texture.hpp"
#include "render/embree_device.hpp"

#include <algorithm>
#include <chrono>
#include <set>

namespace jt {

void WorldBox::add(const Vec3& point) {
    lower = lower ? glm::min(*lower, point) : point;
    upper = upper ? glm::max(*upper, point) : point;
}

void WorldBox::add(const WorldBox& box) {
    if (!box.empty()) add(*box.lower), add(*box.upper);
}

namespace {

std::size_t model_bytes(const Model& m) {
    return m.positions.size() * sizeof(m.positions[0]) + m.normals.size() * sizeof(m.normals[0]) +
           m.uvs.size() * sizeof(m.uvs[0]) + m.triangles.size() * sizeof(m.triangles[0]) +
           m.colours.size() * sizeof(m.colours[0]) + m.part_of.size() * sizeof(m.part_of[0]);
}

bool has_normals(const Model& m) {
    return std::any_of(m.normals.begin(), m.normals.end(),
                       [](const glm::vec3& n) { return n != glm::vec3(0.0f); });
}

struct ReadModel {
    Expected<Model> model = Error{""};
    double seconds = 0.0;
};

}  // namespace

std::vector<MeshPartInfo> mesh_parts(const Model& model) {
    std::vector<MeshPartInfo> parts(model.parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const ModelPart& part = model.parts[i];
        parts[i].name = part.name;
        if (part.has_material) parts[i].base = part.base;
        parts[i].texture = part.texture_name;
        parts[i].vertex_colours = part.vertex_colours;
    }
    for (const std::uint32_t part : model.part_of) ++parts[part].triangles;
    // Materials of meshes no node places, or of points and lines only.
    std::erase_if(parts, [](const MeshPartInfo& part) { return part.triangles == 0; });
    return parts;
}

MeshInfo mesh_info(const Scene& scene, const Primitive& primitive, const Mesh& mesh,
                   const Model& model) {
    MeshInfo info;
    info.file = mesh.file;
    info.path = asset_path(scene, mesh.file);
    info.triangles = model.triangles.size();
    info.vertices = model.positions.size();
    info.normals = has_normals(model)                                                ? "file"
                   : mesh.shading == kSmoothShading && mesh.smooth_angle.has_value() ? "generated"
                                                                                     : "none";
    info.shading = mesh.shading;
    info.materials = mesh.materials;
    info.parts = mesh_parts(model);
    const auto transform = object_transform(primitive.transforms);
    if (const auto* placed = std::get_if<ObjectTransform>(&transform))
        for (const auto& triangle : model.triangles)
            for (std::uint32_t corner : triangle)
                info.world_box.add(apply_point(placed->to_world, Vec3(model.positions[corner])));
    return info;
}

Expected<MeshInfo> mesh_info(const Scene& scene, const Primitive& primitive) {
    const auto* mesh = shape_if<Mesh>(&primitive.shape);
    if (!mesh) return Error{"not a mesh"};
    const Expected<std::shared_ptr<const Model>> model = shared_model(
        asset_path(scene, mesh->file), scene.asset_folder, mesh->materials == kFileMaterials);
    if (!model) return model.error();
    return mesh_info(scene, primitive, *mesh, **model);
}

Expected<SceneInfo> scene_info(const Scene& scene) {
    SceneInfo info;
    for (const Shape& kind :
         {Shape{Sphere{}}, Shape{Plane{}}, Shape{Cylinder{}}, Shape{Triangle{}}, Shape{Mesh{}}})
        info.primitives[std::string(keyword_of(kind))] = 0;
    // Each file read once (once more when also with its materials), timed.
    std::map<std::pair<std::filesystem::path, bool>, ReadModel> models;
    std::set<const Texture*> textures;  // the models' own, each counted once
    for (const Primitive& p : scene.primitives) {
        ++info.primitives[std::string(keyword_of(p.shape))];
        if (!std::holds_alternative<ObjectTransform>(object_transform(p.transforms))) {
            ++info.left_out;
            continue;
        }
        if (shape_is<Plane>(p.shape)) {
            ++info.unbounded;
        } else if (const auto* mesh = shape_if<Mesh>(&p.shape)) {
            const std::filesystem::path path = asset_path(scene, mesh->file);
            const bool file_materials = mesh->materials == kFileMaterials;
            auto [at, fresh] = models.try_emplace({path, file_materials});
            if (fresh) {
                const auto start = std::chrono::steady_clock::now();
                at->second.model = read_model(path, scene.asset_folder, file_materials);
                at->second.seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (at->second.model) {
                    info.memory.models += model_bytes(*at->second.model);
                    // The pictures of its parts count with the image maps.
                    for (const ModelPart& part : at->second.model->parts)
                        if (part.texture && textures.insert(part.texture.get()).second)
                            info.memory.image_maps +=
                                part.texture->rgb8.size() + part.texture->rgb16.size() * 2;
                }
            }
            if (!at->second.model) return at->second.model.error();
            MeshInfo row = mesh_info(scene, p, *mesh, *at->second.model);
            row.load_seconds = at->second.seconds;
            row.read_before = !fresh;
            info.world_box.add(row.world_box);
            info.meshes.push_back(std::move(row));
        } else if (const std::optional<Bounds> box = primitive_bounds(p)) {
            info.world_box.add(box->lower);
            info.world_box.add(box->upper);
        }
    }
    // Each picture's memory once, though a material may name the background
    // map's file too: they share one decoded copy.
    const std::filesystem::path sky = scene.settings.background_map.empty()
                                          ? std::filesystem::path()
                                          : asset_path(scene, scene.settings.background_map);
    std::vector<std::filesystem::path> material_maps;
    for (const Primitive& p : scene.primitives)
        if (!p.material.finish->image_map.empty())
            material_maps.push_back(asset_path(scene, p.material.finish->image_map));
    for (const std::filesystem::path& path : named_files(scene).images) {
        const Expected<std::shared_ptr<const Texture>> texture = load_texture(path);
        if (!texture) return texture.error();
        const std::size_t bytes = (*texture)->rgb8.size() + (*texture)->rgb16.size() * 2;
        info.memory.image_maps += bytes;
        const ImageMapInfo row{path, (*texture)->width, (*texture)->height, bytes};
        if (!sky.empty() && path == sky) info.background_map = row;
        if (std::find(material_maps.begin(), material_maps.end(), path) != material_maps.end())
            info.image_maps.push_back(row);
    }
    info.memory.primitives = scene.primitives.size() * sizeof(Primitive);

    const std::int64_t before = embree_device_bytes();
    const Expected<std::shared_ptr<const PreparedScene>> prepared = prepare_scene(scene);
    if (!prepared) return prepared.error();
    info.memory.embree =
        static_cast<std::size_t>(std::max<std::int64_t>(embree_device_bytes() - before, 0));
    return info;
}

}  // namespace jt

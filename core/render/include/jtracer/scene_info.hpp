#pragma once
// Figures about a scene once loaded: how many primitives of each kind, each
// mesh's triangles and world box, the image maps' and background map's sizes,
// and the memory its prepared form takes. `jtracer-cli info` prints them; the
// viewer's Objects panel shows a selected mesh's.

#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/scene.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace jt {

// An axis-aligned box in world space; empty until a point is added.
struct WorldBox {
    std::optional<Vec3> lower, upper;
    bool empty() const { return !lower; }
    Vec3 size() const { return empty() ? Vec3(0.0) : *upper - *lower; }
    void add(const Vec3& point);
    void add(const WorldBox& box);
};

// One part of a model read with `materials: "file"` (docs/language.md §14.5).
struct MeshPartInfo {
    std::string name;             // the material's name; "" for the faces without one
    std::optional<Colour> base;   // none for the faces without a material
    std::string texture;          // as the file names it; "" for none
    bool vertex_colours = false;  // some triangle has a colour at all three corners
    std::size_t triangles = 0;
};

// The model's parts that hold a triangle, in the order first used, each with
// its triangles; empty for a model read without its materials.
std::vector<MeshPartInfo> mesh_parts(const Model& model);

struct MeshInfo {
    std::string file;            // as the scene names it
    std::filesystem::path path;  // where it was read from (asset_path)
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    // Where its shading normals come from: "file" (the file gives them),
    // "generated" (smooth with smooth_angle: the missing ones are made) or
    // "none" (its triangles are shaded flat, docs/language.md 14.4).
    std::string normals;
    std::string shading;              // the mesh's `shading`
    std::string materials;            // the mesh's `materials`
    std::vector<MeshPartInfo> parts;  // with materials "file": mesh_parts
    WorldBox world_box;               // around its triangles' corners, through its transforms
    double load_seconds = 0.0;        // to read the file (scene_info only)
    bool read_before = false;         // the file of an earlier mesh (scene_info only)
};

// A mesh's figures from its model, through the primitive's transforms (its
// box is empty when they flatten it or leave the range of doubles).
MeshInfo mesh_info(const Scene& scene, const Primitive& primitive, const Mesh& mesh,
                   const Model& model);

// The same from the shared model cache (model_cache.hpp): what the viewer
// shows, without reading a file the render has read. Fails as the read does.
Expected<MeshInfo> mesh_info(const Scene& scene, const Primitive& primitive);

struct ImageMapInfo {
    std::filesystem::path path;
    int width = 0, height = 0;
    std::size_t bytes = 0;  // of its decoded texels
};

// Bytes of the prepared scene (render_job.hpp's prepare_scene).
struct SceneMemory {
    std::size_t models = 0;      // vertices and triangles of the models read
    std::size_t image_maps = 0;  // decoded texels, the background map's included
    std::size_t primitives = 0;  // the primitive records
    // What Embree holds while the prepared scene lives: its acceleration
    // structure and its copy of the triangles, as its memory monitor counts
    // them while the scene is prepared.
    std::size_t embree = 0;
    std::size_t total() const { return models + image_maps + primitives + embree; }
};

struct SceneInfo {
    std::map<std::string, int> primitives;  // by keyword, every kind listed
    std::vector<MeshInfo> meshes;           // in scene order, each mesh a row
    WorldBox world_box;                     // of every bounded primitive
    int unbounded = 0;                      // planes: no box holds them
    int left_out = 0;                       // flattened by a zero scale, or out of range
    std::vector<ImageMapInfo> image_maps;   // each file once, in scene order
    // render_settings' background_map, when it names one.
    std::optional<ImageMapInfo> background_map;
    SceneMemory memory;
};

// Reads each model file once (timed) and each image map, then prepares the
// scene to count Embree's memory. For a scene that passed check_scene: fails
// with the error of a file that cannot be read, or when Embree cannot start.
// Embree's figure is its device's growth while preparing: another scene
// prepared in the process at the same time would be counted in it.
Expected<SceneInfo> scene_info(const Scene& scene);

}  // namespace jt

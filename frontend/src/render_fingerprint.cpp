#include "jtracer/frontend/render_fingerprint.hpp"

#include "jtracer/digest.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/texture.hpp"

#include <fstream>
#include <string_view>
#include <vector>

namespace jt::frontend {

namespace {

void add_file(Digest128& digest, const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chunk(1 << 20);
    if (!in) return digest.add(std::string_view("unreadable"));
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        digest.add(std::string_view(chunk.data(), static_cast<std::size_t>(in.gcount())));
    }
}

}  // namespace

RenderFingerprint render_fingerprint(const Scene& scene, const RenderOptions& render,
                                     double clock) {
    Digest128 digest;
    // The scene without its primitives, then each primitive as the
    // serializer writes it: never the whole text at once, which for a
    // scene of millions of primitives is gigabytes. The settings the
    // fingerprint or the placement hold apart, or that differ from part to
    // part, are set to their defaults first.
    Scene head;
    head.settings = scene.settings;
    head.cameras = scene.cameras;
    head.lights = scene.lights;
    const RenderSettings defaults;
    head.settings.filename = defaults.filename;
    head.settings.width = defaults.width;
    head.settings.height = defaults.height;
    head.settings.samples = defaults.samples;
    head.settings.active_camera = defaults.active_camera;
    digest.add(serialize_scene(head));
    for (const Primitive& primitive : scene.primitives)
        for (const std::string& line : block_lines(primitive)) digest.add(line);
    const NamedFiles files = named_files(scene);
    for (const auto* list : {&files.models, &files.images})
        for (const std::filesystem::path& path : *list) add_file(digest, path);
    RenderFingerprint fingerprint;
    fingerprint.scene = digest.bytes();
    fingerprint.samples = render.samples;
    fingerprint.camera = render.camera;
    if (render.camera >= 0 && static_cast<std::size_t>(render.camera) < scene.cameras.size())
        fingerprint.camera_name = scene.cameras[static_cast<std::size_t>(render.camera)].name;
    fingerprint.camera_name.resize(std::min<std::size_t>(fingerprint.camera_name.size(), 32));
    fingerprint.clock = clock;
    return fingerprint;
}

}  // namespace jt::frontend

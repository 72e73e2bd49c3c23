#include "jtracer/frontend/render_fingerprint.hpp"

#include "jtracer/serializer.hpp"
#include "jtracer/texture.hpp"

#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

namespace jt::frontend {

namespace {

// Two independent multiply-xorshift lanes, 8 bytes a step: 128 bits, so that
// an accidental match is out of the question, at the speed of reading.
struct Digest {
    std::uint64_t a = 0x9E3779B97F4A7C15ull;
    std::uint64_t b = 0xC2B2AE3D27D4EB4Full;

    void add(std::uint64_t v) {
        a = (a ^ v) * 0xFF51AFD7ED558CCDull;
        a ^= a >> 33;
        b = (b + v) * 0x94D049BB133111EBull;
        b ^= b >> 31;
    }
    void add(std::string_view bytes) {
        add(static_cast<std::uint64_t>(bytes.size()));
        std::size_t i = 0;
        for (; i + 8 <= bytes.size(); i += 8) {
            std::uint64_t v = 0;
            std::memcpy(&v, bytes.data() + i, 8);
            add(v);
        }
        std::uint64_t rest = 0;
        std::memcpy(&rest, bytes.data() + i, bytes.size() - i);
        add(rest);
    }
    std::array<std::uint8_t, 16> bytes() const {
        std::array<std::uint8_t, 16> out{};
        for (int i = 0; i < 8; ++i) {
            out[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(a >> (8 * i));
            out[static_cast<std::size_t>(8 + i)] = static_cast<std::uint8_t>(b >> (8 * i));
        }
        return out;
    }
};

void add_file(Digest& digest, const std::filesystem::path& path) {
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
    Digest digest;
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

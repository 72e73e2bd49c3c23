#include "jtracer/frontend/render_fingerprint.hpp"

#include "jtracer/digest.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/texture.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
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

// One member's value: a number by its bits (the same on every machine that
// uses IEEE doubles, which the language's shortest round-trip text assumes
// too), an optional as whether it is set and then its value.
void add_value(Digest128& digest, double value) {
    digest.add(value);
}
void add_value(Digest128& digest, const Vec3& value) {
    digest.add(value.x);
    digest.add(value.y);
    digest.add(value.z);
}
void add_value(Digest128& digest, const std::string& value) {
    digest.add(std::string_view(value));
}
template <class T>
void add_value(Digest128& digest, const std::optional<T>& value) {
    digest.add(static_cast<std::uint64_t>(value.has_value()));
    if (value) add_value(digest, *value);
}

// Every property the schema gives the block, in its order, whether or not the
// serializer would write it: the schema is what the serializer writes from,
// so this covers at least what the block's canonical text does.
template <class Block>
void add_block(Digest128& digest, const Block& block) {
    for (const PropertySpec<Block>& property : schema_of<Block>().properties)
        std::visit([&](const auto& member) { add_value(digest, member_ref(block, member)); },
                   property.member);
}

// A primitive's values straight from the model, not through its text: the
// text of each number costs more than reading it did, which for a scene of
// many primitives made the fingerprint slower than the parse.
void add_primitive(Digest128& digest, const Primitive& primitive) {
    visit_shape(
        [&](const auto& shape) {
            digest.add(schema_of<std::decay_t<decltype(shape)>>().keyword);
            add_block(digest, shape);
        },
        primitive.shape);
    add_block(digest, primitive.material);
    digest.add(static_cast<std::uint64_t>(primitive.transforms.size()));
    for (const TransformOp& op : primitive.transforms) {
        digest.add(transform_op(op.kind).property.name);
        add_value(digest, op.vector);
        add_value(digest, op.degrees);
    }
}

}  // namespace

RenderFingerprint render_fingerprint(const Scene& scene, const RenderOptions& render,
                                     double clock) {
    Digest128 digest;
    // The scene without its primitives as the serializer writes it, then
    // each primitive's values. The settings the fingerprint or the placement
    // hold apart, or that differ from part to part, are set to their
    // defaults first.
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
    digest.add(static_cast<std::uint64_t>(scene.primitives.size()));
    for (const Primitive& primitive : scene.primitives) add_primitive(digest, primitive);
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

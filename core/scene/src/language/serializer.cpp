#include "jtracer/serializer.hpp"

#include "jtracer/schema.hpp"
#include "language/scene_writer.hpp"

#include <string_view>

namespace jt {

namespace lang {

std::vector<std::string> Writer::lines() const {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

void write_primitive(Writer& w, const Primitive& p) {
    w.open(keyword_of(p.shape));
    visit_shape([&](const auto& shape) { write_properties(w, shape); }, p.shape);
    write_block(w, p.material);
    if (!p.transforms.empty()) write_transform(w, p.transforms);
    w.close();
}

}  // namespace lang

using lang::Writer;

std::string transform_op_statement(const TransformOp& op) {
    const PropertySpec<TransformOp>& property = transform_op(op.kind).property;
    return std::string(property.name) + ": " + value_text(property, op) + ";";
}

namespace {
// The lines `write` writes.
template <class Write>
std::vector<std::string> lines_written(Write write) {
    Writer w;
    write(w);
    return w.lines();
}
}  // namespace

std::vector<std::string> block_lines(const Primitive& primitive) {
    return lines_written([&](Writer& w) { lang::write_primitive(w, primitive); });
}
std::vector<std::string> block_lines(const PointLight& light) {
    return lines_written([&](Writer& w) { lang::write_block(w, light); });
}
std::vector<std::string> block_lines(const Camera& camera) {
    return lines_written([&](Writer& w) { lang::write_block(w, camera); });
}
std::vector<std::string> block_lines(const Material& material) {
    return lines_written([&](Writer& w) { lang::write_block(w, material); });
}
std::vector<std::string> transform_block_lines(const std::vector<TransformOp>& ops) {
    return lines_written([&](Writer& w) { lang::write_transform(w, ops); });
}

std::string serialize_scene(const Scene& scene) {
    Writer w;
    w.text = lang::kWrittenBy;
    lang::write_blocks(
        w, scene, [&] { lang::write_block(w, scene.settings); },
        [&](std::size_t i) { lang::write_block(w, scene.cameras[i]); },
        [&](std::size_t i) { lang::write_primitive(w, scene.primitives[i]); },
        [&](std::size_t i) { lang::write_block(w, scene.lights[i]); });
    return std::move(w.text);
}

}  // namespace jt

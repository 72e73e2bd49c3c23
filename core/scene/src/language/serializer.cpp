#include "jtracer/serializer.hpp"

#include "jtracer/schema.hpp"

#include <string_view>

namespace jt {

namespace {

// Four spaces of indentation per nesting level.
class Writer {
  public:
    std::string text;

    void open(std::string_view keyword) {
        indent();
        text.append(keyword).append(" {\n");
        ++depth_;
    }
    void close() {
        --depth_;
        indent();
        text.append("}\n");
    }
    void property(std::string_view name, std::string_view value) {
        indent();
        text.append(name).append(": ").append(value).append(";\n");
    }
    void line(std::string_view content) {
        indent();
        text.append(content).append("\n");
    }
    void blank() { text += '\n'; }

    std::vector<std::string> lines() const {
        std::vector<std::string> out;
        std::size_t start = 0;
        while (start < text.size()) {
            const std::size_t end = text.find('\n', start);
            out.push_back(text.substr(start, end - start));
            start = end + 1;
        }
        return out;
    }

  private:
    void indent() { text.append(static_cast<std::size_t>(depth_) * 4, ' '); }
    int depth_ = 0;
};

// Every property of the block, in the schema's order.
template <class Block>
void write_properties(Writer& w, const Block& block) {
    for (const PropertySpec<Block>& property : schema_of<Block>().properties) {
        if (!is_written(property, block)) continue;
        w.property(property.name, value_text(property, block));
    }
}

template <class Block>
void write_block(Writer& w, const Block& block) {
    w.open(schema_of<Block>().keyword);
    write_properties(w, block);
    w.close();
}

void write_transform(Writer& w, const std::vector<TransformOp>& ops) {
    w.open(kTransformKeyword);
    for (const TransformOp& op : ops) w.line(transform_op_statement(op));
    w.close();
}

void write_primitive(Writer& w, const Primitive& p) {
    w.open(keyword_of(p.shape));
    std::visit([&](const auto& shape) { write_properties(w, shape); }, p.shape);
    write_block(w, p.material);
    if (!p.transforms.empty()) write_transform(w, p.transforms);
    w.close();
}

}  // namespace

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
    return lines_written([&](Writer& w) { write_primitive(w, primitive); });
}
std::vector<std::string> block_lines(const PointLight& light) {
    return lines_written([&](Writer& w) { write_block(w, light); });
}
std::vector<std::string> block_lines(const Camera& camera) {
    return lines_written([&](Writer& w) { write_block(w, camera); });
}
std::vector<std::string> block_lines(const Material& material) {
    return lines_written([&](Writer& w) { write_block(w, material); });
}
std::vector<std::string> transform_block_lines(const std::vector<TransformOp>& ops) {
    return lines_written([&](Writer& w) { write_transform(w, ops); });
}

std::string serialize_scene(const Scene& scene) {
    Writer w;
    w.text = "# Written by JTracer.\n\n";
    write_block(w, scene.settings);
    w.blank();
    w.open(kCamerasKeyword);
    for (const Camera& c : scene.cameras) write_block(w, c);
    w.close();
    w.blank();
    w.open(kSceneKeyword);
    for (const Primitive& p : scene.primitives) write_primitive(w, p);
    for (const PointLight& light : scene.lights) write_block(w, light);
    w.close();
    return std::move(w.text);
}

}  // namespace jt

#include "jtracer/serializer.hpp"

#include "jtracer/schema.hpp"

#include <string_view>

namespace jt {

namespace {

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
    void blank() { text += '\n'; }

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

void write_primitive(Writer& w, const Primitive& p) {
    w.open(keyword_of(p.shape));
    std::visit([&](const auto& shape) { write_properties(w, shape); }, p.shape);
    write_block(w, p.material);
    if (!p.transforms.empty()) {
        w.open(kTransformKeyword);
        for (const TransformOp& op : p.transforms) {
            const PropertySpec<TransformOp>& property = transform_op(op.kind).property;
            w.property(property.name, value_text(property, op));
        }
        w.close();
    }
    w.close();
}

}  // namespace

std::string serialize_scene(const Scene& scene) {
    Writer w;
    w.text = "# Written by JTracer.\n\n";
    write_block(w, scene.settings);
    w.blank();
    w.open("cameras");
    for (const Camera& c : scene.cameras) write_block(w, c);
    w.close();
    w.blank();
    w.open("scene");
    for (const Primitive& p : scene.primitives) write_primitive(w, p);
    for (const PointLight& light : scene.lights) write_block(w, light);
    w.close();
    return std::move(w.text);
}

}  // namespace jt

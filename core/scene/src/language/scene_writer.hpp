#pragma once
// The canonical layout of .jts text, shared by serialize_scene (serializer.hpp)
// and the serializer that keeps a text's names (source_serializer.hpp): four
// spaces of indentation a level, a block's properties in the schema's order,
// each property on a line of its own. Only how a value is spelled differs, so
// the two write it through one PropertyText choice per property.

#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace jt::lang {

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

    std::vector<std::string> lines() const;

  private:
    void indent() { text.append(static_cast<std::size_t>(depth_) * 4, ' '); }
    int depth_ = 0;
};

// How one property of a block is written.
struct PropertyText {
    enum class How : std::uint8_t {
        canonical,   // its value as value_text, unless writes_canonically says not
        literal,     // its value as value_text, always
        as_written,  // `text`, the value as a file wrote it
        omitted,     // not at all
    };
    How how = How::canonical;
    std::string_view text;
};

// Whether the canonical layout writes the property: not when the schema omits
// its default, nor when its default is a value its own range refuses. A
// `mesh { }` without its `file` parses (the validator reports it) and holds
// "", which written as `file: "";` would not read back.
template <class Block>
bool writes_canonically(const PropertySpec<Block>& property, const Block& block) {
    if (!is_written(property, block)) return false;
    return !(is_default(property, block) && value_problem(property, block));
}

// Whether `choose` writes anything of `block`.
template <class Block, class Choose>
bool writes_any(const Block& block, Choose choose) {
    for (const PropertySpec<Block>& property : schema_of<Block>().properties) {
        const PropertyText how = choose(property);
        if (how.how != PropertyText::How::omitted &&
            (how.how != PropertyText::How::canonical || writes_canonically(property, block)))
            return true;
    }
    return false;
}

// Every property of the block, in the schema's order, as `choose` says.
template <class Block, class Choose>
void write_properties(Writer& w, const Block& block, Choose choose) {
    for (const PropertySpec<Block>& property : schema_of<Block>().properties) {
        const PropertyText how = choose(property);
        switch (how.how) {
            case PropertyText::How::canonical:
                if (writes_canonically(property, block))
                    w.property(property.name, value_text(property, block));
                break;
            case PropertyText::How::literal:
                w.property(property.name, value_text(property, block));
                break;
            case PropertyText::How::as_written:
                w.property(property.name, how.text);
                break;
            case PropertyText::How::omitted:
                break;
        }
    }
}

template <class Block>
void write_properties(Writer& w, const Block& block) {
    write_properties(w, block, [](const PropertySpec<Block>&) { return PropertyText{}; });
}

template <class Block>
void write_block(Writer& w, const Block& block) {
    w.open(schema_of<Block>().keyword);
    write_properties(w, block);
    w.close();
}

// A transform block holding `ops`; `as_written(i)` gives the i-th operation's
// value as a file wrote it, or an empty view for its value_text.
template <class AsWritten>
void write_transform(Writer& w, const std::vector<TransformOp>& ops, AsWritten as_written) {
    w.open(kTransformKeyword);
    for (std::size_t i = 0; i < ops.size(); ++i) {
        const std::string_view written = as_written(i);
        if (written.empty())
            w.line(transform_op_statement(ops[i]));
        else
            w.property(transform_op(ops[i].kind).property.name, written);
    }
    w.close();
}

inline void write_transform(Writer& w, const std::vector<TransformOp>& ops) {
    write_transform(w, ops, [](std::size_t) { return std::string_view(); });
}

// A primitive with every value as value_text.
void write_primitive(Writer& w, const Primitive& p);

// The three top-level blocks, after whatever `w` holds: `settings`,
// `camera(i)`, `primitive(i)` and `light(i)` write each block.
template <class WriteSettings, class WriteCamera, class WritePrimitive, class WriteLight>
void write_blocks(Writer& w, const Scene& scene, WriteSettings settings, WriteCamera camera,
                  WritePrimitive primitive, WriteLight light) {
    settings();
    w.blank();
    w.open(kCamerasKeyword);
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) camera(i);
    w.close();
    w.blank();
    w.open(kSceneKeyword);
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) primitive(i);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) light(i);
    w.close();
}

// The first line of every serialised text.
inline constexpr std::string_view kWrittenBy = "# Written by JTracer.\n\n";

}  // namespace jt::lang

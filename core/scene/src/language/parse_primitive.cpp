// A primitive's body: its shape's properties, its material (a block of its
// own, a named material it uses, or both: docs/language.md §15.2) and its
// transforms.

#include "jtracer/schema.hpp"
#include "language/block_body.hpp"
#include "language/quote.hpp"
#include "language/scene_parser.hpp"
#include "language/suggest.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace jt::lang {
namespace {

// Copies into `to` each material property whose bit is clear in `kept`.
void inherit_material(const Material& from, Material& to, std::uint32_t kept) {
    const auto properties = schema_of<Material>().properties;
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (kept & (1u << i)) continue;
        copy_value(properties[i], from, to);
    }
}

constexpr bool material_names_are_unique() {
    const auto properties = schema_of<Material>().properties;
    for (std::size_t i = 0; i < properties.size(); ++i)
        for (std::size_t j = i + 1; j < properties.size(); ++j)
            if (same_name(properties[i].name, properties[j].name)) return false;
    return true;
}
static_assert(material_names_are_unique(), "material_mask stops at a name's first match");

// The bits of the material properties named in `records`. Names are unique,
// so the search for each stops at its match: the common ones come first, and
// comparing every name with each record was 7% of a parse.
std::uint32_t material_mask(std::span<const PropertySource> records) {
    const auto properties = schema_of<Material>().properties;
    std::uint32_t mask = 0;
    for (const PropertySource& p : records) {
        for (std::size_t i = 0; i < properties.size() && i < 32; ++i) {
            if (same_name(properties[i].name, p.name)) {
                mask |= 1u << i;
                break;
            }
        }
    }
    return mask;
}

// How a message names the kind of a name's value.
std::string kind_words(const Symbol& symbol) {
    switch (symbol.value.kind) {
        case ExprValue::Kind::number:
            return "a number";
        case ExprValue::Kind::vector:
            return "a vector";
        default:
            return "a string";
    }
}

}  // namespace

// A primitive's children go straight to the scene's array of child records:
// nothing else is added there until the primitive's '}', so they stay together.
void SceneParser::parse_primitive_body(Primitive& primitive, OpenBlock& open) {
    BlockSource& block = open.source;
    std::vector<BlockSource>& children = result_.source.children;
    const std::size_t first_child = children.size();
    std::uint32_t own_material = 0;  // the properties its own material blocks set
    const Symbol* named = nullptr;
    SourcePos named_at;
    parse_body(
        block, primitive_blocks(),
        [&](const Property& p) { reader_.apply(primitive.shape, open, p); },
        [&] {
            BlockSource child;
            bool opened;
            const bool material = same_name(cur_->text, schema_of<Material>().keyword);
            if (material && next_->kind == TokenKind::colon) {
                const SourcePos at = cur_->pos;
                if (const Symbol* found = read_material_reference()) {
                    if (named) {
                        sink_.error(at,
                                    "a primitive names at most one material; this one "
                                    "already names one at " +
                                        include_.where(named_at, at));
                        return;
                    }
                    named = found;
                    named_at = at;
                    if (found->reads_clock) expressions_.note_clock_read();
                    inherit_material(found->material, primitive.material, own_material);
                    block.named_material = found->definition;
                }
                return;
            }
            if (material && next_->kind == TokenKind::word) {
                sink_.error(cur_->pos,
                            "a named material is defined at the top level; inside a "
                            "primitive, write 'material: NAME;' to use one");
                skip_block();
                return;
            }
            if (material) {
                opened = parse_property_block(child, 1, primitive.material,
                                              schema_of<Material>().keyword);
                // Unopened, the block read nothing: the buffer still holds
                // the records of the last block read at this level.
                if (opened) own_material |= material_mask(property_buffers_[1]);
            } else if (same_name(cur_->text, kTransformKeyword)) {
                opened = parse_property_block(child, 1, primitive.transforms);
            } else {
                unknown_block("in '" + std::string(block.keyword) + "'", primitive_blocks(),
                              &block);
                return;
            }
            if (opened && source_map_ && keep_primitives_) children.push_back(child);
        });
    block.children = {static_cast<std::uint32_t>(first_child),
                      static_cast<std::uint32_t>(children.size() - first_child)};
}

const Symbol* SceneParser::read_material_reference() {
    advance();
    advance();
    const Token name = *cur_;
    const std::string expected =
        "'material:' takes the name of a material defined at the top level with "
        "'material NAME { ... }'";
    if (name.kind != TokenKind::word) {
        if (name.kind != TokenKind::bad_value)
            sink_.error(name.pos, expected + ", got " + describe(name));
        skip_statement();
        return nullptr;
    }
    const Symbol* symbol = names_.find(name.text);
    advance();
    if (!symbol) {
        if (!names_.reports_unknown()) {
            skip_statement();
            return nullptr;
        }
        std::string message = "unknown name " + quote(name.text.substr(0, 40)) +
                              " (names must be defined before they are used)";
        const std::vector<std::string_view> known = names_.names();
        if (std::string_view near = nearest_name(name.text, known); !near.empty())
            message += "; did you mean " + quote(near) + "?";
        sink_.error(name.pos, std::move(message));
        skip_statement();
        return nullptr;
    }
    if (symbol->kind != Symbol::Kind::material) {
        if (!symbol->bad)
            sink_.error(name.pos, quote(name.text) + " is " + kind_words(*symbol) +
                                      ", not a material: " + expected);
        skip_statement();
        return nullptr;
    }
    if (!at(TokenKind::semicolon)) {
        sink_.error(cur_->pos, "expected ';' after 'material: " + std::string(name.text) +
                                   "', got " + describe(*cur_));
        skip_statement();
        return symbol->bad ? nullptr : symbol;
    }
    advance();
    return symbol->bad ? nullptr : symbol;
}

}  // namespace jt::lang

#pragma once
// How the body of every block is read: the loop over its entries
// (parse_body), the records of its properties (read_properties) and the runs
// of plain properties read without tokens (read_plain_run). Templates,
// defined where each kind of block's reader can see them, and declared
// inline: they are the parse's inner loop, and GCC inlines read_plain_run
// into parse_body only so (out of line it cost a call a block).

#include "jtracer/schema.hpp"
#include "language/properties.hpp"
#include "language/scene_parser.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt::lang {

// How many records `items` adds at the end of `all`, as a range of indices.
// Each record takes at least 4 bytes of a text under 4 GiB, so 32 bits hold it.
template <class T>
IndexRange append_records(std::vector<T>& all, std::span<const T> items) {
    IndexRange range{static_cast<std::uint32_t>(all.size()),
                     static_cast<std::uint32_t>(items.size())};
    all.insert(all.end(), items.begin(), items.end());
    return range;
}

template <class Read>
inline void SceneParser::read_properties(BlockSource& block, std::size_t level, Read read) {
    std::vector<PropertySource>& buffer = property_buffers_[level];
    buffer.clear();
    OpenBlock open{block, buffer};
    read(open);
    if (source_map_ && !(in_primitive_ && !keep_primitives_)) {
        block.properties =
            append_records(result_.source.properties, std::span<const PropertySource>(buffer));
    }
}

template <class OnProperty, class OnChild>
inline void SceneParser::parse_body(BlockSource& block,
                                    std::span<const std::string_view> child_names,
                                    OnProperty on_property, OnChild on_child, bool included) {
    if (tokens_behind_) {
        tokens_behind_ = false;
        read_plain_run(child_names, on_property, false);
    }
    for (;;) {
        switch (cur_->kind) {
            case TokenKind::rbrace:
                if (included) {
                    sink_.error(cur_->pos,
                                "this '}' closes no block of this file: a block opened in a "
                                "file closes in that file");
                    advance();
                    break;
                }
                block.close_brace = static_cast<std::uint32_t>(cur_->offset);
                advance();
                return;
            case TokenKind::end:
                if (included) return;
                sink_.error(block.keyword_span.pos,
                            "this '" + std::string(block.keyword) +
                                "' block is never closed: expected '}' before the end of "
                                "the file");
                return;
            case TokenKind::word:
                if (next_->kind != TokenKind::colon && same_name(cur_->text, kIncludeKeyword) &&
                    (block.keyword == kCamerasKeyword || block.keyword == kSceneKeyword)) {
                    parse_include(
                        [&] { parse_body(block, child_names, on_property, on_child, true); });
                    break;
                }
                if (top_level_only(block.keyword)) break;
                if (next_->kind == TokenKind::equals &&
                    !block_has_property(block.keyword, cur_->text)) {
                    bare_assignment(/*top_level=*/false);
                    break;
                }
                // In cameras or scene, a word before a string is no property:
                // most likely a misspelt include, which the list suggests.
                if (next_->kind == TokenKind::lbrace || contains(child_names, cur_->text) ||
                    (next_->kind == TokenKind::string &&
                     (block.keyword == kCamerasKeyword || block.keyword == kSceneKeyword))) {
                    on_child();
                } else if (plain_properties_) {
                    if (!read_plain_properties(child_names, on_property) &&
                        read_property(property_, false, block.keyword))
                        on_property(property_);
                } else if (read_property(property_, true, block.keyword)) {
                    on_property(property_);
                }
                break;
            case TokenKind::bad_value:  // already reported by the lexer
                advance();
                skip_statement();
                break;
            default:
                unexpected_token((block.keyword == kCamerasKeyword || block.keyword == kSceneKeyword
                                      ? "a block or '}' in '"
                                      : "a property name or '}' in '") +
                                 std::string(block.keyword) + "'");
                if (at(TokenKind::lbrace)) {
                    skip_braced();
                } else {
                    advance();
                    skip_statement();
                }
                break;
        }
    }
}

template <class Target>
inline bool SceneParser::parse_property_block(BlockSource& block, std::size_t level, Target& target,
                                              std::string_view keyword) {
    if (!open_block(block, keyword.empty() ? static_keyword(cur_->text) : keyword,
                    /*behind=*/true))
        return false;
    read_properties(block, level, [&](OpenBlock& open) {
        parse_body(
            block, kNoBlocks, [&](const Property& p) { reader_.apply(target, open, p); },
            [&] { block_in_property_block(block); });
    });
    return true;
}

inline void SceneParser::set_plain_value(const Lexer::PlainValue& plain, SourcePos pos,
                                         Value& v) const {
    const auto length = static_cast<std::uint32_t>(plain.length);
    if (plain.is_vector) {
        v.form = Value::Form::vector;
        v.vector = plain.vector;
        v.number = 0.0;
        v.text = {};
    } else {
        v.form = Value::Form::number;
        v.number = plain.number;
        v.vector = Vec3{0.0};
        v.text = text_.substr(plain.offset, plain.length);
    }
    v.span = {static_cast<std::uint32_t>(plain.offset), length, pos};
    v.end = {pos.line, pos.column + static_cast<int>(length), pos.file};
    v.origin = ValueOrigin::literal;
}

inline bool SceneParser::read_plain_value_in_place(Value& v) {
    if (sink_.stopped()) return false;
    Lexer::PlainValue plain;
    if (!reading_->read_plain_value(plain)) return false;
    const Token& colon = *next_;  // the value is on its line
    set_plain_value(
        plain,
        {colon.pos.line, colon.pos.column + static_cast<int>(plain.offset - colon.offset),
         colon.pos.file},
        v);
    return true;
}

template <class OnProperty>
inline bool SceneParser::read_plain_properties(std::span<const std::string_view> child_names,
                                               OnProperty& on_property) {
    if (next_->kind != TokenKind::colon) return false;
    if (!read_plain_value_in_place(property_.value)) return false;
    property_.name = cur_->text;
    property_.name_span = span_of(*cur_);
    read_plain_run(child_names, on_property, true);
    return true;
}

template <class OnProperty>
inline void SceneParser::read_plain_run(std::span<const std::string_view> child_names,
                                        OnProperty& on_property, bool pending) {
    Property& property = property_;
    Lexer::PlainProperty& plain = plain_property_;
    while (!sink_.stopped()) {
        const std::size_t past = reading_->plain_property(plain);
        if (past == 0 || contains(child_names, plain.name)) break;
        if (pending) {
            on_property(property);
            if (sink_.stopped()) {
                // The tokens had read the next name and ':', then nothing more.
                reading_->continue_at(plain.name_offset + plain.name.size() + 1, plain);
                reading_->next(*cur_);
                reading_->next(*next_);
                return;
            }
        }
        reading_->continue_at(past, plain);
        property.name = plain.name;
        property.name_span = {static_cast<std::uint32_t>(plain.name_offset),
                              static_cast<std::uint32_t>(plain.name.size()), plain.name_pos};
        set_plain_value(plain.value, plain.value_pos, property.value);
        pending = true;
    }
    reading_->next(*cur_);
    reading_->next(*next_);
    if (pending) on_property(property);
}

template <class Statements>
inline void SceneParser::parse_include(Statements statements) {
    IncludeResume resume;
    if (!enter_include(resume)) return;
    statements();
    leave_include(resume);
}

}  // namespace jt::lang

// The file's top level, the blocks that hold only properties or only blocks,
// and how bad input is skipped: each error is reported where it happened and
// reading resumes at the next ';' or '}' (a brace counter, never recursion).

#include "jtracer/schema.hpp"
#include "language/block_body.hpp"
#include "language/quote.hpp"
#include "language/scene_parser.hpp"
#include "language/suggest.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

namespace jt::lang {
namespace {

constexpr std::array<std::string_view, 1> kIncludeOnly{kIncludeKeyword};
constexpr auto kTopStatements = schema_detail::joined(
    schema_detail::kTopBlocks, std::array<std::string_view, 3>{kIncludeKeyword, kDefineKeyword,
                                                               schema_of<Material>().keyword});
constexpr auto kCamerasStatements =
    schema_detail::joined(schema_detail::kCamerasBlocks, kIncludeOnly);
constexpr auto kSceneStatements = schema_detail::joined(schema_detail::kSceneBlocks, kIncludeOnly);

}  // namespace

std::span<const std::string_view> top_statements() {
    return kTopStatements;
}
std::span<const std::string_view> cameras_statements() {
    return kCamerasStatements;
}
std::span<const std::string_view> scene_statements() {
    return kSceneStatements;
}

std::string_view static_keyword(std::string_view word) {
    for (std::string_view k : block_keywords())
        if (same_name(k, word)) return k;
    return {};  // never: blocks are opened only at a known keyword
}

void SceneParser::skip_braced() {
    const SourcePos open = cur_->pos;
    std::size_t depth = 0;
    do {
        if (at(TokenKind::lbrace)) ++depth;
        if (at(TokenKind::rbrace)) --depth;
        advance();
    } while (depth > 0 && !at(TokenKind::end));
    if (depth > 0) {
        sink_.error(open, "this '{' is never closed: expected '}' before the end of the file");
    }
}

void SceneParser::skip_statement() {
    while (!at(TokenKind::end) && !at(TokenKind::rbrace)) {
        if (at(TokenKind::semicolon)) {
            advance();
            return;
        }
        if (at(TokenKind::lbrace)) {
            skip_braced();
            return;
        }
        advance();
    }
}

void SceneParser::skip_block() {
    advance();
    if (at(TokenKind::lbrace)) {
        skip_braced();
    } else {
        skip_statement();
    }
}

bool SceneParser::open_block(BlockSource& block) {
    return open_block(block, static_keyword(cur_->text));
}

bool SceneParser::open_block(BlockSource& block, std::string_view keyword, bool behind) {
    block.keyword = keyword;
    block.keyword_span = span_of(*cur_);
    if (behind && plain_properties_ && next_->kind == TokenKind::lbrace) {
        block.open_brace = static_cast<std::uint32_t>(next_->offset);
        tokens_behind_ = true;
        return true;
    }
    advance();
    if (at(TokenKind::lbrace)) {
        block.open_brace = static_cast<std::uint32_t>(cur_->offset);
        advance();
        return true;
    }
    sink_.error(cur_->pos,
                "expected '{' after '" + std::string(block.keyword) + "', got " + describe(*cur_));
    skip_statement();
    return false;
}

bool SceneParser::top_level_only(std::string_view block) {
    if (next_->kind == TokenKind::colon) return false;
    if (same_name(cur_->text, kDefineKeyword)) {
        sink_.error(cur_->pos, "'define' may stand only at the top level, outside every block");
    } else if (same_name(cur_->text, kIncludeKeyword)) {
        sink_.error(cur_->pos,
                    "'include' may stand only at the top level, directly in 'cameras' or "
                    "directly in 'scene'");
    } else if (same_name(cur_->text, schema_of<Material>().keyword) &&
               next_->kind == TokenKind::word && !contains(shape_keywords(), block)) {
        sink_.error(cur_->pos,
                    "a named material ('material NAME { ... }') may stand only at the top "
                    "level, outside every block");
    } else {
        return false;
    }
    skip_statement();
    return true;
}

namespace {

// Where a block of the language stands, for one written elsewhere
// (docs/language.md §3.3); empty for a word that is no block keyword.
std::string block_home(std::string_view keyword) {
    if (contains(top_blocks(), keyword)) return "at the top level";
    if (contains(cameras_blocks(), keyword)) return "in 'cameras { ... }'";
    if (contains(scene_blocks(), keyword)) return "in 'scene { ... }'";
    if (keyword == schema_of<Material>().keyword)
        return "in a primitive (" + listed(shape_keywords(), "or") +
               "), or named at the top level as 'material NAME { ... }'";
    if (contains(primitive_blocks(), keyword))
        return "in a primitive (" + listed(shape_keywords(), "or") + ")";
    return {};
}

// How deep a block stands: 0 at the top level, 1 in cameras or scene, 2 in a
// primitive.
int block_depth(std::string_view keyword) {
    if (contains(top_blocks(), keyword)) return 0;
    if (contains(cameras_blocks(), keyword) || contains(scene_blocks(), keyword)) return 1;
    return 2;
}

}  // namespace

void SceneParser::unknown_block(std::string_view where, std::span<const std::string_view> allowed,
                                const BlockSource* inside) {
    if (const std::string home = block_home(cur_->text); !home.empty()) {
        // A known block in the wrong place: say where it goes. One that
        // stands beside the block it is in, or further out (a sphere in a
        // sphere), most often follows a '}' left out.
        std::string message =
            quote(cur_->text) + " cannot stand " + std::string(where) + ": it stands " + home;
        if (inside && block_depth(cur_->text) <= block_depth(inside->keyword))
            message += " (is the '}' of the '" + std::string(inside->keyword) + "' at " +
                       include_.line_column_from(inside->keyword_span.pos, cur_->pos) +
                       " missing?)";
        sink_.error(cur_->pos, message);
    } else if (const std::string ours_home = block_home(pov_ray_word("block", cur_->text));
               !ours_home.empty() && !contains(allowed, pov_ray_word("block", cur_->text))) {
        // POV-Ray's word for a block that does not stand here either.
        const std::string_view ours = pov_ray_word("block", cur_->text);
        sink_.error(cur_->pos, "unknown block " + quote(cur_->text.substr(0, 40)) + " " +
                                   std::string(where) + "; POV-Ray's " + quote(cur_->text) +
                                   " is " + quote(ours) + " here, which stands " + ours_home);
    } else if (allowed.empty()) {
        sink_.error(cur_->pos, "unexpected block " + quote(cur_->text.substr(0, 40)) + " " +
                                   std::string(where) + ", which holds only properties");
    } else {
        sink_.error(cur_->pos, unknown_name_message("block", cur_->text, where, allowed));
    }
    skip_block();
}

void SceneParser::unexpected_token(std::string_view what) {
    std::string message = "expected " + std::string(what) + ", got " + describe(*cur_);
    if (at(TokenKind::semicolon)) {
        std::size_t i = cur_->offset;
        while (i > 0 && (text_[i - 1] == ' ' || text_[i - 1] == '\t' || text_[i - 1] == '\r' ||
                         text_[i - 1] == '\n'))
            --i;
        if (i > 0 && text_[i - 1] == '}')
            message += " (a block ends at its '}', with no ';' after it)";
    } else if (at(TokenKind::rbrace)) {
        message += " (this '}' closes no block: is there one '}' too many?)";
    }
    sink_.error(cur_->pos, message);
}

void SceneParser::only_blocks(const BlockSource& block, std::span<const std::string_view> allowed,
                              const Property& p) {
    sink_.error(p.name_span.pos, quote(block.keyword) + " holds only blocks (" +
                                     listed(allowed, "and") + "), not properties like " +
                                     quote(p.name));
}

void SceneParser::block_in_property_block(const BlockSource& block) {
    if (block.keyword == schema_of<PointLight>().keyword &&
        contains(primitive_blocks(), cur_->text)) {
        sink_.error(cur_->pos, takes_no_message(block.keyword, cur_->text));
        skip_block();
        return;
    }
    unknown_block("in '" + std::string(block.keyword) + "'", kNoBlocks, &block);
}

void SceneParser::parse_file() {
    while (!at(TokenKind::end)) {
        if (at(TokenKind::word) && cur_->text == schema_of<RenderSettings>().keyword) {
            parse_render_settings();
        } else if (at(TokenKind::word) && cur_->text == kCamerasKeyword) {
            parse_cameras();
        } else if (at(TokenKind::word) && cur_->text == kSceneKeyword) {
            parse_scene();
        } else if (at(TokenKind::word) && cur_->text == kDefineKeyword) {
            parse_define();
        } else if (at(TokenKind::word) && cur_->text == kIncludeKeyword) {
            parse_include([&] { parse_file(); });
        } else if (at(TokenKind::word) && same_name(cur_->text, schema_of<Material>().keyword) &&
                   next_->kind != TokenKind::lbrace) {
            parse_named_material();
        } else if (at(TokenKind::word) && same_name(cur_->text, schema_of<Material>().keyword)) {
            sink_.error(cur_->pos,
                        "a material at the top level needs a name: 'material NAME { ... }', "
                        "used in a primitive with 'material: NAME;'");
            skip_block();
        } else if (at(TokenKind::word) && next_->kind == TokenKind::equals) {
            bare_assignment(/*top_level=*/true);
        } else if (at(TokenKind::word)) {
            unknown_block("at the top level", top_statements());
        } else if (at(TokenKind::lbrace)) {
            sink_.error(cur_->pos,
                        "expected a block name (" + listed(top_blocks(), "or") + ") before '{'");
            skip_braced();
        } else {
            if (!at(TokenKind::bad_value)) {  // a bad value was reported by the lexer
                unexpected_token("a block (" + listed(top_blocks(), "or") + ")");
            }
            advance();
        }
    }
}

void SceneParser::parse_render_settings() {
    BlockSource block;
    RenderSettings settings;  // a later block replaces the earlier one whole
    if (!parse_property_block(block, 0, settings)) return;
    if (result_.source.render_settings) {
        sink_.warning(block.keyword_span.pos,
                      "another 'render_settings' block: only the last one is used, so the "
                      "one at " +
                          include_.line_from(result_.source.render_settings->keyword_span.pos,
                                             block.keyword_span.pos) +
                          " is ignored");
    }
    result_.scene.settings = std::move(settings);
    result_.source.render_settings = std::move(block);
}

void SceneParser::parse_cameras() {
    BlockSource cameras;
    if (!open_block(cameras)) return;
    parse_body(
        cameras, cameras_blocks(),
        [&](const Property& p) { only_blocks(cameras, cameras_blocks(), p); },
        [&] {
            if (cur_->text != schema_of<Camera>().keyword) {
                unknown_block("in '" + std::string(kCamerasKeyword) + "'", cameras_statements());
                return;
            }
            BlockSource block;
            Camera camera;
            if (!parse_property_block(block, 0, camera)) return;
            result_.scene.cameras.push_back(std::move(camera));
            result_.source.cameras.push_back(std::move(block));
        });
}

}  // namespace jt::lang

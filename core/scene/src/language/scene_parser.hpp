#pragma once
// The .jts parser: tokens -> Scene + SceneSource + diagnostics, behind
// parse_scene (jtracer/parser.hpp). Its state and the helpers its parts share.
//
// The grammar has a fixed depth (file > scene > sphere > material), so each
// level is a function of its own and nothing recurses on the input's nesting;
// unknown blocks are skipped with a brace counter. Every error is reported
// where it happened and parsing resumes at the next ';' or '}'. Which blocks
// each level holds, and their keywords, come from the schema (schema.hpp): a
// new shape or block is an entry there, not a list here.
//
// One class, its members defined by concept, each file read alone:
//   parser.cpp             parse_scene, the parser's set-up and its result
//   parse_blocks.cpp       the top level, blocks of properties, skipping bad input
//   block_body.hpp         the loop every block's body is read by and the runs of
//                          plain properties (templates and inline: the inner loop)
//   parse_values.cpp       values and properties (docs/language.md §3.2, §15.3)
//   parse_scene_block.cpp  the scene block: its primitives and lights
//   parse_primitive.cpp    a primitive's body: its material, transforms, named material
//   scene_parts.cpp        a large scene block read in parts on threads
//   parse_names.cpp        define, named materials and --define (§15.2)
//   parse_include.cpp      include (§15.6)
//   count_hints.cpp        the scene's array sizes, counted before the parse

#include "jtracer/finish_table.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/shared.hpp"
#include "jtracer/source_map.hpp"
#include "language/diagnostic_sink.hpp"
#include "language/expression.hpp"
#include "language/include_stack.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"
#include "language/properties.hpp"
#include "language/scene_parts.hpp"

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace jt {
class PageWarmer;
}

namespace jt::lang {

// Whether `word` is one of `names`, as the language compares names.
inline bool contains(std::span<const std::string_view> names, std::string_view word) {
    for (std::string_view name : names)
        if (same_name(name, word)) return true;
    return false;
}

// Offsets fit in 32 bits: parse_scene refuses texts of 4 GiB or more.
inline TextSpan span_of(const Token& t) {
    return {static_cast<std::uint32_t>(t.offset), static_cast<std::uint32_t>(t.length), t.pos};
}

// The blocks a block of properties holds: none.
inline constexpr std::array<std::string_view, 0> kNoBlocks{};

// Added to "expected ';' after the value" when a name touches the value.
inline constexpr std::string_view glued_hint =
    " (a name cannot follow a value directly: '2pi' is written '2 * pi')";
// ... and when one follows it after a space on its line (SceneParser::beside).
inline constexpr std::string_view beside_hint =
    " (two values side by side are not multiplied: write '*' between them)";
// ... and when '<' or '>' follows one (SceneParser::comparison_after).
inline constexpr std::string_view comparison_hint =
    " (there are no comparisons: '<' and '>' only bracket vectors like <0, 1, 0>)";
// ... and when '=' follows one ('define r = 1 = 2;', 'x == 1').
inline constexpr std::string_view equals_hint =
    " ('=' is not an operator: it stands once, in 'define NAME = VALUE;', whose value is one "
    "number, vector or string; there are no comparisons such as '==')";
// ... and when '(' follows one ('pi()', 'r(2)', '2(3)').
inline constexpr std::string_view call_hint =
    " ('(' after a value neither calls it nor multiplies: only the functions take '(', pi, "
    "clock and defined names are values, and a product is written with '*')";

// The schema's own copy of a block keyword, so that records point at the
// schema's literals rather than at the text.
std::string_view static_keyword(std::string_view word);

// What may stand at the top level, in `cameras` and in `scene`: their blocks
// and the statements of language 1.3 (include; at the top level also define
// and named materials), for the list and the did-you-mean of an unknown word.
std::span<const std::string_view> top_statements();
std::span<const std::string_view> cameras_statements();
std::span<const std::string_view> scene_statements();

class SceneParser final : private TokenCursor {
  public:
    // `primitives` false: the primitives and their records are read (for the
    // diagnostics) but not kept (validation.hpp's source_without_primitives).
    SceneParser(std::string_view text, const ParseOptions& options, bool primitives = true);
    // A reader of one part of a large scene block, on a thread of its own: from
    // the keyword at `begin`, with the names defined before the block.
    SceneParser(std::string_view text, const ParseOptions& options, const NameTable& names,
                std::size_t begin);
    SceneParser(const SceneParser&) = delete;  // cur_ and next_ point into tokens_
    SceneParser& operator=(const SceneParser&) = delete;

    ParseResult run();

  private:
    // --- tokens --------------------------------------------------------------

    // The two tokens swap places: the lexer writes the new one in place (lexer.hpp).
    void advance() override {
        std::swap(cur_, next_);
        reading_->next(*next_);
    }
    const Token& cur() const override { return *cur_; }
    const Token& peek() const override { return *next_; }
    // In the main file, the files read before, or the one being read.
    std::string directive_comment(SourcePos from) const override;
    bool at(TokenKind kind) const { return cur_->kind == kind; }
    // Whether what follows `value` is a mistake the lexer has reported (a
    // malformed number, a byte that starts no token): the value's statement
    // is then skipped, with no "expected ';'" and no finding about the value
    // cut short, which would only echo that one mistake.
    bool cut_short(const Value& value) const {
        return at(TokenKind::bad_value) ||
               reading_->skipped_between(value.span.offset + value.span.length, cur_->offset);
    }
    // The hint for the missing ';' after a value: a comparison ('1 < 2')
    // where '<' or '>' follows it, a call or product ('pi()', '2(3)') where
    // '(' does, a second '=' where '=' does, else none.
    std::string_view comparison_after() const {
        if (at(TokenKind::lparen)) return call_hint;
        if (at(TokenKind::equals)) return equals_hint;
        return at(TokenKind::less) || at(TokenKind::greater) ? comparison_hint : std::string_view{};
    }
    // Whether a name touches the value that ends at `end` ('2pi', '0x10',
    // '1_000'): no next statement, whose ';' is missing, but a mistake in
    // this one, which is then skipped whole, its value with it.
    bool glued_to(SourcePos end) const { return at(TokenKind::word) && cur_->pos == end; }
    // Whether a name after a space on the line of the value that ends at
    // `end` continues it ('2 pi', '2 r'), rather than starting the next
    // property ('name:'), block ('name {') or statement, whose ';' is missing.
    bool beside(SourcePos end) const {
        return at(TokenKind::word) && cur_->pos.file == end.file && cur_->pos.line == end.line &&
               next_->kind != TokenKind::colon && next_->kind != TokenKind::lbrace &&
               !contains(top_statements(), cur_->text);
    }

    // --- skipping bad input (parse_blocks.cpp) -------------------------------

    // Skips a brace-balanced group starting at '{', with a counter, not recursion.
    void skip_braced();
    // Skips to just past the next ';', or to the next '}' (left for the enclosing block).
    void skip_statement();
    // At a block's keyword: skips it and its braced body (or, with no '{', its statement).
    void skip_block();

    // --- the top level and blocks (parse_blocks.cpp, block_body.hpp) ---------

    void parse_file();
    void parse_render_settings();
    void parse_cameras();
    // At the block's keyword: consumes it and the '{'. False (recovered) when '{' is missing.
    bool open_block(BlockSource& block);
    // The same where the caller has matched the word at hand to `keyword`, a
    // schema keyword: primitives and their materials, two blocks a sphere,
    // skip static_keyword's search of the dozen keywords (3% of a parse).
    // `behind`: a '{' next is not read past (tokens_behind_, for parse_body).
    bool open_block(BlockSource& block, std::string_view keyword, bool behind = false);
    // Runs `read(open)` with the block's properties collected in a buffer
    // reused from block to block, then appends them to the scene's one array of
    // property records, where they stay together (a primitive's properties and
    // its material's interleave in the text). `level` is the nesting depth: a
    // primitive's material is read while the primitive's own buffer is in use.
    template <class Read>
    void read_properties(BlockSource& block, std::size_t level, Read read);
    // Reads a block's entries up to and including its '}'. `on_property` gets
    // each well-formed property; `on_child` is called at the keyword of each
    // nested block and must consume it whole.
    // `included`: reading the statements of a file included in the block,
    // which end at that file's end, and where a '}' closes nothing.
    template <class OnProperty, class OnChild>
    void parse_body(BlockSource& block, std::span<const std::string_view> child_names,
                    OnProperty on_property, OnChild on_child, bool included = false);
    // Reads a block that holds only properties (render_settings,
    // perspective_camera, point_light, material, transform) into `target`, from
    // its keyword to its '}'. False (recovered) when its '{' is missing.
    // `keyword`: the schema's keyword the word at hand was matched to, if known.
    template <class Target>
    bool parse_property_block(BlockSource& block, std::size_t level, Target& target,
                              std::string_view keyword = {});
    // At a block's keyword inside a block of properties: reported and skipped.
    void block_in_property_block(const BlockSource& block);
    // At a block's keyword `where` (e.g. "in 'scene'") only `allowed` may stand;
    // `inside`, when given, is the block it stands in.
    void unknown_block(std::string_view where, std::span<const std::string_view> allowed,
                       const BlockSource* inside = nullptr);
    // At a token that starts no statement: the error, "expected WHAT, got
    // ..." (with a word on C's and POV-Ray's ';' after a block's '}').
    void unexpected_token(std::string_view what);
    // A property in a block that holds only blocks (cameras, scene): reported.
    void only_blocks(const BlockSource& block, std::span<const std::string_view> allowed,
                     const Property& p);
    // At `define`, `include` or a named material inside block `block`: an
    // error at the keyword (a property of that name, with ':', is left to the
    // block, and a primitive says how it names a material).
    bool top_level_only(std::string_view block);

    // --- values and properties (parse_values.cpp, block_body.hpp) ------------

    // A value: a literal, a name or an expression, evaluated (§15.3). A lone
    // number before ';' takes a short path: most values of most scenes are one.
    Value read_value(bool evaluate = true);
    // What read_value makes of a plain value (lexer.hpp) at `pos`.
    void set_plain_value(const Lexer::PlainValue& plain, SourcePos pos, Value& v) const;
    // At a property's ':': a value of plain numbers followed by ';', read by the
    // lexer in one scan (lexer.hpp), into what read_value would make of it,
    // with the lexer left just past the ';' and the tokens not yet read on.
    // False, with nothing consumed, for anything else. Most values of most
    // scenes are such: their tokens and the expression reader are the most of
    // a parse. A stopped sink ends the tokens, so it ends this path too.
    bool read_plain_value_in_place(Value& v);
    // The same, the tokens then read on past the ';'.
    bool read_plain_value(Value& v);
    // At a property's name and ':' whose value is plain: that property and
    // the run of plain properties after it (read_plain_run). False, with
    // nothing consumed, when the value is not plain: read_property reads it.
    template <class OnProperty>
    bool read_plain_properties(std::span<const std::string_view> child_names,
                               OnProperty& on_property);
    // From the lexer's place, with the tokens not read on (just past a
    // block's '{' or, `pending`, past the ';' of property_, not yet given to
    // `on_property`): the properties that follow, each a name, ':' and a
    // plain value after spaces or a line break and its indentation
    // (Lexer::plain_property; as generators write a block on one line,
    // `center:<1,2,3>;radius:0.5;`, and people one a line), read without
    // tokens for their names and ':' and given to `on_property` in turn, then
    // the tokens read on. Each is given where the tokens would give it,
    // after the two tokens that follow it (those of a property read here
    // report nothing). A run ends where the text holds anything else, a
    // child block's name or a stopped sink.
    template <class OnProperty>
    void read_plain_run(std::span<const std::string_view> child_names, OnProperty& on_property,
                        bool pending);
    // At a property's name: NAME ':' value ';' into `property`; true when it
    // applies. False (reported, skipped) with no ':' or no good value; a
    // missing ';' is reported and the property applies. `try_plain`: first as
    // a plain value (read_plain_value), which the caller has not tried.
    // `keyword`: the block's, so that a name it does not know has its value
    // skipped rather than evaluated (empty: every name is read).
    bool read_property(Property& property, bool try_plain, std::string_view keyword = {});

    // --- the scene block (parse_scene_block.cpp) -----------------------------

    void parse_scene();
    // At the keyword of a block in `scene`: reads it into `into`.
    void parse_scene_child(SceneChildren& into, PageWarmer& warmer);
    // At a primitive's keyword: keeps the earlier parse's primitive at index
    // `placed` of `primitives` when it was read from here and read no `clock`,
    // and goes on after its '}'. False: read it.
    bool take_earlier(std::vector<Primitive>& primitives, std::size_t& placed,
                      std::vector<PrimitiveReading>& readings);
    // ParseOptions::text_passed, every text_passed_step bytes of the main
    // text: nothing before the token at hand is read again (the lookahead and
    // the lexer are past it).
    void report_text_passed();
    // A finish of the parser's own, at its default value, for a primitive's
    // material blocks to write into: reading a primitive allocates a finish
    // only when it is one not met before (share_finish keeps that one).
    // Both inline, defined beside parse_scene_child, their one caller.
    inline Shared<Finish> take_scratch_finish();
    // Makes the material share an equal finish met before; when it does, the
    // finish it was read into is the scratch again.
    inline void share_finish(Material& material);

    // --- a primitive's body (parse_primitive.cpp) ----------------------------

    // Just past a primitive's '{': its properties and child blocks.
    void parse_primitive_body(Primitive& primitive, OpenBlock& open);
    // At `material` ':' in a primitive: reads `material: NAME;` whole and
    // returns the named material, or nullptr (reported).
    const Symbol* read_material_reference();
    // --- a large scene block read in parts (scene_parts.cpp) -----------------

    // Just past a scene block's '{': starts threads reading the parts after
    // the first, when the rest of the text is large enough to share out.
    // `hint` bounds the number of primitives in the block.
    void start_scene_parts(ScenePartThreads& parts, std::size_t hint);
    // A part's reading, on its thread. Stops unusable at the first diagnostic
    // or at anything but a block's keyword and '{'.
    // `blocks` and `properties` bound the part's counts as the whole text's
    // hints do (blocks a few times over: a primitive's material counts too).
    void read_scene_part(ScenePart& part, std::size_t blocks, std::size_t properties,
                         const std::atomic<bool>& cancelled);
    // At the keyword of a block in `scene`: when a part read on a thread
    // begins here and is usable, takes what it read into `into` and goes on
    // where it ended. False: read on here.
    bool take_scene_part(ScenePartThreads& parts, SceneChildren& into);

    // --- names (parse_names.cpp, docs/language.md §15.2) ---------------------

    // The --define values, evaluated before the file: a bad one (the front
    // ends check them first) is an error without a location.
    void set_command_line_names(const ParseOptions& options);
    // At a name being defined: false (reported) when it is reserved or taken.
    // `overridden` is set for a name a --define holds.
    bool claim_name(const Token& name, bool& overridden);
    // At `define`: define NAME '=' (STRING | expr) ';'
    void parse_define();
    // At NAME before '=', a definition without `define` (a POV-Ray habit):
    // one error that shows the fix, at the top level or inside a block.
    void bare_assignment(bool top_level);
    // At `material` NAME: a named material, `material NAME { property* }`.
    void parse_named_material();
    std::size_t error_count() const { return static_cast<std::size_t>(sink_.error_count()); }

    // --- include (parse_include.cpp, docs/language.md §15.6) -----------------

    // At `include`: include STRING ';'. The file's text is read right here,
    // by `statements`, with its own lexer; then reading resumes after the ';'.
    template <class Statements>
    void parse_include(Statements statements);
    // Where reading resumes after an included file.
    struct IncludeResume {
        std::array<Token, 2> tokens;
        std::string_view text;
        Lexer* lexer = nullptr;
        std::optional<Lexer> included;  // the included file's
    };
    // At `include`: reads the statement and, when the file can be read, makes
    // its text the one read, true. False (reported) for no file to read.
    bool enter_include(IncludeResume& resume);
    std::string include_path_hint(const Token& token) const;
    // At the included file's end: reading resumes after the include.
    void leave_include(IncludeResume& resume);
    // A file name (`file`, `image_map`, `background_map`) written in an
    // included file is relative to that file's folder: the scene holds it
    // relative to the main file's, as every other.
    void rebase_file_name(Property& property);

    std::string_view text_;  // the text being read: the main one or an included one
    DiagnosticSink sink_;
    Lexer lexer_;               // the main text's
    Lexer* reading_ = &lexer_;  // the text being read's
    // The first POV-Ray directive comment of an included file read so far (or
    // of one still open around the one being read); line 0: none.
    SourcePos included_directive_{0, 0, 0};
    PropertyReader reader_;
    IncludeStack include_;
    std::deque<std::string> rebased_names_;  // values point at these: a deque keeps them put
    NameTable names_;
    std::vector<std::pair<std::string, Symbol*>> command_line_;  // each --define name once
    ExpressionReader expressions_;
    std::array<Token, 2> tokens_;
    Token* cur_ = &tokens_[0];   // the token at hand
    Token* next_ = &tokens_[1];  // one token of lookahead
    ParseResult result_;
    std::size_t primitive_hint_ = 0;
    std::size_t property_hint_ = 0;  // over the whole text, as primitive_hint_
    bool source_map_;                // false: records are still made (for messages) but not kept
    bool keep_primitives_;
    bool record_readings_;
    EarlierParse* earlier_;  // null: read every primitive
    const ParseOptions& options_;
    // ParseOptions::text_passed is called (by the main text's reader only).
    bool reports_text_passed_ = false;
    std::size_t next_text_passed_ = 0;
    bool in_primitive_ = false;     // reading a primitive's block
    bool plain_properties_ = true;  // ParseOptions::plain_properties
    // Just past a block's '{', the tokens not read on: parse_body starts
    // with read_plain_run (open_block's `behind`).
    bool tokens_behind_ = false;
    std::array<std::vector<PropertySource>, 2> property_buffers_;
    // The property being read, reused: read_property sets all of it, and a
    // fresh one cleared 136 bytes per property first.
    Property property_;
    // read_plain_run's, reused: a fresh one cleared 128 bytes a block.
    Lexer::PlainProperty plain_property_;
    FinishTable finishes_;           // the primitives' finishes, each value once
    Shared<Finish> scratch_finish_;  // see take_scratch_finish
};

}  // namespace jt::lang

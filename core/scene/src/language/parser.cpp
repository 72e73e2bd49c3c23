// The .jts parser: tokens -> Scene + SceneSource + diagnostics.
//
// The grammar has a fixed depth (file > scene > sphere > material), so each
// level is a function of its own and nothing recurses on the input's nesting;
// unknown blocks are skipped with a brace counter. Every error is reported
// where it happened and parsing resumes at the next ';' or '}'.

#include "jtracer/parser.hpp"

#include "io/page_warmer.hpp"
#include "io/reserve_records.hpp"
#include "jtracer/finish_table.hpp"
#include "jtracer/schema.hpp"
#include "language/define_value.hpp"
#include "language/expression.hpp"
#include "language/include_stack.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"
#include "language/properties.hpp"
#include "language/quote.hpp"
#include "language/scene_parts.hpp"
#include "language/suggest.hpp"
#include "language/validation.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <limits>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace jt {
namespace lang {
namespace {

// Which blocks each level holds, and their keywords, come from the schema
// (schema.hpp): a new shape or block is an entry there, not a list here.
constexpr std::array<std::string_view, 0> kNoBlocks{};

// How often ParseOptions::text_passed hears of the parse's progress: often
// enough that little is held behind it, rarely enough to cost nothing.
constexpr std::size_t text_passed_step = std::size_t{4} << 20;

// The default shape a primitive keyword opens, or nullopt for another word.
template <std::size_t I = 0>
std::optional<Shape> shape_of_keyword(std::string_view word) {
    if constexpr (I == std::variant_size_v<Shape>) {
        return std::nullopt;
    } else {
        using Alternative = ShapeAlternative<I>;
        if (same_name(word, schema_of<Alternative>().keyword)) return Shape(Alternative{});
        return shape_of_keyword<I + 1>(word);
    }
}

bool contains(std::span<const std::string_view> names, std::string_view word) {
    for (std::string_view name : names)
        if (same_name(name, word)) return true;
    return false;
}

// Offsets fit in 32 bits: parse_scene refuses texts of 4 GiB or more.
TextSpan span_of(const Token& t) {
    return {static_cast<std::uint32_t>(t.offset), static_cast<std::uint32_t>(t.length), t.pos};
}

// The schema's own copy of a block keyword, so that records point at the
// schema's literals rather than at the text.
std::string_view static_keyword(std::string_view word) {
    for (std::string_view k : block_keywords())
        if (same_name(k, word)) return k;
    return {};  // never: blocks are opened only at a known keyword
}

// "a, b and c" (or "a, b or c" with `last` "or").
std::string listed(std::span<const std::string_view> names, std::string_view last) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " " + std::string(last) + " " : ", ";
        out += names[i];
    }
    return out;
}

// How many records `items` adds at the end of `all`, as a range of indices.
// Each record takes at least 4 bytes of a text under 4 GiB, so 32 bits hold it.
template <class T>
IndexRange append_records(std::vector<T>& all, std::span<const T> items) {
    IndexRange range{static_cast<std::uint32_t>(all.size()),
                     static_cast<std::uint32_t>(items.size())};
    all.insert(all.end(), items.begin(), items.end());
    return range;
}

// The '{' and ':' of a text, counted in one pass eight bytes at a time: the
// upper bounds below size the scene's arrays once, and two byte-by-byte counts
// were 8% of a dense parse.
struct BraceAndColonCount {
    std::size_t braces = 0;
    std::size_t colons = 0;
};

BraceAndColonCount count_braces_and_colons(std::string_view text) {
    constexpr std::uint64_t ones = 0x0101010101010101ull, lows = 0x7F7F7F7F7F7F7F7Full;
    // 0x01 in each byte of `w` equal to `byte`, 0 in the others.
    auto matches = [](std::uint64_t w, unsigned char byte) {
        const std::uint64_t x = w ^ (ones * byte);
        return (~(((x & lows) + lows) | x | lows)) >> 7;
    };
    // The sum of the eight byte counters of `lanes`, each at most 255.
    auto sum = [](std::uint64_t lanes) {
        constexpr std::uint64_t even = 0x00FF00FF00FF00FFull;
        const std::uint64_t pairs = (lanes & even) + ((lanes >> 8) & even);
        return static_cast<std::size_t>((pairs * 0x0001000100010001ull) >> 48);
    };
    constexpr std::size_t words_per_flush = 255;  // a byte counter holds 255
    BraceAndColonCount count;
    const char* p = text.data();
    std::size_t left = text.size();
#if defined(__SSE2__)
    // Sixteen bytes at a time with SSE2 (every x86-64 has it): a comparison
    // makes 0xFF of each match, and subtracting that adds one to a byte
    // counter; the counters are summed before they can pass 255.
    const __m128i braces16 = _mm_set1_epi8('{'), colons16 = _mm_set1_epi8(':');
    const __m128i zero = _mm_setzero_si128();
    auto total = [&](__m128i counters) {  // the sum of the 16 byte counters
        const __m128i sums = _mm_sad_epu8(counters, zero);
        return static_cast<std::size_t>(_mm_cvtsi128_si32(sums)) +
               static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(sums, sums)));
    };
    while (left >= 16) {
        const std::size_t blocks = std::min(left / 16, words_per_flush);
        __m128i braces = zero, colons = zero;
        for (std::size_t k = 0; k < blocks; ++k, p += 16) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
            braces = _mm_sub_epi8(braces, _mm_cmpeq_epi8(v, braces16));
            colons = _mm_sub_epi8(colons, _mm_cmpeq_epi8(v, colons16));
        }
        count.braces += total(braces);
        count.colons += total(colons);
        left -= blocks * 16;
    }
#endif
    while (left >= 8) {
        const std::size_t words = std::min(left / 8, words_per_flush);
        std::uint64_t braces = 0, colons = 0;
        for (std::size_t k = 0; k < words; ++k, p += 8) {
            std::uint64_t w;
            std::memcpy(&w, p, 8);
            braces += matches(w, '{');
            colons += matches(w, ':');
        }
        count.braces += sum(braces);
        count.colons += sum(colons);
        left -= words * 8;
    }
    for (; left > 0; --left, ++p) {
        count.braces += *p == '{';
        count.colons += *p == ':';
    }
    return count;
}

// An upper bound on the primitives a text can hold (each has a '{'), capped by
// its size, so that the scene's arrays are sized once instead of growing by
// copies: for a million spheres those copies cost more than the parsing.
std::size_t primitive_count_hint(std::string_view text, const BraceAndColonCount& count) {
    constexpr std::size_t bytes_per_primitive_at_least = 32;  // a hint, not a limit
    return std::min(count.braces, text.size() / bytes_per_primitive_at_least);
}

// The same for property records: each has a ':' and takes 4 bytes at least.
std::size_t property_count_hint(std::string_view text, const BraceAndColonCount& count) {
    return std::min(count.colons, text.size() / 4);
}

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

std::string where(SourcePos pos) {
    return std::to_string(pos.line) + ":" + std::to_string(pos.column);
}

class Parser final : private TokenCursor {
  public:
    // `primitives` false: the primitives and their records are read (for the
    // diagnostics) but not kept (validation.hpp's source_without_primitives).
    Parser(std::string_view text, const ParseOptions& options, bool primitives = true)
        : text_(text),
          lexer_(text, sink_),
          reader_(sink_),
          include_(options),
          expressions_(*this, sink_, names_, options.clock),
          source_map_(options.source_map),
          keep_primitives_(primitives),
          record_readings_(options.record_primitive_readings && primitives),
          earlier_(options.earlier && !options.source_map && primitives &&
                           options.earlier->text == text
                       ? options.earlier
                       : nullptr),
          options_(options),
          reports_text_passed_(static_cast<bool>(options.text_passed)),
          plain_properties_(options.plain_properties) {
        if (keep_primitives_) {
            const BraceAndColonCount count = count_braces_and_colons(text);
            primitive_hint_ = primitive_count_hint(text, count);
            property_hint_ = property_count_hint(text, count);
            if (source_map_) {
                reserve_records(result_.source.properties, property_hint_);
                reserve_records(result_.source.children, primitive_hint_);
            }
        }
        set_command_line_names(options);
        lexer_.next(*cur_);
        lexer_.next(*next_);
    }

    // A reader of one part of a large scene block, on a thread of its own: from
    // the keyword at `begin`, with the names defined before the block.
    Parser(std::string_view text, const ParseOptions& options, const NameTable& names,
           std::size_t begin)
        : text_(text),
          lexer_(text, sink_),
          reader_(sink_),
          include_(options),
          names_(names),
          expressions_(*this, sink_, names_, options.clock),
          source_map_(options.source_map),
          keep_primitives_(true),
          record_readings_(false),
          earlier_(nullptr),
          options_(options),
          plain_properties_(options.plain_properties) {
        lexer_.resume_at(begin, position_of(text, begin));
        lexer_.next(*cur_);
        lexer_.next(*next_);
    }

    Parser(const Parser&) = delete;  // cur_ and next_ point into tokens_
    Parser& operator=(const Parser&) = delete;

    ParseResult run() {
        parse_file();
        for (const auto& [name, symbol] : command_line_)
            if (!symbol->defined_in_file && sink_.accepts_warnings())
                sink_.warning({}, "--define " + name + ": the scene defines no " + quote(name));
        result_.diagnostics = sink_.take();
        result_.reads_clock = result_.reads_clock || expressions_.read_clock();
        if (!source_map_) result_.source = {};
        // Kept with or without the map: diagnostics quote the included texts.
        result_.source.files = include_.take_files();
        result_.source.unread_includes = include_.take_unread();
        return std::move(result_);
    }

  private:
    // The two tokens swap places: the lexer writes the new one in place (lexer.hpp).
    void advance() override {
        std::swap(cur_, next_);
        reading_->next(*next_);
    }
    const Token& cur() const override { return *cur_; }
    const Token& peek() const override { return *next_; }
    bool at(TokenKind kind) const { return cur_->kind == kind; }

    // --- recovery -------------------------------------------------------

    // Skips a brace-balanced group starting at '{', with a counter, not recursion.
    void skip_braced() {
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

    // Skips to just past the next ';', or to the next '}' (left for the enclosing block).
    void skip_statement() {
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

    // At a block's keyword: skips it and its braced body (or, with no '{', its statement).
    void skip_block() {
        advance();
        if (at(TokenKind::lbrace)) {
            skip_braced();
        } else {
            skip_statement();
        }
    }

    // Inside '<' ... : skips to just past the next '>', or to a ';' or '}'.
    void skip_vector() {
        while (!at(TokenKind::end) && !at(TokenKind::rbrace) && !at(TokenKind::semicolon)) {
            bool closing = at(TokenKind::greater);
            advance();
            if (closing) return;
        }
    }

    // --- values and properties ------------------------------------------

    // Whether the token can start a value: anything else is "expected a value".
    static bool starts_value(TokenKind kind) {
        switch (kind) {
            case TokenKind::number:
            case TokenKind::string:
            case TokenKind::word:
            case TokenKind::less:
            case TokenKind::lparen:
            case TokenKind::plus:
            case TokenKind::minus:
            case TokenKind::bad_value:
                return true;
            default:
                return false;
        }
    }

    // A value: a literal, a name or an expression, evaluated (§15.3). A lone
    // number before ';' takes a short path: most values of most scenes are one.
    Value read_value(bool evaluate = true) {
        Value v;
        if (!starts_value(cur_->kind)) return v;  // none; nothing consumed
        if (cur_->kind == TokenKind::number && next_->kind == TokenKind::semicolon) {
            v.form = Value::Form::number;
            v.number = cur_->number;
            v.text = cur_->text;
            v.span = span_of(*cur_);
            v.end = {cur_->pos.line, cur_->pos.column + static_cast<int>(cur_->length),
                     cur_->pos.file};
            advance();
            return v;
        }
        // So does a vector of plain numbers, the other most common value.
        if (cur_->kind == TokenKind::less && evaluate) {
            Vec3 vector;
            if (const std::size_t end = reading_->plain_vector(cur_->offset, vector)) {
                const auto length = static_cast<std::uint32_t>(end - cur_->offset);
                v.form = Value::Form::vector;
                v.vector = vector;
                v.span = {static_cast<std::uint32_t>(cur_->offset), length, cur_->pos};
                v.end = {cur_->pos.line, cur_->pos.column + static_cast<int>(length),
                         cur_->pos.file};
                reading_->skip_to(end);
                reading_->next(*cur_);
                reading_->next(*next_);
                return v;
            }
        }
        const ParsedValue parsed = expressions_.read(evaluate);
        v.span = parsed.span;
        v.end = parsed.end;
        v.origin = parsed.origin;
        if (!parsed.ok) {
            v.form = Value::Form::bad;
            return v;
        }
        switch (parsed.value.kind) {
            case ExprValue::Kind::number:
                v.form = Value::Form::number;
                v.number = parsed.value.number;
                if (parsed.origin == ValueOrigin::literal)
                    v.text = text_.substr(v.span.offset, v.span.length);
                break;
            case ExprValue::Kind::vector:
                v.form = Value::Form::vector;
                v.vector = parsed.value.vector;
                break;
            case ExprValue::Kind::string:
                v.form = Value::Form::string;
                v.text = parsed.value.text;
                break;
        }
        return v;
    }

    // What read_value makes of a plain value (lexer.hpp) at `pos`.
    void set_plain_value(const Lexer::PlainValue& plain, SourcePos pos, Value& v) const {
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

    // At a property's ':': a value of plain numbers followed by ';', read by the
    // lexer in one scan (lexer.hpp), into what read_value would make of it,
    // with the lexer left just past the ';' and the tokens not yet read on.
    // False, with nothing consumed, for anything else. Most values of most
    // scenes are such: their tokens and the expression reader are the most of
    // a parse. A stopped sink ends the tokens, so it ends this path too.
    bool read_plain_value_in_place(Value& v) {
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

    // The same, the tokens then read on past the ';'.
    bool read_plain_value(Value& v) {
        if (!read_plain_value_in_place(v)) return false;
        reading_->next(*cur_);
        reading_->next(*next_);
        return true;
    }

    // At a property's name and ':' whose value is plain: that property and
    // the run of plain properties after it (read_plain_run). False, with
    // nothing consumed, when the value is not plain: read_property reads it.
    template <class OnProperty>
    bool read_plain_properties(std::span<const std::string_view> child_names,
                               OnProperty& on_property) {
        if (next_->kind != TokenKind::colon) return false;
        if (!read_plain_value_in_place(property_.value)) return false;
        property_.name = cur_->text;
        property_.name_span = span_of(*cur_);
        read_plain_run(child_names, on_property, true);
        return true;
    }

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
                        bool pending) {
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

    // `try_plain`: first as a plain value (read_plain_value), which the
    // caller has not tried.
    bool read_property(Property& property, bool try_plain) {
        property.name = cur_->text;
        property.name_span = span_of(*cur_);
        if (try_plain && next_->kind == TokenKind::colon && read_plain_value(property.value))
            return true;
        advance();
        if (!at(TokenKind::colon)) {
            sink_.error(cur_->pos, "expected ':' after '" + std::string(property.name) + "', got " +
                                       describe(*cur_));
            skip_statement();
            return false;
        }
        advance();
        property.value = read_value();
        rebase_file_name(property);
        if (property.value.form == Value::Form::none) {
            sink_.error(cur_->pos, "expected a value after '" + std::string(property.name) +
                                       ":', got " + describe(*cur_));
            skip_statement();
            return false;
        }
        if (property.value.form == Value::Form::bad) {
            skip_statement();
            return false;
        }
        if (at(TokenKind::semicolon)) {
            advance();
            return true;
        }
        sink_.error(property.value.end,
                    "expected ';' after the value of '" + std::string(property.name) + "'");
        // A name or '}' next is most likely the next line: carry on from there.
        if (!at(TokenKind::word) && !at(TokenKind::rbrace)) skip_statement();
        return true;
    }

    // --- blocks ---------------------------------------------------------

    // At the block's keyword: consumes it and the '{'. False (recovered) when '{' is missing.
    bool open_block(BlockSource& block) { return open_block(block, static_keyword(cur_->text)); }
    // The same where the caller has matched the word at hand to `keyword`, a
    // schema keyword: primitives and their materials, two blocks a sphere,
    // skip static_keyword's search of the dozen keywords (3% of a parse).
    // `behind`: a '{' next is not read past (tokens_behind_, for parse_body).
    bool open_block(BlockSource& block, std::string_view keyword, bool behind = false) {
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
        sink_.error(cur_->pos, "expected '{' after '" + std::string(block.keyword) + "', got " +
                                   describe(*cur_));
        skip_statement();
        return false;
    }

    // Runs `read(open)` with the block's properties collected in a buffer
    // reused from block to block, then appends them to the scene's one array of
    // property records, where they stay together (a primitive's properties and
    // its material's interleave in the text). `level` is the nesting depth: a
    // primitive's material is read while the primitive's own buffer is in use.
    template <class Read>
    void read_properties(BlockSource& block, std::size_t level, Read read) {
        std::vector<PropertySource>& buffer = property_buffers_[level];
        buffer.clear();
        OpenBlock open{block, buffer};
        read(open);
        if (source_map_ && !(in_primitive_ && !keep_primitives_)) {
            block.properties =
                append_records(result_.source.properties, std::span<const PropertySource>(buffer));
        }
    }

    // Reads a block's entries up to and including its '}'. `on_property` gets
    // each well-formed property; `on_child` is called at the keyword of each
    // nested block and must consume it whole.
    // `included`: reading the statements of a file included in the block,
    // which end at that file's end, and where a '}' closes nothing.
    template <class OnProperty, class OnChild>
    void parse_body(BlockSource& block, std::span<const std::string_view> child_names,
                    OnProperty on_property, OnChild on_child, bool included = false) {
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
                    if (top_level_only()) break;
                    if (next_->kind == TokenKind::lbrace || contains(child_names, cur_->text)) {
                        on_child();
                    } else if (plain_properties_) {
                        if (!read_plain_properties(child_names, on_property) &&
                            read_property(property_, false))
                            on_property(property_);
                    } else if (read_property(property_, true)) {
                        on_property(property_);
                    }
                    break;
                case TokenKind::bad_value:  // already reported by the lexer
                    advance();
                    skip_statement();
                    break;
                default:
                    sink_.error(cur_->pos, "expected a property name or '}' in '" +
                                               std::string(block.keyword) + "', got " +
                                               describe(*cur_));
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

    // At `define` or `include` inside a block: an error at the keyword (a
    // property of that name, with ':', is left to the block).
    bool top_level_only() {
        if (next_->kind == TokenKind::colon) return false;
        const bool define = same_name(cur_->text, kDefineKeyword);
        if (!define && !same_name(cur_->text, kIncludeKeyword)) return false;
        if (define) {
            sink_.error(cur_->pos, "'define' may stand only at the top level, outside every block");
            skip_statement();
        } else {
            sink_.error(cur_->pos,
                        "'include' may stand only at the top level, directly in 'cameras' or "
                        "directly in 'scene'");
            skip_statement();
        }
        return true;
    }

    // --- include (docs/language.md §15.5) -------------------------------

    // At `include`: include STRING ';'. The file's text is read right here,
    // by `statements`, with its own lexer; then reading resumes after the ';'.
    template <class Statements>
    void parse_include(Statements statements) {
        advance();
        if (!at(TokenKind::string)) {
            if (!at(TokenKind::bad_value))
                sink_.error(cur_->pos,
                            "expected the path of a file in double quotes after "
                            "'include', got " +
                                describe(*cur_));
            skip_statement();
            return;
        }
        const Token path = *cur_;
        advance();
        if (at(TokenKind::semicolon)) {
            advance();
        } else {
            sink_.error(
                {path.pos.line, path.pos.column + static_cast<int>(path.length), path.pos.file},
                "expected ';' after 'include \"" + std::string(path.text.substr(0, 40)) + "\"'");
        }
        bool unreadable = false;
        const std::optional<IncludeStack::Opened> opened =
            include_.open(path.text, path.pos, sink_, unreadable);
        if (!opened) {
            if (unreadable) names_.stop_reporting_unknown();
            return;
        }
        // An included file that changed since the earlier parse: its offsets
        // say nothing of what it holds now.
        if (earlier_ && (opened->file > earlier_->files.size() ||
                         earlier_->files[opened->file - 1].text != opened->text))
            earlier_ = nullptr;
        const std::array<Token, 2> resume{*cur_, *next_};
        const std::string_view resume_text = text_;
        Lexer* const resume_lexer = reading_;
        Lexer lexer(opened->text, sink_, opened->file);
        reading_ = &lexer;
        text_ = opened->text;
        lexer.next(*cur_);
        lexer.next(*next_);
        statements();
        include_.close();
        *cur_ = resume[0];
        *next_ = resume[1];
        reading_ = resume_lexer;
        text_ = resume_text;
    }

    // A file name (`file`, `image_map`, `background_map`) written in an
    // included file is relative to that file's folder: the scene holds it
    // relative to the main file's, as every other.
    void rebase_file_name(Property& property) {
        if (property.value.form != Value::Form::string || property.name_span.pos.file == 0 ||
            !names_a_file(property.name))
            return;
        std::string rebased =
            include_.rebased_asset(property.value.text, property.name_span.pos.file);
        if (!rebased.empty()) property.value.text = rebased_names_.emplace_back(std::move(rebased));
    }

    void unknown_block(std::string_view where, std::span<const std::string_view> allowed) {
        if (allowed.empty()) {
            sink_.error(cur_->pos, "unexpected block " + quote(cur_->text.substr(0, 40)) + " " +
                                       std::string(where) + ", which holds only properties");
        } else {
            sink_.error(cur_->pos, unknown_name_message("block", cur_->text, where, allowed));
        }
        skip_block();
    }

    // A property in a block that holds only blocks (cameras, scene).
    auto only_blocks(const BlockSource& block, std::span<const std::string_view> allowed) {
        return [this, &block, allowed](const Property& p) {
            std::string list;
            for (std::string_view name : allowed)
                list += (list.empty() ? "" : ", ") + std::string(name);
            sink_.error(p.name_span.pos,
                        "'" + std::string(block.keyword) + "' holds only blocks (" + list +
                            "), not properties like '" + std::string(p.name) + "'");
        };
    }

    // Reads a block that holds only properties (render_settings,
    // perspective_camera, point_light, material, transform) into `target`, from
    // its keyword to its '}'. False (recovered) when its '{' is missing.
    // `keyword`: the schema's keyword the word at hand was matched to, if known.
    template <class Target>
    bool parse_property_block(BlockSource& block, std::size_t level, Target& target,
                              std::string_view keyword = {}) {
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

    void block_in_property_block(const BlockSource& block) {
        if (block.keyword == schema_of<PointLight>().keyword &&
            contains(primitive_blocks(), cur_->text)) {
            sink_.error(cur_->pos, "a " + std::string(block.keyword) + " takes no '" +
                                       std::string(cur_->text) + "' block: only " +
                                       listed(shape_keywords(), "and") + " do");
            skip_block();
            return;
        }
        unknown_block("in '" + std::string(block.keyword) + "'", kNoBlocks);
    }

    void parse_file() {
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
            } else if (at(TokenKind::word) &&
                       same_name(cur_->text, schema_of<Material>().keyword) &&
                       next_->kind != TokenKind::lbrace) {
                parse_named_material();
            } else if (at(TokenKind::word)) {
                unknown_block("at the top level", top_blocks());
            } else if (at(TokenKind::lbrace)) {
                sink_.error(cur_->pos, "expected a block name (" + listed(top_blocks(), "or") +
                                           ") before '{'");
                skip_braced();
            } else {
                if (!at(TokenKind::bad_value)) {  // a bad value was reported by the lexer
                    sink_.error(cur_->pos, "expected a block (" + listed(top_blocks(), "or") +
                                               "), got " + describe(*cur_));
                }
                advance();
            }
        }
    }

    void parse_render_settings() {
        BlockSource block;
        RenderSettings settings;  // a later block replaces the earlier one whole
        if (!parse_property_block(block, 0, settings)) return;
        if (result_.source.render_settings) {
            sink_.warning(
                block.keyword_span.pos,
                "another 'render_settings' block: only the last one is used, so the "
                "one at line " +
                    std::to_string(result_.source.render_settings->keyword_span.pos.line) +
                    " is ignored");
        }
        result_.scene.settings = std::move(settings);
        result_.source.render_settings = std::move(block);
    }

    void parse_cameras() {
        BlockSource cameras;
        if (!open_block(cameras)) return;
        parse_body(cameras, cameras_blocks(), only_blocks(cameras, cameras_blocks()), [&] {
            if (cur_->text != schema_of<Camera>().keyword) {
                unknown_block("in '" + std::string(kCamerasKeyword) + "'", cameras_blocks());
                return;
            }
            BlockSource block;
            Camera camera;
            if (!parse_property_block(block, 0, camera)) return;
            result_.scene.cameras.push_back(std::move(camera));
            result_.source.cameras.push_back(std::move(block));
        });
    }

    void parse_scene() {
        BlockSource block;
        SceneChildren children;
        if (!open_block(block)) return;
        // Only the first scene block gets the hint: it was counted over the whole text.
        std::size_t hint = std::exchange(primitive_hint_, 0);
        // The earlier parse's primitives stay where they are, each replaced
        // by the one read at its index unless taken: a frame holds one array.
        if (earlier_) children.primitives = std::move(earlier_->primitives);
        // A large array's fresh pages are faulted in beside the parse (io/page_warmer.hpp).
        PageWarmer warmer;
        if (children.primitives.empty()) {
            reserve_records(children.primitives, hint);
            warmer.start(children.primitives.data(),
                         children.primitives.capacity() * sizeof(Primitive));
        }
        if (source_map_) reserve_records(children.primitive_sources, hint);
        ScenePartThreads parts;
        // The warmer already has a second core faulting in the scene's array,
        // the most of a huge scene's parse: parts would write it twice (their
        // own arrays, then the scene's), which measured slower on a million spheres.
        if (hint > 0 && !warmer.warming()) start_scene_parts(parts, hint);
        // Threads reading parts read ahead of this one, and a part not taken
        // is read again here: no text may be given back while they run.
        if (!parts.empty()) reports_text_passed_ = false;
        parse_body(block, scene_blocks(), only_blocks(block, scene_blocks()), [&] {
            if (!take_scene_part(parts, children)) parse_scene_child(children, warmer);
        });
        parts.stop();
        if (result_.source.scene) {
            sink_.warning(block.keyword_span.pos,
                          "another 'scene' block: only the last one is used, so the one at line " +
                              std::to_string(result_.source.scene->keyword_span.pos.line) +
                              " is ignored");
        }
        std::vector<Primitive>& primitives = children.primitives;
        primitives.erase(primitives.begin() + static_cast<std::ptrdiff_t>(children.placed),
                         primitives.end());
        warmer.finish(primitives.data(), primitives.size() * sizeof(Primitive));
        result_.scene.primitives = std::move(primitives);
        result_.primitive_readings = std::move(children.readings);
        result_.scene.lights = std::move(children.lights);
        result_.source.primitives = std::move(children.primitive_sources);
        result_.source.lights = std::move(children.light_sources);
        result_.source.scene = std::move(block);
    }

    // At the keyword of a block in `scene`: reads it into `into`.
    void parse_scene_child(SceneChildren& into, PageWarmer& warmer) {
        std::string_view kind = cur_->text;
        if (same_name(kind, schema_of<PointLight>().keyword)) {
            BlockSource light_block;
            PointLight light;
            if (!parse_property_block(light_block, 0, light)) return;
            into.lights.push_back(light);
            into.light_sources.push_back(std::move(light_block));
        } else if (std::optional<Shape> shape = shape_of_keyword(kind)) {
            if (take_earlier(into.primitives, into.placed, into.readings)) return;
            const std::uint32_t file = cur_->pos.file;
            const auto keyword = static_cast<std::uint32_t>(cur_->offset);
            const std::uint64_t clock_reads = expressions_.clock_reads();
            Primitive primitive;
            primitive.shape = std::move(*shape);
            BlockSource primitive_block;
            if (!open_block(primitive_block, keyword_of(primitive.shape), /*behind=*/true)) return;
            in_primitive_ = true;
            primitive.material.finish = take_scratch_finish();
            read_properties(primitive_block, 0,
                            [&](OpenBlock& open) { parse_primitive_body(primitive, open); });
            in_primitive_ = false;
            if (!keep_primitives_) return;
            share_finish(primitive.material);
            if (into.placed < into.primitives.size())
                into.primitives[into.placed] = std::move(primitive);
            else
                into.primitives.push_back(std::move(primitive));
            ++into.placed;
            warmer.filled(into.placed * sizeof(Primitive));
            report_text_passed();
            if (source_map_) into.primitive_sources.push_back(primitive_block);
            if (record_readings_)
                into.readings.push_back({file, keyword, static_cast<std::uint32_t>(cur_->offset),
                                         cur_->pos, expressions_.clock_reads() > clock_reads});
        } else {
            unknown_block("in '" + std::string(kSceneKeyword) + "'", scene_blocks());
        }
    }

    // ParseOptions::text_passed, every text_passed_step bytes of the main
    // text: nothing before the token at hand is read again (the lookahead and
    // the lexer are past it).
    void report_text_passed() {
        if (!reports_text_passed_ || reading_ != &lexer_ || cur_->pos.file != 0 ||
            cur_->offset < next_text_passed_)
            return;
        next_text_passed_ = cur_->offset + text_passed_step;
        options_.text_passed(cur_->offset);
    }

    // --- a large scene block read in parts (scene_parts.hpp) ------------

    // Just past a scene block's '{': starts threads reading the parts after
    // the first, when the rest of the text is large enough to share out.
    // `hint` bounds the number of primitives in the block.
    void start_scene_parts(ScenePartThreads& parts, std::size_t hint) {
        if (!keep_primitives_ || earlier_ || record_readings_ || reading_ != &lexer_) return;
        const std::size_t from = cur_->offset;
        const std::size_t bytes = text_.size() - from;
        const unsigned count = scene_part_count(bytes, options_.threads);
        if (count < 2) return;
        std::vector<std::size_t> starts = guess_scene_part_starts(text_, from, count);
        if (starts.empty()) return;
        std::vector<ScenePart> planned(starts.size());
        for (std::size_t i = 0; i < starts.size(); ++i) {
            planned[i].begin = starts[i];
            planned[i].end = i + 1 < starts.size() ? starts[i + 1] : text_.size();
        }
        const std::string_view text = text_;
        const ParseOptions& options = options_;
        // A copy each, made here: an include the parser meets in the first part
        // may still mark this table while the parts are read.
        const NameTable names = names_;
        const std::atomic<bool>& cancelled = parts.cancelled();
        const std::size_t properties = property_hint_;
        parts.start(std::move(planned), [=, &options, &cancelled](ScenePart& part) {
            // The whole text's counts, shared out by size with an eighth to spare:
            // arrays that grow as they go take 4 KiB page faults, 18 us each here.
            const double share =
                1.125 * static_cast<double>(part.end - part.begin) / static_cast<double>(bytes);
            const auto hint_for_part = [share](std::size_t count) {
                return static_cast<std::size_t>(static_cast<double>(count) * share) + 1;
            };
            try {
                Parser reader(text, options, names, part.begin);
                reader.read_scene_part(part, hint_for_part(hint), hint_for_part(properties),
                                       cancelled);
            } catch (const std::exception&) {
                part.usable = false;  // read again by the parser, which reports what it meets
            }
        });
    }

    // A part's reading, on its thread. Stops unusable at the first diagnostic
    // or at anything but a block's keyword and '{'.
    // `blocks` and `properties` bound the part's counts as the whole text's
    // hints do (blocks a few times over: a primitive's material counts too).
    void read_scene_part(ScenePart& part, std::size_t blocks, std::size_t properties,
                         const std::atomic<bool>& cancelled) {
        SceneChildren& children = part.children;
        const std::size_t per_array = std::min(blocks, kPartArrayPrimitives);
        reserve_records(children.primitives, per_array);
        if (source_map_) {
            reserve_records(children.primitive_sources, blocks);
            reserve_records(result_.source.children, blocks);
            reserve_records(result_.source.properties, properties);
        }
        PageWarmer unused;
        for (;;) {
            if (sink_.any() || cancelled.load(std::memory_order_relaxed)) return;
            if (at(TokenKind::rbrace) || (at(TokenKind::word) && cur_->offset >= part.end)) break;
            if (!at(TokenKind::word) || next_->kind != TokenKind::lbrace) return;
            if (children.primitives.size() == children.primitives.capacity()) {
                part.filled.push_back(std::move(children.primitives));
                reserve_records(children.primitives, per_array);
            }
            parse_scene_child(children, unused);
        }
        part.properties = std::move(result_.source.properties);
        part.nested = std::move(result_.source.children);
        part.reads_clock = result_.reads_clock || expressions_.read_clock();
        part.stop = cur_->offset;
        part.stop_pos = cur_->pos;
        part.usable = true;
    }

    // At the keyword of a block in `scene`: when a part read on a thread
    // begins here and is usable, takes what it read into `into` and goes on
    // where it ended. False: read on here.
    bool take_scene_part(ScenePartThreads& parts, SceneChildren& into) {
        // In an included file, offsets are into another text.
        if (parts.empty() || reading_ != &lexer_) return false;
        ScenePart* part = parts.take_at(cur_->offset);
        if (part == nullptr || !part->usable) return false;
        SceneChildren& read = part->children;
        const auto property_base = static_cast<std::uint32_t>(result_.source.properties.size());
        const auto nested_base = static_cast<std::uint32_t>(result_.source.children.size());
        for (BlockSource& b : part->nested) b.properties.first += property_base;
        for (BlockSource& b : read.primitive_sources) {
            b.properties.first += property_base;
            b.children.first += nested_base;
        }
        for (BlockSource& b : read.light_sources) b.properties.first += property_base;
        append_moved(result_.source.properties, part->properties);
        append_moved(result_.source.children, part->nested);
        append_moved(into.primitive_sources, read.primitive_sources);
        append_moved(into.light_sources, read.light_sources);
        append_moved(into.lights, read.lights);
        part->filled.push_back(std::move(read.primitives));
        for (std::vector<Primitive>& array : part->filled) append_moved(into.primitives, array);
        into.placed = into.primitives.size();
        read = {};
        result_.reads_clock = result_.reads_clock || part->reads_clock;
        ++result_.scene_parts_taken;
        lexer_.resume_at(part->stop, part->stop_pos);
        lexer_.next(*cur_);
        lexer_.next(*next_);
        return true;
    }

    template <class T>
    static void append_moved(std::vector<T>& to, std::vector<T>& from) {
        to.insert(to.end(), std::make_move_iterator(from.begin()),
                  std::make_move_iterator(from.end()));
        from = std::vector<T>();  // `= {}` would keep the memory
    }

    // At a primitive's keyword: keeps the earlier parse's primitive at index
    // `placed` of `primitives` when it was read from here and read no `clock`,
    // and goes on after its '}'. False: read it.
    bool take_earlier(std::vector<Primitive>& primitives, std::size_t& placed,
                      std::vector<PrimitiveReading>& readings) {
        if (!earlier_ || placed >= earlier_->readings.size() || placed >= primitives.size())
            return false;
        const PrimitiveReading& reading = earlier_->readings[placed];
        if (reading.reads_clock || reading.file != cur_->pos.file ||
            reading.keyword != cur_->offset)
            return false;
        ++placed;
        if (record_readings_) readings.push_back(reading);
        reading_->resume_at(reading.resume, reading.resume_pos);
        reading_->next(*cur_);
        reading_->next(*next_);
        return true;
    }

    // A finish of the parser's own, at its default value, for a primitive's
    // material blocks to write into: reading a primitive allocates a finish
    // only when it is one not met before (share_finish keeps that one).
    Shared<Finish> take_scratch_finish() {
        if (scratch_finish_.unique())
            scratch_finish_.edit() = Finish{};
        else
            scratch_finish_ = Shared<Finish>(Finish{});
        return std::move(scratch_finish_);
    }

    // Makes the material share an equal finish met before; when it does, the
    // finish it was read into is the scratch again.
    void share_finish(Material& material) {
        Shared<Finish> read = material.finish;
        finishes_.share(material.finish);
        if (!material.finish.shares_with(read)) scratch_finish_ = std::move(read);
    }

    // A primitive's children go straight to the scene's array of child records:
    // nothing else is added there until the primitive's '}', so they stay together.
    void parse_primitive_body(Primitive& primitive, OpenBlock& open) {
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
                                            where(named_at));
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
                    unknown_block("in '" + std::string(block.keyword) + "'", primitive_blocks());
                    return;
                }
                if (opened && source_map_ && keep_primitives_) children.push_back(child);
            });
        block.children = {static_cast<std::uint32_t>(first_child),
                          static_cast<std::uint32_t>(children.size() - first_child)};
    }

    // At `material` ':' in a primitive: reads `material: NAME;` whole and
    // returns the named material, or nullptr (reported).
    const Symbol* read_material_reference() {
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

    static std::string kind_words(const Symbol& symbol) {
        switch (symbol.value.kind) {
            case ExprValue::Kind::number:
                return "a number";
            case ExprValue::Kind::vector:
                return "a vector";
            default:
                return "a string";
        }
    }

    // --- names (docs/language.md §15.2) --------------------------------

    // The --define values, evaluated before the file: a bad one (the front
    // ends check them first) is an error without a location.
    void set_command_line_names(const ParseOptions& options) {
        for (const Define& define : options.defines) {
            // Over-cautious for a string that holds the word; never wrong.
            if (define.value.find("clock") != std::string::npos) result_.reads_clock = true;
            ExprValue value;
            std::string error;
            if (!evaluate_define_value(define.value, options.clock, value, error)) {
                sink_.error({}, "--define " + define.name + "=" + define.value + ": " + error);
                continue;
            }
            Symbol* symbol = names_.find(define.name);
            if (symbol) {
                if (sink_.accepts_warnings())
                    sink_.warning({}, "--define " + define.name +
                                          " is given more than once; the last value is used");
            } else {
                symbol = &names_.add(define.name);
                command_line_.emplace_back(define.name, symbol);
            }
            symbol->from_command_line = true;
            symbol->reads_clock = define.value.find("clock") != std::string::npos;
            symbol->value = value;
            if (value.kind == ExprValue::Kind::string)
                NameTable::set_string(*symbol, std::string(value.text));
        }
    }

    // At a name being defined: false (reported) when it is reserved or taken.
    // `overridden` is set for a name a --define holds.
    bool claim_name(const Token& name, bool& overridden) {
        overridden = false;
        if (is_reserved_name(name.text)) {
            sink_.error(name.pos, quote(name.text) +
                                      " is reserved (a keyword, a function, pi or clock) and "
                                      "cannot be defined");
            return false;
        }
        Symbol* existing = names_.find(name.text);
        if (!existing) return true;
        if (existing->from_command_line && !existing->defined_in_file) {
            existing->defined_in_file = true;
            existing->defined_at = name.pos;
            overridden = true;
            return true;
        }
        std::string message = quote(name.text) + " is defined twice: it was first defined at " +
                              include_.where(existing->defined_at);
        if (name.pos.file != 0) message += "; read again here" + include_.chain(name.pos.file);
        sink_.error(name.pos, std::move(message));
        return false;
    }

    // At `define`: define NAME '=' (STRING | expr) ';'
    void parse_define() {
        advance();
        if (!at(TokenKind::word)) {
            if (!at(TokenKind::bad_value))
                sink_.error(cur_->pos, "expected a name after 'define', got " + describe(*cur_));
            skip_statement();
            return;
        }
        const Token name = *cur_;
        bool overridden = false;
        const bool claimed = claim_name(name, overridden);
        advance();
        if (!at(TokenKind::equals)) {
            sink_.error(cur_->pos, "expected '=' after 'define " + std::string(name.text) +
                                       "', got " + describe(*cur_));
            skip_statement();
            return;
        }
        advance();
        const std::uint64_t clock_reads = expressions_.clock_reads();
        Value value = read_value(!overridden);
        if (value.form == Value::Form::none) {
            sink_.error(cur_->pos, "expected a value after 'define " + std::string(name.text) +
                                       " =', got " + describe(*cur_));
            skip_statement();
            return;
        }
        const bool good = value.form != Value::Form::bad;
        if (claimed && !overridden) {
            Symbol& symbol = names_.add(name.text);
            symbol.defined_at = name.pos;
            symbol.definition = static_cast<std::uint32_t>(result_.source.definitions.size());
            symbol.bad = !good;
            symbol.reads_clock = expressions_.clock_reads() > clock_reads;
            if (value.form == Value::Form::number) {
                symbol.value.kind = ExprValue::Kind::number;
                symbol.value.number = value.number;
            } else if (value.form == Value::Form::vector) {
                symbol.value.kind = ExprValue::Kind::vector;
                symbol.value.vector = value.vector;
            } else if (value.form == Value::Form::string) {
                NameTable::set_string(symbol, std::string(value.text));
            }
        }
        if (overridden) {
            sink_.note(name.pos,
                       quote(name.text) + " is set by --define; this definition is ignored");
        }
        if (source_map_ && claimed) {
            result_.source.definitions.push_back(
                {std::string(name.text), span_of(name), value.span, value.origin, std::nullopt});
        }
        if (!good) {
            skip_statement();
            return;
        }
        if (at(TokenKind::semicolon)) {
            advance();
            return;
        }
        sink_.error(value.end,
                    "expected ';' after the value of 'define " + std::string(name.text) + "'");
        if (!at(TokenKind::word) && !at(TokenKind::rbrace)) skip_statement();
    }

    // At `material` NAME: a named material, `material NAME { property* }`.
    void parse_named_material() {
        BlockSource block;
        block.keyword = schema_of<Material>().keyword;
        block.keyword_span = span_of(*cur_);
        advance();
        if (!at(TokenKind::word)) {
            sink_.error(cur_->pos,
                        "expected a name or '{' after 'material', got " + describe(*cur_));
            skip_statement();
            return;
        }
        const Token name = *cur_;
        bool overridden = false;
        bool claimed = claim_name(name, overridden);
        if (overridden) {
            // A --define holds a value of that name: a material cannot replace it.
            sink_.error(name.pos,
                        quote(name.text) + " is set by --define; a material cannot have its name");
            claimed = false;
        }
        advance();
        if (!at(TokenKind::lbrace)) {
            sink_.error(cur_->pos, "expected '{' after 'material " + std::string(name.text) +
                                       "', got " + describe(*cur_));
            skip_statement();
            return;
        }
        block.open_brace = static_cast<std::uint32_t>(cur_->offset);
        advance();
        Material material;
        const std::size_t errors_before = error_count();
        const std::uint64_t clock_reads = expressions_.clock_reads();
        read_properties(block, 0, [&](OpenBlock& open) {
            parse_body(
                block, kNoBlocks, [&](const Property& p) { reader_.apply(material, open, p); },
                [&] { block_in_property_block(block); });
        });
        if (!claimed) return;
        finishes_.share(material.finish);
        Symbol& symbol = names_.add(name.text);
        symbol.kind = Symbol::Kind::material;
        symbol.material = material;
        symbol.defined_at = name.pos;
        symbol.bad = error_count() != errors_before;
        symbol.reads_clock = expressions_.clock_reads() > clock_reads;
        symbol.definition = static_cast<std::uint32_t>(result_.source.definitions.size());
        if (source_map_) {
            result_.source.definitions.push_back({std::string(name.text),
                                                  span_of(name),
                                                  {},
                                                  ValueOrigin::literal,
                                                  block.properties});
        }
    }

    std::size_t error_count() const { return static_cast<std::size_t>(sink_.error_count()); }

    std::string_view text_;  // the text being read: the main one or an included one
    DiagnosticSink sink_;
    Lexer lexer_;               // the main text's
    Lexer* reading_ = &lexer_;  // the text being read's
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

}  // namespace
}  // namespace lang

SceneSource lang::source_without_primitives(std::string_view text, const ParseOptions& options) {
    ParseOptions with_map = options;
    with_map.source_map = true;
    return lang::Parser(text, with_map, false).run().source;
}

ParseResult parse_scene(std::string_view text, ParseOptions options) {
    try {
        std::size_t bad = lang::find_invalid_text_byte(text);
        if (bad != std::string_view::npos) {
            ParseResult result;
            std::string what = text[bad] == '\0' ? "a NUL byte" : "a byte that is not UTF-8 text";
            result.diagnostics.push_back({Severity::error, lang::position_of(text, bad),
                                          "the file is not a text file: it contains " + what});
            return result;
        }
        if (text.size() >= std::numeric_limits<std::uint32_t>::max()) {
            ParseResult result;
            result.diagnostics.push_back(
                {Severity::error, {}, "the scene text is too large: 4 GiB or more"});
            return result;
        }
        return lang::Parser(text, options).run();
    } catch (const std::bad_alloc&) {
        ParseResult result;
        result.out_of_memory = true;
        result.diagnostics.push_back(
            {Severity::error,
             {},
             "out of memory: the scene is too large for the memory available"});
        return result;
    } catch (const std::exception& e) {
        ParseResult result;
        result.diagnostics.push_back(
            {Severity::error, {}, std::string("the scene could not be read: ") + e.what()});
        return result;
    }
}

}  // namespace jt

#pragma once
// Splits .jts text into tokens (docs/language.md §2). Tokens are views into
// the text: lexing allocates nothing per token.

#include "jtracer/scene.hpp"
#include "language/diagnostic_sink.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace jt::lang {

enum class TokenKind {
    word,       // [a-z_A-Z][a-zA-Z0-9_]*: keywords and names (case is checked by the parser)
    number,     // a finite unsigned number; its value is in Token::number
    string,     // "..."; Token::text excludes the quotes
    bad_value,  // a malformed number or string, already reported
    lbrace,
    rbrace,
    colon,
    semicolon,
    less,
    greater,
    comma,
    // Language 1.3 (docs/language.md §15): definitions and arithmetic.
    equals,
    lparen,
    rparen,
    plus,
    minus,
    star,
    slash,
    end,
};

struct Token {
    TokenKind kind = TokenKind::end;
    std::string_view text;   // the token's bytes (a string's without its quotes)
    std::size_t offset = 0;  // of the first byte, quotes included
    std::size_t length = 0;  // in bytes, quotes included
    SourcePos pos;
    double number = 0.0;
};

// Whether `c` may stand in a word after its first byte: [A-Za-z0-9_].
bool is_word_char(char c);

class Lexer {
  public:
    // `file` is the text's index (SourcePos::file): 0 the main file.
    Lexer(std::string_view text, DiagnosticSink& sink, std::uint32_t file = 0)
        : text_(text), sink_(sink), file_(file) {
        // A UTF-8 byte order mark is harmless: skip it (columns still count its bytes).
        if (text_.starts_with("\xEF\xBB\xBF")) at_ = 3;
        words_stop_inside_ = !text_.empty() && !is_word_char(text_.back());
    }
    // Reads the next token into `out`; `end` at the end of the text or once the
    // sink has stopped. Written in place, field by field: returning a Token by
    // value made the parser copy it with wide loads right after the lexer's
    // narrow stores, a store-forwarding stall per token (a quarter of a parse).
    void next(Token& out);

    // A value of plain numbers, read by read_plain_value without tokens.
    struct PlainValue {
        bool is_vector = false;
        double number = 0.0;     // when !is_vector
        Vec3 vector{0.0};        // when is_vector
        std::size_t offset = 0;  // of its first byte: its sign, its first digit or '<'
        std::size_t length = 0;
    };
    // From just past the last token read (a property's ':'): a number with at
    // most one sign, or a vector of three such (`<0.5, -1, 2e3>`), written on
    // that line without comments and followed by ';' on it, as generators and
    // people write most values. Sets `out` to what the tokens and the
    // expression reader make of it and continues after the ';'; returns false
    // and moves nothing for anything else, or for a number the tokens would
    // read with an error or not on Clinger's fast path (read those by tokens).
    bool read_plain_value(PlainValue& out);
    // At the '<' at `offset` (anywhere on the line of the last token read):
    // the same for a vector, followed by ';'. Returns the offset just past its
    // '>' and moves nothing, or returns 0.
    std::size_t plain_vector(std::size_t offset, Vec3& out) const;
    // A property as generators and people write most: a name directly
    // followed by ':' and a value as read_plain_value reads it.
    struct PlainProperty {
        std::string_view name;  // a view into the text, as the name's token
        std::size_t name_offset = 0;
        SourcePos name_pos;
        PlainValue value;
        SourcePos value_pos;  // of value.offset
        int line = 0;         // the line it is on
        std::size_t line_start = 0;
    };
    // The property just past the last token read, when only spaces, or one
    // line break and an indentation of spaces, stand between them: fills
    // `out` with what the tokens (a word, ':') and read_plain_value make of
    // it and returns the offset just past its ';', moving nothing
    // (continue_at moves there). Returns 0 for anything else: the tokens
    // read that.
    std::size_t plain_property(PlainProperty& out) const;
    // Continues from `offset`, on the line of `property` (plain_property's).
    void continue_at(std::size_t offset, const PlainProperty& property) {
        at_ = offset;
        line_ = property.line;
        line_start_ = property.line_start;
    }
    // Continues from `offset`, on the line of the last token read.
    void skip_to(std::size_t offset) { at_ = offset; }
    // The first comment read that starts as a POV-Ray directive ("#include",
    // "#declare", "#local"); line 0 when none has.
    SourcePos directive_comment() const { return directive_comment_; }
    // Whether a byte that starts no token (reported and skipped) stood in
    // [from, to): then a parser's "expected ';'" there would only repeat it.
    bool skipped_between(std::size_t from, std::size_t to) const {
        return skipped_at_ != npos_skipped && skipped_at_ >= from && skipped_at_ < to;
    }
    // Continues from `offset`, which is at `pos` (a token this text gave before).
    void resume_at(std::size_t offset, SourcePos pos) {
        at_ = offset;
        line_ = pos.line;
        line_start_ = offset - static_cast<std::size_t>(pos.column - 1);
    }

  private:
    void skip_space_and_comments();
    // At at_: a word or a one-byte token read into `out`, or false.
    inline bool take_word_or_mark(Token& out);
    // The tokens next() leaves: strings, numbers, unexpected bytes, the end.
    [[gnu::noinline]] void next_rare(Token& out);
    // The rare tokens and the errors stay out of next(): inlined, their
    // strings made next() save six registers and a frame for every token.
    [[gnu::noinline]] void lex_number(std::size_t start, Token& out);
    [[gnu::noinline]] void lex_string(std::size_t start, Token& out);
    [[gnu::noinline]] void lex_curly_string(std::size_t start, Token& out);
    // Whether '//' or '/*' starts at `offset`.
    bool c_comment_at(std::size_t offset) const {
        return text_[offset] == '/' && offset + 1 < text_.size() &&
               (text_[offset + 1] == '/' || text_[offset + 1] == '*');
    }
    // Reports the '//' or '/*' comment at at_ and skips it.
    [[gnu::noinline]] void skip_c_comment();
    // Reports the byte at at_, which starts no token, and skips it.
    [[gnu::noinline]] void skip_unexpected();
    SourcePos pos_of(std::size_t offset) const {
        return {line_, static_cast<int>(offset - line_start_) + 1, file_};
    }

    std::string_view text_;
    DiagnosticSink& sink_;
    std::uint32_t file_;
    std::size_t at_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0;
    // Whether the text's last byte ends a word: then every word ends inside
    // the text, and next() scans one with no test of the end.
    bool words_stop_inside_ = false;
    static constexpr std::size_t npos_skipped = static_cast<std::size_t>(-1);
    // The offset of the last byte skip_unexpected() reported.
    std::size_t skipped_at_ = npos_skipped;
    SourcePos directive_comment_{0, 0, 0};
    [[gnu::noinline]] void note_directive_comment();
};

// A short description of a token for messages: "the number 2", "'}'", "the word 'foo'".
std::string describe(const Token& token);

// Offset of the first byte that makes `text` not valid UTF-8 text or that is a
// NUL byte; npos when there is none.
std::size_t find_invalid_text_byte(std::string_view text);

// 1-based line and byte column of `offset` in `text`.
SourcePos position_of(std::string_view text, std::size_t offset);

}  // namespace jt::lang

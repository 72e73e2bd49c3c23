#include "language/lexer.hpp"

#include "jtracer/utf8.hpp"
#include "language/quote.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace jt::lang {

namespace {

enum CharClass : unsigned char { digit = 1, word_start = 2, number_part = 4, blank = 8 };

constexpr auto char_classes = [] {
    std::array<unsigned char, 256> table{};
    for (int c = '0'; c <= '9'; ++c) table[c] = digit | number_part;
    for (int c = 'a'; c <= 'z'; ++c) table[c] = word_start;
    for (int c = 'A'; c <= 'Z'; ++c) table[c] = word_start;
    table['_'] = word_start;
    // Characters that continue something that started like a number, so that
    // ".3.2" and "1..2" are each one malformed number. A sign is an operator
    // (docs/language.md §15.1) except right after an exponent's 'e'.
    table['.'] = number_part;
    table['e'] |= number_part;
    table['E'] |= number_part;
    // What skip_space_and_comments skips.
    for (char c : {' ', '\t', '\r', '\n', '#'}) table[static_cast<unsigned char>(c)] = blank;
    return table;
}();

// The token each byte that is a token alone makes; `end` for the others.
constexpr auto single_byte_tokens = [] {
    std::array<TokenKind, 256> table{};
    table.fill(TokenKind::end);
    table['{'] = TokenKind::lbrace;
    table['}'] = TokenKind::rbrace;
    table[':'] = TokenKind::colon;
    table[';'] = TokenKind::semicolon;
    table['<'] = TokenKind::less;
    table['>'] = TokenKind::greater;
    table[','] = TokenKind::comma;
    table['='] = TokenKind::equals;
    table['('] = TokenKind::lparen;
    table[')'] = TokenKind::rparen;
    table['+'] = TokenKind::plus;
    table['-'] = TokenKind::minus;
    table['*'] = TokenKind::star;
    table['/'] = TokenKind::slash;
    return table;
}();

bool has_class(char c, unsigned char cls) {
    return char_classes[static_cast<unsigned char>(c)] & cls;
}
bool is_digit(char c) {
    return has_class(c, digit);
}
bool is_word_start(char c) {
    return has_class(c, word_start);
}
bool is_number_char(char c) {
    return has_class(c, number_part);
}
bool starts_blank_or_comment(char c) {
    return has_class(c, blank);
}

void set(Token& out, TokenKind kind, std::string_view text, std::size_t offset, std::size_t length,
         SourcePos pos) {
    out.kind = kind;
    out.text = text;
    out.offset = offset;
    out.length = length;
    out.pos = pos;
    out.number = 0.0;
}

std::string byte_name(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", c);
    return buf;
}

// The spaces at `i`, eight at a time while eight remain: indentation is the
// most of the blank bytes people's scenes hold.
std::size_t skip_spaces(std::string_view text, std::size_t i) {
    constexpr std::uint64_t spaces = 0x2020202020202020ull;
    while (i + 8 <= text.size()) {
        std::uint64_t w;
        std::memcpy(&w, text.data() + i, 8);
        const std::uint64_t other = w ^ spaces;  // nonzero in the bytes that are not spaces
        if (other != 0) {
            if constexpr (std::endian::native == std::endian::little)
                return i + static_cast<std::size_t>(std::countr_zero(other)) / 8;
            break;
        }
        i += 8;
    }
    while (i < text.size() && text[i] == ' ') ++i;
    return i;
}

}  // namespace

bool is_word_char(char c) {
    return has_class(c, word_start | digit);
}

void Lexer::skip_space_and_comments() {
    const std::size_t n = text_.size();
    while (at_ < n) {
        char c = text_[at_];
        if (c == ' ') {
            at_ = skip_spaces(text_, at_ + 1);
        } else if (c == '\t' || c == '\r') {
            ++at_;
        } else if (c == '\n') {
            ++at_;
            ++line_;
            line_start_ = at_;
        } else if (c == '#') {
            if (directive_comment_.line == 0 && at_ + 1 < n &&
                (text_[at_ + 1] == 'i' || text_[at_ + 1] == 'd' || text_[at_ + 1] == 'l'))
                note_directive_comment();
            const void* nl = std::memchr(text_.data() + at_, '\n', n - at_);
            at_ = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text_.data()) : n;
        } else {
            return;
        }
    }
}

void Lexer::note_directive_comment() {
    const std::string_view rest = text_.substr(at_ + 1);
    for (std::string_view directive : {"include", "declare", "local"})
        if (rest.starts_with(directive) && rest.size() > directive.size() &&
            (rest[directive.size()] == ' ' || rest[directive.size()] == '\t'))
            directive_comment_ = pos_of(at_);
}

bool Lexer::take_word_or_mark(Token& out) {
    const std::size_t start = at_;
    const char c = text_[start];
    // Words first, then the one-byte tokens from a table: a switch's
    // jump, taken to a different place each token, was mispredicted.
    if (is_word_start(c)) {
        // A local index: at_ itself would be stored back at every byte,
        // as the text's bytes might alias it for all the compiler knows.
        const char* const data = text_.data();
        const std::size_t n = text_.size();
        std::size_t end = start + 1;
        if (words_stop_inside_) {
            while (is_word_char(data[end])) ++end;
        } else {
            while (end < n && is_word_char(data[end])) ++end;
        }
        at_ = end;
        set(out, TokenKind::word, std::string_view(data + start, end - start), start, end - start,
            pos_of(start));
        return true;
    }
    if (const TokenKind kind = single_byte_tokens[static_cast<unsigned char>(c)];
        kind != TokenKind::end && !(kind == TokenKind::slash && c_comment_at(start))) {
        ++at_;
        set(out, kind, text_.substr(start, 1), start, 1, pos_of(start));
        return true;
    }
    return false;
}

void Lexer::next(Token& out) {
    // Most tokens follow another directly, one space, or a line break and
    // an indentation: skip the call then.
    if (at_ < text_.size() && starts_blank_or_comment(text_[at_])) {
        if (text_[at_] == '\n') {
            ++line_;
            line_start_ = at_ + 1;
            at_ = skip_spaces(text_, at_ + 1);
        } else if (text_[at_] == ' ') {
            at_ = skip_spaces(text_, at_ + 1);
        }
        if (at_ < text_.size() && starts_blank_or_comment(text_[at_])) skip_space_and_comments();
    }
    // A word or a one-byte token here, the rest out of line: with the loop
    // and the rare tokens in it, every token paid for saving five registers.
    if (!sink_.stopped() && at_ < text_.size() && take_word_or_mark(out)) return;
    next_rare(out);
}

namespace {

// Whether a curly double quote (U+201C, U+201D or U+201E) starts at `i`.
bool curly_quote_at(std::string_view text, std::size_t i) {
    return i + 2 < text.size() && text[i] == '\xE2' && text[i + 1] == '\x80' &&
           (text[i + 2] == '\x9C' || text[i + 2] == '\x9D' || text[i + 2] == '\x9E');
}

// What a character pasted from a word processor or a web page stands for.
std::string_view look_alike(char32_t code) {
    switch (code) {
        case 0x201C:
        case 0x201D:
        case 0x201E:
            return "a curly quote: strings take plain double quotes \"";
        case 0x2018:
        case 0x2019:
            return "a curly apostrophe";
        case 0x2212:
        case 0x2013:
        case 0x2014:
            return "a dash: minus is the plain -";
        case 0x00D7:
            return "a multiplication sign: multiply with *";
        case 0x00F7:
            return "a division sign: divide with /";
        case 0x00A0:
        case 0x202F:
            return "a no-break space: use a plain space";
        default:
            return "outside comments a scene is ASCII";
    }
}

}  // namespace

void Lexer::next_rare(Token& out) {
    while (!sink_.stopped() && at_ < text_.size()) {
        if (c_comment_at(at_)) {
            skip_c_comment();
            continue;
        }
        if (take_word_or_mark(out)) return;
        const std::size_t start = at_;
        const char c = text_[start];
        if (c == '"') {
            lex_string(start, out);
            return;
        }
        if (is_digit(c) || c == '.') {
            lex_number(start, out);
            return;
        }
        if (curly_quote_at(text_, start)) {
            lex_curly_string(start, out);
            return;
        }
        skip_unexpected();
    }
    set(out, TokenKind::end, {}, text_.size(), 0, pos_of(at_));
}

// A string in curly quotes, as a word processor writes one: one error, and
// the whole of it a bad value, up to its closing quote (curly or plain) or
// the end of the line, so that its words are not read as names.
void Lexer::lex_curly_string(std::size_t start, Token& out) {
    skipped_at_ = start;
    sink_.error(pos_of(start), "unexpected character U+" +
                                   std::string(text_[start + 2] == '\x9D' ? "201D" : "201C") +
                                   " (" + std::string(look_alike(0x201C)) + ")");
    std::size_t i = start + 3;
    const std::size_t n = text_.size();
    while (i < n && text_[i] != '\n' && text_[i] != '\r') {
        if (text_[i] == '"') {
            ++i;
            break;
        }
        if (curly_quote_at(text_, i)) {
            i += 3;
            break;
        }
        ++i;
    }
    at_ = i;
    set(out, TokenKind::bad_value, text_.substr(start, i - start), start, i - start, pos_of(start));
}

// A POV-Ray or C comment ('//' or '/*'): no value has '/' before '/' or '*',
// so it is one error, and the comment is skipped as '#' would have been, so
// that its words are not read as the scene.
void Lexer::skip_c_comment() {
    const std::size_t start = at_;
    const std::size_t n = text_.size();
    const bool line = text_[start + 1] == '/';
    sink_.error(pos_of(start), std::string(line ? "'//'" : "'/*'") +
                                   " starts no comment here: a comment runs from '#' to the "
                                   "end of the line");
    std::size_t i = start + 2;
    if (line) {
        while (i < n && text_[i] != '\n') ++i;
    } else {
        while (i < n && !(text_[i] == '*' && i + 1 < n && text_[i + 1] == '/')) {
            if (text_[i] == '\n') {
                ++line_;
                line_start_ = i + 1;
            }
            ++i;
        }
        i = i < n ? i + 2 : n;
    }
    at_ = i;
    skip_space_and_comments();
}

void Lexer::skip_unexpected() {
    const std::size_t start = at_;
    skipped_at_ = start;
    const char c = text_[start];
    auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
        sink_.error(pos_of(start), std::string("unexpected character '") + c + "'");
    } else if (const std::optional<Utf8Character> character =
                   u >= 0x80 ? utf8_character_at(text_, start) : std::nullopt) {
        char name[16];
        std::snprintf(name, sizeof name, "U+%04lX", static_cast<unsigned long>(character->code));
        sink_.error(pos_of(start), "unexpected character " + std::string(name) + " (" +
                                       std::string(look_alike(character->code)) + ")");
    } else {
        sink_.error(pos_of(start), "unexpected byte " + byte_name(u));
    }
    ++at_;
    // Skip the rest of a multi-byte UTF-8 character as part of the same mistake.
    while (at_ < text_.size() && (static_cast<unsigned char>(text_[at_]) & 0xC0) == 0x80) ++at_;
    skip_space_and_comments();
}

namespace {

enum class NumberScan { malformed, exact, needs_library };

// Exact doubles: Clinger's fast path divides or multiplies by one of them.
constexpr double powers_of_ten[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// One pass over a number-like run: checks the grammar
//   (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?
// and computes the value on Clinger's fast path: at most 15 significant digits
// and a power of ten up to 22 make m / 10^k or m * 10^k one correctly rounded
// operation, the same double std::from_chars gives. Other numbers need the library.
NumberScan scan_number(std::string_view s, double& out) {
    const std::size_t n = s.size();
    std::size_t i = 0;
    std::uint64_t mantissa = 0;
    int significant = 0, scale = 0;
    std::size_t digits = 0;
    for (; i < n && is_digit(s[i]); ++i, ++digits) {
        if (mantissa != 0 || s[i] != '0') {  // leading zeros are not significant
            mantissa = mantissa * 10 + static_cast<unsigned>(s[i] - '0');
            ++significant;
        }
    }
    if (i < n && s[i] == '.') {
        for (++i; i < n && is_digit(s[i]); ++i, ++digits) {
            --scale;
            if (mantissa != 0 || s[i] != '0') {
                mantissa = mantissa * 10 + static_cast<unsigned>(s[i] - '0');
                ++significant;
            }
        }
    }
    if (digits == 0) return NumberScan::malformed;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        bool negative_exponent = false;
        if (i < n && (s[i] == '+' || s[i] == '-')) negative_exponent = s[i++] == '-';
        const std::size_t first = i;
        int exponent = 0;
        for (; i < n && is_digit(s[i]); ++i) {
            if (exponent < 100000) exponent = exponent * 10 + (s[i] - '0');
        }
        if (i == first) return NumberScan::malformed;
        scale += negative_exponent ? -exponent : exponent;
    }
    if (i != n) return NumberScan::malformed;
    if (significant > 15 || scale < -22 || scale > 22) return NumberScan::needs_library;
    double value = static_cast<double>(mantissa);
    value = scale < 0 ? value / powers_of_ten[-scale] : value * powers_of_ten[scale];
    out = value;
    return NumberScan::exact;
}

}  // namespace

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

void skip_blanks(std::string_view s, std::size_t& i) {
    while (i < s.size() && is_blank(s[i])) ++i;
}

// The number at `i`, in one pass, when lex_number would take it as one
// token and scan_number would give it exactly: the same grammar, the same
// mantissa and scale, the same division or product. False for anything else
// (malformed, or needing the library), which the tokens then read and report.
// Out of line: read_short_number reads the most numbers, and this one's
// registers, inlined, made every call save and restore six of them.
[[gnu::noinline]] bool read_exact_number(std::string_view s, std::size_t& i, double& out) {
    const std::size_t n = s.size();
    std::size_t k = i;
    std::uint64_t mantissa = 0;
    std::size_t digits = 0, significant = 0;
    std::int64_t scale = 0;
    // Zeros before the first other digit are not significant.
    const std::size_t leading = k;
    while (k < n && s[k] == '0') ++k;
    digits += k - leading;
    std::size_t first = k;
    for (; k < n && is_digit(s[k]); ++k)
        mantissa = mantissa * 10 + static_cast<unsigned>(s[k] - '0');
    digits += k - first;
    significant += k - first;
    if (k < n && s[k] == '.') {
        ++k;
        if (mantissa == 0) {
            const std::size_t zeros = k;
            while (k < n && s[k] == '0') ++k;
            digits += k - zeros;
            scale -= static_cast<std::int64_t>(k - zeros);
        }
        first = k;
        for (; k < n && is_digit(s[k]); ++k)
            mantissa = mantissa * 10 + static_cast<unsigned>(s[k] - '0');
        digits += k - first;
        significant += k - first;
        scale -= static_cast<std::int64_t>(k - first);
    }
    if (digits == 0) return false;
    if (k < n && (s[k] == 'e' || s[k] == 'E')) {
        ++k;
        bool negative_exponent = false;
        if (k < n && (s[k] == '+' || s[k] == '-')) negative_exponent = s[k++] == '-';
        first = k;
        int exponent = 0;
        for (; k < n && is_digit(s[k]); ++k) {
            if (exponent < 100000) exponent = exponent * 10 + (s[k] - '0');
        }
        if (k == first) return false;
        scale += negative_exponent ? -exponent : exponent;
    }
    // The lexer's run goes on past the grammar: one malformed number.
    if (k < n && is_number_char(s[k])) return false;
    if (significant > 15 || scale < -22 || scale > 22) return false;
    double value = static_cast<double>(mantissa);
    value = scale < 0 ? value / powers_of_ten[-scale] : value * powers_of_ten[scale];
    out = value;
    i = k;
    return true;
}

// The value of the digits at `p` (advanced past them) added to `mantissa`.
// Unbounded: the caller knows the text ends in a byte that stops the run.
std::uint64_t read_digits(const char*& p, std::uint64_t mantissa) {
    for (;; ++p) {
        const unsigned d = static_cast<unsigned char>(*p) - unsigned{'0'};
        if (d > 9) return mantissa;
        mantissa = mantissa * 10 + d;
    }
}

// read_exact_number for what generators and people write most: digits, a
// '.' and digits, 15 digits at most and no exponent. With so few digits no
// count of the significant ones is needed (leading zeros add nothing to the
// mantissa and each fraction digit, zero or not, one to the scale), so it is
// one loop a run. False, with `i` unmoved, for anything else: an exponent,
// more digits, or what is malformed, which read_exact_number then reads.
// Also false for a text whose last byte could continue a number (its loops
// test no bound: a text ends that way almost never).
bool read_short_number(std::string_view s, std::size_t& i, double& out) {
    constexpr std::size_t max_short_digits = 15;  // Clinger's fast path, whatever the zeros
    if (s.empty() || is_number_char(s.back())) return false;
    const char* const start = s.data() + i;
    const char* p = start;
    std::uint64_t mantissa = read_digits(p, 0);
    const auto integer_digits = static_cast<std::size_t>(p - start);
    std::size_t fraction_digits = 0;
    if (*p == '.') {
        const char* const first = ++p;
        mantissa = read_digits(p, mantissa);
        fraction_digits = static_cast<std::size_t>(p - first);
    }
    const std::size_t digits = integer_digits + fraction_digits;
    if (digits == 0 || digits > max_short_digits) return false;
    // An exponent, a second '.', or a run the lexer would take on.
    if (is_number_char(*p)) return false;
    out = static_cast<double>(mantissa) / powers_of_ten[fraction_digits];
    i += static_cast<std::size_t>(p - start);
    return true;
}

// At most one sign, blanks, then a number as read_exact_number reads it: what
// the expression reader takes for a signed literal.
bool read_signed_number(std::string_view s, std::size_t& i, double& out) {
    std::size_t k = i;
    bool negative = false;
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) {
        negative = s[k] == '-';
        ++k;
        skip_blanks(s, k);
    }
    if (k >= s.size() || !(is_digit(s[k]) || s[k] == '.')) return false;
    double value = 0.0;
    if (!read_short_number(s, k, value) && !read_exact_number(s, k, value)) return false;
    out = negative ? -value : value;
    i = k;
    return true;
}

// read_plain_vector for what generators write: `<a,b,c>`, no blanks but
// spaces after the commas, each number an optional '-', then digits, a '.'
// and digits, 15 digits at most and no exponent: each is read_short_number's
// mantissa and division. With so little to look for a number costs half the
// general reader's. False, with `i` unmoved, for anything else (a '+', a
// blank elsewhere, an exponent, more digits), which read_plain_vector then
// reads. The caller has checked that the text's last byte could not continue
// a number, so no run of digits reaches the end: one test of the end a number.
[[gnu::always_inline]] inline bool read_dense_vector(std::string_view s, std::size_t& i,
                                                     Vec3& out) {
    constexpr std::ptrdiff_t max_short_digits = 15;
    const char* const end = s.data() + s.size();
    const char* p = s.data() + i + 1;
    double parts[3];
    for (int c = 0; c < 3; ++c) {
        if (c > 0)
            while (p < end && *p == ' ') ++p;
        // A sign and a digit, or a digit and what ends the number.
        if (end - p < 2) return false;
        const bool negative = *p == '-';
        p += negative ? 1 : 0;
        const char* const first = p;
        std::uint64_t mantissa = read_digits(p, 0);
        std::ptrdiff_t digits = p - first;
        std::size_t fraction_digits = 0;
        if (*p == '.') {
            const char* const point = ++p;
            mantissa = read_digits(p, mantissa);
            fraction_digits = static_cast<std::size_t>(p - point);
            digits += p - point;
        }
        if (digits == 0 || digits > max_short_digits || *p != (c < 2 ? ',' : '>')) return false;
        const double value = static_cast<double>(mantissa) / powers_of_ten[fraction_digits];
        parts[c] = negative ? -value : value;
        ++p;
    }
    out = Vec3{parts[0], parts[1], parts[2]};
    i = static_cast<std::size_t>(p - s.data());
    return true;
}

// At the '<' at `i`: three signed numbers between commas and '>'.
bool read_plain_vector(std::string_view s, std::size_t& i, Vec3& out) {
    std::size_t k = i + 1;
    double parts[3];
    for (int c = 0; c < 3; ++c) {
        skip_blanks(s, k);
        if (c > 0) {
            if (k >= s.size() || s[k] != ',') return false;
            ++k;
            skip_blanks(s, k);
        }
        if (!read_signed_number(s, k, parts[c])) return false;
    }
    skip_blanks(s, k);
    if (k >= s.size() || s[k] != '>') return false;
    out = Vec3{parts[0], parts[1], parts[2]};
    i = k + 1;
    return true;
}

// Blanks and a ';' at `i`.
bool semicolon_follows(std::string_view s, std::size_t i) {
    skip_blanks(s, i);
    return i < s.size() && s[i] == ';';
}

// The plain value at `i` (at or after a ':'): read_plain_value's scan, which
// continues at the returned offset past the ';', or 0.
std::size_t plain_value_at(std::string_view text, std::size_t i, Lexer::PlainValue& out) {
    skip_blanks(text, i);
    const std::size_t start = i;
    if (i < text.size() && text[i] == '<') {
        if (!(!is_number_char(text.back()) && read_dense_vector(text, i, out.vector)) &&
            !read_plain_vector(text, i, out.vector))
            return 0;
        out.is_vector = true;
    } else {
        if (!read_signed_number(text, i, out.number)) return 0;
        out.is_vector = false;
    }
    out.offset = start;
    out.length = i - start;
    skip_blanks(text, i);
    if (i >= text.size() || text[i] != ';') return 0;
    return i + 1;
}

}  // namespace

bool Lexer::read_plain_value(PlainValue& out) {
    const std::size_t past = plain_value_at(text_, at_, out);
    if (past == 0) return false;
    at_ = past;
    return true;
}

std::size_t Lexer::plain_property(PlainProperty& out) const {
    const std::size_t n = text_.size();
    std::size_t start = at_;
    int line = line_;
    std::size_t line_start = line_start_;
    // The blanks next() skips itself; it leaves any other to
    // skip_space_and_comments, and so does this.
    if (start < n && text_[start] == '\n') {
        ++line;
        line_start = start + 1;
        start = skip_spaces(text_, start + 1);
    } else if (start < n && text_[start] == ' ') {
        start = skip_spaces(text_, start + 1);
    }
    if (start >= n || !is_word_start(text_[start])) return 0;
    std::size_t end = start + 1;
    if (words_stop_inside_) {
        while (is_word_char(text_[end])) ++end;
    } else {
        while (end < n && is_word_char(text_[end])) ++end;
    }
    if (end >= n || text_[end] != ':') return 0;
    const std::size_t past = plain_value_at(text_, end + 1, out.value);
    if (past == 0) return 0;
    out.name = text_.substr(start, end - start);
    out.name_offset = start;
    out.name_pos = {line, static_cast<int>(start - line_start) + 1, file_};
    out.value_pos = {line, static_cast<int>(out.value.offset - line_start) + 1, file_};
    out.line = line;
    out.line_start = line_start;
    return past;
}

std::size_t Lexer::plain_vector(std::size_t offset, Vec3& out) const {
    std::size_t i = offset;
    Vec3 vector;
    if (!read_plain_vector(text_, i, vector) || !semicolon_follows(text_, i)) return 0;
    out = vector;
    return i;
}

namespace {

// The power of ten of a well-formed number's first significant digit
// (0 for 1.5, -400 for 1e-400), so that the error for a number beyond the
// doubles can tell too large from too small without the C library's
// locale-dependent strtod.
long long decimal_order(std::string_view number) {
    const std::size_t e = number.find_first_of("eE");
    const std::string_view mantissa = number.substr(0, e);
    long long exponent = 0;
    if (e != std::string_view::npos) {
        std::string_view digits = number.substr(e + 1);
        const bool negative = !digits.empty() && digits[0] == '-';
        if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
        if (std::from_chars(digits.data(), digits.data() + digits.size(), exponent).ec !=
            std::errc())
            exponent = 1'000'000'000;  // beyond every double either way
        if (negative) exponent = -exponent;
    }
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    const std::size_t first = mantissa.find_first_of("123456789");
    if (first == std::string_view::npos) return 0;
    const long long order = first < point ? static_cast<long long>(point - first) - 1
                                          : -static_cast<long long>(first - point);
    return order + exponent;
}

}  // namespace

void Lexer::lex_number(std::size_t start, Token& token) {
    const std::size_t n = text_.size();
    while (at_ < n) {
        const char c = text_[at_];
        const bool exponent_sign = (c == '+' || c == '-') && at_ > start &&
                                   (text_[at_ - 1] == 'e' || text_[at_ - 1] == 'E');
        if (!is_number_char(c) && !exponent_sign) break;
        ++at_;
    }
    std::string_view run = text_.substr(start, at_ - start);
    set(token, TokenKind::number, run, start, run.size(), pos_of(start));
    switch (scan_number(run, token.number)) {
        case NumberScan::exact:
            return;
        case NumberScan::malformed:
            // POV-Ray's `v.x`: a lone '.' before a letter is no number at all.
            if (run == "." && at_ < n && is_word_start(text_[at_]))
                sink_.error(token.pos,
                            "unexpected '.': values have no components such as .x (the x of v "
                            "is dot(v, <1, 0, 0>))");
            else
                sink_.error(token.pos, "malformed number '" + std::string(run.substr(0, 40)) + "'");
            token.kind = TokenKind::bad_value;
            return;
        case NumberScan::needs_library:
            break;
    }
    auto [end, ec] = std::from_chars(run.data(), run.data() + run.size(), token.number);
    if (ec != std::errc() || end != run.data() + run.size() || !std::isfinite(token.number)) {
        // Too large, or too small: not zero, yet its nearest double is.
        const bool tiny = decimal_order(run) < 0;
        sink_.error(token.pos, "the number " + std::string(run.substr(0, 40)) +
                                   (run.size() > 40 ? "..." : "") +
                                   (tiny ? " is too small: its nearest double is 0, and only a "
                                           "zero may be written as 0 (write 0, or a number of "
                                           "at least 5e-324)"
                                         : " is out of range (numbers must be finite doubles)"));
        token.kind = TokenKind::bad_value;
    }
}

void Lexer::lex_string(std::size_t start, Token& out) {
    const SourcePos open = pos_of(start);
    std::size_t i = start + 1;
    const std::size_t n = text_.size();
    while (i < n) {
        auto u = static_cast<unsigned char>(text_[i]);
        if (u == '"') {
            at_ = i + 1;
            set(out, TokenKind::string, text_.substr(start + 1, i - start - 1), start, at_ - start,
                open);
            return;
        }
        if (u == '\n' || u == '\r') {
            sink_.error(open, "string is not closed before the end of the line");
            at_ = i;
            set(out, TokenKind::bad_value, text_.substr(start, i - start), start, i - start, open);
            return;
        }
        if (u < 0x20 || u >= 0x7f) {
            sink_.error(open, "a string may hold only printable ASCII characters; byte " +
                                  byte_name(u) + " at column " +
                                  std::to_string(i - line_start_ + 1) + " is not");
            // Resume after the closing quote, or at the end of the line.
            while (i < n && text_[i] != '"' && text_[i] != '\n') ++i;
            at_ = (i < n && text_[i] == '"') ? i + 1 : i;
            set(out, TokenKind::bad_value, text_.substr(start, at_ - start), start, at_ - start,
                open);
            return;
        }
        ++i;
    }
    sink_.error(open, "string is not closed before the end of the file");
    at_ = n;
    set(out, TokenKind::bad_value, text_.substr(start), start, n - start, open);
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::word:
            return "the word '" + std::string(token.text.substr(0, 40)) + "'";
        case TokenKind::number:
            return "the number " + std::string(token.text.substr(0, 40));
        case TokenKind::string:
            return "the string \"" + std::string(token.text.substr(0, 40)) +
                   (token.text.size() > 40 ? "...\"" : "\"");
        case TokenKind::bad_value:
            return "a malformed value";
        case TokenKind::end:
            return "the end of the file";
        default:
            return quote(token.text);
    }
}

namespace {

// Whether the 32 bytes at `p` are all ASCII and none is NUL: SSE2 (every
// x86-64 has it) checks 16 bytes in three instructions, a quarter of what
// the eight-byte test below takes for them.
bool plain_ascii_32([[maybe_unused]] const unsigned char* p) {
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16));
    // A byte's top bit: set from 0x80 up, and by the comparison for a NUL.
    const __m128i marked = _mm_or_si128(_mm_or_si128(a, _mm_cmpeq_epi8(a, zero)),
                                        _mm_or_si128(b, _mm_cmpeq_epi8(b, zero)));
    return _mm_movemask_epi8(marked) == 0;
#else
    return false;
#endif
}

}  // namespace

std::size_t find_invalid_text_byte(std::string_view text) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        if (i + 32 <= n && plain_ascii_32(s + i)) {
            i += 32;
            continue;
        }
        // Fast path: eight ASCII bytes with no NUL among them.
        if (i + 8 <= n) {
            std::uint64_t w;
            std::memcpy(&w, s + i, 8);
            constexpr std::uint64_t lows = 0x0101010101010101ull, highs = 0x8080808080808080ull;
            if (((w & highs) | ((w - lows) & ~w & highs)) == 0) {
                i += 8;
                continue;
            }
        }
        if (s[i] == 0) return i;
        const std::optional<Utf8Character> character = utf8_character_at(text, i);
        if (!character) return i;
        i += character->length;
    }
    return std::string_view::npos;
}

SourcePos position_of(std::string_view text, std::size_t offset) {
    // memchr: a part of a large scene starts tens of MB into its text.
    const std::size_t end = std::min(offset, text.size());
    int line = 1;
    std::size_t line_start = 0;
    while (line_start < end) {
        const void* nl = std::memchr(text.data() + line_start, '\n', end - line_start);
        if (nl == nullptr) break;
        ++line;
        line_start = static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) + 1;
    }
    return {line, static_cast<int>(offset - line_start) + 1};
}

}  // namespace jt::lang

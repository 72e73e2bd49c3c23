// A property's value of plain numbers is read by the lexer in one scan
// (lexer.hpp's read_plain_value), not by tokens and the expression reader.
// These tests hold the scan to the token path on the same texts: the same
// value to the bit, the same span and origin, the same tokens after it, no
// message where the tokens give none, and nothing read where it declines
// (the tokens then read the value and give their messages).

#include "language/diagnostic_sink.hpp"
#include "language/expression.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

namespace jt {
namespace {

using lang::DiagnosticSink;
using lang::ExpressionReader;
using lang::Lexer;
using lang::NameTable;
using lang::ParsedValue;
using lang::Token;
using lang::TokenKind;

// The parser's two tokens, for the expression reader.
class Cursor final : public lang::TokenCursor {
  public:
    explicit Cursor(Lexer& lexer) : lexer_(lexer) {
        lexer_.next(cur_);
        lexer_.next(next_);
    }
    const Token& cur() const override { return cur_; }
    const Token& peek() const override { return next_; }
    void advance() override {
        cur_ = next_;
        lexer_.next(next_);
    }

  private:
    Lexer& lexer_;
    Token cur_, next_;
};

bool same_token(const Token& a, const Token& b) {
    return a.kind == b.kind && a.offset == b.offset && a.length == b.length && a.pos == b.pos &&
           std::memcmp(&a.number, &b.number, sizeof a.number) == 0;
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;  // -0 and 0 differ
}

// Numerals as people and generators write them, and as they should not.
std::string numeral(std::mt19937_64& rng) {
    static const char* const odd[] = {"0",
                                      "00",
                                      "007",
                                      ".5",
                                      "5.",
                                      "0.000",
                                      "1e5",
                                      "1E+05",
                                      "2e-3",
                                      "1e",
                                      "1e+",
                                      "1.2.3",
                                      ".",
                                      "1..2",
                                      "1e999",
                                      "4.9e-324",
                                      "123456789012345678",
                                      "0.1234567890123456",
                                      "1e22",
                                      "1e23",
                                      "1e-22",
                                      "1e-23",
                                      "0x10",
                                      "1_",
                                      "3.e2",
                                      ".e2",
                                      "9007199254740993",
                                      "000000000000000001.5"};
    switch (rng() % 5) {
        case 0:
            return odd[rng() % std::size(odd)];
        case 1: {
            // Runs of up to 20 digits, zeros first or not, on either side of
            // the point: the lengths around 8 and 15 that the scan reads apart.
            const auto digits = [&rng](std::size_t length) {
                std::string run;
                const bool zeros = rng() % 3 == 0;
                for (std::size_t d = 0; d < length; ++d)
                    run += zeros && d < length / 2 ? '0' : static_cast<char>('0' + rng() % 10);
                return run;
            };
            std::string s = digits(rng() % 21);
            if (rng() % 2) s += "." + digits(rng() % 21);
            return s;
        }
        default: {
            std::string s = std::to_string(rng() % 100000);
            if (rng() % 3) s += "." + std::to_string(rng() % 1000000);
            if (rng() % 5 == 0)
                s += std::string(rng() % 2 ? "e" : "E") + (rng() % 2 ? "-" : "") +
                     std::to_string(rng() % 30);
            return s;
        }
    }
}

std::string blanks(std::mt19937_64& rng) {
    static const char* const kinds[] = {"", "", " ", "  ", "\t", "\r", " \t "};
    return kinds[rng() % std::size(kinds)];
}

std::string signed_numeral(std::mt19937_64& rng) {
    static const char* const signs[] = {"", "", "-", "+", "- ", "-\t", "--", "+-", "-\n"};
    return signs[rng() % std::size(signs)] + numeral(rng);
}

std::string value(std::mt19937_64& rng) {
    if (rng() % 2) return signed_numeral(rng);
    const int parts = rng() % 8 == 0 ? 2 + static_cast<int>(rng() % 3) : 3;  // 2, 3 or 4
    std::string s = "<" + blanks(rng);
    for (int k = 0; k < parts; ++k) {
        if (k > 0) s += blanks(rng) + (rng() % 30 == 0 ? ";" : ",") + blanks(rng);
        s += signed_numeral(rng);
    }
    return s + blanks(rng) + ">";
}

// What follows a value: its ';' on the line or not, or more of an expression,
// and with `more`, another property on the line.
std::string after(std::mt19937_64& rng, bool more = true) {
    static const char* const kinds[] = {";",   ";",       " ;", "\t;",         "\r;", "\r\n;",
                                        "\n;", " # c\n;", ";}", "x;",          "*2;", " + 1;",
                                        "",    " }",      ")",  "; radius: 2;"};
    return blanks(rng) + kinds[rng() % (std::size(kinds) - (more ? 0 : 1))];
}

// Reads `text` ("radius:" and a value) by the tokens and the expression
// reader and by read_plain_value, and expects the same, or nothing read by
// the scan; counts which.
void expect_scan_agrees(const std::string& text, int& fast, int& declined) {
    SCOPED_TRACE(text);

    // The tokens: the name, the ':', then the value by the expression reader.
    DiagnosticSink token_sink;
    Lexer token_lexer(text, token_sink);
    Cursor tokens(token_lexer);
    ASSERT_EQ(tokens.cur().kind, TokenKind::word);
    ASSERT_EQ(tokens.peek().kind, TokenKind::colon);
    tokens.advance();
    tokens.advance();
    const Token first = tokens.cur();  // the value's first token
    NameTable names;
    ExpressionReader reader(tokens, token_sink, names, 0.0);
    const ParsedValue parsed = reader.read();

    // The scan, from just past the ':'.
    DiagnosticSink scan_sink;
    Lexer scan_lexer(text, scan_sink);
    Token name, colon, next;
    scan_lexer.next(name);
    scan_lexer.next(colon);
    Lexer::PlainValue plain;
    if (!scan_lexer.read_plain_value(plain)) {
        ++declined;
        // Nothing read: the tokens go on from the value's first one.
        scan_lexer.next(next);
        ASSERT_TRUE(same_token(next, first));
        return;
    }
    ++fast;
    EXPECT_TRUE(scan_sink.take().empty());
    ASSERT_TRUE(token_sink.take().empty());
    ASSERT_TRUE(parsed.ok);
    EXPECT_EQ(parsed.origin, ValueOrigin::literal);
    EXPECT_EQ(parsed.span.offset, plain.offset);
    EXPECT_EQ(parsed.span.length, plain.length);
    EXPECT_EQ(parsed.span.pos, first.pos);
    if (plain.is_vector) {
        ASSERT_EQ(parsed.value.kind, lang::ExprValue::Kind::vector);
        EXPECT_TRUE(same_bits(plain.vector.x, parsed.value.vector.x));
        EXPECT_TRUE(same_bits(plain.vector.y, parsed.value.vector.y));
        EXPECT_TRUE(same_bits(plain.vector.z, parsed.value.vector.z));
    } else {
        ASSERT_EQ(parsed.value.kind, lang::ExprValue::Kind::number);
        EXPECT_TRUE(same_bits(plain.number, parsed.value.number));
    }
    // Then the ';', and the scan goes on where the tokens do after it.
    ASSERT_EQ(tokens.cur().kind, TokenKind::semicolon);
    tokens.advance();
    scan_lexer.next(next);
    ASSERT_TRUE(same_token(next, tokens.cur()));
}

TEST(PlainValue, AgreesWithTheTokensAndTheExpressionReader) {
    std::mt19937_64 rng(1);
    int fast = 0, declined = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const std::string text = std::string(rng() % 2 ? "" : "\r\n  ") + "radius:" + blanks(rng) +
                                 value(rng) + after(rng);
        expect_scan_agrees(text, fast, declined);
        if (HasFatalFailure()) return;
    }
    // Both ways were taken, often.
    EXPECT_GT(fast, 2500);
    EXPECT_GT(declined, 2500);
}

// Vectors as generators write them (`<1.5,-2,0.25>`, or with a space after
// each comma), read by the scan's shorter path for them (read_dense_vector),
// and near misses that it must leave to the general one.
TEST(PlainValue, DenseVectorsAgreeWithTheTokens) {
    std::mt19937_64 rng(3);
    static const char* const signs[] = {"", "", "", "-", "-", "+", "--", "- "};
    static const char* const commas[] = {",", ",", ",", ", ", ",  ", " ,", ",\t", ";"};
    int fast = 0, declined = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::string text = "radius:<";
        for (int k = 0; k < 3; ++k) {
            if (k > 0) text += commas[rng() % (rng() % 4 == 0 ? std::size(commas) : 2)];
            text += signs[rng() % std::size(signs)] + numeral(rng);
        }
        static const char* const closings[] = {">", " >", "", ";", "x", ">>", ",4>"};
        text += closings[rng() % 4 == 0 ? rng() % std::size(closings) : 0];
        text += rng() % 20 == 0 ? "x;" : ";";
        // Texts ending in the value, where a run of digits may reach the end.
        if (rng() % 30 == 0) text.resize(text.size() - 1 - rng() % 4);
        expect_scan_agrees(text, fast, declined);
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(fast, 4000);
    EXPECT_GT(declined, 2500);
}

// The parser builds from the scan what it builds from the tokens: a newline
// before the ';' sends the same value the token way.
TEST(PlainValue, ParsesAsTheTokenPathDoes) {
    std::mt19937_64 rng(2);
    for (int trial = 0; trial < 3000; ++trial) {
        const std::string text = rng() % 2 ? "radius: " + signed_numeral(rng) + after(rng, false)
                                           : "center:" + value(rng) + after(rng, false);
        auto scene = [&](std::string_view before_semicolon) {
            std::string s = "scene { sphere { " + text + " } }";
            if (const std::size_t semicolon = s.find(';'); semicolon != std::string::npos)
                s.insert(semicolon, before_semicolon);
            return s;
        };
        const ParseResult fast = parse_scene(scene(""));
        const ParseResult slow = parse_scene(scene("\n"));
        SCOPED_TRACE(scene(""));
        ASSERT_EQ(fast.ok(), slow.ok());
        if (!fast.ok()) continue;
        const Sphere& a = shape_as<Sphere>(fast.scene.primitives.at(0).shape);
        const Sphere& b = shape_as<Sphere>(slow.scene.primitives.at(0).shape);
        EXPECT_TRUE(same_bits(a.radius, b.radius));
        EXPECT_EQ(std::memcmp(&a.center, &b.center, sizeof a.center), 0);
        ASSERT_EQ(fast.source.properties.size(), slow.source.properties.size());
        ASSERT_FALSE(fast.source.properties.empty());
        EXPECT_EQ(fast.source.properties[0], slow.source.properties[0]);
        EXPECT_EQ(test::brief(fast.diagnostics), test::brief(slow.diagnostics));
    }
}

// Once the error cap stops the tokens, it stops the scan too: what is read
// after it is what the tokens read, nothing.
TEST(PlainValue, StopsWithTheTokens) {
    std::string errors;
    for (int i = 0; i <= DiagnosticSink::max_errors; ++i) errors += "radius: -1;";
    const ParseResult fast = parse_scene("scene { sphere { " + errors + "center: <1, 2, 3>; } }");
    const ParseResult slow = parse_scene("scene { sphere { " + errors + "center: <1, 2, 3>\n; } }");
    EXPECT_EQ(fast.diagnostics.size(), static_cast<std::size_t>(DiagnosticSink::max_errors) + 1);
    EXPECT_EQ(fast.source.properties.size(), slow.source.properties.size());
    EXPECT_EQ(shape_as<Sphere>(fast.scene.primitives.at(0).shape).center,
              shape_as<Sphere>(slow.scene.primitives.at(0).shape).center);
}

// A value out of range or of the wrong kind read by the scan gets the
// messages the tokens give it: they quote the number as written.
TEST(PlainValue, MessagesQuoteTheValueAsWritten) {
    EXPECT_EQ(test::brief("scene { sphere { radius: -0.50; } }"),
              "1:26: error: 'radius' must be greater than 0 and at most 1e+09, got -0.50");
    EXPECT_EQ(test::brief("scene { sphere { radius: - 2; } }"),
              "1:26: error: 'radius' must be greater than 0 and at most 1e+09, got - 2");
    EXPECT_EQ(test::brief("scene { sphere { center: 1; } }"),
              "1:26: error: 'center' takes a vector like <0, 1, 0>, got the number 1");
}

}  // namespace
}  // namespace jt

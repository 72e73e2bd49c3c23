// docs/language.md §2: lexical rules.

#include "test_util.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/utf8.hpp"
#include "language/lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

double radius_of(std::string_view number) {
    std::string text = "scene { sphere { radius: " + std::string(number) + "; } }";
    ParseResult r = parse_clean(text);
    if (r.scene.primitives.size() != 1) return -1;
    return shape_as<Sphere>(r.scene.primitives[0].shape).radius;
}

TEST(Numbers, AcceptEveryFormTheSemanticsList) {
    EXPECT_EQ(radius_of("1"), 1.0);
    EXPECT_EQ(radius_of("0.5"), 0.5);
    EXPECT_EQ(radius_of("3.14159"), 3.14159);
    EXPECT_EQ(radius_of(".5"), 0.5);
    EXPECT_EQ(radius_of("5."), 5.0);
    EXPECT_EQ(radius_of("+2"), 2.0);
    EXPECT_EQ(radius_of("1e-3"), 1e-3);
    EXPECT_EQ(radius_of("2.5E+2"), 250.0);
    EXPECT_EQ(radius_of("0.1"), 0.1);
    EXPECT_EQ(radius_of("123456789.123456789"), 123456789.123456789);
    EXPECT_EQ(radius_of("1e9"), 1e9);
    // A number is read whatever its size; a property then holds it to the
    // language's limit (docs/language.md §4), which names the number as written.
    EXPECT_EQ(brief("scene { sphere { radius: 1e300; } }"),
              "1:26: error: 'radius' must be greater than 0 and at most 1e+09, got 1e300");
    EXPECT_EQ(radius_of("4.9406564584124654e-324"), 4.9406564584124654e-324);
}

TEST(Numbers, NegativeNumbersReadNegative) {
    ParseResult r = parse_clean("scene { plane { distance: -1.25; } }");
    EXPECT_EQ(shape_as<Plane>(r.scene.primitives.at(0).shape).distance, -1.25);
}

TEST(Numbers, MalformedNumberIsOneErrorAtItsStart) {
    EXPECT_EQ(brief("scene { sphere { center: <1.0, 9.1, .3.2>; } }"),
              "1:37: error: malformed number '.3.2'");
    EXPECT_EQ(brief("scene { plane { distance: 1..2; } }"), "1:27: error: malformed number '1..2'");
    EXPECT_EQ(brief("scene { plane { distance: 1e; } }"), "1:27: error: malformed number '1e'");
    EXPECT_EQ(brief("scene { plane { distance: 1.5.; } }"), "1:27: error: malformed number '1.5.'");
}

// Language 1.3 (docs/language.md §15.1): a sign is an operator, except in an exponent.
TEST(Numbers, SignsAreOperatorsExceptInAnExponent) {
    auto distance = [](const std::string& value) {
        ParseResult r = parse_clean("scene { plane { distance: " + value + "; } }");
        return shape_as<Plane>(r.scene.primitives.at(0).shape).distance;
    };
    EXPECT_EQ(distance("--1"), 1.0);
    EXPECT_EQ(distance("1-2"), -1.0);
    EXPECT_EQ(distance("2*-3"), -6.0);
    EXPECT_EQ(distance("1e-3"), 1e-3);
    EXPECT_EQ(distance("1E+2-1"), 99.0);
    EXPECT_EQ(distance("+2"), 2.0);
}

TEST(Numbers, OutOfRangeIsAnError) {
    EXPECT_EQ(brief("scene { plane { distance: 1e400; } }"),
              "1:27: error: the number 1e400 is out of range (numbers must be finite doubles)");
    // Too small is not out of the finite doubles: the message says what it is.
    const std::string tiny = brief(
        "scene { plane { distance: 1e-400; }\n"
        "        plane { distance: 0.0000000000000000000000000000000"
        "0000000000000000000000000000000000000000000000000000000000"
        "0000000000000000000000000000000000000000000000000000000000"
        "0000000000000000000000000000000000000000000000000000000000"
        "0000000000000000000000000000000000000000000000000000000000"
        "0000000000000000000000000000000000000000000000000000000000"
        "0000000000000000001; } }");
    EXPECT_EQ(tiny,
              "1:27: error: the number 1e-400 is too small: its nearest double is 0, and only a "
              "zero may be written as 0 (write 0, or a number of at least 5e-324)\n"
              "2:27: error: the number 0.00000000000000000000000000000000000000... is too small: "
              "its nearest double is 0, and only a zero may be written as 0 (write 0, or a "
              "number of at least 5e-324)");
    EXPECT_TRUE(parse_clean("scene { plane { distance: 5e-324; } }").ok());
}

TEST(Numbers, NanAndInfinitySpelledOutAreUnknownNamesThatMustBeFinite) {
    EXPECT_EQ(brief("scene { plane { distance: nan; } }"),
              "1:27: error: unknown name 'nan' (names must be defined before they are used); "
              "numbers must be finite");
    EXPECT_EQ(brief("scene { plane { distance: inf; } }"),
              "1:27: error: unknown name 'inf' (names must be defined before they are used); "
              "numbers must be finite");
    EXPECT_EQ(brief("scene { sphere { center: <0, Infinity, 0>; } }"),
              "1:30: error: unknown name 'Infinity' (names must be defined before they are "
              "used); numbers must be finite");
}

// POV-Ray's `color rgb <1, 0, 0>` says that a colour is the vector alone.
TEST(Numbers, PovRayColourWordsSayAColourIsTheVectorAlone) {
    EXPECT_EQ(brief("scene { sphere { material { pigment: color rgb <1, 0, 0>;\n"
                    "  diffuse: rgb 1; ambient: Colour; } } }"),
              "1:38: error: unknown name 'color' (names must be defined before they are used); "
              "POV-Ray's 'color' is not written here: a colour is the vector <r, g, b> alone, "
              "like <1, 0.5, 0>\n"
              "2:12: error: unknown name 'rgb' (names must be defined before they are used); "
              "POV-Ray's 'rgb' is not written here: a colour is the vector <r, g, b> alone, like "
              "<1, 0.5, 0>\n"
              "2:28: error: unknown name 'Colour' (names must be defined before they are used); "
              "POV-Ray's 'Colour' is not written here: a colour is the vector <r, g, b> alone, "
              "like <1, 0.5, 0>");
    // A name the file defines is that name.
    EXPECT_EQ(brief("define rgb = <1, 0, 0>;\nscene { sphere { material { pigment: rgb; } } }"),
              "");
}

TEST(Strings, ReadPrintableAscii) {
    ParseResult r = parse_clean("render_settings { filename: \"Red Spheres #1.bmp\"; }");
    EXPECT_EQ(r.scene.settings.filename, "Red Spheres #1.bmp");
}

TEST(Strings, LineBreakInsideIsAnErrorAtTheOpeningQuote) {
    EXPECT_EQ(brief("render_settings {\n  filename: \"abc\n; }"),
              "2:13: error: string is not closed before the end of the line");
}

TEST(Strings, EndOfFileInsideIsAnErrorAtTheOpeningQuote) {
    EXPECT_EQ(brief("render_settings { filename: \"abc"),
              "1:29: error: string is not closed before the end of the file\n"
              "1:1: error: this 'render_settings' block is never closed: expected '}' before "
              "the end of the file");
}

TEST(Strings, ControlOrNonAsciiByteInsideIsAnErrorAtTheOpeningQuote) {
    EXPECT_EQ(brief("render_settings { filename: \"a\tb\"; }"),
              "1:29: error: a string may hold only printable ASCII characters; byte 0x09 at "
              "column 31 is not");
    EXPECT_EQ(brief("render_settings { filename: \"caf\xC3\xA9\"; }"),
              "1:29: error: a string may hold only printable ASCII characters; byte 0xC3 at "
              "column 33 is not");
}

TEST(Comments, RunToTheEndOfTheLine) {
    ParseResult r = parse_clean(
        "# a comment { not a block\nrender_settings { # here too ;\n width: 2; # w\n}# end");
    EXPECT_EQ(r.scene.settings.width, 2);
}

TEST(Whitespace, TabsAndCarriageReturnsAreSpace) {
    ParseResult r = parse_clean("render_settings\t{\r\n\twidth:\t3;\r\n}\r\n");
    EXPECT_EQ(r.scene.settings.width, 3);
}

TEST(Words, AreCaseSensitiveWithASuggestion) {
    EXPECT_EQ(brief("scene { Sphere { } }"),
              "1:9: error: unknown block 'Sphere' in 'scene'; did you mean 'sphere'? (allowed: "
              "sphere, plane, cylinder, triangle, mesh, point_light, include)");
}

TEST(Text, NulByteIsRejectedAtItsLineAndColumn) {
    std::string text = "scene {\n  sph";
    text += '\0';
    text += "ere { }\n}";
    EXPECT_EQ(brief(text), "2:6: error: the file is not a text file: it contains a NUL byte");
}

TEST(Text, InvalidUtf8IsRejectedAtItsLineAndColumn) {
    EXPECT_EQ(brief("# ok\n# caf\xC3\xA9 is fine\nscene { \xFF }"),
              "3:9: error: the file is not a text file: it contains a byte that is not UTF-8 "
              "text");
    EXPECT_EQ(brief("\xC3("),
              "1:1: error: the file is not a text file: it contains a byte "
              "that is not UTF-8 text");
    EXPECT_EQ(brief("\xED\xA0\x80"),
              "1:1: error: the file is not a text file: it contains a "
              "byte that is not UTF-8 text");  // a surrogate
}

// The first byte a text is refused for, byte by byte: what the lexer's fast
// paths over blocks of ASCII must agree with.
std::size_t first_refused_byte(std::string_view text) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = s[i];
        if (c == 0) return i;
        if (c < 0x80) {
            ++i;
            continue;
        }
        const std::size_t length = (c & 0xE0) == 0xC0   ? 2
                                   : (c & 0xF0) == 0xE0 ? 3
                                   : (c & 0xF8) == 0xF0 ? 4
                                                        : 0;
        if (length == 0 || i + length > text.size()) return i;
        std::uint32_t code = c & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) {
            if ((s[i + k] & 0xC0) != 0x80) return i;
            code = (code << 6) | (s[i + k] & 0x3F);
        }
        const std::uint32_t least = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
        if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return i;
        i += length;
    }
    return std::string_view::npos;
}

TEST(Text, TheFirstRefusedByteIsFoundWhereverItIs) {
    std::mt19937_64 rng(3);
    static const char* const inserts[] = {"\0",   "\xC3\xA9", "\xE2\x82\xAC", "\xFF",
                                          "\x80", "\xC3",     "\xED\xA0\x80"};
    int refused = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::string text(rng() % 130, 'x');
        for (char& c : text) c = static_cast<char>(' ' + rng() % 95);
        for (int k = static_cast<int>(rng() % 3); k > 0 && !text.empty(); --k) {
            const char* insert = inserts[rng() % std::size(inserts)];
            const std::size_t length = insert[0] == 0 ? 1 : std::strlen(insert);
            text.insert(rng() % text.size(), insert, length);
        }
        SCOPED_TRACE(trial);
        const std::size_t expected = first_refused_byte(text);
        refused += expected != std::string_view::npos;
        EXPECT_EQ(lang::find_invalid_text_byte(text), expected);
    }
    EXPECT_GT(refused, 5000);  // and many were accepted
    EXPECT_LT(refused, 15000);
}

TEST(Text, Utf8InCommentsIsFineAndOutsideIsAnUnexpectedCharacter) {
    parse_clean("# caf\xC3\xA9\n");
    EXPECT_EQ(brief("scene { \xC3\xA9 }"),
              "1:9: error: unexpected character U+00E9 (outside comments a scene is ASCII)");
    // A stray byte that starts no character is named as a byte.
    EXPECT_EQ(brief("scene { \x01 }"), "1:9: error: unexpected byte 0x01");
}

// What a word processor or a web page puts in a pasted scene, named.
TEST(Text, PastedLookAlikesSayWhatToTypeInstead) {
    EXPECT_EQ(brief("render_settings { filename: \xE2\x80\x9Cout.bmp\xE2\x80\x9D; }"),
              "1:29: error: unexpected character U+201C (a curly quote: strings take plain "
              "double quotes \")");
    EXPECT_EQ(brief("scene { sphere { radius:\xC2\xA0"
                    "2; } }"),
              "1:25: error: unexpected character U+00A0 (a no-break space: use a plain space)");
    EXPECT_EQ(brief("define r = \xE2\x88\x92"
                    "2;"),
              "1:12: error: unexpected character U+2212 (a dash: minus is the plain -)");
}

TEST(Text, ByteOrderMarkIsSkipped) {
    parse_clean("\xEF\xBB\xBFscene { }");
}

TEST(Text, UnexpectedCharacterIsReportedAndSkipped) {
    EXPECT_EQ(brief("scene { sphere { radius: 2; } @ }"), "1:31: error: unexpected character '@'");
}

// One mistake, one error: a value cut short by a byte or number the lexer
// refused is not also "expected ';'" (reported before the lexer's own error,
// at an earlier column) nor a finding about what was left of the value.
TEST(Text, AMistakeTheLexerReportedIsNotRepeatedByTheParser) {
    EXPECT_EQ(brief("define r = 2^3;\nscene { sphere { radius: r; } }"),
              "1:13: error: unexpected character '^'");
    EXPECT_EQ(brief("define r = 2 \xC3\x97 3;"),
              "1:14: error: unexpected character U+00D7 (a multiplication sign: multiply with *)");
    EXPECT_EQ(brief("define \xCE\xA3 = 1;"),
              "1:8: error: unexpected character U+03A3 (outside comments a scene is ASCII)");
    EXPECT_EQ(brief("define v = <1, 2, 3>;\ncameras { perspective_camera { fov: 40 * v.x; } }"),
              "2:43: error: unexpected '.': values have no components such as .x (the x of v is "
              "dot(v, <1, 0, 0>))");
    EXPECT_EQ(brief("scene { sphere { radius: 5 % 2; center: <0, 0, 1>; } }"),
              "1:28: error: unexpected character '%'");
    // Two values side by side are still the missing ';' they look like.
    EXPECT_EQ(brief("scene { sphere { radius: 2 3; } }"),
              "1:27: error: expected ';' after the value of 'radius'");
}

}  // namespace
}  // namespace jt

namespace jt {
namespace {

// The lexer reads short decimals on a fast path; it must give exactly the
// double std::from_chars gives, for every spelling.
TEST(Numbers, FastPathAgreesWithFromChars) {
    std::mt19937_64 rng(2024);
    auto digits = [&](int n) {
        std::string s;
        for (int i = 0; i < n; ++i) s += static_cast<char>('0' + rng() % 10);
        return s;
    };
    for (int trial = 0; trial < 20000; ++trial) {
        std::string number = digits(static_cast<int>(rng() % 12));
        if (rng() % 2 || number.empty()) {
            number += '.';
            number += digits(1 + static_cast<int>(rng() % 12));
        }
        if (rng() % 3 == 0) {
            number += rng() % 2 ? "e-" : "e";
            number += std::to_string(rng() % 30);
        }
        if (rng() % 2) number.insert(number.begin(), '-');
        double expected = 0;
        auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), expected);
        ASSERT_EQ(ec, std::errc()) << number;
        ParseResult r = parse_scene("scene { plane { distance: " + number + "; } }");
        if (std::abs(expected) > kMaxMagnitude) {
            ASSERT_FALSE(r.ok()) << number << " is past the language's limit";
            continue;
        }
        ASSERT_TRUE(r.ok()) << number;
        double got = shape_as<Plane>(r.scene.primitives.at(0).shape).distance;
        ASSERT_EQ(got, expected) << number;
    }
}

// A vector of plain numbers is read on a fast path (lexer.hpp's plain_vector);
// it must give the value and the spans the token-by-token path gives, which
// a newline before the ';' forces.
TEST(Numbers, PlainVectorsAgreeWithTheExpressionPath) {
    std::mt19937_64 rng(31);
    auto component = [&] {
        std::string s;
        const int sign = static_cast<int>(rng() % 4);
        if (sign == 1) s += "-";
        if (sign == 2) s += "+";
        if (sign == 3) s += "- ";
        s += std::to_string(rng() % 1000);
        if (rng() % 2) s += "." + std::to_string(rng() % 100000);
        if (rng() % 4 == 0) s += (rng() % 2 ? "e-" : "E") + std::to_string(rng() % 40);
        return s;
    };
    auto blank = [&] { return std::string(rng() % 3, rng() % 2 ? ' ' : '\t'); };
    for (int trial = 0; trial < 5000; ++trial) {
        const std::string vector = "<" + blank() + component() + blank() + "," + blank() +
                                   component() + "," + component() + blank() + ">";
        const ParseResult fast =
            parse_scene("scene { sphere { center: " + vector + blank() + "; } }");
        const ParseResult slow = parse_scene("scene { sphere { center: " + vector + "\n; } }");
        ASSERT_EQ(fast.ok(), slow.ok()) << vector;
        ASSERT_EQ(fast.diagnostics.size(), slow.diagnostics.size()) << vector;
        if (!fast.ok()) continue;
        const Vec3 a = shape_as<Sphere>(fast.scene.primitives.at(0).shape).center;
        const Vec3 b = shape_as<Sphere>(slow.scene.primitives.at(0).shape).center;
        ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << vector;  // -0 too
        const PropertySource& p = fast.source.properties.at(0);
        const PropertySource& q = slow.source.properties.at(0);
        ASSERT_EQ(p.value_span, q.value_span) << vector;
        ASSERT_EQ(p.origin, q.origin) << vector;
    }
}

// What is not a plain vector followed by ';' is still read as an expression.
TEST(Numbers, OnlyAPlainVectorTakesTheFastPath) {
    ParseResult r = parse_scene("scene { sphere { center: <1, 2, 3> * 2; } }");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).center, Vec3(2, 4, 6));
    EXPECT_EQ(r.source.properties.at(0).origin, ValueOrigin::expression);
    r = parse_scene("scene { sphere { center: <1, --2, 3>; } }");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).center, Vec3(1, 2, 3));
    EXPECT_EQ(r.source.properties.at(0).origin, ValueOrigin::expression);
    EXPECT_FALSE(parse_scene("scene { sphere { center: <1, 2>; } }").ok());
    EXPECT_FALSE(parse_scene("scene { sphere { center: <1, 2, 3, 4>; } }").ok());
    EXPECT_FALSE(parse_scene("scene { sphere { center: <1, 2.3.4, 3>; } }").ok());
    EXPECT_FALSE(parse_scene("scene { sphere { center: <1, 2, 1e999>; } }").ok());
}

// The one decoder the reader, its messages and the viewer share.
TEST(Utf8, ACharacterIsItsCodeAndLengthOrNothing) {
    const auto code = [](std::string_view text) {
        const std::optional<Utf8Character> c = utf8_character_at(text, 0);
        return c ? std::pair<long, std::size_t>{c->code, c->length}
                 : std::pair<long, std::size_t>{-1, 0};
    };
    EXPECT_EQ(code("a"), (std::pair<long, std::size_t>{'a', 1}));
    EXPECT_EQ(code("\xC3\xA9"), (std::pair<long, std::size_t>{0xE9, 2}));
    EXPECT_EQ(code("\xE2\x80\x9C"), (std::pair<long, std::size_t>{0x201C, 3}));
    EXPECT_EQ(code("\xF0\x9F\x98\x80"), (std::pair<long, std::size_t>{0x1F600, 4}));
    for (const char* bad : {"\x80", "\xC3", "\xC0\x80", "\xE0\x80\x80", "\xED\xA0\x80",
                            "\xF4\x90\x80\x80", "\xF8\x88\x80\x80\x80", "\xC3("})
        EXPECT_EQ(code(bad).first, -1) << bad;
    EXPECT_FALSE(utf8_character_at("a", 1)) << "past the end";
}

// POV-Ray's and C's comments are one error each, and skipped as a '#'
// comment would be: nothing in them is read, and the scene around them is.
TEST(Lexical, CAndPovRayCommentsAreOneErrorEachAndSkipped) {
    ParseResult r = parse_scene(
        "// a POV-Ray scene { sphere\n"
        "scene { sphere { radius: 2; // big; { ball\n"
        "  center: /* here */ <1, 0, 0>; } /* two\n"
        "  lines: sphere { } */ plane { } }\n");
    EXPECT_EQ(brief(r.diagnostics),
              "1:1: error: '//' starts no comment here: a comment runs from '#' to the end of "
              "the line\n"
              "2:29: error: '//' starts no comment here: a comment runs from '#' to the end of "
              "the line\n"
              "3:11: error: '/*' starts no comment here: a comment runs from '#' to the end of "
              "the line\n"
              "3:35: error: '/*' starts no comment here: a comment runs from '#' to the end of "
              "the line");
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    const auto& ball = shape_as<Sphere>(r.scene.primitives[0].shape);
    EXPECT_EQ(ball.radius, 2.0);
    EXPECT_EQ(ball.center, Vec3(1, 0, 0));
    // An unclosed '/*' runs to the end of the file; one '/' divides as before.
    EXPECT_EQ(brief("scene { sphere { radius: 4 / 2; } } /* sphere {"),
              "1:37: error: '/*' starts no comment here: a comment runs from '#' to the end of "
              "the line");
}

}  // namespace
}  // namespace jt

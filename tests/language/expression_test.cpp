// Language 1.3 expressions (docs/language.md §15.3).

#include "jtracer/parser.hpp"
#include "jtracer/schema.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

// The distance of a plane written as `value`.
double number_of(const std::string& value, const ParseOptions& options = {}) {
    ParseResult r = parse_scene("scene { plane { distance: " + value + "; } }", options);
    EXPECT_EQ(test::brief(r.diagnostics), "") << value;
    if (r.scene.primitives.empty()) return std::nan("");
    return shape_as<Plane>(r.scene.primitives[0].shape).distance;
}

Vec3 vector_of(const std::string& value) {
    ParseResult r = parse_clean("scene { sphere { center: " + value + "; } }");
    if (r.scene.primitives.empty()) return Vec3{std::nan("")};
    return shape_as<Sphere>(r.scene.primitives[0].shape).center;
}

std::string plane_error(const std::string& value) {
    return brief("scene { plane { distance: " + value + "; } }");
}

// What lets a frame sequence read a scene once (docs/language.md §15.4).
TEST(Expressions, AParseSaysWhetherAnyValueReadTheClock) {
    auto reads = [](const std::string& text, const ParseOptions& options = {}) {
        return parse_scene(text, options).reads_clock;
    };
    EXPECT_FALSE(reads("scene { sphere { radius: 2 * pi; } }"));
    EXPECT_FALSE(reads("define c = \"clock\"; scene { sphere { radius: 1; } }"));
    EXPECT_TRUE(reads("scene { sphere { radius: 1 + clock; } }"));
    EXPECT_TRUE(reads("define r = clock; scene { sphere { radius: 1; } }"));
    ParseOptions defined;
    defined.defines = {{"r", "0.5 + clock"}};
    EXPECT_TRUE(reads("define r = 1; scene { sphere { radius: r; } }", defined));
    // A definition that --define overrides is not evaluated.
    defined.defines = {{"r", "0.5"}};
    EXPECT_FALSE(reads("define r = clock; scene { sphere { radius: r; } }", defined));
}

TEST(Expressions, ArithmeticFollowsPrecedenceLeftToRight) {
    EXPECT_EQ(number_of("1 + 2 * 3"), 7.0);
    EXPECT_EQ(number_of("(1 + 2) * 3"), 9.0);
    EXPECT_EQ(number_of("8 / 4 / 2"), 1.0);
    EXPECT_EQ(number_of("1 - 2 - 3"), -4.0);
    EXPECT_EQ(number_of("-(2 + 1)"), -3.0);
    EXPECT_EQ(number_of("- - -2"), -2.0);
    // Each operation rounded once, in the order written.
    EXPECT_EQ(number_of("0.1 + 0.2"), 0.1 + 0.2);
    EXPECT_EQ(number_of("1e16 + 1 - 1e16"), (1e16 + 1) - 1e16);
}

TEST(Expressions, PiClockAndFunctionsInDegrees) {
    EXPECT_EQ(number_of("pi"), 3.141592653589793);
    EXPECT_EQ(number_of("clock"), 0.0);
    ParseOptions at_half;
    at_half.clock = 0.5;
    EXPECT_EQ(number_of("clock * 4", at_half), 2.0);
    EXPECT_EQ(number_of("sin(30)"), 0.49999999999999994);
    EXPECT_EQ(number_of("sin(180)"), 1.2246467991473532e-16);
    EXPECT_EQ(number_of("cos(0)"), 1.0);
    EXPECT_EQ(number_of("tan(45)"), std::tan((45 * 3.141592653589793) / 180));
    EXPECT_EQ(number_of("asin(1)"), 90.0);
    EXPECT_EQ(number_of("acos(-1)"), 180.0);
    EXPECT_EQ(number_of("atan2(1, 1)"), 45.0);
    EXPECT_EQ(number_of("atan2(0, 0)"), 0.0);
    EXPECT_EQ(number_of("atan2(-0, -1)"), 180.0);  // the range is (-180, 180]
    EXPECT_EQ(number_of("sqrt(16)"), 4.0);
    EXPECT_EQ(number_of("abs(-3)"), 3.0);
    EXPECT_EQ(number_of("floor(-1.5)"), -2.0);
    EXPECT_EQ(number_of("min(3, 1, 2)"), 1.0);
    EXPECT_EQ(number_of("max(3, 1, 5, 2)"), 5.0);
    EXPECT_TRUE(std::signbit(number_of("min(-0, 0)")));  // of equal values, the first
    EXPECT_FALSE(std::signbit(number_of("max(0, -0)")));
    EXPECT_EQ(number_of("pow(2, 10)"), 1024.0);
    EXPECT_EQ(number_of("length(<3, 4, 0>)"), 5.0);
    EXPECT_EQ(number_of("dot(<1, 2, 3>, <4, 5, 6>)"), 32.0);
}

TEST(Expressions, VectorAlgebra) {
    EXPECT_EQ(vector_of("<1, 2, 3> + <1, 1, 1>"), Vec3(2, 3, 4));
    EXPECT_EQ(vector_of("<1, 2, 3> - <1, 1, 1>"), Vec3(0, 1, 2));
    EXPECT_EQ(vector_of("2 * <1, 2, 3>"), Vec3(2, 4, 6));
    EXPECT_EQ(vector_of("<1, 2, 3> * 2"), Vec3(2, 4, 6));
    EXPECT_EQ(vector_of("<2, 4, 6> / 2"), Vec3(1, 2, 3));
    EXPECT_EQ(vector_of("-<1, 2, 3>"), Vec3(-1, -2, -3));
    EXPECT_EQ(vector_of("<1 + 1, 2 * 2, -(3)>"), Vec3(2, 4, -3));
    EXPECT_EQ(vector_of("cross(<1, 0, 0>, <0, 1, 0>)"), Vec3(0, 0, 1));
    const double s = 1.0 / std::sqrt(9.0 + 16.0);
    EXPECT_EQ(vector_of("normalize(<3, 4, 0>)"), Vec3(3 * s, 4 * s, 0));
}

TEST(Expressions, AColourIsClippedOnceAfterEvaluation) {
    ParseResult r = parse_scene(
        "scene { sphere { material { pigment: <2, 0, 0> * 0.5; diffuse: <2, 0, 0>; } } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:64: warning: 'diffuse' <2, 0, 0> is outside the colour range [0, 1]: clipped "
              "to <1, 0, 0>");
    EXPECT_EQ(r.scene.primitives.at(0).material.pigment, Vec3(1, 0, 0));
}

TEST(Expressions, AWholeNumberIsTruncatedThenChecked) {
    ParseResult r = parse_clean("render_settings { width: 641 / 2; }");
    EXPECT_EQ(r.scene.settings.width, 320);
    EXPECT_EQ(brief("render_settings { width: 1e300 * 1; }"),
              "1:26: error: 'width' must be a whole number from 0 to 65535, got 1e+300");
}

TEST(Expressions, EvaluationErrorsPointAtTheOperationWithTheValues) {
    EXPECT_EQ(plane_error("1 + 4 / (2 - 2)"), "1:33: error: division by zero: 4 / 0");
    EXPECT_EQ(plane_error("sqrt(0 - 1)"),
              "1:27: error: sqrt(-1): the square root of a negative "
              "number");
    EXPECT_EQ(plane_error("asin(2)"), "1:27: error: asin(2): the argument must be in [-1, 1]");
    EXPECT_EQ(plane_error("1e300 * 1e300"),
              "1:33: error: the result of 1e+300 * 1e+300 is not finite");
    EXPECT_EQ(plane_error("pow(10, 400)"), "1:27: error: pow(10, 400) is not finite");
    EXPECT_EQ(plane_error("length(<1e200, 0, 0>)"),
              "1:27: error: length(<1e+200, 0, 0>) is not finite: its squared length overflows");
    EXPECT_EQ(brief("scene { plane { normal: normalize(<0, 0, 0>); } }"),
              "1:25: error: normalize(<0, 0, 0>): the zero vector has no direction");
    // Not the zero vector: its squared length underflows, and 1 / 0 is not finite.
    EXPECT_EQ(brief("scene { plane { normal: normalize(<1e-200, 0, 0>); } }"),
              "1:25: error: normalize(<1e-200, 0, 0>) is not finite: its squared length "
              "underflows to 0");
    // The first failing operation, left to right.
    EXPECT_EQ(plane_error("1 / 0 + sqrt(-1)"), "1:29: error: division by zero: 1 / 0");
    // The zero keeps its sign, written or computed.
    EXPECT_EQ(plane_error("1 / -0"), "1:29: error: division by zero: 1 / -0");
    EXPECT_EQ(plane_error("1 / (0 * -1)"), "1:29: error: division by zero: 1 / -0");
}

TEST(Expressions, KindMistakesAreErrorsAtTheOperatorOrCall) {
    EXPECT_EQ(brief("scene { sphere { center: <1, 0, 0> * <0, 1, 0>; } }"),
              "1:36: error: cannot multiply two vectors (use dot or cross): <1, 0, 0> * <0, 1, "
              "0>");
    EXPECT_EQ(plane_error("1 + <1, 0, 0>"),
              "1:29: error: cannot add a number and a vector: 1 + <1, 0, 0>");
    EXPECT_EQ(plane_error("2 / <1, 1, 1>"),
              "1:29: error: cannot divide by a vector: 2 / <1, 1, 1>");
    EXPECT_EQ(plane_error("sin(<1, 0, 0>)"),
              "1:27: error: 'sin' takes numbers, got the vector <1, 0, 0> as argument 1");
    EXPECT_EQ(plane_error("pow(2)"), "1:27: error: 'pow' takes 2 arguments, got 1");
    EXPECT_EQ(plane_error("min(2)"), "1:27: error: 'min' takes at least 2 arguments, got 1");
    EXPECT_EQ(plane_error("sin 30"),
              "1:31: error: 'sin' is a function: expected '(' after it, got the number 30");
    // A vector where a number is expected: at the value's first token.
    EXPECT_EQ(plane_error("2 * <1, 0, 0>"),
              "1:27: error: 'distance' takes a number like 1.5, got the vector <2, 0, 0>");
    // A component must be a number: at that component.
    EXPECT_EQ(brief("scene { sphere { center: <1, <0, 0, 0>, 2>; } }"),
              "1:30: error: each component of a vector must be a number, got the vector <0, 0, "
              "0>");
    // A string in arithmetic: at the string.
    EXPECT_EQ(brief("render_settings { filename: \"a\" + 1; }"),
              "1:29: error: a string cannot be used in arithmetic, got the string \"a\"");
    // Nor in parentheses: a string value is one literal or one name.
    EXPECT_EQ(brief("define s = \"a.bmp\";\nrender_settings { filename: (s); }"),
              "2:29: error: parentheses hold numbers and vectors, not a string: write the "
              "string, or the name of one, alone");
    EXPECT_EQ(brief("define s = ((\"a.bmp\"));"),
              "1:12: error: parentheses hold numbers and vectors, not a string: write the "
              "string, or the name of one, alone");
    EXPECT_EQ(brief("define s = \"a.bmp\";\ndefine t = s;\nrender_settings { filename: t; }"), "");
}

// A word followed by '(' is a call: an unknown one is suggested among the
// functions, not among the names (POV-Ray's vlength is our length).
TEST(Expressions, AnUnknownFunctionSuggestsAFunction) {
    const std::string functions =
        " (functions: sin, cos, tan, asin, acos, atan2, sqrt, abs, floor, min, max, pow, "
        "length, normalize, dot, cross)";
    EXPECT_EQ(plane_error("vlength(<3, 4, 0>)"),
              "1:27: error: unknown function 'vlength'; did you mean 'length'?" + functions);
    EXPECT_EQ(brief("define sqrt2 = 1.4;\nscene { plane { distance: sqrtt(2); } }"),
              "2:27: error: unknown function 'sqrtt'; did you mean 'sqrt'?" + functions);
    EXPECT_EQ(plane_error("Sin(30)"),
              "1:27: error: unknown function 'Sin'; did you mean 'sin'?" + functions);
    EXPECT_EQ(plane_error("radians(30)"), "1:27: error: unknown function 'radians'" + functions);
    // A name alone is still a name.
    EXPECT_EQ(plane_error("sqrtt"),
              "1:27: error: unknown name 'sqrtt' (names must be defined before they are used)");
}

TEST(Expressions, SyntaxErrorsWinOverEvaluation) {
    EXPECT_EQ(plane_error("1 / 0 +"),
              "1:34: error: expected a value (a number, a name, '(' or '<'), got ';'");
    EXPECT_EQ(plane_error("(1 + 2"), "1:33: error: expected ')' or an operator, got ';'");
    EXPECT_EQ(plane_error("max(1, 2"),
              "1:35: error: expected ',' or ')' in the arguments of 'max', got ';'");
}

// '<' and '>' only bracket vectors: a comparison gets the usual missing-';'
// error, which says why, once.
TEST(Expressions, AComparisonSaysThereAreNone) {
    const std::string why =
        " (there are no comparisons: '<' and '>' only bracket vectors like <0, 1, 0>)";
    EXPECT_EQ(brief("define r = 1 < 2;"),
              "1:13: error: expected ';' after the value of 'define r'" + why);
    EXPECT_EQ(brief("scene { sphere { radius: 1 > 0; } }"),
              "1:27: error: expected ';' after the value of 'radius'" + why);
}

// A second '=' is neither an operator nor a comparison: the missing-';'
// error says so, for a define and for a property alike.
TEST(Expressions, ASecondEqualsSaysADefineTakesOneValue) {
    const std::string why =
        " ('=' is not an operator: it stands once, in 'define NAME = VALUE;', whose value is one "
        "number, vector or string; there are no comparisons such as '==')";
    EXPECT_EQ(brief("define r = 1 = 2;"),
              "1:13: error: expected ';' after the value of 'define r'" + why);
    EXPECT_EQ(brief("define r = 1 == 2;"),
              "1:13: error: expected ';' after the value of 'define r'" + why);
    EXPECT_EQ(brief("scene { sphere { radius: 1 = 2; } }"),
              "1:27: error: expected ';' after the value of 'radius'" + why);
}

TEST(Expressions, NestingIsCappedAt256Levels) {
    const std::string deep_ok = std::string(256, '(') + "1" + std::string(256, ')');
    EXPECT_EQ(number_of(deep_ok), 1.0);
    const std::string too_deep = std::string(257, '(') + "1" + std::string(257, ')');
    EXPECT_EQ(plane_error(too_deep),
              "1:283: error: expressions nest too deeply: at most 256 parentheses, calls and "
              "vectors inside one another");
}

// Hostile input: no recursion per token beyond the cap, and linear time.
TEST(Expressions, HugeAndDeepInputsAreQuickAndLocated) {
    const auto start = std::chrono::steady_clock::now();
    const std::string nested = std::string(100000, '(') + "1" + std::string(100000, ')');
    EXPECT_EQ(plane_error(nested),
              "1:283: error: expressions nest too deeply: at most 256 parentheses, calls and "
              "vectors inside one another");
    const std::string signs = std::string(100000, '-') + "1";
    EXPECT_EQ(number_of(signs), 1.0);
    // A 10 MB chain of additions evaluates without a stack per operator.
    std::string sum = "0";
    sum.reserve(10u << 20);
    while (sum.size() < (10u << 20)) sum += " + 1";
    EXPECT_EQ(number_of(sum), static_cast<double>((sum.size() - 1) / 4));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Release takes about a second and ASan on a loaded machine ten; a
    // quadratic reading of the 2.6 million operators would take hours.
    EXPECT_LT(seconds, 60.0);
}

TEST(Expressions, AValueRemembersHowItWasWritten) {
    ParseResult r = parse_clean(
        "define r = 2;\n"
        "scene { sphere { radius: r; center: <1, -2, 3>; } sphere { radius: r * 2; "
        "center: <0, clock, 0>; } sphere { radius: -1 + 3; center: <0, 0, 0> * 1; } }");
    ASSERT_EQ(r.source.properties.size(), 6u);
    EXPECT_EQ(r.source.properties[0].origin, ValueOrigin::name);
    EXPECT_EQ(r.source.properties[1].origin, ValueOrigin::literal);
    EXPECT_EQ(r.source.properties[2].origin, ValueOrigin::expression);
    EXPECT_EQ(r.source.properties[3].origin, ValueOrigin::expression);
    EXPECT_EQ(r.source.properties[4].origin, ValueOrigin::expression);
    EXPECT_EQ(r.source.properties[5].origin, ValueOrigin::expression);
    // The span covers the whole expression.
    const TextSpan& span = r.source.properties[2].value_span;
    EXPECT_EQ(std::string_view("define r = 2;\nscene { sphere { radius: r; center: <1, -2, 3>; } "
                               "sphere { radius: r * 2; ")
                  .substr(span.offset, span.length),
              "r * 2");
}

}  // namespace
}  // namespace jt

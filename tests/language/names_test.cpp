// Language 1.3 names: define, named materials, --define (docs/language.md §15.2).

#include "jtracer/parser.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/source_edit.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

#include <string>

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

std::string brief_with(std::string_view text, const ParseOptions& options) {
    return brief(parse_scene(text, options).diagnostics);
}

const Sphere& sphere(const ParseResult& r, std::size_t i = 0) {
    return shape_as<Sphere>(r.scene.primitives.at(i).shape);
}

TEST(Names, DefineNumbersVectorsAndStrings) {
    ParseResult r = parse_clean(
        "define r = 2;\n"
        "define c = <0, r, 0>;\n"
        "define out = \"x.bmp\";\n"
        "define radius = r / 4;\n"  // property names are not reserved
        "render_settings { filename: out; }\n"
        "scene { sphere { center: c * 2; radius: radius; } }\n");
    EXPECT_EQ(r.scene.settings.filename, "x.bmp");
    EXPECT_EQ(sphere(r).center, Vec3(0, 4, 0));
    EXPECT_EQ(sphere(r).radius, 0.5);
    ASSERT_EQ(r.source.definitions.size(), 4u);
    EXPECT_EQ(r.source.definitions[1].name, "c");
    EXPECT_EQ(r.source.definitions[1].origin, ValueOrigin::expression);
    EXPECT_EQ(r.source.definitions[0].name_span.pos, (SourcePos{1, 8}));
}

TEST(Names, DefineValuesAreNeverClippedOnlyProperties) {
    ParseResult r = parse_scene(
        "define big = <2, 0, 0>;\n"
        "scene { sphere { material { pigment: big / 2; } } }\n");
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(r.scene.primitives.at(0).material.pigment, Vec3(1, 0, 0));
}

TEST(Names, MustBeDefinedBeforeUseWithDidYouMean) {
    EXPECT_EQ(brief("scene { sphere { radius: r; } }\ndefine r = 1;\n"),
              "1:26: error: unknown name 'r' (names must be defined before they are used)");
    EXPECT_EQ(brief("define radius1 = 1;\nscene { sphere { radius: radus1; } }\n"),
              "2:26: error: unknown name 'radus1' (names must be defined before they are "
              "used); did you mean 'radius1'?");
}

// A POV-Ray user's directives are comments here ('#' starts one), which is
// why their names are unknown: the message says so, and where.
TEST(Names, AnUnknownNameAfterAPovRayDirectiveSaysItIsAComment) {
    const std::string hint =
        "; POV-Ray's #include and #declare are comments here, as at 2:1: write include "
        "\"FILE\"; and define NAME = VALUE;";
    EXPECT_EQ(brief("# a scene\n#declare R = 1;\nscene { sphere { radius: R; } }"),
              "3:26: error: unknown name 'R' (names must be defined before they are used)" + hint);
    EXPECT_EQ(brief("# a scene\n#include \"colors.inc\"\nscene { sphere { radius: R; } }"),
              "3:26: error: unknown name 'R' (names must be defined before they are used)" + hint);
    // Other comments say nothing.
    EXPECT_EQ(brief("# include guard\n#includes\nscene { sphere { radius: R; } }"),
              "3:26: error: unknown name 'R' (names must be defined before they are used)");
}

TEST(Names, DefiningTwiceNamesTheFirst) {
    EXPECT_EQ(brief("define r = 1;\ndefine r = 2;\n"),
              "2:8: error: 'r' is defined twice: it was first defined at 1:8");
    EXPECT_EQ(brief("material r { }\ndefine r = 2;\n"),
              "2:8: error: 'r' is defined twice: it was first defined at 1:10");
}

TEST(Names, ReservedWordsCannotBeDefined) {
    for (const char* word : {"pi", "clock", "sin", "sphere", "material", "include", "define"}) {
        EXPECT_EQ(brief("define " + std::string(word) + " = 1;"),
                  "1:8: error: '" + std::string(word) +
                      "' is reserved (a keyword, a function, pi or clock) and cannot be defined")
            << word;
    }
}

TEST(Names, DefineMistakesAreLocated) {
    EXPECT_EQ(brief("define 3 = 1;"),
              "1:8: error: expected a name after 'define', got the number 3");
    EXPECT_EQ(brief("define r 1;"), "1:10: error: expected '=' after 'define r', got the number 1");
    EXPECT_EQ(brief("define r = ;"), "1:12: error: expected a value after 'define r =', got ';'");
    EXPECT_EQ(brief("define r = 1\ndefine s = 2;"),
              "1:13: error: expected ';' after the value of 'define r'");
    // A definition cut short still defines its name: the uses say nothing
    // more than its one error, not that the name is unknown.
    EXPECT_EQ(brief("define r = ;\nscene { sphere { radius: r; } }"),
              "1:12: error: expected a value after 'define r =', got ';'");
    EXPECT_EQ(brief("define r 1;\nscene { sphere { radius: r; } }"),
              "1:10: error: expected '=' after 'define r', got the number 1");
    EXPECT_EQ(brief("material m pigment: <1, 0, 0>;\nscene { sphere { material: m; } }"),
              "1:12: error: expected '{' after 'material m', got the word 'pigment'");
    // Errors are reported where the value is written, used or not; uses stay quiet.
    EXPECT_EQ(brief("define r = 1 / 0;\nscene { sphere { radius: r; } }"),
              "1:14: error: division by zero: 1 / 0");
    EXPECT_EQ(brief("scene { define r = 1; }"),
              "1:9: error: 'define' may stand only at the top level, outside every block");
    EXPECT_EQ(brief("scene { sphere { define r = 1; } }"),
              "1:18: error: 'define' may stand only at the top level, outside every block");
}

// 'NAME = value;' without 'define' (a POV-Ray or programmer's habit): one
// error that shows the fix, and the name's uses say nothing more.
TEST(Names, AnAssignmentWithoutDefineSuggestsDefine) {
    EXPECT_EQ(brief("size = 1 - clock;\nscene { sphere { radius: size; } }"),
              "1:1: error: 'size = ...' needs the keyword 'define': write 'define size = ...;'");
    const std::string in_block =
        " error: 'size = ...' defines nothing here: names are defined at the top level, "
        "outside every block, with 'define size = ...;'";
    EXPECT_EQ(brief("scene { size = 1; sphere { radius: size; } }"), "1:9:" + in_block);
    EXPECT_EQ(brief("scene { sphere { size = 1; radius: size; } }"), "1:18:" + in_block);
    // A property's own name before '=' is a property missing its ':'.
    EXPECT_EQ(brief("scene { sphere { radius = 1; } }"),
              "1:25: error: expected ':' after 'radius', got '='");
    EXPECT_EQ(brief("scene { sphere { radius: 1; size = 1; radius: size; } }"), "1:29:" + in_block);
    // The same when properties are read through tokens only.
    ParseOptions tokens;
    tokens.plain_properties = false;
    EXPECT_EQ(brief_with("scene { sphere { radius: 1; size = 1; radius: size; } }", tokens),
              "1:29:" + in_block);
    EXPECT_EQ(brief_with("scene { sphere { radius = 1; } }", tokens),
              "1:25: error: expected ':' after 'radius', got '='");
}

TEST(Names, NamedMaterialsApplyFirstThenThePrimitivesOwnBlocks) {
    const std::string shiny = "material shiny { pigment: <1, 0, 0>; reflection: 0.5; }\n";
    ParseResult r = parse_clean(shiny +
                                "scene {\n"
                                "  sphere { material: shiny; }\n"
                                "  sphere { material { reflection: 0.25; } material: shiny; }\n"
                                "  sphere { material: shiny; material { pigment: <0, 1, 0>; } }\n"
                                "}\n");
    EXPECT_EQ(r.scene.primitives.at(0).material.pigment, Vec3(1, 0, 0));
    EXPECT_EQ(r.scene.primitives.at(0).material.finish->reflection, 0.5);
    // The own block wins wherever the `material:` line stands.
    EXPECT_EQ(r.scene.primitives.at(1).material.finish->reflection, 0.25);
    EXPECT_EQ(r.scene.primitives.at(1).material.pigment, Vec3(1, 0, 0));
    EXPECT_EQ(r.scene.primitives.at(2).material.pigment, Vec3(0, 1, 0));
    EXPECT_EQ(r.scene.primitives.at(2).material.finish->reflection, 0.5);
    ASSERT_EQ(r.source.definitions.size(), 1u);
    ASSERT_TRUE(r.source.definitions[0].material_properties.has_value());
    EXPECT_EQ(r.source.definitions[0].material_properties->count, 2u);
    EXPECT_EQ(r.source.primitives.at(0).named_material, 0u);
}

TEST(Names, NamedMaterialMistakes) {
    const std::string shiny = "define r = 1;\nmaterial shiny { reflection: 0.5; }\n";
    EXPECT_EQ(brief(shiny + "scene { sphere { material: shiny; material: shiny; } }"),
              "3:35: error: a primitive names at most one material; this one already names "
              "one at 3:18");
    EXPECT_EQ(brief(shiny + "scene { sphere { radius: shiny; } }"),
              "3:26: error: 'shiny' is a material, not a value: a primitive uses it with "
              "'material: shiny;'");
    EXPECT_EQ(brief(shiny + "scene { sphere { material: r; } }"),
              "3:28: error: 'r' is a number, not a material: 'material:' takes the name of a "
              "material defined at the top level with 'material NAME { ... }'");
    EXPECT_EQ(brief(shiny + "scene { sphere { material: 1; } }"),
              "3:28: error: 'material:' takes the name of a material defined at the top level "
              "with 'material NAME { ... }', got the number 1");
    EXPECT_EQ(brief(shiny + "scene { sphere { material: shiny2; } }"),
              "3:28: error: unknown name 'shiny2' (names must be defined before they are "
              "used); did you mean 'shiny'?");
    EXPECT_EQ(brief(shiny + "scene { sphere { material other { } } }"),
              "3:18: error: a named material is defined at the top level; inside a primitive, "
              "write 'material: NAME;' to use one");
    // Elsewhere than in a primitive, as 'define': one error at the keyword,
    // and what follows is read.
    const std::string top_only =
        "error: a named material ('material NAME { ... }') may stand only at the top level, "
        "outside every block";
    EXPECT_EQ(brief("scene { material m { pigment: <1, 0, 0>; } sphere { } }"), "1:9: " + top_only);
    EXPECT_EQ(brief("cameras { material m { } }"), "1:11: " + top_only);
    EXPECT_EQ(brief("render_settings { material m { } width: 2; }"), "1:19: " + top_only);
    EXPECT_EQ(brief("scene { sphere { transform { material m { } } } }"), "1:30: " + top_only);
    EXPECT_EQ(brief("scene { sphere { material { material m { } } } }"), "1:29: " + top_only);
    EXPECT_EQ(brief("material n { material m { } }"), "1:14: " + top_only);
    EXPECT_EQ(parse_scene("scene { material m { } sphere { } }").scene.primitives.size(), 1u);
    // Range-checked where it is defined.
    EXPECT_EQ(brief("material m { diffuse_k: 0; }"),
              "1:25: error: 'diffuse_k' must be greater than 0 and at most 1e+09, got 0");
    EXPECT_EQ(brief("material { pigment: <1, 0, 0>; }"),
              "1:1: error: a material at the top level needs a name: 'material NAME { ... }', "
              "used in a primitive with 'material: NAME;'");
}

// POV-Ray's '#declare M = material { ... }' written as a define, or a block
// keyword where a value goes: the keyword is never a name, so "unknown
// name 'material'" hid the fix.
TEST(Names, ABlockKeywordAsAValueSaysWhatToWriteInstead) {
    EXPECT_EQ(brief("define m = material { pigment: <1, 1, 1>; }\n"),
              "1:12: error: 'material' is a block, not a value: a material is named with "
              "'material NAME { ... }' at the top level and used in a primitive with "
              "'material: NAME;'");
    EXPECT_EQ(brief("define s = sphere { radius: 2; }\n"),
              "1:12: error: 'sphere' is a block keyword, not a value (a number, a vector, a "
              "string or a defined name)");
    EXPECT_EQ(brief("scene { sphere { radius: transform; } }"),
              "1:26: error: 'transform' is a block keyword, not a value (a number, a vector, "
              "a string or a defined name)");
    // Said even when an unread include might have defined other names.
    EXPECT_NE(brief("include \"missing.jts\";\ndefine m = material { };\n")
                  .find("2:12: error: 'material' is a block, not a value"),
              std::string::npos);
}

// A misspelt or misplaced property is the mistake reported, not what its
// value's evaluation would say: that hid the name behind "unknown name" or
// "a material, not a value: use it with 'material: shiny;'" (which it was).
TEST(Names, AnUnknownPropertyIsReportedNotItsValue) {
    const std::string shiny = "define r = 1;\nmaterial shiny { reflection: 0.5; }\n";
    EXPECT_EQ(brief(shiny + "cameras { perspective_camera { fox: zz * 2; } }"),
              "3:32: error: unknown property 'fox' in 'perspective_camera'; did you mean 'fov'? "
              "(allowed: name, position, look_at, up, aspect, fov, aperture, focus_distance)");
    EXPECT_EQ(brief(shiny + "scene { point_light { radus: 1 / 0; } }"),
              "3:23: error: unknown property 'radus' in 'point_light'; did you mean 'radius'? "
              "(allowed: position, intensity, radius, shadow_samples)");
    EXPECT_EQ(brief(shiny + "scene { point_light { material: shiny; } }"),
              "3:23: error: a point_light takes no 'material': only sphere, plane, cylinder, "
              "triangle and mesh do");
    EXPECT_EQ(brief(shiny + "material dull { material: shiny; }"),
              "3:17: error: a material cannot use another material: 'material: NAME;' stands "
              "directly in a sphere, plane, cylinder, triangle or mesh");
    EXPECT_EQ(brief(shiny + "scene { sphere { transform { turn: r; } } }"),
              "3:30: error: unknown property 'turn' in 'transform' (allowed: translate, scale, "
              "xrotate, yrotate, zrotate)");
    // A known name still has its value read, and its value's errors said.
    EXPECT_EQ(brief(shiny + "scene { sphere { radius: zz; } }"),
              "3:26: error: unknown name 'zz' (names must be defined before they are used)");
}

// A material block missing its '{' sets nothing, so it keeps nothing of the
// named material from applying, whatever block the text read before it.
TEST(Names, AMaterialBlockMissingItsBraceKeepsNothingFromTheNamedMaterial) {
    const std::string text =
        "material red { pigment: <1, 0, 0>; reflection: 0.5; }\n"
        "scene {\n"
        "  sphere { material { pigment: <0, 1, 0>; } }\n"
        "  sphere { material ; material: red; }\n"
        "}\n";
    for (const bool source_map : {true, false}) {
        ParseResult r = parse_scene(text, {.source_map = source_map});
        EXPECT_EQ(brief(r.diagnostics), "4:21: error: expected '{' after 'material', got ';'");
        ASSERT_EQ(r.scene.primitives.size(), 2u);
        EXPECT_EQ(r.scene.primitives[0].material.pigment, Vec3(0, 1, 0));
        EXPECT_EQ(r.scene.primitives[1].material.pigment, Vec3(1, 0, 0)) << source_map;
        EXPECT_EQ(r.scene.primitives[1].material.finish->reflection, 0.5) << source_map;
    }
}

TEST(Names, CommandLineDefinesWinWithANote) {
    ParseOptions options;
    options.defines = {{"r", "3"}, {"s", "\"out.bmp\""}};
    // The messages name the defines as a front end gives them (here the
    // command line's flags), never in words of their own.
    options.value_names = {"--define", "--define ", "", "--clock"};
    const std::string text =
        "define r = 1 / 0;\n"  // parsed, not evaluated
        "define s = \"a.bmp\";\n"
        "render_settings { filename: s; }\n"
        "scene { sphere { radius: r; } }\n";
    ParseResult r = parse_scene(text, options);
    EXPECT_EQ(brief(r.diagnostics),
              "1:8: note: 'r' is set by --define; this definition is ignored\n"
              "2:8: note: 's' is set by --define; this definition is ignored");
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(sphere(r).radius, 3.0);
    EXPECT_EQ(r.scene.settings.filename, "out.bmp");
    // A syntax error in the overridden definition is still reported.
    EXPECT_EQ(brief_with("define r = (1;", options),
              "1:14: error: expected ')' or an operator, got ';'\n"
              "1:8: note: 'r' is set by --define; this definition is ignored\n"
              "0:0: warning: --define s: the scene defines no 's'");
    // Defining it twice in the file is still an error.
    EXPECT_EQ(brief_with("define r = 1;\ndefine r = 2;\ndefine s = \"\";", options),
              "1:8: note: 'r' is set by --define; this definition is ignored\n"
              "2:8: error: 'r' is defined twice: it was first defined at 1:8\n"
              "3:8: note: 's' is set by --define; this definition is ignored");
}

TEST(Names, CommandLineDefineWarnings) {
    ParseOptions options;
    options.defines = {{"r", "1"}, {"r", "2 * clock"}};
    options.clock = 2;
    ParseResult r = parse_scene("define r = 0;\nscene { sphere { radius: r; } }", options);
    EXPECT_EQ(brief(r.diagnostics),
              "0:0: warning: define r is given more than once; the last value is used\n"
              "1:8: note: 'r' is set by ParseOptions::defines; this definition is ignored");
    EXPECT_EQ(sphere(r).radius, 4.0);
    // Named as Python names them.
    options.value_names = {"defines", "defines['", "']", "clock="};
    options.defines = {{"r", "sqrt(-clock)"}, {"s", "1"}, {"t", "1"}};
    EXPECT_EQ(brief(parse_scene("define r = 0;\ndefine s = 0;", options).diagnostics),
              "0:0: error: defines['r']=sqrt(-clock): at column 1: sqrt(-2): the square root of "
              "a negative number\n"
              "2:8: note: 's' is set by defines; this definition is ignored\n"
              "0:0: warning: defines['t']: the scene defines no 't'");
}

TEST(Names, DefineOptionIsChecked) {
    EXPECT_TRUE(parse_define("r=2").has_value());
    EXPECT_EQ(parse_define("c=<1, 0, 0> * pi").value().value, "<1, 0, 0> * pi");
    EXPECT_EQ(parse_define("s=\"out.png\"").value().name, "s");
    EXPECT_EQ(parse_define("r").error().message,
              "expected NAME=VALUE, like r=2 or 'c=<1, 0, 0>', got 'r'");
    EXPECT_EQ(parse_define("2r=1").error().message,
              "'2r' is not a name (letters, digits and '_', not starting with a digit)");
    EXPECT_EQ(parse_define("clock=1").error().message,
              "clock cannot be defined; set it with ParseOptions::clock");
    EXPECT_EQ(parse_define("clock=1", {.clock = "--clock"}).error().message,
              "clock cannot be defined; set it with --clock");
    EXPECT_EQ(parse_define("sin=1").error().message,
              "'sin' is reserved (a keyword, a function or pi) and cannot be defined");
    EXPECT_EQ(parse_define("r=").error().message, "the value of r: the value is empty");
    EXPECT_EQ(parse_define("r=1/0").error().message,
              "the value of r: at column 2: division by zero: 1 / 0");
    EXPECT_EQ(parse_define("r=q").error().message,
              "the value of r: at column 1: unknown name 'q' (names must be defined before "
              "they are used)");
    EXPECT_EQ(parse_define("r=1 2").error().message,
              "the value of r: at column 3: expected the end of the value, got the number 2");
    // A file's habit: the value is the whole option, with no ';' to end it.
    EXPECT_EQ(parse_define("r=1;").error().message,
              "the value of r: at column 2: expected the end of the value, got ';' (the value "
              "takes no ';')");
}

// The clock of a render is not known when its --define is checked: a value
// that fails at clock 0 alone is good, and the parse at the render's clock
// evaluates it (and reports it, when it fails there too).
TEST(Names, DefineOptionOfTheClockIsCheckedAtTheRendersClock) {
    EXPECT_EQ(parse_define("r=1/clock").value().value, "1/clock");
    EXPECT_EQ(parse_define("r=sqrt(clock - 0.5)").value().value, "sqrt(clock - 0.5)");
    EXPECT_EQ(parse_define("r=1/clock +").error().message,
              "the value of r: at column 10: expected a value (a number, a name, '(' or '<'), "
              "got the end of the value");
    EXPECT_EQ(parse_define("r=1/clock + q").error().message,
              "the value of r: at column 11: unknown name 'q' (names must be defined before "
              "they are used)");
    EXPECT_EQ(parse_define("r=1/0").error().message,
              "the value of r: at column 2: division by zero: 1 / 0");
    ParseOptions options;
    options.defines = {{"r", "1/clock"}};
    options.clock = 2;
    const ParseResult r = parse_scene("define r = 1;\nscene { sphere { radius: r; } }", options);
    EXPECT_EQ(sphere(r).radius, 0.5);
    options.clock = 0;
    EXPECT_EQ(brief_with("define r = 1;\nscene { sphere { radius: r; } }", options),
              "0:0: error: define r=1/clock: at column 2: division by zero: 1 / 0");
    // What a front end asks at each clock it renders.
    EXPECT_EQ(define_error_at({"r", "1/clock"}, 0.0), "at column 2: division by zero: 1 / 0");
    EXPECT_EQ(define_error_at({"r", "1/clock"}, 2.0), std::nullopt);
}

// A scene that uses names and expressions serialises to literal text that
// parses to the same scene.
TEST(Names, ScenesWithNamesRoundTripThroughTheSerializer) {
    ParseResult r = parse_clean(
        "define r = 2 / 3;\n"
        "material m { pigment: <1, 0.5, 0> / 3; reflection: 0.1 * 3; }\n"
        "render_settings { width: 64; height: 48; }\n"
        "cameras { perspective_camera { position: <0, 1, 5> * r; fov: atan2(1, 3); } }\n"
        "scene { sphere { radius: r; material: m; transform { yrotate: asin(0.3); } } }\n");
    const std::string text = serialize_scene(r.scene);
    ParseResult again = parse_clean(text);
    EXPECT_TRUE(again.scene == r.scene) << text;
}

// Save-in-place never writes a literal over a name or an expression.
TEST(Names, SavingInPlaceRefusesToOverwriteNamesAndExpressions) {
    const std::string text =
        "define r = 2;\n"
        "scene { sphere { radius: r; } sphere { radius: r * 2; } "
        "sphere { radius: 3; center: <1, -2, 3>; } }\n";
    ParseResult r = parse_clean(text);
    for (std::size_t i : {0u, 1u}) {
        Scene edited = r.scene;
        shape_as<Sphere>(edited.primitives[i].shape).radius = 5;
        SourceEditResult edit = apply_scene_edits(text, r.source, r.scene, edited);
        EXPECT_FALSE(edit.ok());
        EXPECT_EQ(edit.text, text);
        EXPECT_EQ(edit.error, i == 0 ? "'radius' at line 2 is written as the name r; edit it in "
                                       "the text, not as a value"
                                     : "'radius' at line 2 is written as the expression r * 2; "
                                       "edit it in the text, not as a value");
    }
    // A literal beside them is still written in place, a signed component kept.
    Scene edited = r.scene;
    shape_as<Sphere>(edited.primitives[2].shape).center.x = 4;
    SourceEditResult edit = apply_scene_edits(text, r.source, r.scene, edited);
    ASSERT_TRUE(edit.ok()) << edit.error;
    EXPECT_NE(edit.text.find("center: <4, -2, 3>;"), std::string::npos) << edit.text;
}

// A value inherited from a named material is written into the primitive's own
// material block, never into the shared material.
TEST(Names, EditingAnInheritedMaterialValueWritesThePrimitivesOwnBlock) {
    const std::string text =
        "material m { reflection: 0.5; }\n"
        "scene { sphere { material: m; } }\n";
    ParseResult r = parse_clean(text);
    Scene edited = r.scene;
    edited.primitives[0].material.finish.edit().reflection = 0.25;
    SourceEditResult edit = apply_scene_edits(text, r.source, r.scene, edited);
    ASSERT_TRUE(edit.ok()) << edit.error;
    EXPECT_NE(edit.text.find("material m { reflection: 0.5; }"), std::string::npos) << edit.text;
    ParseResult again = parse_clean(edit.text);
    EXPECT_TRUE(again.scene == edited) << edit.text;
}

}  // namespace
}  // namespace jt

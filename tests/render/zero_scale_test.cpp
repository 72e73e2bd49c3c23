// A primitive whose transform list holds a `scale` with a zero component is
// left out whatever comes before or after it (docs/language.md §5.5): its scene
// renders byte for byte as the same scene without it, through the whole core
// path (text -> parse -> validate -> prepare -> render), and the validator
// warns at that scale. The same primitive with the zero made 1 must show, so
// that every case can fail.

#include "scene_builder.hpp"

#include "jtracer/parser.hpp"
#include "jtracer/validate.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace jt::test {
namespace {

// The issue's scene: all black, as the flattened sphere is left out.
constexpr const char* issue_scene =
    "render_settings { width: 64; height: 48; ambient_light: <1,1,1>; }\n"
    "cameras { perspective_camera { position: <0,0,5>; } }\n"
    "scene { sphere { material { pigment: <1,1,1>; ambient: <1,1,1>; } transform { yrotate: 150; "
    "scale: <0,1,1>; yrotate: 60; } } }\n";

struct Parsed {
    Scene scene;
    std::vector<Diagnostic> diagnostics;  // parser's, then the validator's
};

Parsed parse_and_validate(const std::string& text) {
    ParseResult r = parse_scene(text);
    Parsed p{r.scene, r.diagnostics};
    for (Diagnostic& d : validate_scene(r.scene, r.source)) p.diagnostics.push_back(d);
    return p;
}

Image8 render_text(const std::string& text) {
    Parsed p = parse_and_validate(text);
    EXPECT_FALSE(has_errors(p.diagnostics)) << text;
    return render(p.scene);
}

// The warnings about zero scales, as "LINE:COL".
std::vector<std::string> zero_scale_warnings(const std::vector<Diagnostic>& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::warning &&
            d.message.find("zero component") != std::string::npos)
            out.push_back(std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column));
    return out;
}

// "LINE:COL" of the first occurrence of `needle` in `text`.
std::string position_of(const std::string& text, const std::string& needle) {
    std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    int line = 1, column = 1;
    for (std::size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

TEST(ZeroScale, TheIssueSceneIsAllBlack) {
    Parsed p = parse_and_validate(issue_scene);
    EXPECT_EQ(zero_scale_warnings(p.diagnostics),
              std::vector<std::string>{position_of(issue_scene, "scale")});
    Image8 image = render(p.scene);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(at(image, x, y), (Rgb{0, 0, 0})) << x;

    // With the zero made 1 the sphere is there: the case can fail.
    std::string unflattened = issue_scene;
    unflattened.replace(unflattened.find("<0,1,1>"), 7, "<1,1,1>");
    EXPECT_NE(render_text(unflattened), image);
}

// A lit floor, a mirror ball and a light, so that a primitive left out must
// also be missing from shadows and reflections; `crowd` adds small spheres
// until the scene has more than 8 bounded shapes and renders through the BVH.
std::string surroundings(bool crowd) {
    std::string s =
        "  plane { normal: <0,1,0>; distance: -1.2; material { pigment: <0.8,0.8,0.8>; "
        "diffuse: <1,1,1>; ambient: <1,1,1>; reflection: 0.3; } }\n"
        "  sphere { center: <2.2,0,-1>; radius: 0.8; material { pigment: <0.9,0.3,0.2>; "
        "diffuse: <1,1,1>; specular: <1,1,1>; reflection: 0.5; } }\n"
        "  point_light { position: <3,6,5>; intensity: <0.8,0.8,0.8>; }\n"
        "  point_light { position: <-5,2,3>; intensity: <0.3,0.3,0.4>; }\n";
    if (crowd)
        for (int i = 0; i < 10; ++i)
            s += "  sphere { center: <" + std::to_string(-3.0 + 0.7 * i) + ", " +
                 std::to_string(1.8 + 0.1 * (i % 3)) +
                 ", -2>; radius: 0.25; material { pigment: "
                 "<0.2,0.8,0.3>; diffuse: <1,1,1>; } }\n";
    return s;
}

std::string scene_text(const std::string& primitive, bool crowd) {
    return "render_settings { width: 48; height: 36; background: <0.1,0.2,0.3>; "
           "ambient_light: <0.2,0.2,0.2>; recurse_depth: 2; }\n"
           "cameras { perspective_camera { position: <0,2,8>; look_at: <0,0.3,0>; "
           "aspect: 1.3333333333333333; } }\n"
           "scene {\n" +
           surroundings(crowd) + primitive + "}\n";
}

constexpr const char* material =
    "material { pigment: <0.9,0.9,0.2>; diffuse: <1,1,1>; specular: <0.5,0.5,0.5>; } ";

struct Case {
    std::string shape;       // "sphere { radius: 1.2; " ... up to the transforms
    std::string transforms;  // one or more transform blocks, with ZERO where the scale goes
};

std::string with_scale(const Case& c, const std::string& scale) {
    std::string transforms = c.transforms;
    transforms.replace(transforms.find("ZERO"), 4, scale);
    return "  " + c.shape + material + transforms + " }\n";
}

// Each case renders as its scene without the primitive, warns at the zero
// scale, and shows when the zero is made 1.
void expect_left_out(const Case& c, bool crowd) {
    const Image8 without = render_text(scene_text("", crowd));
    for (const char* zero : {"<0, 1.3, 0.8>", "<1.3, 0, 0.8>", "<1.3, 0.8, 0>", "<0, 0, 0>"}) {
        const std::string text = scene_text(with_scale(c, zero), crowd);
        SCOPED_TRACE(text);
        Parsed p = parse_and_validate(text);
        EXPECT_EQ(zero_scale_warnings(p.diagnostics),
                  std::vector<std::string>{position_of(text, std::string("scale: ") + zero)});
        EXPECT_EQ(render(p.scene), without);
    }
    const std::string shown = scene_text(with_scale(c, "<1.3, 1, 0.8>"), crowd);
    EXPECT_NE(render_text(shown), without) << "the primitive must show when not flattened\n"
                                           << shown;
}

const std::vector<Case>& cases() {
    static const std::vector<Case> all = {
        // Before, between and after rotations and translations.
        {"sphere { radius: 1.2; ", "transform { scale: ZERO; yrotate: 60; translate: <0.3,0,0>; }"},
        {"sphere { radius: 1.2; ", "transform { yrotate: 150; scale: ZERO; yrotate: 60; }"},
        {"sphere { radius: 1.2; ",
         "transform { translate: <0.2,0.1,0>; xrotate: 33; zrotate: 71; scale: ZERO; }"},
        {"sphere { center: <0.1,0.2,0>; ",
         "transform { xrotate: 17; translate: <0,0.4,0>; scale: ZERO; zrotate: 40; "
         "translate: <-0.5,0,0>; }"},
        // In a second transform block.
        {"sphere { radius: 1.1; ",
         "transform { zrotate: 25; translate: <0,0.2,0>; } transform { xrotate: 10; scale: ZERO; "
         "yrotate: 80; }"},
        // A cylinder and a plane (a wall behind everything, tilted).
        {"cylinder { radius: 0.8; height: 1.5; ",
         "transform { zrotate: 35; scale: ZERO; xrotate: 20; translate: <-0.4,-0.8,0>; }"},
        {"cylinder { radius: 0.8; height: 1.5; ",
         "transform { translate: <0,-1,0>; } transform { yrotate: 45; xrotate: 30; scale: ZERO; }"},
        {"plane { normal: <0,0,1>; distance: -3; ",
         "transform { yrotate: 20; scale: ZERO; xrotate: 5; }"},
        {"plane { normal: <0.2,0,1>; distance: -3; ",
         "transform { translate: <0,0,0.5>; } transform { scale: ZERO; zrotate: 30; }"},
    };
    return all;
}

TEST(ZeroScale, LeftOutWhereverItStands) {
    for (const Case& c : cases()) expect_left_out(c, false);
}

TEST(ZeroScale, LeftOutUnderTheBvh) {
    for (const Case& c : cases()) expect_left_out(c, true);
}

// One warning at each zero scale of a primitive; a list whose magnitudes leave
// the doubles is left out too, warned at the op where that happens.
TEST(ZeroScale, WarningsSayWhichOpLeavesThePrimitiveOut) {
    const std::string two = scene_text(
        "  sphere { transform { scale: <0, 1, 1>; yrotate: 30; } transform { scale: <1, 1, -0>; "
        "} }\n",
        false);
    EXPECT_EQ(zero_scale_warnings(parse_and_validate(two).diagnostics),
              (std::vector<std::string>{position_of(two, "scale: <0"),
                                        position_of(two, "scale: <1, 1, -0")}));
    // Each number is within the language's limit (1e9); their product is not.
    std::string ops;
    for (int i = 0; i < 34; ++i) ops += "scale: <1e9, 1e9, 1e9>; ";
    const std::string huge = scene_text(
        "  sphere { transform { " + ops + "zrotate: 20; scale: <1e9, 1, 1>; } }\n", false);
    Parsed p = parse_and_validate(huge);
    std::vector<std::string> warned;
    for (const Diagnostic& d : p.diagnostics)
        if (d.message.find("range of double precision") != std::string::npos)
            warned.push_back(std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column));
    EXPECT_EQ(warned, std::vector<std::string>{position_of(huge, "scale: <1e9, 1,")});
    EXPECT_EQ(render(p.scene), render_text(scene_text("", false)));
}

// The viewer's panels edit the Scene and prepare it again from the previous
// preparation: a scale component dragged to 0 leaves the primitive out by the
// same rule, and dragged back brings it back.
TEST(ZeroScale, AnEditToZeroIsLeftOutLikeTheText) {
    for (bool crowd : {false, true}) {
        const Case& c = cases()[1];
        Parsed shown = parse_and_validate(scene_text(with_scale(c, "<1.3, 1, 0.8>"), crowd));
        Parsed without = parse_and_validate(scene_text("", crowd));
        RenderOptions options;
        options.width = shown.scene.settings.width;
        options.height = shown.scene.settings.height;
        auto first = prepare_scene(shown.scene).value();
        const Image8 before = render_image(first, options);

        Scene edited = shown.scene;
        TransformOp& op = edited.primitives.back().transforms[1];
        ASSERT_EQ(op.kind, TransformKind::scale);
        op.vector.x = 0.0;
        EXPECT_EQ(zero_scale_warnings(validate_scene(edited, SceneSource{})).size(), 1u);
        auto second = prepare_scene(edited, first).value();
        EXPECT_EQ(render_image(second, options), render(without.scene)) << crowd;

        op.vector.x = 1.3;
        EXPECT_EQ(render_image(prepare_scene(edited, second).value(), options), before) << crowd;
    }
}

}  // namespace
}  // namespace jt::test

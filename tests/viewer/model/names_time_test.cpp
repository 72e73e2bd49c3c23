// Language 1.3 in the viewer's model (docs/language.md §15): --define applied
// to every load, panel fields that know where their values come from (a
// literal, a name, an expression, a named material), and the time slider's
// clock, which computes the scene again and never touches the file.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/parser.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/field_sources.hpp"
#include "model/scene_time.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

constexpr const char* kNamed = R"(define r = 0.5;
define lift = 2 * r;
material shiny {
    pigment: <0.9, 0.2, 0.1>;
    reflection: 0.25;
}
render_settings { width: 48; height: 32; samples: 1; }
cameras { perspective_camera { position: <0, 1, 6>; look_at: <0, 0.5, 0>; aspect: 1.5; fov: 40; } }
scene {
    sphere {
        center: <0, lift, 0>;
        radius: r;
        material: shiny;
        material { diffuse: <0.8, 0.8, 0.8>; }
    }
    sphere { center: <1.5, 0.5, 0>; radius: 0.5; material: shiny; }
    point_light { position: <2, 5, 3>; intensity: <1, 1, 1>; }
}
)";

class ViewerNames : public ScratchTest {
  protected:
    fs::path write_scene(const std::string& text) {
        const fs::path path = dir / "scene.jts";
        write_file(path, text);
        return path;
    }
    void open(const std::string& text) {
        open_scene(state, write_scene(text));
        ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    }
    const BlockSource* primitive(std::size_t i) {
        return block_source(state.doc, EditedBlock{EditedBlock::Kind::primitive, i});
    }
    AppState state{test_config()};
    ModelLoop model;
};

TEST_F(ViewerNames, ADefineFromTheCommandLineIsAppliedOnOpenAndOnEveryReload) {
    state.doc.options.defines = {Define{"r", "2"}};
    open(kNamed);
    const auto radius = [&] {
        return shape_as<Sphere>(state.doc.scene.primitives[0].shape).radius;
    };
    EXPECT_EQ(radius(), 2.0) << "--define r=2 wins over the file's r = 0.5";
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[0].shape).center, Vec3(0, 4, 0))
        << "lift = 2 * r sees the --define";
    bool noted = false;
    for (const Diagnostic& d : state.doc.parse_diagnostics)
        noted = noted || d.message.find("' is set by ") != std::string::npos;
    EXPECT_TRUE(noted) << "the file's own definition is noted as ignored";
    // Another program changes the file: the reload still applies the define.
    std::string changed = kNamed;
    changed.replace(changed.find("radius: 0.5;"), 12, "radius: 0.75;");
    write_file(state.doc.path, changed);
    reload_scene(state);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).radius, 0.75) << "reloaded";
    EXPECT_EQ(radius(), 2.0) << "the reload is parsed with the --define too";
}

TEST_F(ViewerNames, AFieldKnowsWhetherItIsALiteralANameAnExpressionOrInherited) {
    open(kNamed);
    const BlockSource* first = primitive(0);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(field_source(state.doc, first, "radius").origin, FieldOrigin::name);
    EXPECT_EQ(field_source(state.doc, first, "center").origin, FieldOrigin::expression);
    EXPECT_EQ(material_field_source(state.doc, first, "diffuse").origin, FieldOrigin::literal);
    EXPECT_EQ(material_field_source(state.doc, first, "reflection").origin, FieldOrigin::inherited);
    EXPECT_EQ(material_field_source(state.doc, first, "phong").origin, FieldOrigin::unwritten);
    EXPECT_EQ(field_source(state.doc, primitive(1), "radius").origin, FieldOrigin::literal);
    EXPECT_TRUE(read_only(field_source(state.doc, first, "radius")));
    EXPECT_FALSE(read_only(material_field_source(state.doc, first, "reflection")));

    EXPECT_EQ(describe_source(state.doc, field_source(state.doc, first, "radius")),
              "From r, defined at scene.jts:1. The value is computed: edit it in the text "
              "editor (T), where the name is defined.");
    const std::string expression =
        describe_source(state.doc, field_source(state.doc, first, "center"));
    EXPECT_EQ(expression.rfind("Computed from the expression `<0, lift, 0>`", 0), 0u) << expression;
    const std::string inherited =
        describe_source(state.doc, material_field_source(state.doc, first, "reflection"));
    EXPECT_EQ(inherited.rfind("Inherited from material shiny, defined at scene.jts:3", 0), 0u)
        << inherited;
    EXPECT_EQ(describe_source(state.doc, field_source(state.doc, primitive(1), "radius")), "");

    state.doc.options.defines = {Define{"r", "2"}};
    EXPECT_EQ(describe_source(state.doc, field_source(state.doc, first, "radius"))
                  .rfind("From r, set by --define r=2 on the command line.", 0),
              0u);
}

TEST_F(ViewerNames, EditingAnInheritedFieldWritesTheObjectsOwnMaterialNeverTheSharedOne) {
    open(kNamed);
    const std::size_t steps = state.history.undo.size();
    // The second sphere has no material block of its own: one is made.
    edit_scene(state, [](Scene& s) { s.primitives[1].material.finish.edit().reflection = 0.75; });
    // The first has one: the value goes into it.
    edit_scene(state, [](Scene& s) { s.primitives[0].material.finish.edit().reflection = 0.5; });
    const std::string text = document_text(state.doc);
    EXPECT_NE(text.find("material shiny {\n    pigment: <0.9, 0.2, 0.1>;\n    reflection: 0.25;"),
              std::string::npos)
        << "the shared material stays as it was:\n"
        << text;
    EXPECT_NE(text.find("radius: 0.5; material: shiny; material { reflection: 0.75; } }"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("material { diffuse: <0.8, 0.8, 0.8>; reflection: 0.5; }"),
              std::string::npos)
        << text;
    ASSERT_TRUE(save_scene_in_place(state.doc));
    const ParseResult saved = parse_scene(read_file(state.doc.path));
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.scene.primitives[0].material.finish->reflection, 0.5);
    EXPECT_EQ(saved.scene.primitives[1].material.finish->reflection, 0.75);
    EXPECT_EQ(saved.scene.primitives[1].material.pigment, Colour(0.9, 0.2, 0.1)) << "still shiny";
    EXPECT_EQ(state.history.undo.size(), steps + 2) << "one undo step an edit";
}

TEST_F(ViewerNames, SavingNeverReplacesANameOrAnExpressionByALiteral) {
    open(kNamed);
    const std::string before = read_file(state.doc.path);
    // What a panel cannot do (the field is read-only), a script tries.
    edit_scene(state,
               [](Scene& s) { shape_as<Sphere>(s.primitives[0].shape).center = Vec3(0, 3, 0); });
    EXPECT_FALSE(save_scene_in_place(state.doc));
    EXPECT_EQ(read_file(state.doc.path), before) << "the file is left as it was";
}

TEST_F(ViewerNames, TheWordClockInAValueShowsTheSliderAndNothingElseDoes) {
    open(kNamed);
    EXPECT_FALSE(state.doc.uses_clock);
    open(
        "# the clock is not used here\n"
        "define clockwise = 1;\n"
        "render_settings { filename: \"clock.bmp\"; width: clockwise * 8; height: 8; }\n"
        "cameras { perspective_camera { position: <0, 1, 6>; look_at: <0, 0, 0>; aspect: 1; fov: "
        "40; } }\n"
        "scene { sphere { radius: 1; } }\n");
    EXPECT_FALSE(state.doc.uses_clock) << "a comment, a string or another word is not clock";
    open(
        "define t = clock * 2;\nrender_settings { width: 8; height: 8; }\ncameras { "
        "perspective_camera { position: <0, 1, 6>; look_at: <0, 0, 0>; aspect: 1; fov: 40; } }\n"
        "scene { sphere { "
        "radius: 1 + t; } }\n");
    EXPECT_TRUE(state.doc.uses_clock) << "in a define";
    open(
        "render_settings { width: 8; height: 8; }\ncameras { perspective_camera { position: <0, 1, "
        "6>; look_at: <0, 0, 0>; aspect: 1; fov: 40; } }\n"
        "scene { sphere { radius: 1 + clock; } }\n");
    EXPECT_TRUE(state.doc.uses_clock) << "in a property";
}

constexpr const char* kTimed = R"(render_settings { width: 48; height: 32; samples: 1; }
cameras { perspective_camera { position: <0, 1, 6>; look_at: <0, 0.5, 0>; aspect: 1.5; fov: 40; } }
scene {
    sphere { center: <clock * 2 - 1, 0.5, 0>; radius: 0.5; material { pigment: <0.9, 0.2, 0.1>; } }
    sphere { center: <0, -100, 0>; radius: 99.5; }
    point_light { position: <2, 5, 3>; intensity: <1, 1, 1>; }
}
)";

TEST_F(ViewerNames, TheClockComputesTheSceneAgainKeepsPanelEditsAndNeverWritesTheFile) {
    open(kTimed);
    ASSERT_TRUE(state.doc.uses_clock);
    const auto center = [&] {
        return shape_as<Sphere>(state.doc.scene.primitives[0].shape).center;
    };
    EXPECT_EQ(center(), Vec3(-1, 0.5, 0));
    const std::size_t steps = state.history.undo.size();
    edit_scene(state, [](Scene& s) { shape_as<Sphere>(s.primitives[1].shape).radius = 99.25; });
    ASSERT_TRUE(set_clock(state, 0.75));
    EXPECT_EQ(center(), Vec3(0.5, 0.5, 0)) << "computed at clock 0.75";
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).radius, 99.25)
        << "the panel edit stays";
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "moving the clock is no undo step";
    EXPECT_EQ(read_file(state.doc.path), kTimed) << "nor an edit of the file";
    EXPECT_NE(document_text(state.doc).find("center: <clock * 2 - 1, 0.5, 0>"), std::string::npos)
        << "saving would keep the expression:\n"
        << document_text(state.doc);
    ASSERT_TRUE(save_scene_in_place(state.doc));
    EXPECT_NE(read_file(state.doc.path).find("radius: 99.25;"), std::string::npos);
    EXPECT_NE(read_file(state.doc.path).find("<clock * 2 - 1, 0.5, 0>"), std::string::npos);
    // Undo brings the radius back, at the clock the slider stands at now.
    undo(state);
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).radius, 99.5);
    EXPECT_EQ(center(), Vec3(0.5, 0.5, 0)) << "undo does not move the clock back";
}

TEST_F(ViewerNames, AReloadAndATextEditKeepTheClockTheSliderStandsAt) {
    open(kTimed);
    ASSERT_TRUE(set_clock(state, 1.0));
    std::string changed = kTimed;
    changed.replace(changed.find("radius: 0.5;"), 12, "radius: 0.4;");
    write_file(state.doc.path, changed);
    reload_scene(state);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[0].shape).radius, 0.4);
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[0].shape).center, Vec3(1, 0.5, 0));
}

TEST_F(ViewerNames, PlayLoopsTheClockFromZeroToOne) {
    open(kTimed);
    const auto start = std::chrono::steady_clock::now();
    toggle_play(state, start);
    ASSERT_TRUE(state.time.playing);
    step_play(state, start + kPlayLoop / 4);
    EXPECT_DOUBLE_EQ(state.doc.options.clock, 0.25);
    step_play(state, start + kPlayLoop * 5 / 4);
    EXPECT_NEAR(state.doc.options.clock, 0.25, 1e-12) << "past 1 it starts again from 0";
    toggle_play(state, start + kPlayLoop * 2);
    EXPECT_FALSE(state.time.playing);
    step_play(state, start + kPlayLoop * 3);
    EXPECT_NEAR(state.doc.options.clock, 0.25, 1e-12) << "paused";
}

TEST_F(ViewerNames, AClockAtWhichTheSceneHasAnErrorLeavesTheLastGoodOne) {
    open(
        "render_settings { width: 8; height: 8; }\ncameras { perspective_camera { position: <0, 1, "
        "6>; look_at: <0, 0, 0>; aspect: 1; fov: 40; } }\n"
        "scene { sphere { radius: 1 - clock; } }\n");
    EXPECT_FALSE(set_clock(state, 1.0)) << "radius 0 is out of range";
    EXPECT_EQ(state.doc.options.clock, 0.0);
    EXPECT_NE(state.message.find("At clock 1 the scene has an error (3:"), std::string::npos)
        << state.message;
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[0].shape).radius, 1.0);
}

}  // namespace
}  // namespace jt::view

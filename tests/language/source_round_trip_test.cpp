// Property test of serialize_scene(scene, {text, parsed}): random scenes that
// use names, named materials and expressions everywhere the language allows
// them read back as the same scene, keep every name and expression, and
// still do after random edits of their values (fixed seeds: the same scenes
// on every run).

#include "jtracer/schema.hpp"
#include "jtracer/source_serializer.hpp"

#include "test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace jt {
namespace {

// Random .jts text. Every value it writes is valid where it stands, so the
// text parses without errors (colours may be clipped, with a warning).
class SceneMaker {
  public:
    explicit SceneMaker(std::uint32_t seed) : random_(seed) {}

    std::string text() {
        std::string out;
        const int defines = pick(1, 5);
        for (int i = 0; i < defines; ++i) {
            const std::string name = "n" + std::to_string(i);
            out += "define " + name + " = " + number(2) + ";\n";
            numbers_.push_back(name);
            if (chance(2)) {
                const std::string vector_name = "v" + std::to_string(i);
                out += "define " + vector_name + " = " + vector(2) + ";\n";
                vectors_.push_back(vector_name);
            }
        }
        out += "define out = \"random.bmp\";\n";
        const int materials = pick(0, 3);
        for (int i = 0; i < materials; ++i) {
            const std::string name = "m" + std::to_string(i);
            out += "material " + name + " {" + material_properties() + "}\n";
            materials_.push_back(name);
        }
        out += "render_settings { width: floor(abs(" + number(1) + ")) + 8; height: 6; " +
               "filename: out; background: " + vector(1) + "; }\n";
        out += "cameras {\n";
        for (int i = pick(1, 3); i > 0; --i)
            out += "    perspective_camera { position: " + vector(2) + "; fov: min(max(abs(" +
                   number(2) + "), 1), 170); aspect: " + positive() + "; }\n";
        out += "}\nscene {\n";
        for (int i = pick(1, 6); i > 0; --i) out += primitive();
        for (int i = pick(1, 3); i > 0; --i)
            out +=
                "    point_light { position: " + vector(2) + "; intensity: " + vector(1) + "; }\n";
        // A define after the blocks that use none of it, as a file may end.
        out += "}\ndefine last = " + number(2) + ";\n";
        return out;
    }

  private:
    int pick(int low, int high) {
        return low + static_cast<int>(random_() % static_cast<std::uint32_t>(high - low + 1));
    }
    bool chance(int in) { return pick(1, in) == 1; }

    std::string literal() {
        const int whole = pick(-9, 9);
        return (whole < 0 ? "-" : "") + std::to_string(std::abs(whole)) + "." +
               std::to_string(pick(0, 99));
    }

    // A number expression of names, pi, clock, operators and functions, at
    // most `depth` levels deep; its magnitude stays far below the limits.
    std::string number(int depth) {
        const int choice = depth == 0 ? pick(0, 3) : pick(0, 11);
        switch (choice) {
            case 0:
            case 1:
                return literal();
            case 2:
                return numbers_.empty() ? literal() : numbers_[random_() % numbers_.size()];
            case 3:
                return chance(2) ? "pi" : "clock";
            case 4:
                return number(depth - 1) + " + " + number(depth - 1);
            case 5:
                return number(depth - 1) + " - " + number(depth - 1);
            case 6:
                return "(" + number(depth - 1) + ") * " + number(depth - 1);
            case 7:
                return number(depth - 1) + " / (abs(" + number(depth - 1) + ") + 1)";
            case 8:
                return std::string(chance(2) ? "sin" : "cos") + "(" + number(depth - 1) + ")";
            case 9:
                return "sqrt(abs(" + number(depth - 1) + "))";
            case 10:
                return std::string(chance(2) ? "min" : "max") + "(" + number(depth - 1) + ", " +
                       number(depth - 1) + ", " + number(depth - 1) + ")";
            default:
                return "length(" + vector(depth - 1) + ")";
        }
    }

    std::string vector(int depth) {
        const int choice = depth == 0 ? pick(0, 1) : pick(0, 5);
        switch (choice) {
            case 0:
                return "<" + literal() + ", " + literal() + ", " + literal() + ">";
            case 1:
                return vectors_.empty() || chance(3)
                           ? "<" + number(0) + ", " + number(0) + ", " + number(0) + ">"
                           : vectors_[random_() % vectors_.size()];
            case 2:
                return "<" + number(depth - 1) + ", " + number(depth - 1) + ", " +
                       number(depth - 1) + ">";
            case 3:
                return vector(depth - 1) + " + " + vector(depth - 1);
            case 4:
                return "(" + number(depth - 1) + ") * " + vector(depth - 1);
            default:
                return "cross(" + vector(depth - 1) + ", " + vector(depth - 1) + ") / 10";
        }
    }

    std::string positive() { return "abs(" + number(2) + ") + 0.25"; }

    // A few material properties, each at most once.
    std::string material_properties() {
        std::string out;
        if (chance(2)) out += " pigment: " + vector(2) + ";";
        if (chance(2)) out += " diffuse: " + vector(1) + ";";
        if (chance(2)) out += " reflection: " + number(2) + ";";
        if (chance(3)) out += " diffuse_k: " + positive() + ";";
        if (chance(3)) out += " checker: " + vector(1) + ";";
        if (chance(3)) out += " ior: " + positive() + ";";
        return out + " ";
    }

    std::string primitive() {
        std::string out;
        switch (pick(0, 3)) {
            case 0:
                out = "    sphere { center: " + vector(2) + "; radius: " + positive() + ";";
                // A literal first, then the value that wins.
                if (chance(3)) out += " radius: 2; radius: " + positive() + ";";
                break;
            case 1:
                out = "    plane { normal: <0, 1, 0> + (" + vector(1) +
                      ") * 0; distance: " + number(2) + ";";
                break;
            case 2:
                out = "    cylinder { radius: " + positive() + "; height: " + positive() + ";";
                break;
            default:
                out = "    triangle { a: " + vector(1) + "; b: <1, 0, 0> + <" + number(1) +
                      ", 0, 0> * 0; c: <0, 1, 0>;";
                break;
        }
        if (!materials_.empty() && chance(2))
            out += " material: " + materials_[random_() % materials_.size()] + ";";
        for (int i = pick(0, 2); i > 0; --i) out += " material {" + material_properties() + "}";
        if (chance(2)) {
            out += " transform {";
            for (int i = pick(1, 3); i > 0; --i) {
                switch (pick(0, 2)) {
                    case 0:
                        out += " translate: " + vector(2) + ";";
                        break;
                    case 1:
                        out += " scale: <1, 1, 1> + (" + vector(0) + ") * 0;";
                        break;
                    default:
                        out += " yrotate: " + number(2) + ";";
                        break;
                }
            }
            out += " }";
        }
        return out + " }\n";
    }

    std::mt19937 random_;
    std::vector<std::string> numbers_, vectors_, materials_;
};

// The value texts of the last record of each property (the one in effect)
// that is a name or an expression, and of every definition, sorted.
std::vector<std::string> expressions(std::string_view text, const SceneSource& source) {
    std::vector<std::string> out;
    auto add = [&](const TextSpan& span) {
        out.emplace_back(text.substr(span.offset, span.length));
    };
    auto add_block = [&](std::span<const PropertySource> records, bool repeats_apply) {
        for (std::size_t i = 0; i < records.size(); ++i) {
            if (records[i].origin == ValueOrigin::literal) continue;
            const bool overridden =
                !repeats_apply && std::any_of(records.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                              records.end(), [&](const PropertySource& later) {
                                                  return later.name == records[i].name;
                                              });
            if (!overridden) add(records[i].value_span);
        }
    };
    for (const DefinitionSource& d : source.definitions) {
        if (!d.material_properties)
            add(d.value_span);
        else
            add_block(std::span(source.properties)
                          .subspan(d.material_properties->first, d.material_properties->count),
                      false);
    }
    auto add_blocks = [&](const std::vector<BlockSource>& blocks) {
        for (const BlockSource& block : blocks) {
            add_block(properties_of(source, block), false);
            // A primitive's material blocks together: a later one's value wins.
            std::vector<PropertySource> material;
            for (const BlockSource& child : children_of(source, block)) {
                const auto records = properties_of(source, child);
                if (child.keyword == kTransformKeyword)
                    add_block(records, true);
                else
                    material.insert(material.end(), records.begin(), records.end());
            }
            add_block(material, false);
        }
    };
    if (source.render_settings) add_block(properties_of(source, *source.render_settings), false);
    add_blocks(source.cameras);
    add_blocks(source.primitives);
    add_blocks(source.lights);
    std::sort(out.begin(), out.end());
    return out;
}

class SourceRoundTrip : public testing::TestWithParam<std::uint32_t> {};

TEST_P(SourceRoundTrip, KeepsEveryNameAndReadsBackAsTheSameScene) {
    const std::string text = SceneMaker(GetParam()).text();
    const ParseResult parsed = parse_scene(text);
    ASSERT_TRUE(parsed.ok()) << test::brief(parsed.diagnostics) << "\n" << text;
    const std::string out = serialize_scene(parsed.scene, {text, parsed});
    const ParseResult again = parse_scene(out);
    ASSERT_TRUE(again.ok()) << test::brief(again.diagnostics) << "\n" << out;
    EXPECT_TRUE(again.scene == parsed.scene) << text << "\n" << out;
    EXPECT_EQ(expressions(out, again.source), expressions(text, parsed.source)) << out;
    std::vector<std::string> names, names_again;
    for (const DefinitionSource& d : parsed.source.definitions) names.push_back(d.name);
    for (const DefinitionSource& d : again.source.definitions) names_again.push_back(d.name);
    EXPECT_EQ(names_again, names);
    for (std::size_t i = 0; i < parsed.source.primitives.size(); ++i)
        EXPECT_EQ(again.source.primitives[i].named_material,
                  parsed.source.primitives[i].named_material)
            << i << "\n"
            << out;
    EXPECT_EQ(serialize_scene(again.scene, {out, again}), out);
}

// Values changed at random: each is written as its literal, the rest as before.
TEST_P(SourceRoundTrip, EditedValuesReadBackAsEdited) {
    const std::string text = SceneMaker(GetParam()).text();
    const ParseResult parsed = parse_scene(text);
    ASSERT_TRUE(parsed.ok()) << test::brief(parsed.diagnostics) << "\n" << text;
    std::mt19937 random(GetParam() + 1000);
    auto chance = [&](unsigned in) { return random() % in == 0; };
    Scene edited = parsed.scene;
    if (chance(2)) edited.settings.width += 1;
    for (Camera& c : edited.cameras)
        if (chance(2)) c.position.y += 0.5;
    for (Primitive& p : edited.primitives) {
        if (chance(3)) p.material.finish.edit().reflection = 0.25;
        if (chance(3)) p.material.pigment = {0.5, 0.5, 0.5};
        if (chance(4)) p.material.finish.edit().checker.reset();
        if (chance(4)) p.material.finish.edit().transmission = 0.5;
        if (!p.transforms.empty() && chance(2)) {
            TransformOp& op = p.transforms.front();
            const bool moves =
                op.kind == TransformKind::translate || op.kind == TransformKind::scale;
            (moves ? op.vector.x : op.degrees) += 1;
        }
        if (chance(4)) p.transforms.push_back({TransformKind::xrotate, Vec3(0.0), 10});
        if (auto* s = shape_if<Sphere>(&p.shape); s && chance(2)) s->radius = 0.5;
    }
    if (chance(3)) edited.primitives.erase(edited.primitives.begin());
    if (chance(3)) edited.primitives.push_back(Primitive{Cylinder{}, {}, {}});
    const std::string out = serialize_scene(edited, {text, parsed});
    const ParseResult again = parse_scene(out);
    ASSERT_TRUE(again.ok()) << test::brief(again.diagnostics) << "\n" << out;
    EXPECT_TRUE(again.scene == edited) << text << "\n" << out;
    EXPECT_EQ(again.source.definitions.size(), parsed.source.definitions.size());
}

INSTANTIATE_TEST_SUITE_P(Seeds, SourceRoundTrip,
                         testing::Range(std::uint32_t{1}, std::uint32_t{201}));

}  // namespace
}  // namespace jt

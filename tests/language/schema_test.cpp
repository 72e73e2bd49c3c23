// The property schema (jtracer/schema.hpp), enumerated: the table matches the
// language's property table (docs/language.md §4); every block keyword parses
// in its place; and every property, one test case each, parses, serialises,
// reads back, edits in place, and has its range enforced with one located
// message, in the parser and in the validator. The cases come from the schema
// and the Shape variant: a new property or shape needs nothing here.

#include "jtracer/schema.hpp"

#include "jtracer/serializer.hpp"
#include "jtracer/source_edit.hpp"
#include "jtracer/validate.hpp"
#include "jtracer/value_text.hpp"
#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

namespace jt {
namespace {

using test::brief;

// --- the table against the language's ------------------------------------------

// A range in brief: '[' or ']' an inclusive bound, '(' or ')' an open one,
// '<' or '>' a clamping one; then "nonzero" or "nonempty" when they apply.
std::string allowed(const ValueRange& r, ValueKind kind) {
    if (r.nonzero) return "nonzero";
    if (r.nonempty) return "nonempty";
    if (!r.choices.empty()) {
        std::string out = "one of";
        for (std::string_view c : r.choices) out += " " + std::string(c);
        return out;
    }
    if (kind == ValueKind::string) return "any";
    std::string out = r.clamp_low ? "<" : r.low_open ? "(" : "[";
    out += number_text(r.low) + ", " + number_text(r.high);
    return out + (r.clamp_high ? ">" : r.high_open ? ")" : "]");
}

const char* kind_name(ValueKind kind) {
    switch (kind) {
        case ValueKind::whole:
            return "int";
        case ValueKind::number:
            return "number";
        case ValueKind::vector:
            return "vector";
        case ValueKind::colour:
            return "colour";
        case ValueKind::string:
            return "string";
    }
    return "?";
}

template <class Block>
std::string describe(std::string_view keyword, const PropertySpec<Block>& p, bool with_default) {
    std::string line = std::string(keyword) + "." + std::string(p.name) + " " + kind_name(p.kind);
    if (with_default) line += " " + value_text(p, Block{});
    line += " " + allowed(p.range, p.kind);
    if (!p.unit.empty()) line += " " + std::string(p.unit);
    if (p.omit_default) line += " omitted-when-default";
    if (!p.alias.empty()) line += " alias:" + std::string(p.alias);
    return line;
}

template <class Block>
std::string describe_block() {
    std::string out;
    for (const PropertySpec<Block>& p : schema_of<Block>().properties)
        out += describe(schema_of<Block>().keyword, p, true) + "\n";
    return out;
}

// Written out by hand from the language's table, not from the schema: a
// changed name, kind, default, range, unit or order in the schema fails here.
TEST(Schema, MatchesTheLanguagesPropertyTable) {
    std::string all =
        describe_block<RenderSettings>() + describe_block<Camera>() + describe_block<Sphere>() +
        describe_block<Plane>() + describe_block<Cylinder>() + describe_block<Triangle>() +
        describe_block<Mesh>() + describe_block<PointLight>() + describe_block<Material>();
    for (const TransformOpSpec& op : transform_ops())
        all += describe("transform", op.property, false) + "\n";
    EXPECT_EQ(all,
              "render_settings.width int 0 [0, 65535]\n"
              "render_settings.height int 0 [0, 65535]\n"
              "render_settings.recurse_depth int 0 [0, 256>\n"
              "render_settings.filename string \"jtracer.bmp\" nonempty\n"
              "render_settings.active_camera string \"\" any omitted-when-default\n"
              "render_settings.background colour <0, 0, 0> <0, 1>\n"
              "render_settings.ambient_light colour <0, 0, 0> <0, 1>\n"
              "render_settings.samples int 1 [1, 1024] omitted-when-default\n"
              "render_settings.background_map string \"\" any omitted-when-default\n"
              "perspective_camera.name string \"\" any alias:active_camera\n"
              "perspective_camera.position vector <0, 0, 0> [-1e+09, 1e+09]\n"
              "perspective_camera.look_at vector <0, 0, -1> [-1e+09, 1e+09]\n"
              "perspective_camera.up vector <0, 1, 0> [-1e+09, 1e+09]\n"
              "perspective_camera.aspect number 1 (0, 1e+09]\n"
              "perspective_camera.fov number 45 (0, 180) degrees\n"
              "perspective_camera.aperture number 0 [0, 1e+09] omitted-when-default\n"
              "perspective_camera.focus_distance number  (0, 1e+09] omitted-when-default\n"
              "sphere.center vector <0, 0, 0> [-1e+09, 1e+09]\n"
              "sphere.radius number 1 (0, 1e+09]\n"
              "plane.normal vector <0, 1, 0> nonzero\n"
              "plane.distance number 0 [-1e+09, 1e+09]\n"
              "cylinder.radius number 0.5 (0, 1e+09]\n"
              "cylinder.height number 1 (0, 1e+09]\n"
              "triangle.a vector <0, 0, 0> [-1e+09, 1e+09]\n"
              "triangle.b vector <1, 0, 0> [-1e+09, 1e+09]\n"
              "triangle.c vector <0, 1, 0> [-1e+09, 1e+09]\n"
              "triangle.uv_a vector <0, 0, 0> [-1e+09, 1e+09] omitted-when-default\n"
              "triangle.uv_b vector <1, 0, 0> [-1e+09, 1e+09] omitted-when-default\n"
              "triangle.uv_c vector <0, 1, 0> [-1e+09, 1e+09] omitted-when-default\n"
              "mesh.file string \"\" nonempty\n"
              "mesh.shading string \"smooth\" one of smooth flat omitted-when-default\n"
              "mesh.smooth_angle number  [0, 180] degrees omitted-when-default\n"
              "mesh.materials string \"scene\" one of scene file omitted-when-default\n"
              "point_light.position vector <0, 0, 0> [-1e+09, 1e+09]\n"
              "point_light.intensity colour <0, 0, 0> <0, 1>\n"
              "point_light.radius number 0 [0, 1e+09] omitted-when-default\n"
              "point_light.shadow_samples int 16 [1, 1024] omitted-when-default\n"
              "material.pigment colour <0, 0, 0> <0, 1>\n"
              "material.ambient colour <0, 0, 0> <0, 1>\n"
              "material.diffuse colour <0, 0, 0> <0, 1>\n"
              "material.specular colour <0, 0, 0> <0, 1>\n"
              "material.diffuse_k number 1 (0, 1e+09]\n"
              "material.specular_k number 64 (0, 1e+09]\n"
              "material.reflection number 0 <0, 1>\n"
              "material.transmission number 0 <0, 1> omitted-when-default\n"
              "material.ior number 1 (0, 1e+09] omitted-when-default\n"
              "material.checker colour  <0, 1> omitted-when-default\n"
              "material.checker_size number 1 (0, 1e+09] omitted-when-default\n"
              "material.image_map string \"\" any omitted-when-default\n"
              "material.map_size number 1 (0, 1e+09] omitted-when-default\n"
              "transform.translate vector [-1e+09, 1e+09]\n"
              "transform.scale vector [-1e+09, 1e+09]\n"
              "transform.xrotate number [-1e+09, 1e+09] degrees\n"
              "transform.yrotate number [-1e+09, 1e+09] degrees\n"
              "transform.zrotate number [-1e+09, 1e+09] degrees\n");
}

// --- the blocks, from the schema --------------------------------------------------

// Calls f(std::type_identity<Block>{}) for every block type that has a schema:
// the settings, a camera, each alternative of the Shape variant, a light, a
// material.
template <class F>
void for_each_block(F f) {
    f(std::type_identity<RenderSettings>{});
    f(std::type_identity<Camera>{});
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (f(std::type_identity<ShapeAlternative<I>>{}), ...);
    }
    (std::make_index_sequence<std::variant_size_v<Shape>>{});
    f(std::type_identity<PointLight>{});
    f(std::type_identity<Material>{});
}

template <class Block>
std::string_view keyword() {
    if constexpr (std::is_same_v<Block, TransformOp>) {
        return kTransformKeyword;
    } else {
        return schema_of<Block>().keyword;
    }
}

bool listed_in(std::span<const std::string_view> names, std::string_view word) {
    return std::find(names.begin(), names.end(), word) != names.end();
}

// The body of a block in a scene that validates clean.
std::string valid_body(std::string_view keyword) {
    if (keyword == schema_of<RenderSettings>().keyword) return "width: 4; height: 4; ";
    if (keyword == kTransformKeyword)
        return std::string(transform_ops()[0].property.name) + ": <0, 0, 0>; ";
    return "";
}

// A one-line scene holding the block `keyword` in its place in the file's
// structure (schema.hpp), with '@' where its properties go.
std::string host_text(std::string_view keyword) {
    const std::string block = std::string(keyword) + " { @ }";
    if (listed_in(top_blocks(), keyword)) return block;
    if (listed_in(cameras_blocks(), keyword))
        return std::string(kCamerasKeyword) + " { " + block + " }";
    if (listed_in(scene_blocks(), keyword))
        return std::string(kSceneKeyword) + " { " + block + " }";
    if (listed_in(primitive_blocks(), keyword))
        return std::string(kSceneKeyword) + " { " + std::string(shape_keywords()[0]) + " { " +
               block + " } }";
    ADD_FAILURE() << keyword << " has no place in the file's structure";
    return "@";
}

// One of every block, each in its place: the top-level blocks, each block the
// containers hold, and the first primitive with each block a primitive holds.
std::string every_block_text() {
    auto block = [](std::string_view keyword, const std::string& inside) {
        return std::string(keyword) + " { " + valid_body(keyword) + inside + "} ";
    };
    std::string text;
    for (std::string_view top : top_blocks()) {
        std::string inside;
        if (top == kCamerasKeyword) {
            for (std::string_view camera : cameras_blocks()) inside += block(camera, "");
        } else if (top == kSceneKeyword) {
            for (std::string_view child : scene_blocks()) {
                std::string primitive_children;
                if (child == shape_keywords()[0])
                    for (std::string_view grandchild : primitive_blocks())
                        primitive_children += block(grandchild, "");
                inside += block(child, primitive_children);
            }
        }
        text += block(top, inside) + "\n";
    }
    return text;
}

// The block in a parsed scene: the first of its kind (the first primitive's
// material and transform).
template <class Block>
Block& block_in(Scene& s) {
    if constexpr (std::is_same_v<Block, RenderSettings>) {
        return s.settings;
    } else if constexpr (std::is_same_v<Block, Camera>) {
        return s.cameras.at(0);
    } else if constexpr (std::is_same_v<Block, PointLight>) {
        return s.lights.at(0);
    } else if constexpr (std::is_same_v<Block, Material>) {
        return s.primitives.at(0).material;
    } else if constexpr (std::is_same_v<Block, TransformOp>) {
        return s.primitives.at(0).transforms.at(0);
    } else {
        for (Primitive& p : s.primitives)
            if (auto* shape = shape_if<Block>(&p.shape)) return *shape;
        throw std::out_of_range("no primitive of that shape");
    }
}

template <class Block>
void expect_distinct_members() {
    std::set<std::string_view> names;
    std::set<std::size_t> members;  // by index and address: no two entries set one member
    Block probe{};
    for (const PropertySpec<Block>& p : schema_of<Block>().properties) {
        EXPECT_TRUE(names.insert(p.name).second) << p.name;
        const void* address = with_member(p, probe, [](auto& v) { return (const void*)&v; });
        EXPECT_TRUE(members.insert(reinterpret_cast<std::size_t>(address)).second)
            << p.name << " sets the member of another property";
        // Kind and member type agree.
        with_member(p, probe, [&](auto& v) {
            using T = std::decay_t<decltype(v)>;
            const bool vector = p.kind == ValueKind::vector || p.kind == ValueKind::colour;
            const bool is_int = std::is_same_v<T, int>,
                       is_double =
                           std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>,
                       is_vec = std::is_same_v<T, Vec3> || std::is_same_v<T, std::optional<Vec3>>,
                       is_string = std::is_same_v<T, std::string>;
            EXPECT_EQ(is_int, p.kind == ValueKind::whole) << p.name;
            EXPECT_EQ(is_double, p.kind == ValueKind::number) << p.name;
            EXPECT_EQ(is_vec, vector) << p.name;
            EXPECT_EQ(is_string, p.kind == ValueKind::string) << p.name;
        });
        // An int member needs bounds an int can hold.
        if (p.kind == ValueKind::whole) {
            EXPECT_GE(p.range.low, std::numeric_limits<int>::min()) << p.name;
            EXPECT_LE(p.range.high, std::numeric_limits<int>::max()) << p.name;
        }
    }
}

TEST(Schema, EachPropertySetsItsOwnMemberOfItsKind) {
    for_each_block([](auto block) {
        using Block = typename decltype(block)::type;
        SCOPED_TRACE(keyword<Block>());
        expect_distinct_members<Block>();
    });
}

// Every block keyword the schema lists parses in its place, each block as the
// scene holds it: nothing here names a block.
TEST(Schema, EveryBlockKeywordParsesInItsPlace) {
    const std::string text = every_block_text();
    ParseResult parsed = parse_scene(text);
    ASSERT_EQ(brief(parsed.diagnostics), "") << text;
    const SceneSource& source = parsed.source;
    std::set<std::string_view> recorded{kCamerasKeyword};  // holds only blocks; not recorded
    if (source.render_settings) recorded.insert(source.render_settings->keyword);
    if (source.scene) recorded.insert(source.scene->keyword);
    for (const auto* records :
         {&source.cameras, &source.primitives, &source.lights, &source.children})
        for (const BlockSource& b : *records) recorded.insert(b.keyword);
    const std::set<std::string_view> keywords(block_keywords().begin(), block_keywords().end());
    EXPECT_EQ(recorded, keywords) << text;
    EXPECT_EQ(keywords.size(), block_keywords().size()) << "a keyword listed twice";
    // The primitives in the Shape variant's order, each of its own shape.
    ASSERT_EQ(parsed.scene.primitives.size(), shape_keywords().size());
    for (std::size_t i = 0; i < shape_keywords().size(); ++i) {
        EXPECT_EQ(parsed.scene.primitives[i].shape.index(), i);
        EXPECT_EQ(keyword_of(parsed.scene.primitives[i].shape), shape_keywords()[i]);
    }
    EXPECT_EQ(parsed.scene.cameras.size(), cameras_blocks().size());
    EXPECT_EQ(parsed.scene.lights.size(), 1u);
    EXPECT_EQ(parsed.scene.primitives[0].transforms.size(), 1u);
    // Every block of the scene model is somewhere in the structure.
    for_each_block([](auto block) {
        using Block = typename decltype(block)::type;
        EXPECT_NE(host_text(keyword<Block>()), "@") << keyword<Block>();
    });
}

// --- every property through every consumer ---------------------------------------

std::string with_property(std::string_view host, std::string_view property) {
    std::string text(host);
    text.replace(text.find('@'), 1, property);
    return text;
}

// Two in-range values unlike each other and unlike the default, and the text
// the first is written as in the file: not the shortest, so that an edit
// which keeps a component's text shows.
struct Samples {
    int whole[2] = {7, 3};
    double number[5] = {2.5, 0.75, 0.25, 33.5, -4.25};   // the first two in range are used
    Vec3 vector[2] = {{0.25, -1.5, 3}, {0.5, -1.5, 3}};  // only x differs
    const char* vector_written = "<0.250, -1.50, 3.0>";
    const char* vector_edited = "<0.5, -1.50, 3.0>";
    Vec3 colour[2] = {{0.25, 0.5, 0.75}, {0.25, 0.5, 1}};  // only z differs
    const char* colour_written = "<0.250, 0.50, 0.750>";
    const char* colour_edited = "<0.250, 0.50, 1>";
    std::string string[2] = {"sample.bmp", "other name"};
};

template <class Block>
struct Case {
    const PropertySpec<Block>& spec;
    std::string host;        // host_text of the block, with the properties it needs (below)
    Block fresh;             // the block before the property is set (a transform op has its kind)
    std::size_t others = 0;  // properties the host writes besides this one
};

// Sets the property to sample `i` in `block`; returns the file text of sample
// 0 (as written) or sample 1 (as an edit writes it, other components kept).
template <class Block>
std::string set_sample(const PropertySpec<Block>& spec, Block& block, int i) {
    const Samples s;
    return with_member(spec, block, [&](auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, int>) {
            v = s.whole[i];
            return std::to_string(v);
        } else if constexpr (std::is_same_v<T, double> ||
                             std::is_same_v<T, std::optional<double>>) {
            // The first two candidates in range and not the default.
            const Block defaults{};
            const double default_value = with_member(spec, defaults, [](const auto& d) {
                if constexpr (std::is_same_v<std::decay_t<decltype(d)>, double>) return d;
                return -1.0;  // an unset optional: every candidate differs
            });
            int found = 0;
            bool set = false;
            for (double candidate : s.number) {
                if (candidate == default_value ||
                    check_range(spec.range, candidate).verdict != RangeVerdict::inside)
                    continue;
                if (found++ == i) {
                    v = candidate;
                    set = true;
                    break;
                }
            }
            EXPECT_TRUE(set) << "no sample in the range of " << spec.name;
            // Sample 0 as a file might write it: a trailing 0 the shortest text has not.
            const double written = schema_detail::set_value(v);
            return i == 0 ? number_text(written) + "0" : number_text(written);
        } else if constexpr (std::is_same_v<T, std::optional<Vec3>>) {
            v = s.colour[i];
            return i == 0 ? s.colour_written : s.colour_edited;
        } else if constexpr (std::is_same_v<T, Vec3>) {
            const bool colour = spec.kind == ValueKind::colour;
            v = colour ? s.colour[i] : s.vector[i];
            if (colour) return i == 0 ? s.colour_written : s.colour_edited;
            return i == 0 ? s.vector_written : s.vector_edited;
        } else if (!spec.range.choices.empty()) {
            // A word of the choices: first those that are not the default, then the default.
            std::vector<std::string> words;
            Block defaults{};
            const std::string default_word =
                with_member(spec, defaults, [](const auto& d) -> std::string {
                    if constexpr (std::is_same_v<std::decay_t<decltype(d)>, std::string>) return d;
                    return {};
                });
            for (std::string_view c : spec.range.choices)
                if (c != default_word) words.emplace_back(c);
            words.push_back(default_word);
            v = words.at(static_cast<std::size_t>(i) % words.size());
            return string_text(v);
        } else {
            v = s.string[i];
            return string_text(v);
        }
    });
}

template <class Block>
Scene parsed_with(const Case<Block>& c, std::string_view property) {
    return parse_scene(with_property(c.host, property)).scene;
}

// Parses, serialises, reads back, edits in place (replaced and inserted).
template <class Block>
void check_round_trips(const Case<Block>& c) {
    const std::string name(c.spec.name);
    // The scene with the property set, built without the parser.
    Scene expected = parse_scene(with_property(c.host, "")).scene;
    if constexpr (std::is_same_v<Block, TransformOp>)
        expected.primitives.at(0).transforms = {c.fresh};
    Block& target = block_in<Block>(expected);
    const std::string written = set_sample(c.spec, target, 0);

    // Parses to exactly that scene.
    const std::string text = with_property(c.host, name + ": " + written + ";");
    ParseResult parsed = parse_scene(text);
    EXPECT_EQ(brief(parsed.diagnostics), "") << text;
    EXPECT_TRUE(parsed.scene == expected) << text;
    ASSERT_EQ(parsed.source.properties.size(), 1u + c.others) << text;
    EXPECT_EQ(parsed.source.properties[0].name, c.spec.name);

    // Serialises as `name: value;` and reads back the same.
    const std::string serialized = serialize_scene(expected);
    EXPECT_NE(serialized.find(name + ": " + value_text(c.spec, target) + ";\n"), std::string::npos)
        << serialized;
    ParseResult again = parse_scene(serialized);
    EXPECT_EQ(brief(again.diagnostics), "") << serialized;
    EXPECT_TRUE(again.scene == expected) << serialized;

    // Edits in place: only the value's bytes change, other components kept.
    Scene edited = expected;
    const std::string new_text = set_sample(c.spec, block_in<Block>(edited), 1);
    SourceEditResult edit = apply_scene_edits(text, parsed.source, parsed.scene, edited);
    EXPECT_TRUE(edit.ok()) << edit.error;
    EXPECT_EQ(edit.values_changed, 1);
    EXPECT_EQ(edit.text, with_property(c.host, name + ": " + new_text + ";"));
    EXPECT_TRUE(parse_scene(edit.text).scene == edited) << edit.text;

    // A property the file does not write yet is inserted into its block.
    if constexpr (!std::is_same_v<Block, TransformOp>) {
        const std::string bare = with_property(c.host, "");
        ParseResult base = parse_scene(bare);
        SourceEditResult insert = apply_scene_edits(bare, base.source, base.scene, expected);
        EXPECT_TRUE(insert.ok()) << insert.error;
        ParseResult inserted = parse_scene(insert.text);
        EXPECT_EQ(brief(inserted.diagnostics), "") << insert.text;
        EXPECT_TRUE(inserted.scene == expected) << insert.text;
    }
}

// A value past each bound of the property's range, and the verdict the range gives it.
struct Probe {
    double value;
    RangeVerdict verdict;
    double clamped;
};

std::vector<Probe> probes(const ValueRange& r, ValueKind kind) {
    const double step = kind == ValueKind::whole ? 1.0 : 0.5;
    std::vector<Probe> out;
    if (kind == ValueKind::string) return out;
    {
        out.push_back({r.low_open ? r.low : r.low - step,
                       r.clamp_low ? RangeVerdict::clamped : RangeVerdict::outside, r.low});
        if (!r.low_open) out.push_back({r.low, RangeVerdict::inside, r.low});
    }
    {
        out.push_back({r.high_open ? r.high : r.high + step,
                       r.clamp_high ? RangeVerdict::clamped : RangeVerdict::outside, r.high});
        if (!r.high_open) out.push_back({r.high, RangeVerdict::inside, r.high});
    }
    return out;
}

// A vector probe moves the first component only.
Vec3 probe_vector(double x) {
    return {x, 0.5, 0.5};
}

// The parser: one message at the value, the value rejected (left at its default)
// or clamped; at an inclusive bound, no message.
template <class Block>
void check_parsed_ranges(const Case<Block>& c) {
    const std::string name(c.spec.name);
    const std::size_t column = c.host.find('@') + name.size() + 3;
    auto expect_one = [&](const std::string& written, Severity severity,
                          const std::string& message) {
        const std::string text = with_property(c.host, name + ": " + written + ";");
        const ParseResult r = parse_scene(text);
        EXPECT_EQ(brief(r.diagnostics),
                  "1:" + std::to_string(column) +
                      (severity == Severity::error ? ": error: " : ": warning: ") + message)
            << text;
        return r;
    };
    const bool is_vector = c.spec.kind == ValueKind::vector || c.spec.kind == ValueKind::colour;
    if (c.spec.range.nonzero) {
        const ParseResult r =
            expect_one("<0, 0, 0>", Severity::error, out_of_range_message(c.spec, "<0, 0, 0>"));
        Scene bare = parsed_with(c, "");
        EXPECT_TRUE(r.scene == bare) << "a rejected value leaves the default";
    }
    if (c.spec.range.nonempty) {
        const ParseResult r = expect_one("\"\"", Severity::error, out_of_range_message(c.spec, ""));
        EXPECT_TRUE(r.scene == parsed_with(c, "")) << "a rejected value leaves the default";
    }
    for (const Probe& p : probes(c.spec.range, c.spec.kind)) {
        const std::string written =
            is_vector ? vector_text(probe_vector(p.value)) : number_text(p.value);
        const std::string clamped =
            is_vector ? vector_text(probe_vector(p.clamped)) : number_text(p.clamped);
        if (p.verdict == RangeVerdict::inside) {
            EXPECT_EQ(
                brief(parse_scene(with_property(c.host, name + ": " + written + ";")).diagnostics),
                "")
                << written;
        } else if (p.verdict == RangeVerdict::outside) {
            const ParseResult r =
                expect_one(written, Severity::error, out_of_range_message(c.spec, written));
            EXPECT_TRUE(r.scene == parsed_with(c, "")) << "a rejected value leaves the default";
        } else {
            ParseResult r = expect_one(written, Severity::warning,
                                       past_clamp_message(c.spec, written, clamped));
            Scene expected = parsed_with(c, name + ": " + clamped + ";");
            EXPECT_TRUE(r.scene == expected) << written << " is clamped to " << clamped;
        }
    }
}

// A scene with one of every block, each property inside its range (a property
// whose default is not, as a mesh's file, holds its first sample).
Scene every_block_scene() {
    Scene s = parse_scene(every_block_text()).scene;
    for_each_block([&](auto tag) {
        using Block = typename decltype(tag)::type;
        Block& block = block_in<Block>(s);
        for (const PropertySpec<Block>& spec : schema_of<Block>().properties)
            if (value_problem(spec, block)) set_sample(spec, block, 0);
    });
    return s;
}

std::vector<std::string> error_messages(const Scene& s) {
    std::vector<std::string> out;
    for (const Diagnostic& d : validate_scene(s, SceneSource{}))
        if (d.severity == Severity::error) out.push_back(d.message);
    return out;
}

// The validator, for values set in code: the same message, once, prefixed by
// the block (beside any the scene had before, as a mesh file that is not there).
template <class Block>
void check_validated_ranges(const Case<Block>& c) {
    const std::string name(c.spec.name);
    const Scene base = every_block_scene();
    const std::vector<std::string> before = error_messages(base);
    auto errors_with = [&](auto value) {
        Scene s = base;
        Block& block = block_in<Block>(s);
        if constexpr (std::is_same_v<Block, TransformOp>) block = c.fresh;
        with_member(c.spec, block, [&](auto& member) {
            using M = std::decay_t<decltype(member)>;
            using V = decltype(value);
            if constexpr (std::is_same_v<M, V> ||
                          (std::is_same_v<M, std::optional<Vec3>> && std::is_same_v<V, Vec3>) ||
                          (std::is_same_v<M, std::optional<double>> && std::is_arithmetic_v<V>) ||
                          (std::is_arithmetic_v<M> && std::is_arithmetic_v<V>))
                member = static_cast<M>(value);
        });
        std::vector<std::string> added;
        for (const std::string& message : error_messages(s))
            if (std::find(before.begin(), before.end(), message) == before.end())
                added.push_back(message);
        return added;
    };
    auto expect_one = [&](auto value, const std::string& message) {
        const std::vector<std::string> errors = errors_with(value);
        ASSERT_EQ(errors.size(), 1u) << testing::PrintToString(errors);
        EXPECT_TRUE(errors[0].ends_with(": " + message) || errors[0] == message)
            << errors[0] << "\nexpected to end with: " << message;
    };
    const bool is_vector = c.spec.kind == ValueKind::vector || c.spec.kind == ValueKind::colour;
    if (c.spec.range.nonzero) expect_one(Vec3(0.0), out_of_range_message(c.spec, "<0, 0, 0>"));
    if (c.spec.range.nonempty) expect_one(std::string(), out_of_range_message(c.spec, ""));
    for (const Probe& p : probes(c.spec.range, c.spec.kind)) {
        if (p.verdict == RangeVerdict::inside) continue;
        const std::string got =
            is_vector ? vector_text(probe_vector(p.value)) : number_text(p.value);
        const std::string message = p.verdict == RangeVerdict::outside
                                        ? out_of_range_message(c.spec, got)
                                        : past_clamp_message(c.spec, got);
        if (is_vector)
            expect_one(probe_vector(p.value), message);
        else
            expect_one(p.value, message);
    }
    // Every number and vector must be finite.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (c.spec.kind == ValueKind::number) expect_one(nan, "'" + name + "' must be finite, got nan");
    if (is_vector)
        expect_one(probe_vector(nan),
                   "'" + name + "' must be finite, got " + vector_text(probe_vector(nan)));
}

// One test case a property, named for it ("sphere_radius"), its checks bound
// to its block's type.
struct PropertyCase {
    std::string name;
    std::function<void()> round_trips;
    std::function<void()> parsed_ranges;
    std::function<void()> validated_ranges;
};

template <class Block>
PropertyCase property_case(const PropertySpec<Block>& spec, Block fresh = {}) {
    const std::string block(keyword<Block>());
    Case<Block> c{spec, host_text(block), fresh};
    // A property of the block whose default is outside its range (a mesh's
    // file) is written after '@' with its first sample, so that the block
    // parses and serialises clean whichever property is under test.
    if constexpr (!std::is_same_v<Block, TransformOp>) {
        Block probe{};
        std::string needed;
        for (const PropertySpec<Block>& other : schema_of<Block>().properties)
            if (&other != &spec && value_problem(other, probe)) {
                needed += " " + std::string(other.name) + ": " + set_sample(other, probe, 0) + ";";
                ++c.others;
            }
        c.host.insert(c.host.find('@') + 1, needed);
    }
    return {block + "_" + std::string(spec.name), [c] { check_round_trips(c); },
            [c] { check_parsed_ranges(c); }, [c] { check_validated_ranges(c); }};
}

std::vector<PropertyCase> every_property() {
    std::vector<PropertyCase> cases;
    for_each_block([&](auto tag) {
        using Block = typename decltype(tag)::type;
        for (const PropertySpec<Block>& spec : schema_of<Block>().properties)
            cases.push_back(property_case(spec));
    });
    for (const TransformOpSpec& op : transform_ops())
        cases.push_back(property_case(op.property, TransformOp{op.kind}));
    return cases;
}

class EveryProperty : public testing::TestWithParam<PropertyCase> {};

TEST_P(EveryProperty, ParsesSerialisesAndEditsInPlace) {
    GetParam().round_trips();
}

TEST_P(EveryProperty, ParserEnforcesItsRangeWithOneLocatedMessage) {
    GetParam().parsed_ranges();
}

TEST_P(EveryProperty, ValidatorEnforcesItsRangeWithOneMessage) {
    GetParam().validated_ranges();
}

INSTANTIATE_TEST_SUITE_P(Schema, EveryProperty, testing::ValuesIn(every_property()),
                         [](const testing::TestParamInfo<PropertyCase>& info) {
                             return info.param.name;
                         });

// The messages the table's ranges give, as users read them.
TEST(Schema, RangeRulesReadAsSentences) {
    EXPECT_EQ(range_rule({.low = 0, .high = kMaxImageSide}, ValueKind::whole),
              "must be a whole number from 0 to 65535");
    // A bound not given is the limit on every number in a scene.
    EXPECT_EQ(range_rule({.low = 0, .low_open = true}, ValueKind::number),
              "must be greater than 0 and at most 1e+09");
    EXPECT_EQ(range_rule({.low = 0, .high = 180, .low_open = true, .high_open = true},
                         ValueKind::number, "degrees"),
              "must be between 0 and 180 degrees (exclusive)");
    EXPECT_EQ(range_rule({.low = 0, .high = 256, .clamp_high = true}, ValueKind::whole),
              "must be 0 or more");
    EXPECT_EQ(range_rule({.low = 0, .high = 1}, ValueKind::number), "must be from 0 to 1");
    EXPECT_EQ(range_rule({.high = 2}, ValueKind::number), "must be from -1e+09 to 2");
    EXPECT_EQ(range_rule({.high = 2, .high_open = true}, ValueKind::number),
              "must be at least -1e+09 and less than 2");
    EXPECT_EQ(range_rule({}, ValueKind::vector), "must be from -1e+09 to 1e+09");
}

}  // namespace
}  // namespace jt

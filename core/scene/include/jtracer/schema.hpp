#pragma once
// The scene language's properties as data (docs/language.md §4): for each block,
// each property's name, kind, range and the member of the scene model it sets.
// The parser, the validator, the serializer, save-in-place and the viewer's
// panels all read these tables, so a property is added here and nowhere else;
// a shape is its type in scene.hpp's Shape variant, its table here and its
// geometry. The file's structure (which block holds which) is here too.
//
// A property's default is its member's initial value in scene.hpp
// (default_value below reads it from there): the model and the table cannot
// disagree. Table order is the order the serializer writes and messages list.
//
//   for (const auto& property : schema_of<Camera>().properties)
//       std::cout << property.name << " = " << value_text(property, camera) << "\n";

#include "jtracer/limits.hpp"
#include "jtracer/scene.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace jt {

enum class ValueKind {
    whole,   // int; a number in the text, truncated toward zero
    number,  // double
    vector,  // <x, y, z>
    colour,  // <r, g, b>, each component clipped to [0, 1] when read
    string,  // "text"
};

// The values a property accepts. Past a bound a value is an error, or, for a
// clamping bound, it is moved onto the bound with a warning.
// A bound left unset is the language's limit on every number, kMaxMagnitude.
struct ValueRange {
    double low = -kMaxMagnitude;
    double high = kMaxMagnitude;
    bool low_open = false;  // low itself is outside
    bool high_open = false;
    bool clamp_low = false;  // below low: clamped to low (never with low_open)
    bool clamp_high = false;
    bool nonzero = false;   // a vector: <0, 0, 0> is outside
    bool nonempty = false;  // a string: "" is outside
    // A string: when not empty, the only words allowed.
    std::span<const std::string_view> choices = {};
};

// A pointer to the member a property sets: one of the member types the block
// has. Only those: code that visits a member then never meets a type the
// block cannot hold (GCC would warn about the impossible accesses).
template <class Block, class... T>
using MemberOf = std::variant<T Block::*...>;
template <class Block>
struct MemberTypes;
template <>
struct MemberTypes<RenderSettings> {
    using type = MemberOf<RenderSettings, int, Vec3, std::string>;
};
template <>
struct MemberTypes<Camera> {
    using type = MemberOf<Camera, double, std::optional<double>, Vec3, std::string>;
};
template <>
struct MemberTypes<Sphere> {
    using type = MemberOf<Sphere, double, Vec3>;
};
template <>
struct MemberTypes<Plane> {
    using type = MemberOf<Plane, double, Vec3>;
};
template <>
struct MemberTypes<Cylinder> {
    using type = MemberOf<Cylinder, double>;
};
template <>
struct MemberTypes<Triangle> {
    using type = MemberOf<Triangle, Vec3>;
};
template <>
struct MemberTypes<Mesh> {
    using type = MemberOf<Mesh, std::optional<double>, std::string>;
};
template <>
struct MemberTypes<PointLight> {
    using type = MemberOf<PointLight, int, double, Vec3>;
};
// A member of a part the block holds shared (Shared<Part>, shared.hpp): read
// through the handle, set through edit(), which first copies a shared part.
template <class Block, class Part, class T>
struct SharedPartMember {
    Shared<Part> Block::*part;
    T Part::*member;
};
// A material's pigment is its own; every other property is its finish's.
template <class T>
using FinishMember = SharedPartMember<Material, Finish, T>;
template <>
struct MemberTypes<Material> {
    using type = std::variant<Vec3 Material::*, FinishMember<double>, FinishMember<Vec3>,
                              FinishMember<std::optional<Vec3>>, FinishMember<std::string>>;
};
template <>
struct MemberTypes<TransformOp> {
    using type = MemberOf<TransformOp, double, Vec3>;
};
template <class Block>
using Member = typename MemberTypes<Block>::type;

// The value a member names in `block`: const when `block` is; a mutable
// member of a shared part is the block's own copy (edit()).
template <class Block, class T>
constexpr T& member_ref(Block& block, T Block::*member) {
    return block.*member;
}
template <class Block, class T>
constexpr const T& member_ref(const Block& block, T Block::*member) {
    return block.*member;
}
template <class Block, class Part, class T>
T& member_ref(Block& block, SharedPartMember<Block, Part, T> member) {
    return (block.*member.part).edit().*member.member;
}
template <class Block, class Part, class T>
const T& member_ref(const Block& block, SharedPartMember<Block, Part, T> member) {
    return (*(block.*member.part)).*member.member;
}

template <class Block>
struct PropertySpec {
    std::string_view name;
    ValueKind kind = ValueKind::number;
    Member<Block> member;
    ValueRange range = {};
    std::string_view unit = {};   // after the numbers of a range message: "degrees"
    bool omit_default = false;    // serializer: written only when it differs from the default
    std::string_view alias = {};  // an older name also read as this one, with a warning
};

template <class Block>
struct BlockSchema {
    std::string_view keyword;  // as written in a file
    std::string_view noun;     // in messages about one block: "camera 2"
    std::span<const PropertySpec<Block>> properties;
    std::span<const std::string_view> children = {};  // blocks it may hold besides properties
};

// One transform operation: a property of `transform` whose value is the
// operation's vector or angle.
struct TransformOpSpec {
    TransformKind kind;
    PropertySpec<TransformOp> property;
};

// --- the tables -------------------------------------------------------------

// The block of a primitive's transform operations (transform_ops below).
inline constexpr std::string_view kTransformKeyword = "transform";

namespace schema_detail {

template <class Block>
constexpr PropertySpec<Block> whole(std::string_view name, int Block::*member, ValueRange range,
                                    bool omit_default = false) {
    return {name, ValueKind::whole, member, range, {}, omit_default};
}
template <class Block>
constexpr PropertySpec<Block> number(std::string_view name, double Block::*member,
                                     ValueRange range = {}, std::string_view unit = {}) {
    return {name, ValueKind::number, member, range, unit};
}
template <class Block>
constexpr PropertySpec<Block> vector(std::string_view name, Vec3 Block::*member,
                                     ValueRange range = {}) {
    return {name, ValueKind::vector, member, range};
}
// A colour's channels: each clamped into [0, 1].
inline constexpr ValueRange kColourChannel{
    .low = 0.0, .high = 1.0, .clamp_low = true, .clamp_high = true};

template <class Block>
constexpr PropertySpec<Block> colour(std::string_view name, Vec3 Block::*member) {
    return {name, ValueKind::colour, member, kColourChannel};
}
// The same, for a property of a material's finish: &Finish::ambient.
constexpr PropertySpec<Material> number(std::string_view name, double Finish::*member,
                                        ValueRange range = {}) {
    return {name, ValueKind::number, FinishMember<double>{&Material::finish, member}, range};
}
constexpr PropertySpec<Material> colour(std::string_view name, Vec3 Finish::*member) {
    return {name, ValueKind::colour, FinishMember<Vec3>{&Material::finish, member}, kColourChannel};
}
constexpr PropertySpec<Material> optional_colour(std::string_view name,
                                                 std::optional<Vec3> Finish::*member) {
    return {name, ValueKind::colour, FinishMember<std::optional<Vec3>>{&Material::finish, member},
            kColourChannel};
}
constexpr PropertySpec<Material> string(std::string_view name, std::string Finish::*member) {
    return {name, ValueKind::string, FinishMember<std::string>{&Material::finish, member}};
}
// A colour with no default: unset means the feature is off.
template <class Block>
constexpr PropertySpec<Block> optional_colour(std::string_view name,
                                              std::optional<Vec3> Block::*member) {
    return {name, ValueKind::colour, member, kColourChannel};
}
// A number with no default: unset means the feature is off, or takes a value
// that depends on others (a camera's focus distance).
template <class Block>
constexpr PropertySpec<Block> optional_number(std::string_view name,
                                              std::optional<double> Block::*member,
                                              ValueRange range = {}, std::string_view unit = {}) {
    return {name, ValueKind::number, member, range, unit};
}
// An extension's property is written only when set, so that a scene that
// does not use it serialises as manual-only text.
template <class Block>
constexpr PropertySpec<Block> only_when_set(PropertySpec<Block> property) {
    property.omit_default = true;
    return property;
}
template <class Block>
constexpr PropertySpec<Block> string(std::string_view name, std::string Block::*member,
                                     ValueRange range = {}, bool omit_default = false) {
    return {name, ValueKind::string, member, range, {}, omit_default};
}

inline constexpr ValueRange kPositive{.low = 0.0, .low_open = true};
inline constexpr ValueRange kNonNegative{.low = 0.0};
inline constexpr ValueRange kImageSide{.low = 0.0, .high = kMaxImageSide};

inline constexpr std::array<PropertySpec<RenderSettings>, 9> kRenderSettings{{
    whole("width", &RenderSettings::width, kImageSide),
    whole("height", &RenderSettings::height, kImageSide),
    whole("recurse_depth", &RenderSettings::recurse_depth,
          {.low = 0.0, .high = kMaxRecurseDepth, .clamp_high = true}),
    string("filename", &RenderSettings::filename, {.nonempty = true}),
    string("active_camera", &RenderSettings::active_camera, {}, true),  // empty: the first camera
    colour("background", &RenderSettings::background),
    colour("ambient_light", &RenderSettings::ambient_light),
    // An extension (docs/language.md §9.1): written only when used, so that
    // scenes that do not use it stay manual-only text.
    whole("samples", &RenderSettings::samples, {.low = kMinSamples, .high = kMaxSamples}, true),
    // Extension (docs/language.md §14.3).
    string("background_map", &RenderSettings::background_map, {}, true),
}};

inline constexpr std::array<PropertySpec<Camera>, 8> kCamera{{
    // The manual's own example names a camera with active_camera.
    {.name = "name", .kind = ValueKind::string, .member = &Camera::name, .alias = "active_camera"},
    vector("position", &Camera::position),
    vector("look_at", &Camera::look_at),
    vector("up", &Camera::up),
    number("aspect", &Camera::aspect, kPositive),
    number("fov", &Camera::fov, {.low = 0.0, .high = 180.0, .low_open = true, .high_open = true},
           "degrees"),
    // Extensions (docs/language.md §14.2).
    only_when_set(number("aperture", &Camera::aperture, kNonNegative)),
    only_when_set(optional_number("focus_distance", &Camera::focus_distance, kPositive)),
}};

inline constexpr std::array<PropertySpec<Sphere>, 2> kSphere{{
    vector("center", &Sphere::center),
    number("radius", &Sphere::radius, kPositive),
}};

inline constexpr std::array<PropertySpec<Plane>, 2> kPlane{{
    vector("normal", &Plane::normal, {.nonzero = true}),
    number("distance", &Plane::distance),
}};

inline constexpr std::array<PropertySpec<Cylinder>, 2> kCylinder{{
    number("radius", &Cylinder::radius, kPositive),
    number("height", &Cylinder::height, kPositive),
}};

// Extensions (docs/language.md §13.5).
inline constexpr std::array<PropertySpec<Triangle>, 6> kTriangle{{
    vector("a", &Triangle::a),
    vector("b", &Triangle::b),
    vector("c", &Triangle::c),
    only_when_set(vector("uv_a", &Triangle::uv_a)),
    only_when_set(vector("uv_b", &Triangle::uv_b)),
    only_when_set(vector("uv_c", &Triangle::uv_c)),
}};

inline constexpr std::array<std::string_view, 2> kShadings{kSmoothShading, kFlatShading};
inline constexpr std::array<std::string_view, 2> kMaterialSources{kSceneMaterials, kFileMaterials};
inline constexpr std::array<PropertySpec<Mesh>, 4> kMesh{{
    string("file", &Mesh::file, {.nonempty = true}),
    string("shading", &Mesh::shading, {.choices = kShadings}, true),
    // Extensions (docs/language.md §14.4, §14.5).
    only_when_set(optional_number("smooth_angle", &Mesh::smooth_angle, {.low = 0.0, .high = 180.0},
                                  "degrees")),
    string("materials", &Mesh::materials, {.choices = kMaterialSources}, true),
}};

inline constexpr std::array<PropertySpec<PointLight>, 4> kPointLight{{
    vector("position", &PointLight::position),
    colour("intensity", &PointLight::intensity),
    // Extensions (docs/language.md §14.1): shadow_samples is checked whatever
    // the radius, and used only when the radius is above 0.
    only_when_set(number("radius", &PointLight::radius, kNonNegative)),
    whole("shadow_samples", &PointLight::shadow_samples,
          {.low = kMinShadowSamples, .high = kMaxShadowSamples}, true),
}};

inline constexpr ValueRange kFraction{
    .low = 0.0, .high = 1.0, .clamp_low = true, .clamp_high = true};

inline constexpr std::array<PropertySpec<Material>, 13> kMaterial{{
    colour("pigment", &Material::pigment),
    colour("ambient", &Finish::ambient),
    colour("diffuse", &Finish::diffuse),
    colour("specular", &Finish::specular),
    number("diffuse_k", &Finish::diffuse_k, kPositive),
    number("specular_k", &Finish::specular_k, kPositive),
    number("reflection", &Finish::reflection, kFraction),
    // Extensions (docs/language.md §13.1).
    only_when_set(number("transmission", &Finish::transmission, kFraction)),
    only_when_set(number("ior", &Finish::ior, kPositive)),
    only_when_set(optional_colour("checker", &Finish::checker)),
    only_when_set(number("checker_size", &Finish::checker_size, kPositive)),
    only_when_set(string("image_map", &Finish::image_map)),
    only_when_set(number("map_size", &Finish::map_size, kPositive)),
}};

inline constexpr std::array<TransformOpSpec, 5> kTransformOps{{
    {TransformKind::translate, vector("translate", &TransformOp::vector)},
    {TransformKind::scale, vector("scale", &TransformOp::vector)},
    {TransformKind::xrotate, number("xrotate", &TransformOp::degrees, {}, "degrees")},
    {TransformKind::yrotate, number("yrotate", &TransformOp::degrees, {}, "degrees")},
    {TransformKind::zrotate, number("zrotate", &TransformOp::degrees, {}, "degrees")},
}};

inline constexpr BlockSchema<Material> kMaterialSchema{"material", "material", kMaterial};
inline constexpr std::array<std::string_view, 2> kPrimitiveChildren{kMaterialSchema.keyword,
                                                                    kTransformKeyword};

inline constexpr BlockSchema<RenderSettings> kRenderSettingsSchema{
    "render_settings", "render_settings", kRenderSettings};
inline constexpr BlockSchema<Camera> kCameraSchema{"perspective_camera", "camera", kCamera};
inline constexpr BlockSchema<Sphere> kSphereSchema{"sphere", "sphere", kSphere, kPrimitiveChildren};
inline constexpr BlockSchema<Plane> kPlaneSchema{"plane", "plane", kPlane, kPrimitiveChildren};
inline constexpr BlockSchema<Cylinder> kCylinderSchema{"cylinder", "cylinder", kCylinder,
                                                       kPrimitiveChildren};
inline constexpr BlockSchema<Triangle> kTriangleSchema{"triangle", "triangle", kTriangle,
                                                       kPrimitiveChildren};
inline constexpr BlockSchema<Mesh> kMeshSchema{"mesh", "mesh", kMesh, kPrimitiveChildren};
inline constexpr BlockSchema<PointLight> kPointLightSchema{"point_light", "point_light",
                                                           kPointLight};

}  // namespace schema_detail

// The schema of a block type: schema_of<Camera>(), schema_of<Sphere>(), ...
template <class Block>
constexpr const BlockSchema<Block>& schema_of();
template <>
constexpr const BlockSchema<RenderSettings>& schema_of<RenderSettings>() {
    return schema_detail::kRenderSettingsSchema;
}
template <>
constexpr const BlockSchema<Camera>& schema_of<Camera>() {
    return schema_detail::kCameraSchema;
}
template <>
constexpr const BlockSchema<Sphere>& schema_of<Sphere>() {
    return schema_detail::kSphereSchema;
}
template <>
constexpr const BlockSchema<Plane>& schema_of<Plane>() {
    return schema_detail::kPlaneSchema;
}
template <>
constexpr const BlockSchema<Cylinder>& schema_of<Cylinder>() {
    return schema_detail::kCylinderSchema;
}
template <>
constexpr const BlockSchema<Triangle>& schema_of<Triangle>() {
    return schema_detail::kTriangleSchema;
}
template <>
constexpr const BlockSchema<Mesh>& schema_of<Mesh>() {
    return schema_detail::kMeshSchema;
}
template <>
constexpr const BlockSchema<PointLight>& schema_of<PointLight>() {
    return schema_detail::kPointLightSchema;
}
template <>
constexpr const BlockSchema<Material>& schema_of<Material>() {
    return schema_detail::kMaterialSchema;
}

// "sphere", "plane", "cylinder", "triangle" or "mesh": the keyword of a primitive's shape.
constexpr std::string_view keyword_of(const Shape& shape) {
    return visit_shape([](const auto& s) { return schema_of<std::decay_t<decltype(s)>>().keyword; },
                       shape);
}

// --- the file's structure (docs/language.md §3) ----------------------------

// The two blocks that hold only blocks.
inline constexpr std::string_view kCamerasKeyword = "cameras";
inline constexpr std::string_view kSceneKeyword = "scene";

namespace schema_detail {
template <std::size_t... I>
constexpr auto shape_keywords(std::index_sequence<I...>) {
    return std::array<std::string_view, sizeof...(I)>{schema_of<ShapeAlternative<I>>().keyword...};
}
template <std::size_t... N>
constexpr auto joined(const std::array<std::string_view, N>&... lists) {
    std::array<std::string_view, (N + ...)> out{};
    std::size_t i = 0;
    ((std::copy(lists.begin(), lists.end(), out.begin() + i), i += N), ...);
    return out;
}
inline constexpr auto kShapeKeywords =
    shape_keywords(std::make_index_sequence<std::variant_size_v<Shape>>{});
inline constexpr std::array<std::string_view, 3> kTopBlocks{kRenderSettingsSchema.keyword,
                                                            kCamerasKeyword, kSceneKeyword};
inline constexpr std::array<std::string_view, 1> kCamerasBlocks{kCameraSchema.keyword};
inline constexpr auto kSceneBlocks =
    joined(kShapeKeywords, std::array<std::string_view, 1>{kPointLightSchema.keyword});
inline constexpr auto kBlockKeywords =
    joined(kTopBlocks, kCamerasBlocks, kSceneBlocks, kPrimitiveChildren);
}  // namespace schema_detail

// The blocks of a file's top level: render_settings, cameras, scene.
constexpr std::span<const std::string_view> top_blocks() {
    return schema_detail::kTopBlocks;
}
// The blocks `cameras` holds: perspective_camera.
constexpr std::span<const std::string_view> cameras_blocks() {
    return schema_detail::kCamerasBlocks;
}
// The primitives' keywords, a shape each in the Shape variant's order:
// sphere, plane, cylinder, triangle, mesh.
constexpr std::span<const std::string_view> shape_keywords() {
    return schema_detail::kShapeKeywords;
}
// The blocks `scene` holds: the primitives, then point_light.
constexpr std::span<const std::string_view> scene_blocks() {
    return schema_detail::kSceneBlocks;
}
// The blocks a primitive holds besides its properties: material, transform.
constexpr std::span<const std::string_view> primitive_blocks() {
    return schema_detail::kPrimitiveChildren;
}
// Every block keyword of the language, each once.
constexpr std::span<const std::string_view> block_keywords() {
    return schema_detail::kBlockKeywords;
}

// The string properties that name a file beside the scene: in an included
// file they are relative to that file's folder (docs/language.md §15.6).
inline constexpr std::array<std::string_view, 3> kFileProperties{"file", "image_map",
                                                                 "background_map"};
constexpr bool names_a_file(std::string_view property) {
    for (std::string_view name : kFileProperties)
        if (name == property) return true;
    return false;
}

// The transform block's operations, in the order messages list them.
constexpr std::span<const TransformOpSpec> transform_ops() {
    return schema_detail::kTransformOps;
}
// The operation of that kind.
constexpr const TransformOpSpec& transform_op(TransformKind kind) {
    for (const TransformOpSpec& op : schema_detail::kTransformOps)
        if (op.kind == kind) return op;
    return schema_detail::kTransformOps[0];  // never: every kind has an entry
}

// Whether two names are the same. Names of a block share a few lengths
// (pigment, ambient, diffuse): the length and the first byte decide most,
// and the few bytes of a match are compared here, not by a call to memcmp.
constexpr bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) return false;
    return true;
}

// The property named `name` (or aliased so) in a block, or nullptr.
template <class Block>
constexpr const PropertySpec<Block>* find_property(std::string_view name) {
    for (const PropertySpec<Block>& p : schema_of<Block>().properties)
        if (same_name(p.name, name) || (!p.alias.empty() && same_name(p.alias, name))) return &p;
    return nullptr;
}

// --- values -----------------------------------------------------------------

// Calls f(value) with a reference to the member the property sets in `block`:
// an int&, double&, Vec3& or std::string& (const when `block` is const; a
// mutable one of a material's finish makes the finish the material's own).
template <class Block, class BlockRef, class F>
decltype(auto) with_member(const PropertySpec<Block>& property, BlockRef& block, F&& f) {
    return std::visit([&](auto member) -> decltype(auto) { return f(member_ref(block, member)); },
                      property.member);
}

template <class Block>
bool same_value(const PropertySpec<Block>& property, const Block& a, const Block& b) {
    return std::visit([&](auto member) { return member_ref(a, member) == member_ref(b, member); },
                      property.member);
}

// Sets the property in `to` to its value in `from`.
template <class Block>
void copy_value(const PropertySpec<Block>& property, const Block& from, Block& to) {
    std::visit([&](auto member) { member_ref(to, member) = member_ref(from, member); },
               property.member);
}

// True when `block` holds the property's default (its member's initial value).
template <class Block>
bool is_default(const PropertySpec<Block>& property, const Block& block) {
    static const Block defaults{};
    return same_value(property, block, defaults);
}

// False for a property the serializer leaves out of `block` (omit_default).
template <class Block>
bool is_written(const PropertySpec<Block>& property, const Block& block) {
    return !property.omit_default || !is_default(property, block);
}

// The value as .jts text: "640", "0.5", "<1, 0, 0>", "\"name\"" (see value_text.hpp).
std::string value_text(int value);
std::string value_text(double value);
std::string value_text(const Vec3& value);
std::string value_text(const std::string& value);
// An unset optional value has no text: it is never written.
std::string value_text(const std::optional<Vec3>& value);
std::string value_text(const std::optional<double>& value);

template <class Block>
std::string value_text(const PropertySpec<Block>& property, const Block& block) {
    return with_member(property, block, [](const auto& v) { return value_text(v); });
}

// "a whole number like 640", "a colour like <1, 0.5, 0>": what a kind of
// value looks like, for "'center' takes a vector like <0, 1, 0>".
std::string_view kind_description(ValueKind kind);

// --- ranges -----------------------------------------------------------------

enum class RangeVerdict {
    inside,
    clamped,  // past a clamping bound: `value` is moved onto it
    outside,  // an error
};

template <class T>
struct RangeCheck {
    RangeVerdict verdict = RangeVerdict::inside;
    T value{};
};

// A number (NaN and infinities are outside); a vector, component by component,
// and against `nonzero` (non-finite components are outside); a string against
// `nonempty`.
RangeCheck<double> check_range(const ValueRange& range, double value);
inline RangeCheck<double> check_range(const ValueRange& range, int value) {
    return check_range(range, static_cast<double>(value));
}
RangeCheck<Vec3> check_range(const ValueRange& range, const Vec3& value);
RangeVerdict check_range(const ValueRange& range, std::string_view value);

// The messages about a value against its property's range. The parser writes
// them at the value with `got` as written there; the validator writes them for
// values set in code, with `got` from value_text. An empty `got` leaves out
// the ", got" part.

// Outside: "'samples' must be a whole number from 1 to 1024, got 1025",
// "'fov' must be between 0 and 180 degrees (exclusive), got 180",
// "'normal' must not be the zero vector, got <0, 0, 0>".
template <class Block>
std::string out_of_range_message(const PropertySpec<Block>& property, std::string_view got);

// Past a clamping bound: "'reflection' 1.5 is outside 0..1", "'recurse_depth'
// 1000 is more than 256", "'pigment' <2, 0, 0> is outside the colour range
// [0, 1]"; with `clamped_to` the parser's warning adds ": clamped to 1".
template <class Block>
std::string past_clamp_message(const PropertySpec<Block>& property, std::string_view got,
                               std::string_view clamped_to = {});

// The one problem a value set in code has against its property, or nullopt:
// not finite, outside the range, or past a clamping bound (the parser would
// have clamped it).
template <class Block>
std::optional<std::string> value_problem(const PropertySpec<Block>& property, const Block& block);

// The rule part of an out-of-range message: "must be greater than 0".
std::string range_rule(const ValueRange& range, ValueKind kind, std::string_view unit = {});

namespace schema_detail {
// The value an optional member holds (or a default one when unset, never
// looked at); any other member as it is.
template <class T>
const T& set_value(const T& value) {
    return value;
}
inline const Vec3& set_value(const std::optional<Vec3>& value) {
    static const Vec3 unset{0.0};
    return value ? *value : unset;
}
inline const double& set_value(const std::optional<double>& value) {
    static const double unset = 0.0;
    return value ? *value : unset;
}
template <class T>
inline constexpr bool is_optional_v = false;
template <class T>
inline constexpr bool is_optional_v<std::optional<T>> = true;
bool is_finite(double value);
bool is_finite(const Vec3& value);
// "'position' must be finite, got <nan, 0, 0>"
std::string not_finite_message(std::string_view name, std::string_view got);
std::string out_of_range_message(std::string_view name, const ValueRange& range, ValueKind kind,
                                 std::string_view unit, std::string_view got);
std::string past_clamp_message(std::string_view name, const ValueRange& range, ValueKind kind,
                               std::string_view got, std::string_view clamped_to);
}  // namespace schema_detail

template <class Block>
std::string out_of_range_message(const PropertySpec<Block>& property, std::string_view got) {
    return schema_detail::out_of_range_message(property.name, property.range, property.kind,
                                               property.unit, got);
}

template <class Block>
std::string past_clamp_message(const PropertySpec<Block>& property, std::string_view got,
                               std::string_view clamped_to) {
    return schema_detail::past_clamp_message(property.name, property.range, property.kind, got,
                                             clamped_to);
}

template <class Block>
std::optional<std::string> value_problem(const PropertySpec<Block>& property, const Block& block) {
    return with_member(property, block, [&](const auto& member) -> std::optional<std::string> {
        const auto& v = schema_detail::set_value(member);
        using T = std::decay_t<decltype(v)>;
        if constexpr (schema_detail::is_optional_v<std::decay_t<decltype(member)>>) {
            if (!member) return std::nullopt;
        }
        if constexpr (std::is_same_v<T, std::string>) {
            // A string's message needs no ", got": the rule says what it was.
            if (check_range(property.range, v) == RangeVerdict::outside)
                return out_of_range_message(property, "");
            return std::nullopt;
        } else {
            if (!schema_detail::is_finite(v))
                return schema_detail::not_finite_message(property.name, value_text(v));
            const auto checked = check_range(property.range, v);
            if (checked.verdict == RangeVerdict::outside)
                return out_of_range_message(property, value_text(v));
            if (checked.verdict == RangeVerdict::clamped)
                return past_clamp_message(property, value_text(v));
            return std::nullopt;
        }
    });
}

}  // namespace jt

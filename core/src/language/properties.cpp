#include "language/properties.hpp"

#include "language/number_text.hpp"
#include "language/suggest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>

#include <glm/common.hpp>

namespace jt::lang {

namespace {

constexpr std::array<std::string_view, 8> kRenderSettings{
    "width",         "height",     "recurse_depth", "filename",
    "active_camera", "background", "ambient_light", "samples"};
constexpr std::array<std::string_view, 6> kCamera{"name", "position", "look_at",
                                                  "up",   "aspect",   "fov"};
constexpr std::array<std::string_view, 4> kSphere{"center", "radius", "material", "transform"};
constexpr std::array<std::string_view, 4> kPlane{"normal", "distance", "material", "transform"};
constexpr std::array<std::string_view, 4> kCylinder{"radius", "height", "material", "transform"};
constexpr std::array<std::string_view, 2> kLight{"position", "intensity"};
constexpr std::array<std::string_view, 7> kMaterial{
    "pigment", "ambient", "diffuse", "specular", "diffuse_k", "specular_k", "reflection"};
constexpr std::array<std::string_view, 5> kTransform{"translate", "scale", "xrotate", "yrotate",
                                                     "zrotate"};

// The entry of `names` equal to `name`: the same text, in static storage.
std::string_view known_name(std::span<const std::string_view> names, std::string_view name) {
    for (std::string_view known : names)
        if (known == name) return known;
    return {};  // never: only known names are recorded
}

bool is_non_finite_word(std::string_view w) {
    std::string lower;
    for (char c : w) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return lower == "nan" || lower == "inf" || lower == "infinity";
}

std::string got(const Value& v) {
    switch (v.form) {
        case Value::Form::number:
            return "the number " + std::string(v.text.substr(0, 40));
        case Value::Form::vector:
            return "the vector " + vector_text(v.vector);
        case Value::Form::string:
            return "the string \"" + std::string(v.text.substr(0, 40)) +
                   (v.text.size() > 40 ? "...\"" : "\"");
        case Value::Form::word:
            return "the word '" + std::string(v.text.substr(0, 40)) + "'";
        default:
            return "nothing";
    }
}

}  // namespace

void PropertyReader::kind_error(const Property& p, std::string_view expected) {
    std::string message =
        quote(p.name) + " takes " + std::string(expected) + ", got " + got(p.value);
    if (p.value.form == Value::Form::word && is_non_finite_word(p.value.text)) {
        message += ": numbers must be finite";
    }
    sink_.error(p.value.span.pos, std::move(message));
}

void PropertyReader::range_error(const Property& p, std::string_view rule) {
    std::string value = p.value.form == Value::Form::vector
                            ? vector_text(p.value.vector)
                            : std::string(p.value.text.substr(0, 40));
    std::string message = quote(p.name) + " " + std::string(rule);
    if (!value.empty()) message += ", got " + value;
    sink_.error(p.value.span.pos, std::move(message));
}

bool PropertyReader::number(const Property& p, double& out) {
    if (p.value.form != Value::Form::number) {
        kind_error(p, "a number like 1.5");
        return false;
    }
    out = p.value.number;
    return true;
}

bool PropertyReader::positive(const Property& p, double& out) {
    double v;
    if (!number(p, v)) return false;
    if (!(v > 0.0)) {
        range_error(p, "must be greater than 0");
        return false;
    }
    out = v;
    return true;
}

bool PropertyReader::whole_number(const Property& p, int& out, double low, double high) {
    if (p.value.form != Value::Form::number) {
        kind_error(p, "a whole number like 640");
        return false;
    }
    double v = std::trunc(p.value.number);  // docs/language.md §3.2: ints truncate toward zero
    if (v < low || v > high) {
        range_error(p,
                    "must be a whole number from " + number_text(low) + " to " + number_text(high));
        return false;
    }
    out = static_cast<int>(v);
    return true;
}

bool PropertyReader::vector(const Property& p, Vec3& out) {
    if (p.value.form != Value::Form::vector) {
        kind_error(p, "a vector like <0, 1, 0>");
        return false;
    }
    out = p.value.vector;
    return true;
}

bool PropertyReader::colour(const Property& p, Colour& out) {
    if (p.value.form != Value::Form::vector) {
        kind_error(p, "a colour like <1, 0.5, 0>");
        return false;
    }
    Colour c = glm::clamp(p.value.vector, 0.0, 1.0);
    if (c != p.value.vector) {
        sink_.warning(p.value.span.pos,
                      quote(p.name) + " " + vector_text(p.value.vector) +
                          " is clipped to the colour range [0, 1]: " + vector_text(c));
    }
    out = c;
    return true;
}

bool PropertyReader::string(const Property& p, std::string& out) {
    if (p.value.form != Value::Form::string) {
        kind_error(p, "a string like \"name\"");
        return false;
    }
    out = std::string(p.value.text);
    return true;
}

int FirstLines::find(std::string_view name) const {
    for (std::size_t i = 0; i < count_; ++i)
        if (inline_[i].first == name) return inline_[i].second;
    for (const auto& [known, line] : more_)
        if (known == name) return line;
    return 0;
}

void FirstLines::add(std::string_view name, int line) {
    if (count_ < inline_capacity)
        inline_[count_++] = {name, line};
    else
        more_.emplace_back(name, line);
}

void PropertyReader::record(OpenBlock& block, const Property& p, std::string_view as_name,
                            bool warn_repeat) {
    if (warn_repeat) {
        int first_line = block.first_lines.find(as_name);
        if (first_line == 0) {
            block.first_lines.add(as_name, p.name_span.pos.line);
        } else if (sink_.accepts_warnings()) {
            sink_.warning(p.name_span.pos, quote(as_name) + " is set again in this " +
                                               quote(block.source.keyword) +
                                               "; the later value wins (first set at line " +
                                               std::to_string(first_line) + ")");
        }
    }
    block.properties.push_back({as_name, p.name_span, p.value.span});
}

void PropertyReader::apply(RenderSettings& s, OpenBlock& block, const Property& p) {
    bool ok = false;
    if (p.name == "width") {
        ok = whole_number(p, s.width, 0, 65535);
    } else if (p.name == "height") {
        ok = whole_number(p, s.height, 0, 65535);
    } else if (p.name == "recurse_depth") {
        double depth;
        if (number(p, depth)) {
            depth = std::trunc(depth);
            if (depth < 0) {
                range_error(p, "must be 0 or more");
            } else {
                if (depth > 256) {
                    sink_.warning(p.value.span.pos, "'recurse_depth' " +
                                                        std::string(p.value.text.substr(0, 40)) +
                                                        " is more than 256: clamped to 256");
                    depth = 256;
                }
                s.recurse_depth = static_cast<int>(depth);
                ok = true;
            }
        }
    } else if (p.name == "filename") {
        ok = string(p, s.filename);
        if (ok && s.filename.empty()) {
            range_error(p, "must not be empty");
            s.filename = RenderSettings{}.filename;
            ok = false;
        }
    } else if (p.name == "active_camera") {
        ok = string(p, s.active_camera);
    } else if (p.name == "background") {
        ok = colour(p, s.background);
    } else if (p.name == "ambient_light") {
        ok = colour(p, s.ambient_light);
    } else if (p.name == "samples") {
        ok = whole_number(p, s.samples, 1, 1024);
    } else {
        sink_.error(p.name_span.pos, unknown_name_message("property", p.name,
                                                          "in 'render_settings'", kRenderSettings));
    }
    if (ok) record(block, p, known_name(kRenderSettings, p.name), true);
}

void PropertyReader::apply(Camera& c, OpenBlock& block, const Property& p) {
    bool ok = false;
    std::string_view as_name = known_name(kCamera, p.name);
    if (p.name == "name") {
        ok = string(p, c.name);
    } else if (p.name == "active_camera") {
        // The manual's own example names a camera this way.
        ok = string(p, c.name);
        as_name = "name";
        if (ok) {
            sink_.warning(p.name_span.pos,
                          "'active_camera' inside a camera is read as 'name'; write name: \"" +
                              c.name.substr(0, 40) + "\"; instead");
        }
    } else if (p.name == "position") {
        ok = vector(p, c.position);
    } else if (p.name == "look_at") {
        ok = vector(p, c.look_at);
    } else if (p.name == "up") {
        ok = vector(p, c.up);
    } else if (p.name == "aspect") {
        ok = positive(p, c.aspect);
    } else if (p.name == "fov") {
        double fov;
        if (number(p, fov)) {
            if (fov > 0.0 && fov < 180.0) {
                c.fov = fov;
                ok = true;
            } else {
                range_error(p, "must be between 0 and 180 degrees (exclusive)");
            }
        }
    } else {
        sink_.error(p.name_span.pos,
                    unknown_name_message("property", p.name, "in 'perspective_camera'", kCamera));
    }
    if (ok) record(block, p, as_name, true);
}

void PropertyReader::apply(Shape& shape, OpenBlock& block, const Property& p) {
    bool ok = false;
    bool known = true;
    if (auto* sphere = std::get_if<Sphere>(&shape)) {
        if (p.name == "center") {
            ok = vector(p, sphere->center);
        } else if (p.name == "radius") {
            ok = positive(p, sphere->radius);
        } else {
            known = false;
            sink_.error(p.name_span.pos,
                        unknown_name_message("property", p.name, "in 'sphere'", kSphere));
        }
    } else if (auto* plane = std::get_if<Plane>(&shape)) {
        if (p.name == "normal") {
            Vec3 normal;
            if (vector(p, normal)) {
                if (normal == Vec3(0.0)) {
                    range_error(p, "must not be the zero vector");
                } else {
                    plane->normal = normal;
                    ok = true;
                }
            }
        } else if (p.name == "distance") {
            ok = number(p, plane->distance);
        } else {
            known = false;
            sink_.error(p.name_span.pos,
                        unknown_name_message("property", p.name, "in 'plane'", kPlane));
        }
    } else if (auto* cylinder = std::get_if<Cylinder>(&shape)) {
        if (p.name == "radius") {
            ok = positive(p, cylinder->radius);
        } else if (p.name == "height") {
            ok = positive(p, cylinder->height);
        } else {
            known = false;
            sink_.error(p.name_span.pos,
                        unknown_name_message("property", p.name, "in 'cylinder'", kCylinder));
        }
    }
    if (ok && known) {
        // Every shape's names are among the sphere's, plane's and cylinder's.
        std::string_view name = known_name(kSphere, p.name);
        if (name.empty()) name = known_name(kPlane, p.name);
        if (name.empty()) name = known_name(kCylinder, p.name);
        record(block, p, name, true);
    }
}

void PropertyReader::apply(Material& m, OpenBlock& block, const Property& p) {
    bool ok = false;
    if (p.name == "pigment") {
        ok = colour(p, m.pigment);
    } else if (p.name == "ambient") {
        ok = colour(p, m.ambient);
    } else if (p.name == "diffuse") {
        ok = colour(p, m.diffuse);
    } else if (p.name == "specular") {
        ok = colour(p, m.specular);
    } else if (p.name == "diffuse_k") {
        ok = positive(p, m.diffuse_k);
    } else if (p.name == "specular_k") {
        ok = positive(p, m.specular_k);
    } else if (p.name == "reflection") {
        double r;
        if (number(p, r)) {
            double clamped = std::clamp(r, 0.0, 1.0);
            if (clamped != r) {
                sink_.warning(p.value.span.pos,
                              "'reflection' " + std::string(p.value.text.substr(0, 40)) +
                                  " is outside 0..1: clamped to " + number_text(clamped));
            }
            m.reflection = clamped;
            ok = true;
        }
    } else {
        sink_.error(p.name_span.pos,
                    unknown_name_message("property", p.name, "in 'material'", kMaterial));
    }
    if (ok) record(block, p, known_name(kMaterial, p.name), true);
}

void PropertyReader::apply(PointLight& light, OpenBlock& block, const Property& p) {
    bool ok = false;
    if (p.name == "position") {
        ok = vector(p, light.position);
    } else if (p.name == "intensity") {
        ok = colour(p, light.intensity);
    } else {
        sink_.error(p.name_span.pos,
                    unknown_name_message("property", p.name, "in 'point_light'", kLight));
    }
    if (ok) record(block, p, known_name(kLight, p.name), true);
}

void PropertyReader::apply(std::vector<TransformOp>& transforms, OpenBlock& block,
                           const Property& p) {
    TransformOp op;
    bool ok = false;
    if (p.name == "translate" || p.name == "scale") {
        op.kind = p.name == "translate" ? TransformKind::translate : TransformKind::scale;
        ok = vector(p, op.vector);
    } else if (p.name == "xrotate" || p.name == "yrotate" || p.name == "zrotate") {
        op.kind = p.name == "xrotate"   ? TransformKind::xrotate
                  : p.name == "yrotate" ? TransformKind::yrotate
                                        : TransformKind::zrotate;
        ok = number(p, op.degrees);
    } else {
        sink_.error(p.name_span.pos,
                    unknown_name_message("property", p.name, "in 'transform'", kTransform));
    }
    if (ok) {
        transforms.push_back(op);
        // Every transform property is an operation: repeats apply, with no warning.
        record(block, p, known_name(kTransform, p.name), false);
    }
}

}  // namespace jt::lang

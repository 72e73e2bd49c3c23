#include "jtracer/source_edit.hpp"

#include "edit/text_edits.hpp"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace jt {

std::string format_jts_number(double value) {
    if (value == 0.0) return "0";  // also turns -0 into 0
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string format_jts_vector(const Vec3& v) {
    // Appended piece by piece: `"<" + std::string&&` trips GCC 12's -Wrestrict.
    std::string text = "<";
    text += format_jts_number(v.x);
    text += ", ";
    text += format_jts_number(v.y);
    text += ", ";
    text += format_jts_number(v.z);
    text += ">";
    return text;
}

namespace {

using edit::TextEdit;

// Collects the edits for one save, then splices them in one go.
class SourceWriter {
  public:
    SourceWriter(std::string_view text, const SceneSource& source) : text_(text), source_(source) {}

    std::span<const PropertySource> properties(const BlockSource& block) const {
        return properties_of(source_, block);
    }
    std::span<const BlockSource> children(const BlockSource& block) const {
        return children_of(source_, block);
    }

    void fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
    }
    const std::string& error() const { return error_; }
    int changed() const { return changed_; }
    std::string result() const { return edit::apply_text_edits(text_, edits_); }

    std::string quoted(const std::string& s) {
        for (char c : s)
            if (c < 0x20 || c > 0x7e || c == '"')
                fail("the text \"" + s + "\" cannot be written in a .jts string");
        return "\"" + s + "\"";
    }

    // The value of the last property named one of `names` across `blocks` (in
    // file order) is the one in force: replace it. False when none is written.
    bool replace_last(const std::vector<const BlockSource*>& blocks,
                      std::initializer_list<std::string_view> names, const std::string& value) {
        const PropertySource* last = nullptr;
        for (const BlockSource* block : blocks)
            for (const PropertySource& p : properties(*block))
                for (std::string_view n : names)
                    if (p.name == n) last = &p;
        if (!last) return false;
        replace(*last, value);
        return true;
    }

    void replace(const PropertySource& property, const std::string& value) {
        edits_.push_back({property.value_span.offset, property.value_span.length, value});
        ++changed_;
    }

    // Writes `name: value;` into `block`, replacing the value in force or
    // inserting the property before the block's closing brace.
    void set(const BlockSource& block, std::string_view name, const std::string& value,
             std::initializer_list<std::string_view> aliases = {}) {
        std::vector<std::string_view> names{name};
        names.insert(names.end(), aliases.begin(), aliases.end());
        const PropertySource* last = nullptr;
        for (const PropertySource& p : properties(block))
            for (std::string_view n : names)
                if (p.name == n) last = &p;
        if (last) {
            replace(*last, value);
            return;
        }
        insert_into(block.close_brace, indent_hint(block),
                    {std::string(name) + ": " + value + ";"});
        ++changed_;
    }

    // Inserts `lines` (one statement each, or the lines of a nested block)
    // just before the closing brace at `close`, in the block's own style: on
    // lines of their own with the indentation of the block's first item when
    // the brace has its own line, otherwise inline before the brace.
    void insert_into(std::size_t close, std::optional<std::size_t> first_item,
                     const std::vector<std::string>& lines) {
        if (edit::starts_its_line(text_, close)) {
            std::string indent;
            if (first_item && edit::starts_its_line(text_, *first_item))
                indent = std::string(edit::line_indent(text_, *first_item));
            else
                indent = std::string(edit::line_indent(text_, close)) + "    ";
            std::string inserted;
            for (const std::string& line : lines) inserted += indent + line + "\n";
            edits_.push_back({edit::line_start(text_, close), 0, inserted});
        } else {
            std::string inserted = close > 0 && text_[close - 1] == ' ' ? "" : " ";
            for (const std::string& line : lines) {
                std::size_t start = line.find_first_not_of(" \t");
                inserted += line.substr(start == std::string::npos ? 0 : start) + " ";
            }
            edits_.push_back({close, 0, inserted});
        }
    }

    // Removes the block from its keyword to its closing brace; whole lines
    // when the block has lines of its own, so no blank line is left behind.
    void remove(const BlockSource& block) {
        std::size_t begin = block.keyword_span.offset;
        std::size_t end = block.close_brace + 1;
        std::size_t after = end;
        while (after < text_.size() && (text_[after] == ' ' || text_[after] == '\t')) ++after;
        if (edit::starts_its_line(text_, begin) &&
            (after == text_.size() || text_[after] == '\n')) {
            begin = edit::line_start(text_, begin);
            end = after < text_.size() ? after + 1 : after;
        } else if (end < text_.size() && text_[end] == ' ') {
            ++end;
        }
        edits_.push_back({begin, end - begin, ""});
        ++changed_;
    }

    void append(const std::string& block_text) {
        std::string inserted = !text_.empty() && text_.back() != '\n' ? "\n" : "";
        edits_.push_back({text_.size(), 0, inserted + "\n" + block_text});
        ++changed_;
    }

    std::string_view text() const { return text_; }
    void count_insertion() { ++changed_; }

    std::optional<std::size_t> indent_hint(const BlockSource& block) const {
        std::optional<std::size_t> first;
        const auto own = properties(block);
        const auto nested = children(block);
        if (!own.empty()) first = own.front().name_span.offset;
        if (!nested.empty() && (!first || nested.front().keyword_span.offset < *first))
            first = nested.front().keyword_span.offset;
        return first;
    }

    // The block's material (or transform) blocks, in file order.
    std::vector<const BlockSource*> children_named(const BlockSource& block,
                                                   std::string_view keyword) const {
        std::vector<const BlockSource*> found;
        for (const BlockSource& child : children(block))
            if (child.keyword == keyword) found.push_back(&child);
        return found;
    }

  private:
    std::string_view text_;
    const SceneSource& source_;
    std::vector<TextEdit> edits_;
    std::string error_;
    int changed_ = 0;
};

// Name/value pairs of the fields that differ, formatted as .jts values.
using Changes = std::vector<std::pair<std::string, std::string>>;

void add_if(Changes& changes, const char* name, double before, double after) {
    if (before != after) changes.emplace_back(name, format_jts_number(after));
}
void add_if(Changes& changes, const char* name, int before, int after) {
    if (before != after) changes.emplace_back(name, std::to_string(after));
}
void add_if(Changes& changes, const char* name, const Vec3& before, const Vec3& after) {
    if (before != after) changes.emplace_back(name, format_jts_vector(after));
}

Changes settings_changes(SourceWriter& w, const RenderSettings& a, const RenderSettings& b) {
    Changes c;
    add_if(c, "width", a.width, b.width);
    add_if(c, "height", a.height, b.height);
    add_if(c, "recurse_depth", a.recurse_depth, b.recurse_depth);
    if (a.filename != b.filename) c.emplace_back("filename", w.quoted(b.filename));
    if (a.active_camera != b.active_camera)
        c.emplace_back("active_camera", w.quoted(b.active_camera));
    add_if(c, "background", a.background, b.background);
    add_if(c, "ambient_light", a.ambient_light, b.ambient_light);
    add_if(c, "samples", a.samples, b.samples);
    return c;
}

Changes camera_changes(SourceWriter& w, const Camera& a, const Camera& b) {
    Changes c;
    if (a.name != b.name) c.emplace_back("name", w.quoted(b.name));
    add_if(c, "position", a.position, b.position);
    add_if(c, "look_at", a.look_at, b.look_at);
    add_if(c, "up", a.up, b.up);
    add_if(c, "aspect", a.aspect, b.aspect);
    add_if(c, "fov", a.fov, b.fov);
    return c;
}

Changes material_changes(const Material& a, const Material& b) {
    Changes c;
    add_if(c, "pigment", a.pigment, b.pigment);
    add_if(c, "ambient", a.ambient, b.ambient);
    add_if(c, "diffuse", a.diffuse, b.diffuse);
    add_if(c, "specular", a.specular, b.specular);
    add_if(c, "diffuse_k", a.diffuse_k, b.diffuse_k);
    add_if(c, "specular_k", a.specular_k, b.specular_k);
    add_if(c, "reflection", a.reflection, b.reflection);
    return c;
}

Changes shape_changes(SourceWriter& w, const Shape& a, const Shape& b) {
    Changes c;
    if (a.index() != b.index()) {
        w.fail("a primitive changed its kind; that cannot be saved in place");
        return c;
    }
    if (auto* sa = std::get_if<Sphere>(&a)) {
        const auto& sb = std::get<Sphere>(b);
        add_if(c, "center", sa->center, sb.center);
        add_if(c, "radius", sa->radius, sb.radius);
    } else if (auto* pa = std::get_if<Plane>(&a)) {
        const auto& pb = std::get<Plane>(b);
        add_if(c, "normal", pa->normal, pb.normal);
        add_if(c, "distance", pa->distance, pb.distance);
    } else if (auto* ca = std::get_if<Cylinder>(&a)) {
        const auto& cb = std::get<Cylinder>(b);
        add_if(c, "radius", ca->radius, cb.radius);
        add_if(c, "height", ca->height, cb.height);
    }
    return c;
}

void write_settings(SourceWriter& w, const SceneSource& source, const Scene& a, const Scene& b) {
    const Changes changes = settings_changes(w, a.settings, b.settings);
    if (changes.empty()) return;
    if (source.render_settings) {
        for (const auto& [name, value] : changes) w.set(*source.render_settings, name, value);
        return;
    }
    std::string block = "render_settings {\n";
    for (const auto& [name, value] : changes) block += "    " + name + ": " + value + ";\n";
    w.append(block + "}\n");
}

std::vector<std::string> camera_lines(SourceWriter& w, const Camera& camera) {
    return {"perspective_camera {",
            "    name: " + w.quoted(camera.name) + ";",
            "    position: " + format_jts_vector(camera.position) + ";",
            "    look_at: " + format_jts_vector(camera.look_at) + ";",
            "    up: " + format_jts_vector(camera.up) + ";",
            "    aspect: " + format_jts_number(camera.aspect) + ";",
            "    fov: " + format_jts_number(camera.fov) + ";",
            "}"};
}

// The offset of the '}' that closes the `cameras` block holding `last_camera`:
// only whitespace and comments can sit between the two.
std::optional<std::size_t> cameras_close(std::string_view text, const BlockSource& last_camera) {
    std::size_t i = last_camera.close_brace + 1;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            ++i;
        } else {
            return c == '}' ? std::optional<std::size_t>(i) : std::nullopt;
        }
    }
    return std::nullopt;
}

void write_cameras(SourceWriter& w, const SceneSource& source, const Scene& a, const Scene& b) {
    if (source.cameras.size() != a.cameras.size()) {
        w.fail("the cameras do not match the text; cannot save in place");
        return;
    }
    // Cameras removed from the end (as undoing a new camera does) lose their blocks.
    const std::size_t kept = std::min(a.cameras.size(), b.cameras.size());
    for (std::size_t i = kept; i < a.cameras.size(); ++i) w.remove(source.cameras[i]);
    for (std::size_t i = 0; i < kept; ++i) {
        for (const auto& [name, value] : camera_changes(w, a.cameras[i], b.cameras[i])) {
            // `active_camera` inside a camera is read as its name (docs/language.md §3.5).
            if (name == "name")
                w.set(source.cameras[i], name, value, {"active_camera"});
            else
                w.set(source.cameras[i], name, value);
        }
    }
    if (b.cameras.size() <= a.cameras.size()) return;
    std::vector<std::string> lines;
    for (std::size_t i = a.cameras.size(); i < b.cameras.size(); ++i) {
        auto more = camera_lines(w, b.cameras[i]);
        lines.insert(lines.end(), more.begin(), more.end());
    }
    if (source.cameras.empty()) {
        std::string block = "cameras {\n";
        for (const auto& line : lines) block += "    " + line + "\n";
        w.append(block + "}\n");
        return;
    }
    const auto close = cameras_close(w.text(), source.cameras.back());
    if (!close) {
        w.fail("cannot find the end of the cameras block");
        return;
    }
    w.insert_into(*close, source.cameras.back().keyword_span.offset, lines);
    w.count_insertion();
}

void write_primitive(SourceWriter& w, const BlockSource& block, const Primitive& a,
                     const Primitive& b) {
    for (const auto& [name, value] : shape_changes(w, a.shape, b.shape)) w.set(block, name, value);

    const auto materials = w.children_named(block, "material");
    std::vector<std::string> unwritten;
    for (const auto& [name, value] : material_changes(a.material, b.material)) {
        if (w.replace_last(materials, {name}, value)) continue;
        if (!materials.empty()) {
            w.set(*materials.back(), name, value);
        } else {
            unwritten.push_back(name + ": " + value + ";");
        }
    }
    if (!unwritten.empty()) {
        std::string line = "material {";
        for (const auto& item : unwritten) line += " " + item;
        w.insert_into(block.close_brace, w.indent_hint(block), {line + " }"});
        w.count_insertion();
    }

    if (a.transforms.size() != b.transforms.size()) {
        w.fail("transform operations were added or removed; that cannot be saved in place");
        return;
    }
    std::vector<const PropertySource*> ops;
    for (const BlockSource* t : w.children_named(block, "transform"))
        for (const PropertySource& p : w.properties(*t)) ops.push_back(&p);
    for (std::size_t i = 0; i < a.transforms.size(); ++i) {
        const TransformOp& before = a.transforms[i];
        const TransformOp& after = b.transforms[i];
        if (before == after) continue;
        if (before.kind != after.kind || i >= ops.size()) {
            w.fail("a transform operation changed its kind; that cannot be saved in place");
            return;
        }
        const bool is_vector =
            after.kind == TransformKind::translate || after.kind == TransformKind::scale;
        const std::string value =
            is_vector ? format_jts_vector(after.vector) : format_jts_number(after.degrees);
        w.replace(*ops[i], value);
    }
}

}  // namespace

SourceEditResult apply_scene_edits(std::string_view text, const SceneSource& source,
                                   const Scene& original, const Scene& edited) {
    SourceEditResult result;
    SourceWriter w(text, source);
    if (original.primitives.size() != edited.primitives.size() ||
        source.primitives.size() != original.primitives.size())
        w.fail("primitives were added or removed; that cannot be saved in place");
    if (original.lights.size() != edited.lights.size() ||
        source.lights.size() != original.lights.size())
        w.fail("lights were added or removed; that cannot be saved in place");
    if (w.error().empty()) {
        write_settings(w, source, original, edited);
        write_cameras(w, source, original, edited);
        for (std::size_t i = 0; i < original.primitives.size(); ++i)
            write_primitive(w, source.primitives[i], original.primitives[i], edited.primitives[i]);
        for (std::size_t i = 0; i < original.lights.size(); ++i) {
            Changes c;
            add_if(c, "position", original.lights[i].position, edited.lights[i].position);
            add_if(c, "intensity", original.lights[i].intensity, edited.lights[i].intensity);
            for (const auto& [name, value] : c) w.set(source.lights[i], name, value);
        }
    }
    result.error = w.error();
    result.text = result.error.empty() ? w.result() : std::string(text);
    result.values_changed = result.error.empty() ? w.changed() : 0;
    return result;
}

}  // namespace jt

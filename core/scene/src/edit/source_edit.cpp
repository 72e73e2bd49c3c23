#include "jtracer/source_edit.hpp"

#include "edit/block_layout.hpp"
#include "edit/text_edits.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/value_text.hpp"

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace jt {

namespace {

using edit::TextEdit;

// A property whose value differs between the original and the edited scene.
struct Change {
    std::string_view name;       // as the schema spells it (a parsed alias is recorded under it)
    std::string text;            // the new value as .jts text
    std::optional<Vec3> vector;  // a vector's new value
    bool unset = false;          // an optional value cleared: its statements go
    std::string line() const { return std::string(name) + ": " + text + ";"; }
};

// A string value that no .jts text can hold (there are no escapes) is a failure.
template <class Block, class Fail>
void check_writable(const PropertySpec<Block>& property, const Block& block, Fail& fail) {
    with_member(property, block, [&](const auto& value) {
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::string>) {
            if (!is_writable_string(value))
                fail("the text \"" + value + "\" cannot be written in a .jts string");
        }
    });
}

// Every string a new block would write.
template <class Block, class Fail>
void check_writable(const Block& block, Fail fail) {
    for (const PropertySpec<Block>& property : schema_of<Block>().properties)
        if (is_written(property, block)) check_writable(property, block, fail);
}

// Each of `properties` that differs between `a` and `b`, in their order.
// `fail` hears of a string that no .jts text can hold.
template <class Block, class Fail>
std::vector<Change> changes(std::span<const PropertySpec<Block>> properties, const Block& a,
                            const Block& b, Fail fail) {
    std::vector<Change> found;
    for (const PropertySpec<Block>& property : properties) {
        if (same_value(property, a, b)) continue;
        Change change{property.name, value_text(property, b), std::nullopt};
        with_member(property, b, [&](const auto& value) {
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, Vec3>) change.vector = value;
            // No .jts text unsets a value: clearing one drops its statements.
            if constexpr (std::is_same_v<T, std::optional<Vec3>>) {
                change.vector = value;
                change.unset = !value;
            }
            if constexpr (std::is_same_v<T, std::optional<double>>) change.unset = !value;
            // An extension's string emptied (a background_map cleared in a
            // panel) is not written, as the serializer leaves it out: `""`
            // would be an error there.
            if constexpr (std::is_same_v<T, std::string>)
                change.unset = value.empty() && !is_written(property, b);
        });
        check_writable(property, b, fail);
        found.push_back(std::move(change));
    }
    return found;
}

// Every property of the block that differs, in schema order.
template <class Block, class Fail>
std::vector<Change> changes(const Block& a, const Block& b, Fail fail) {
    return changes(schema_of<Block>().properties, a, b, fail);
}

// Collects the edits for one save, then splices them in one go.
class SourceWriter {
  public:
    SourceWriter(std::string_view text, const SceneSource& source)
        : text_(text), source_(source), edits_(source.files.size() + 1) {}

    std::span<const PropertySource> properties(const BlockSource& block) const {
        return properties_of(source_, block);
    }
    std::span<const BlockSource> children(const BlockSource& block) const {
        return children_of(source_, block);
    }

    void fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
    }
    auto failure() {
        return [this](std::string message) { fail(std::move(message)); };
    }
    const std::string& error() const { return error_; }
    int changed() const { return changed_; }
    std::string result() const { return edit::apply_text_edits(text_, edits_[0]); }

    // The included files the edits change, each once, by their first reading.
    // A file read several times holds one text: the edits of every reading
    // are made in it, and must agree where they touch the same bytes.
    std::vector<EditedFile> edited_files() {
        std::vector<EditedFile> out;
        for (std::uint32_t f = 1; f < edits_.size(); ++f) {
            if (edits_[f].empty()) continue;
            const SourceFile& file = source_.files[f - 1];
            auto same = [&](const EditedFile& e) {
                return source_.files[e.file - 1].canonical == file.canonical;
            };
            if (std::any_of(out.begin(), out.end(), same)) continue;
            std::vector<TextEdit> all;
            int readings = 0;
            for (std::uint32_t g = f; g < edits_.size(); ++g) {
                if (source_.files[g - 1].canonical != file.canonical) continue;
                ++readings;
                for (const TextEdit& e : edits_[g]) {
                    auto clash = std::find_if(all.begin(), all.end(), [&](const TextEdit& o) {
                        return o.offset < e.offset + e.length && e.offset < o.offset + o.length;
                    });
                    if (clash != all.end() &&
                        (clash->offset != e.offset || clash->length != e.length ||
                         clash->replacement != e.replacement)) {
                        fail("'" + file.name +
                             "' is included several times and the edits of its readings "
                             "differ; edit it in the text");
                        return {};
                    }
                    if (clash == all.end()) all.push_back(e);
                }
            }
            out.push_back(
                {f, file.path, edit::apply_text_edits(file.text, std::move(all)), readings});
        }
        return out;
    }

    // The value of the last property named `change.name` across `blocks` (in
    // file order) is the one in force: replace it. False when none is written.
    // An unset value removes every statement of it across the blocks.
    bool replace_last(const std::vector<const BlockSource*>& blocks, const Change& change) {
        if (change.unset) {
            bool removed = false;
            for (const BlockSource* block : blocks) removed = remove_all(*block, change) || removed;
            return removed;
        }
        const PropertySource* last = nullptr;
        for (const BlockSource* block : blocks)
            for (const PropertySource& p : properties(*block))
                if (p.name == change.name) last = &p;
        if (!last) return false;
        replace(*last, change);
        return true;
    }

    // A vector keeps the text of the components that did not change. A value
    // written as a name or an expression is never replaced by a literal
    // (docs/language.md §15.3): such an edit fails, and the text stays as it was.
    void replace(const PropertySource& property, const Change& change) {
        const TextSpan& span = property.value_span;
        const std::string_view text = text_of(span.pos.file);
        if (property.origin != ValueOrigin::literal) {
            constexpr std::size_t shown = 60;
            std::string written(
                text.substr(span.offset, std::min<std::size_t>(span.length, shown)));
            if (span.length > shown) written += "...";
            // Appended, not concatenated: GCC 12 warns (-Wrestrict) about "'" + s.
            std::string message(1, '\'');
            message.append(property.name)
                .append("' at line ")
                .append(std::to_string(property.name_span.pos.line))
                .append(" is written as ")
                .append(property.origin == ValueOrigin::name ? "the name " : "the expression ")
                .append(written)
                .append("; edit it in the text, not as a value");
            fail(std::move(message));
            return;
        }
        const std::string value =
            change.vector
                ? edited_vector_text(text.substr(span.offset, span.length), *change.vector)
                : change.text;
        edits_of(span.pos.file).push_back({span.offset, span.length, value});
        ++changed_;
    }

    // Writes the change into `block`, replacing the value in force or
    // inserting `name: value;` before the block's closing brace.
    void set(const BlockSource& block, const Change& change) {
        if (change.unset) {
            remove_all(block, change);
            return;
        }
        const PropertySource* last = nullptr;
        for (const PropertySource& p : properties(block))
            if (p.name == change.name) last = &p;
        if (last) {
            replace(*last, change);
            return;
        }
        insert_into(file_of(block), block.close_brace, indent_hint(block), {change.line()});
        ++changed_;
    }

    // Removes every statement of `change.name` in `block` (an earlier one
    // would otherwise come back into force); false when it has none.
    bool remove_all(const BlockSource& block, const Change& change) {
        bool removed = false;
        const std::uint32_t file = file_of(block);
        const std::string_view text = text_of(file);
        for (const PropertySource& p : properties(block))
            if (p.name == change.name) {
                edits_of(file).push_back(
                    edit::removal(text, edit::statement_range(text, p), false));
                removed = true;
            }
        if (removed) ++changed_;
        return removed;
    }

    void insert_into(std::uint32_t file, std::size_t close, std::optional<std::size_t> first_item,
                     const std::vector<std::string>& lines) {
        edits_of(file).push_back(
            edit::insertion_before_close(text_of(file), close, first_item, lines));
    }

    void remove(const BlockSource& block) {
        const std::uint32_t file = file_of(block);
        edits_of(file).push_back(edit::removal(text_of(file), edit::block_range(block), false));
        ++changed_;
    }

    void append(const std::string& block_text) {
        std::string inserted = !text_.empty() && text_.back() != '\n' ? "\n" : "";
        edits_[0].push_back({text_.size(), 0, inserted + "\n" + block_text});
        ++changed_;
    }

    // The text of file `file` (SourcePos::file): a block and all it holds
    // are in one file, the file of its keyword.
    std::string_view text_of(std::uint32_t file) const {
        return file_text(source_.files, text_, file);
    }
    static std::uint32_t file_of(const BlockSource& block) { return block.keyword_span.pos.file; }
    void count_insertion() { ++changed_; }

    std::optional<std::size_t> indent_hint(const BlockSource& block) const {
        return edit::first_item(source_, block);
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
    // Edits of a file no source names (never, for a source parsed from the
    // text) are dropped with a failure rather than written elsewhere.
    std::vector<TextEdit>& edits_of(std::uint32_t file) {
        if (file < edits_.size()) return edits_[file];
        fail("an edited value is in a file the scene does not list");
        discarded_.clear();
        return discarded_;
    }

    std::string_view text_;
    const SceneSource& source_;
    std::vector<std::vector<TextEdit>> edits_;  // per file: [0] the main text's
    std::vector<TextEdit> discarded_;
    std::string error_;
    int changed_ = 0;
};

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

void write_settings(SourceWriter& w, const SceneSource& source, const Scene& a, const Scene& b) {
    const auto found = changes(a.settings, b.settings, w.failure());
    if (found.empty()) return;
    if (source.render_settings) {
        for (const Change& change : found) w.set(*source.render_settings, change);
        return;
    }
    std::string block = std::string(schema_of<RenderSettings>().keyword) + " {\n";
    for (const Change& change : found) block += "    " + change.line() + "\n";
    w.append(block + "}\n");
}

void write_cameras(SourceWriter& w, const SceneSource& source, const Scene& a, const Scene& b) {
    if (source.cameras.size() != a.cameras.size()) {
        w.fail("the cameras do not match the text; cannot save in place");
        return;
    }
    // Cameras removed from the end (as undoing a new camera does) lose their blocks.
    const std::size_t kept = std::min(a.cameras.size(), b.cameras.size());
    for (std::size_t i = kept; i < a.cameras.size(); ++i) w.remove(source.cameras[i]);
    for (std::size_t i = 0; i < kept; ++i)
        for (const Change& change : changes(a.cameras[i], b.cameras[i], w.failure()))
            w.set(source.cameras[i], change);
    if (b.cameras.size() <= a.cameras.size()) return;
    std::vector<std::string> lines;
    for (std::size_t i = a.cameras.size(); i < b.cameras.size(); ++i) {
        check_writable(b.cameras[i], w.failure());
        auto more = block_lines(b.cameras[i]);
        lines.insert(lines.end(), more.begin(), more.end());
    }
    if (source.cameras.empty()) {
        std::string block = "cameras {\n";
        for (const auto& line : lines) block += "    " + line + "\n";
        w.append(block + "}\n");
        return;
    }
    const std::uint32_t file = SourceWriter::file_of(source.cameras.back());
    const auto close = cameras_close(w.text_of(file), source.cameras.back());
    if (!close) {
        w.fail("cannot find the end of the cameras block");
        return;
    }
    w.insert_into(file, *close, source.cameras.back().keyword_span.offset, lines);
    w.count_insertion();
}

void write_primitive(SourceWriter& w, const BlockSource& block, const Primitive& a,
                     const Primitive& b) {
    if (a.shape.index() != b.shape.index()) {
        w.fail("a primitive changed its kind; that cannot be saved in place");
        return;
    }
    visit_shape(
        [&](const auto& before) {
            const auto& after = shape_as<std::decay_t<decltype(before)>>(b.shape);
            for (const Change& change : changes(before, after, w.failure())) w.set(block, change);
        },
        a.shape);

    const auto materials = w.children_named(block, schema_of<Material>().keyword);
    std::vector<std::string> unwritten;
    for (const Change& change : changes(a.material, b.material, w.failure())) {
        if (w.replace_last(materials, change) || change.unset) continue;
        if (!materials.empty()) {
            w.set(*materials.back(), change);
        } else {
            unwritten.push_back(change.line());
        }
    }
    if (!unwritten.empty()) {
        std::string line = std::string(schema_of<Material>().keyword) + " {";
        for (const auto& item : unwritten) line += " " + item;
        w.insert_into(SourceWriter::file_of(block), block.close_brace, w.indent_hint(block),
                      {line + " }"});
        w.count_insertion();
    }

    if (a.transforms.size() != b.transforms.size()) {
        w.fail("transform operations were added or removed; that cannot be saved in place");
        return;
    }
    std::vector<const PropertySource*> ops;
    for (const BlockSource* t : w.children_named(block, kTransformKeyword))
        for (const PropertySource& p : w.properties(*t)) ops.push_back(&p);
    for (std::size_t i = 0; i < a.transforms.size(); ++i) {
        const TransformOp& before = a.transforms[i];
        const TransformOp& after = b.transforms[i];
        if (before == after) continue;
        if (before.kind != after.kind || i >= ops.size()) {
            w.fail("a transform operation changed its kind; that cannot be saved in place");
            return;
        }
        const PropertySpec<TransformOp>& property = transform_op(after.kind).property;
        for (const Change& change : changes(std::span(&property, 1), before, after, w.failure()))
            w.replace(*ops[i], change);
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
        for (std::size_t i = 0; i < original.lights.size(); ++i)
            for (const Change& change : changes(original.lights[i], edited.lights[i], w.failure()))
                w.set(source.lights[i], change);
    }
    if (w.error().empty()) result.files = w.edited_files();
    result.error = w.error();
    if (!result.error.empty()) result.files.clear();
    result.text = result.error.empty() ? w.result() : std::string(text);
    result.values_changed = result.error.empty() ? w.changed() : 0;
    return result;
}

}  // namespace jt

#include "language/kept_includes.hpp"

#include "jtracer/check.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/source_map.hpp"
#include "language/diagnostic_sink.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace jt::lang {

namespace {

// Where an include of the main text stands, which says what it may give.
enum class Context : std::uint8_t {
    top,        // at the top level: definitions and whole blocks
    cameras,    // directly in a `cameras` block: cameras
    scene,      // directly in the `scene` block in use: objects and lights
    discarded,  // in a `scene` block a later one replaced: nothing
};

struct MainInclude {
    SourcePos at;              // the opening quote of its string
    std::string_view written;  // its string, quotes included
    Context context = Context::top;
};

// The include statements of the main text, in order. The text parsed without
// errors, so a brace count is its block structure: an include stands at
// depth 0 or directly in a block at depth 1. `scene_brace`: the offset of
// the '{' of the scene block in use, when the main text holds it.
std::vector<MainInclude> main_includes(std::string_view text,
                                       std::optional<std::uint32_t> scene_brace) {
    DiagnosticSink sink;
    Lexer lexer(text, sink);
    std::vector<MainInclude> out;
    int depth = 0;
    std::string_view word;  // the last word at depth 0: the keyword before a '{'
    Context inside = Context::top;
    bool after_include = false;
    for (Token token; lexer.next(token), token.kind != TokenKind::end;) {
        if (after_include && token.kind == TokenKind::string)
            out.push_back({token.pos, text.substr(token.offset, token.length),
                           depth == 0 ? Context::top : inside});
        after_include = token.kind == TokenKind::word && token.text == kIncludeKeyword;
        if (token.kind == TokenKind::word && depth == 0) word = token.text;
        if (token.kind == TokenKind::lbrace && depth++ == 0) {
            inside = Context::top;
            if (word == kCamerasKeyword) inside = Context::cameras;
            if (word == kSceneKeyword)
                inside = scene_brace == token.offset ? Context::scene : Context::discarded;
        }
        if (token.kind == TokenKind::rbrace) --depth;
    }
    return out;
}

// How many `keyword { }` blocks a file's text holds at its top level.
std::size_t top_level_blocks(std::string_view text, std::string_view keyword) {
    DiagnosticSink sink;
    Lexer lexer(text, sink);
    std::size_t n = 0;
    int depth = 0;
    for (Token token; lexer.next(token), token.kind != TokenKind::end;) {
        if (token.kind == TokenKind::word && depth == 0 && token.text == keyword) ++n;
        if (token.kind == TokenKind::lbrace) ++depth;
        if (token.kind == TokenKind::rbrace) --depth;
    }
    return n;
}

// One item of the canonical layout.
struct Item {
    enum class Kind : std::uint8_t { top, camera, object };
    Placement* place = nullptr;  // none for the end of a block
    std::uint32_t owner = 0;  // the reading of a main text include that gave it; 0: the main text
    bool unchanged = true;
    Kind kind = Kind::top;
    std::uint32_t block_owner = 0;  // a camera's or an object's: the owner of its block
};

bool set_by(std::span<const Define> defines, std::string_view name) {
    for (const Define& d : defines)
        if (d.name == name) return true;
    return false;
}

// The items of the layout in its order, each owned by the include of the
// main text it came from. An item of the text that `scene` no longer has
// leaves its owner in `changed`.
class Layout {
  public:
    Layout(const ParseResult& parsed, std::size_t readings) : parsed_(parsed), top_(readings + 1) {
        // A file is read from one read before it (SourceFile::included_at):
        // each reading is seen through the main text's include it is under.
        for (std::uint32_t file = 1; file <= readings; ++file) {
            const std::uint32_t from = parsed.source.files[file - 1].included_at.file;
            JT_DCHECK(from < file, "a file is included from one read before it");
            top_[file] = from == 0 ? file : from < file ? top_[from] : 0;
        }
    }

    // The reading of the main text include that file `file` was read under.
    std::uint32_t owner(std::uint32_t file) const { return file < top_.size() ? top_[file] : 0; }
    std::uint32_t owner(const TextSpan& span) const { return owner(span.pos.file); }

    // Every item of `scene` against the parse, into `plan`.
    std::vector<Item> items(const Scene& scene, std::span<const Define> defines,
                            const std::vector<MainInclude*>& includes, IncludePlan& plan,
                            std::vector<bool>& changed) const;

  private:
    // The include that gave every one of `blocks`, when one at the top level did.
    std::uint32_t whole(const std::vector<BlockSource>& blocks,
                        const std::vector<MainInclude*>& includes) const {
        if (blocks.empty()) return 0;
        const std::uint32_t first = owner(blocks.front().keyword_span);
        for (const BlockSource& block : blocks)
            if (owner(block.keyword_span) != first) return 0;
        return first != 0 && includes[first] && includes[first]->context == Context::top ? first
                                                                                         : 0;
    }

    const ParseResult& parsed_;
    std::vector<std::uint32_t> top_;  // by SourcePos::file: the main text include it is under
};

std::vector<Item> Layout::items(const Scene& scene, std::span<const Define> defines,
                                const std::vector<MainInclude*>& includes, IncludePlan& plan,
                                std::vector<bool>& changed) const {
    const SceneSource& source = parsed_.source;
    const Scene& then = parsed_.scene;
    std::vector<Item> items;
    for (std::size_t i = 0; i < source.definitions.size(); ++i) {
        const DefinitionSource& d = source.definitions[i];
        // A --define stands in the place of the text's definition.
        const bool unchanged = d.material_properties || !set_by(defines, d.name);
        items.push_back({&plan.definitions[i], owner(d.name_span), unchanged, Item::Kind::top});
    }
    const std::uint32_t settings =
        source.render_settings ? owner(source.render_settings->keyword_span) : 0;
    items.push_back({&plan.settings, settings, scene.settings == then.settings, Item::Kind::top});

    // A list of blocks: the scene's, each against the one parsed at its index.
    auto blocks = [&](const auto& now, const auto& was, const std::vector<BlockSource>& where,
                      std::vector<Placement>& places, Item::Kind kind, std::uint32_t block) {
        for (std::size_t i = 0; i < now.size(); ++i)
            items.push_back({&places[i], i < where.size() ? owner(where[i].keyword_span) : 0,
                             i < was.size() && now[i] == was[i], kind, block});
        for (std::size_t i = now.size(); i < where.size(); ++i)
            changed[owner(where[i].keyword_span)] = true;
    };
    const std::uint32_t cameras = whole(source.cameras, includes);
    items.push_back({&plan.cameras_block, cameras, true, Item::Kind::top});
    blocks(scene.cameras, then.cameras, source.cameras, plan.cameras, Item::Kind::camera, cameras);
    items.push_back({nullptr, cameras, true, Item::Kind::top});

    const std::uint32_t whole_scene = source.scene ? owner(source.scene->keyword_span) : 0;
    items.push_back({&plan.scene_block, whole_scene, true, Item::Kind::top});
    blocks(scene.primitives, then.primitives, source.primitives, plan.primitives,
           Item::Kind::object, whole_scene);
    blocks(scene.lights, then.lights, source.lights, plan.lights, Item::Kind::object, whole_scene);
    items.push_back({nullptr, whole_scene, true, Item::Kind::top});
    return items;
}

}  // namespace

IncludePlan plan_includes(const Scene& scene, const ParseResult& parsed, std::string_view main_text,
                          std::span<const Define> defines) {
    const SceneSource& source = parsed.source;
    IncludePlan plan;
    plan.definitions.resize(source.definitions.size());
    plan.cameras.resize(scene.cameras.size());
    plan.primitives.resize(scene.primitives.size());
    plan.lights.resize(scene.lights.size());
    if (source.files.empty()) return plan;

    // The main text's includes, by the SourcePos::file of the reading each made.
    std::optional<std::uint32_t> scene_brace;
    if (source.scene && source.scene->keyword_span.pos.file == 0)
        scene_brace = source.scene->open_brace;
    std::vector<MainInclude> found = main_includes(main_text, scene_brace);
    const std::size_t readings = source.files.size();
    // Both are in the main text's order.
    std::vector<MainInclude*> includes(readings + 1, nullptr);
    auto next = found.begin();
    for (std::uint32_t file = 1; file <= readings; ++file) {
        const SourcePos at = source.files[file - 1].included_at;
        if (at.file != 0) continue;
        while (next != found.end() && (next->at.line != at.line || next->at.column != at.column))
            ++next;
        // A reading the scan cannot place: no include is kept, all is written.
        if (next == found.end()) return plan;
        includes[file] = &*next++;
    }

    const Layout layout(parsed, readings);
    std::vector<bool> changed(readings + 1, false);
    const std::vector<Item> items = layout.items(scene, defines, includes, plan, changed);

    std::vector<std::size_t> first(readings + 1, items.size()), last(readings + 1, 0),
        count(readings + 1, 0);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const Item& item = items[i];
        if (item.owner == 0) continue;
        if (!item.unchanged) changed[item.owner] = true;
        if (count[item.owner]++ == 0) first[item.owner] = i;
        last[item.owner] = i;
    }
    // A kept include gives again every block its files hold, those a later
    // block replaced too. A replaced render_settings block, given again after
    // the one in use (written at its item), would replace that one.
    std::vector<std::size_t> replaced_settings(readings + 1, 0);
    for (std::uint32_t file = 1; file <= readings; ++file)
        replaced_settings[layout.owner(file)] +=
            top_level_blocks(source.files[file - 1].text, schema_of<RenderSettings>().keyword);
    if (source.render_settings) {
        std::size_t& in_use = replaced_settings[layout.owner(source.render_settings->keyword_span)];
        if (in_use > 0) --in_use;
    }
    const std::size_t settings_item = source.definitions.size();  // Layout::items's order
    JT_DCHECK(items[settings_item].place == &plan.settings, "the settings follow the definitions");

    for (std::uint32_t file = 1; file <= readings; ++file) {
        if (!includes[file] || count[file] == 0 || changed[file] ||
            last[file] - first[file] + 1 != count[file] ||
            (replaced_settings[file] > 0 && first[file] > settings_item))
            continue;
        // Where the include stands, it may give only what stands there: at
        // the top level whole blocks (a camera or an object only inside a
        // block it gives whole), in a block only that block's entries.
        const Context context = includes[file]->context;
        bool fits = true;
        for (std::size_t i = first[file]; i <= last[file]; ++i) {
            const Item::Kind kind = items[i].kind;
            if (context == Context::top)
                fits = fits && (kind == Item::Kind::top || items[i].block_owner == file);
            if (context == Context::cameras) fits = fits && kind == Item::Kind::camera;
            if (context == Context::scene) fits = fits && kind == Item::Kind::object;
            if (context == Context::discarded) fits = false;
        }
        if (!fits) continue;
        for (std::size_t i = first[file]; i <= last[file]; ++i)
            if (items[i].place) items[i].place->covered = true;
        if (Placement* place = items[first[file]].place) place->include = includes[file]->written;
    }
    return plan;
}

}  // namespace jt::lang

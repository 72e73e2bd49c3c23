// A large scene block read in parts, each on a thread of its own
// (scene_parts.hpp): where parts may begin, how a part is read, and how the
// parser takes what a part read.

#include "language/scene_parts.hpp"

#include "io/page_warmer.hpp"
#include "io/reserve_records.hpp"
#include "jtracer/schema.hpp"
#include "language/lexer.hpp"
#include "language/scene_parser.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <iterator>
#include <thread>
#include <utility>
#include <vector>

namespace jt::lang {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// The offset of a primitive's or a light's keyword that the '{' at `brace`
// follows (blanks between), standing alone as a word; npos for anything else.
std::size_t scene_block_keyword(std::string_view text, std::size_t brace) {
    std::size_t end = brace;
    while (end > 0 && is_space(text[end - 1])) --end;
    std::size_t begin = end;
    while (begin > 0 && is_word_char(text[begin - 1])) --begin;
    const std::string_view word = text.substr(begin, end - begin);
    if (std::find(scene_blocks().begin(), scene_blocks().end(), word) == scene_blocks().end())
        return std::string_view::npos;
    return begin;
}

// The first such keyword whose '{' lies at or after `from`.
std::size_t next_scene_block(std::string_view text, std::size_t from) {
    std::size_t at = from;
    while (at < text.size()) {
        const void* brace = std::memchr(text.data() + at, '{', text.size() - at);
        if (brace == nullptr) return std::string_view::npos;
        at = static_cast<std::size_t>(static_cast<const char*>(brace) - text.data());
        const std::size_t keyword = scene_block_keyword(text, at);
        if (keyword != std::string_view::npos && keyword >= from) return keyword;
        ++at;
    }
    return std::string_view::npos;
}

// Moves the elements of `from` to the end of `to`, and frees `from`'s memory.
template <class T>
void append_moved(std::vector<T>& to, std::vector<T>& from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
    from = std::vector<T>();  // `= {}` would keep the memory
}

}  // namespace

unsigned scene_part_count(std::size_t bytes, unsigned threads) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t by_size = bytes / kSceneBytesPerPart;
    return static_cast<unsigned>(
        std::max<std::size_t>(1, std::min<std::size_t>({threads, kMaxSceneParts, by_size})));
}

std::vector<std::size_t> guess_scene_part_starts(std::string_view text, std::size_t from,
                                                 unsigned parts) {
    std::vector<std::size_t> starts;
    if (from >= text.size()) return starts;
    const std::size_t length = text.size() - from;
    for (unsigned k = 1; k < parts; ++k) {
        std::size_t target = from + length / parts * k;
        if (!starts.empty()) target = std::max(target, starts.back() + 1);
        const std::size_t start = next_scene_block(text, target);
        if (start == std::string_view::npos) break;
        starts.push_back(start);
    }
    return starts;
}

void SceneParser::start_scene_parts(ScenePartThreads& parts, std::size_t hint) {
    if (!keep_primitives_ || earlier_ || record_readings_ || reading_ != &lexer_) return;
    const std::size_t from = cur_->offset;
    const std::size_t bytes = text_.size() - from;
    const unsigned count = scene_part_count(bytes, options_.threads);
    if (count < 2) return;
    std::vector<std::size_t> starts = guess_scene_part_starts(text_, from, count);
    if (starts.empty()) return;
    std::vector<ScenePart> planned(starts.size());
    for (std::size_t i = 0; i < starts.size(); ++i) {
        planned[i].begin = starts[i];
        planned[i].end = i + 1 < starts.size() ? starts[i + 1] : text_.size();
    }
    const std::string_view text = text_;
    const ParseOptions& options = options_;
    // A copy each, made here: an include the parser meets in the first part
    // may still mark this table while the parts are read.
    const NameTable names = names_;
    const std::atomic<bool>& cancelled = parts.cancelled();
    const std::size_t properties = property_hint_;
    parts.start(std::move(planned), [=, &options, &cancelled](ScenePart& part) {
        // The whole text's counts, shared out by size with an eighth to spare:
        // arrays that grow as they go take 4 KiB page faults, 18 us each here.
        const double share =
            1.125 * static_cast<double>(part.end - part.begin) / static_cast<double>(bytes);
        const auto hint_for_part = [share](std::size_t count) {
            return static_cast<std::size_t>(static_cast<double>(count) * share) + 1;
        };
        try {
            SceneParser reader(text, options, names, part.begin);
            reader.read_scene_part(part, hint_for_part(hint), hint_for_part(properties), cancelled);
        } catch (const std::exception&) {
            part.usable = false;  // read again by the parser, which reports what it meets
        }
    });
}

void SceneParser::read_scene_part(ScenePart& part, std::size_t blocks, std::size_t properties,
                                  const std::atomic<bool>& cancelled) {
    SceneChildren& children = part.children;
    const std::size_t per_array = std::min(blocks, kPartArrayPrimitives);
    reserve_records(children.primitives, per_array);
    if (source_map_) {
        reserve_records(children.primitive_sources, blocks);
        reserve_records(result_.source.children, blocks);
        reserve_records(result_.source.properties, properties);
    }
    PageWarmer unused;
    for (;;) {
        if (sink_.any() || cancelled.load(std::memory_order_relaxed)) return;
        if (at(TokenKind::rbrace) || (at(TokenKind::word) && cur_->offset >= part.end)) break;
        if (!at(TokenKind::word) || next_->kind != TokenKind::lbrace) return;
        if (children.primitives.size() == children.primitives.capacity()) {
            part.filled.push_back(std::move(children.primitives));
            reserve_records(children.primitives, per_array);
        }
        parse_scene_child(children, unused);
    }
    part.properties = std::move(result_.source.properties);
    part.nested = std::move(result_.source.children);
    part.reads_clock = result_.reads_clock || expressions_.read_clock();
    part.stop = cur_->offset;
    part.stop_pos = cur_->pos;
    part.usable = true;
}

bool SceneParser::take_scene_part(ScenePartThreads& parts, SceneChildren& into) {
    // In an included file, offsets are into another text.
    if (parts.empty() || reading_ != &lexer_) return false;
    ScenePart* part = parts.take_at(cur_->offset);
    if (part == nullptr || !part->usable) return false;
    SceneChildren& read = part->children;
    const auto property_base = static_cast<std::uint32_t>(result_.source.properties.size());
    const auto nested_base = static_cast<std::uint32_t>(result_.source.children.size());
    for (BlockSource& b : part->nested) b.properties.first += property_base;
    for (BlockSource& b : read.primitive_sources) {
        b.properties.first += property_base;
        b.children.first += nested_base;
    }
    for (BlockSource& b : read.light_sources) b.properties.first += property_base;
    append_moved(result_.source.properties, part->properties);
    append_moved(result_.source.children, part->nested);
    append_moved(into.primitive_sources, read.primitive_sources);
    append_moved(into.light_sources, read.light_sources);
    append_moved(into.lights, read.lights);
    part->filled.push_back(std::move(read.primitives));
    for (std::vector<Primitive>& array : part->filled) append_moved(into.primitives, array);
    into.placed = into.primitives.size();
    read = {};
    result_.reads_clock = result_.reads_clock || part->reads_clock;
    ++result_.scene_parts_taken;
    lexer_.resume_at(part->stop, part->stop_pos);
    lexer_.next(*cur_);
    lexer_.next(*next_);
    return true;
}

}  // namespace jt::lang

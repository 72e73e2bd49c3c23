#include "language/scene_parts.hpp"

#include "jtracer/schema.hpp"
#include "language/lexer.hpp"

#include <algorithm>
#include <cstring>
#include <thread>

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

}  // namespace jt::lang

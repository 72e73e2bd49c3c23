#include "edit/text_edits.hpp"

#include "jtracer/check.hpp"

#include <algorithm>
#include <numeric>

namespace jt::edit {

std::string apply_text_edits(std::string_view text, std::vector<TextEdit> edits) {
    // Apply back to front; among equal offsets the later-given goes first, so
    // that the earlier-given ends up in front of it.
    std::vector<std::size_t> order(edits.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (edits[a].offset != edits[b].offset) return edits[a].offset > edits[b].offset;
        return a > b;
    });
    if constexpr (kContractsChecked) {
        // In back-to-front order, each replaced range ends before the one applied before it.
        std::size_t limit = std::string_view::npos;
        for (std::size_t i : order) {
            if (edits[i].length == 0) continue;
            JT_DCHECK(edits[i].offset + edits[i].length <= limit,
                      "edits replace no byte another edit replaces");
            limit = edits[i].offset;
        }
    }
    std::string out(text);
    for (std::size_t i : order) {
        const TextEdit& e = edits[i];
        if (e.offset > out.size()) continue;
        out.replace(e.offset, std::min(e.length, out.size() - e.offset), e.replacement);
    }
    return out;
}

std::size_t line_start(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    const std::size_t newline = offset == 0 ? std::string_view::npos : text.rfind('\n', offset - 1);
    return newline == std::string_view::npos ? 0 : newline + 1;
}

std::string_view line_indent(std::string_view text, std::size_t offset) {
    const std::size_t start = line_start(text, offset);
    std::size_t end = start;
    while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
    return text.substr(start, end - start);
}

bool starts_its_line(std::string_view text, std::size_t offset) {
    const std::size_t start = line_start(text, offset);
    for (std::size_t i = start; i < offset && i < text.size(); ++i)
        if (text[i] != ' ' && text[i] != '\t') return false;
    return true;
}

}  // namespace jt::edit

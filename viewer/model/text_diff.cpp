#include "model/text_diff.hpp"

#include <algorithm>
#include <cstdint>

namespace jt::view {

namespace {

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// Every line of both, in order: the longest common subsequence of the
// middles (a table of lengths, which kMaxDiffCells bounds), else all of
// `a`'s middle removed and `b`'s added.
std::vector<DiffLine> all_lines(const std::vector<std::string_view>& a,
                                const std::vector<std::string_view>& b, bool& coarse) {
    std::size_t prefix = 0;
    while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix]) ++prefix;
    std::size_t suffix = 0;
    while (suffix < a.size() - prefix && suffix < b.size() - prefix &&
           a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix])
        ++suffix;
    const std::size_t n = a.size() - prefix - suffix, m = b.size() - prefix - suffix;
    std::vector<DiffLine> out;
    int old_line = 0, new_line = 0;
    const auto same = [&](std::string_view text) {
        out.push_back({DiffLine::Kind::same, std::string(text), ++old_line, ++new_line});
    };
    const auto removed = [&](std::string_view text) {
        out.push_back({DiffLine::Kind::removed, std::string(text), ++old_line, 0});
    };
    const auto added = [&](std::string_view text) {
        out.push_back({DiffLine::Kind::added, std::string(text), 0, ++new_line});
    };
    for (std::size_t i = 0; i < prefix; ++i) same(a[i]);
    coarse = n > 0 && m > 0 && (n + 1) * (m + 1) > kMaxDiffCells;
    if (coarse) {
        for (std::size_t i = 0; i < n; ++i) removed(a[prefix + i]);
        for (std::size_t j = 0; j < m; ++j) added(b[prefix + j]);
    } else {
        // lcs[i][j]: the common subsequence of a's middle from i and b's from j.
        std::vector<std::uint32_t> lcs((n + 1) * (m + 1), 0);
        const auto at = [&](std::size_t i, std::size_t j) -> std::uint32_t& {
            return lcs[i * (m + 1) + j];
        };
        for (std::size_t i = n; i-- > 0;)
            for (std::size_t j = m; j-- > 0;)
                at(i, j) = a[prefix + i] == b[prefix + j] ? at(i + 1, j + 1) + 1
                                                          : std::max(at(i + 1, j), at(i, j + 1));
        std::size_t i = 0, j = 0;
        while (i < n || j < m) {
            if (i < n && j < m && a[prefix + i] == b[prefix + j]) {
                same(a[prefix + i]);
                ++i, ++j;
            } else if (i < n && (j == m || at(i + 1, j) >= at(i, j + 1))) {
                removed(a[prefix + i++]);  // as diff -u: a change's old lines first
            } else {
                added(b[prefix + j++]);
            }
        }
    }
    for (std::size_t k = a.size() - suffix; k < a.size(); ++k) same(a[k]);
    return out;
}

}  // namespace

TextDiff diff_lines(std::string_view old_text, std::string_view new_text, int context) {
    TextDiff diff;
    const std::vector<DiffLine> lines =
        all_lines(split_lines(old_text), split_lines(new_text), diff.coarse);
    // Keep the changes and the `context` lines either side of each.
    std::vector<bool> keep(lines.size(), false);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].kind == DiffLine::Kind::same) continue;
        (lines[i].kind == DiffLine::Kind::removed ? diff.removed : diff.added) += 1;
        const std::size_t from = i >= static_cast<std::size_t>(context) ? i - context : 0;
        const std::size_t to = std::min(lines.size(), i + static_cast<std::size_t>(context) + 1);
        std::fill(keep.begin() + static_cast<long>(from), keep.begin() + static_cast<long>(to),
                  true);
    }
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (keep[i]) diff.lines.push_back(lines[i]);
    return diff;
}

}  // namespace jt::view

#include "model/text_diff.hpp"

#include "model/common_ends.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>

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

enum class Step : char { same, removed, added };

// The shortest edit script from a to b (Myers, "An O(ND) difference
// algorithm"): quick when the texts share most lines, however long they
// are. Gives up (nothing) once the paths it keeps, or the lines it compares,
// pass `budget`: the texts differ in too many places to list line by line.
std::optional<std::vector<Step>> shortest_edit(std::span<const std::string_view> a,
                                               std::span<const std::string_view> b,
                                               std::size_t budget) {
    const long n = static_cast<long>(a.size()), m = static_cast<long>(b.size());
    const long most = n + m;
    // v[most + k]: how far along a the furthest path on diagonal k (x - y) reaches.
    std::vector<long> v(static_cast<std::size_t>(2 * most + 2), 0);
    std::vector<std::vector<long>> trace;  // v[-d..d] after each round d, to walk back
    std::size_t spent = 0;
    long d = 0;
    for (bool done = false; !done; ++d) {
        for (long k = -d; k <= d; k += 2) {
            const bool down = k == -d || (k != d && v[most + k - 1] < v[most + k + 1]);
            long x = down ? v[most + k + 1] : v[most + k - 1] + 1;
            long y = x - k;
            while (x < n && y < m && a[x] == b[y]) ++x, ++y;
            spent += static_cast<std::size_t>(x - (down ? v[most + k + 1] : v[most + k - 1] + 1));
            v[most + k] = x;
            if (x >= n && y >= m) done = true;
        }
        trace.emplace_back(v.begin() + (most - d), v.begin() + (most + d + 1));
        spent += static_cast<std::size_t>(2 * d + 1);
        if (!done && spent > budget) return std::nullopt;
    }
    // Back from the end, one round at a time.
    std::vector<Step> steps;
    long x = n, y = m;
    for (long round = d - 1; round > 0; --round) {
        const std::vector<long>& before = trace[static_cast<std::size_t>(round - 1)];
        const auto at = [&](long k) { return before[static_cast<std::size_t>(k + round - 1)]; };
        const long k = x - y;
        const bool down = k == -round || (k != round && at(k - 1) < at(k + 1));
        const long from_k = down ? k + 1 : k - 1;
        const long from_x = at(from_k), from_y = from_x - from_k;
        for (; x > (down ? from_x : from_x + 1); --x, --y) steps.push_back(Step::same);
        steps.push_back(down ? Step::added : Step::removed);
        x = from_x;
        y = from_y;
    }
    for (; x > 0; --x) steps.push_back(Step::same);  // round 0: the common start
    std::reverse(steps.begin(), steps.end());
    // As diff -u shows a change: its old lines first, then its new ones.
    for (std::size_t i = 0; i < steps.size();) {
        if (steps[i] == Step::same) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < steps.size() && steps[end] != Step::same) ++end;
        std::stable_partition(steps.begin() + static_cast<long>(i),
                              steps.begin() + static_cast<long>(end),
                              [](Step s) { return s == Step::removed; });
        i = end;
    }
    return steps;
}

// Every line of both, in order: the longest common subsequence of the
// middles (a table of lengths, which kMaxDiffCells bounds), else the
// shortest edit script while it stays short; else all of `a`'s middle
// removed and `b`'s added.
std::vector<DiffLine> all_lines(const std::vector<std::string_view>& a,
                                const std::vector<std::string_view>& b, bool& coarse) {
    const auto [prefix, tail, suffix] = common_ends(a, b);
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
    const bool large = n > 0 && m > 0 && (n + 1) * (m + 1) > kMaxDiffCells;
    const std::optional<std::vector<Step>> steps =
        large ? shortest_edit(std::span(a).subspan(prefix, n), std::span(b).subspan(prefix, m),
                              kMaxEditWork)
              : std::nullopt;
    coarse = large && !steps;
    if (steps) {
        std::size_t i = prefix, j = prefix;
        for (const Step step : *steps) {
            if (step == Step::same) {
                same(a[i++]);
                ++j;
            } else if (step == Step::removed) {
                removed(a[i++]);
            } else {
                added(b[j++]);
            }
        }
    } else if (coarse) {
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

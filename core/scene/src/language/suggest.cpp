#include "language/suggest.hpp"

#include "jtracer/schema.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace jt::lang {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Optimal string alignment: insertions, deletions, substitutions and
    // transpositions of neighbours ("widht") each cost one.
    const std::size_t n = b.size();
    std::vector<std::size_t> before(n + 1), previous(n + 1), row(n + 1);
    for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= n; ++j) {
            std::size_t cost = a[i - 1] != b[j - 1];
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                row[j] = std::min(row[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, row);
    }
    return previous[n];
}

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    return out;
}

// A POV-Ray user's words, too far from ours to be taken for a typo.
// Blocks and properties apart: 'pigment:' in a sphere is no material.
struct PovWord {
    std::string_view what, pov, ours;
};
constexpr PovWord kPovRay[] = {
    {"block", "declare", "define"},
    {"block", "local", "define"},
    {"block", "light_source", "point_light"},
    {"block", "finish", "material"},
    {"block", "pigment", "material"},
    {"block", "texture", "material"},
    {"block", "camera", "perspective_camera"},
    {"property", "location", "position"},
    {"property", "angle", "fov"},
};

}  // namespace

std::string_view pov_ray_word(std::string_view what, std::string_view word) {
    for (const PovWord& w : kPovRay)
        if (what == w.what && word == w.pov) return w.ours;
    return {};
}

std::string_view nearest_name(std::string_view word, std::span<const std::string_view> allowed) {
    if (word.size() > 64) return {};
    const std::string folded = lower(word);
    std::string_view best;
    std::size_t best_distance = 0;
    for (std::string_view name : allowed) {
        // A name this much longer is never suggested (its distance is at
        // least the difference of lengths, over the limit below), nor kept
        // out a shorter one that would be: skipping it changes nothing but
        // the time, which for defined names of a megabyte would outweigh the
        // parse.
        if (name.size() > 2 * word.size() + 3) continue;
        std::size_t d = edit_distance(folded, name);
        if (best.empty() || d < best_distance) {
            best = name;
            best_distance = d;
        }
    }
    // A typo changes a few letters; beyond a third of the word it is another word.
    std::size_t limit = std::max<std::size_t>(1, std::max(word.size(), best.size()) / 3);
    return best_distance <= limit ? best : std::string_view{};
}

std::string listed(std::span<const std::string_view> names, std::string_view last) {
    // Built with append: GCC 12 warns falsely on "literal" + std::string&& (quote.hpp).
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0 && i + 1 == names.size())
            out.append(1, ' ').append(last).append(1, ' ');
        else if (i > 0)
            out += ", ";
        out += names[i];
    }
    return out;
}

std::string takes_no_message(std::string_view light_keyword, std::string_view word) {
    std::string out = "a ";
    out.append(light_keyword).append(" takes no '").append(word).append("': only ");
    return out.append(listed(shape_keywords(), "and")).append(" do");
}

std::string unknown_name_message(std::string_view what, std::string_view word,
                                 std::string_view where,
                                 std::span<const std::string_view> allowed) {
    std::string message = "unknown " + std::string(what) + " '" + std::string(word.substr(0, 40)) +
                          "' " + std::string(where);
    std::string_view nearest = nearest_name(word, allowed);
    if (!nearest.empty()) {
        message += "; did you mean '" + std::string(nearest) + "'?";
    } else {
        const std::string_view ours = pov_ray_word(what, word);
        if (!ours.empty() && std::find(allowed.begin(), allowed.end(), ours) != allowed.end())
            message +=
                "; POV-Ray's '" + std::string(word) + "' is '" + std::string(ours) + "' here";
    }
    message += " (allowed: ";
    for (std::size_t i = 0; i < allowed.size(); ++i) {
        if (i) message += ", ";
        message += allowed[i];
    }
    return message + ")";
}

}  // namespace jt::lang

#include "jtracer/diagnostics.hpp"

#include <algorithm>

namespace jt {

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::error; });
}

bool asks_for_frame_size(const Diagnostic& d) {
    return d.setting == "width" || d.setting == "height";
}

namespace {

// The text of 1-based line `line`, without its line break; empty when out of range.
std::string_view line_text(std::string_view source, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        std::size_t nl = source.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    std::size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    std::string_view text = source.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d, std::string_view filename,
                              std::string_view source) {
    std::string out(filename);
    if (d.pos.line > 0) {
        out += ':' + std::to_string(d.pos.line) + ':' + std::to_string(d.pos.column);
    }
    out += d.severity == Severity::error     ? ": error: "
           : d.severity == Severity::warning ? ": warning: "
                                             : ": note: ";
    out += d.message;
    out += '\n';
    if (d.pos.line <= 0) return out;
    std::string_view text = line_text(source, d.pos.line);
    if (text.empty() && d.pos.column <= 1) return out;
    // A long line is quoted as a window around the column, marked with "...".
    constexpr std::size_t max_quote = 200, before = 80;
    const std::size_t column = static_cast<std::size_t>(std::max(d.pos.column, 1)) - 1;
    std::size_t begin = 0, end = text.size();
    if (text.size() > max_quote) {
        begin = column > before ? std::min(column - before, text.size() - max_quote) : 0;
        end = begin + max_quote;
    }
    // Control and non-ASCII bytes show as '?' and tabs as spaces, so the caret lines up.
    std::string quoted = begin > 0 ? "..." : "";
    for (char c : text.substr(begin, end - begin)) {
        auto u = static_cast<unsigned char>(c);
        quoted += (c == '\t') ? ' ' : (u < 0x20 || u >= 0x7f) ? '?' : c;
    }
    if (end < text.size()) quoted += "...";
    out += "    " + quoted + '\n';
    std::size_t caret = std::min(column, end) - begin + (begin > 0 ? 3 : 0);
    out += "    " + std::string(caret, ' ') + "^\n";
    return out;
}

}  // namespace jt

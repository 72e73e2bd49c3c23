#include "edit/block_layout.hpp"

namespace jt::edit {

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// True when the line starting at `start` holds only whitespace.
bool blank_line_at(std::string_view text, std::size_t start) {
    if (start >= text.size()) return false;
    for (std::size_t i = start; i < text.size() && text[i] != '\n'; ++i)
        if (!is_blank(text[i])) return false;
    return true;
}

// The first non-blank character of the line starting at `start`, or '\n'.
char first_char_of_line(std::string_view text, std::size_t start) {
    for (std::size_t i = start; i < text.size() && text[i] != '\n'; ++i)
        if (!is_blank(text[i])) return text[i];
    return '\n';
}

// The start of the line before the one starting at `start` (which is not 0).
std::size_t previous_line_start(std::string_view text, std::size_t start) {
    return line_start(text, start - 1);
}

// The lines joined with single spaces, their indentation dropped.
std::string inline_text(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& line : lines) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos) continue;
        if (!out.empty()) out += ' ';
        out += line.substr(start);
    }
    return out;
}

}  // namespace

std::string indented_lines(const std::vector<std::string>& lines, std::string_view indent) {
    std::string out;
    for (const std::string& line : lines) {
        if (!line.empty()) out.append(indent).append(line);
        out += '\n';
    }
    return out;
}

Range block_range(const BlockSource& block) {
    return {block.keyword_span.offset, std::size_t{block.close_brace} + 1};
}

Range statement_range(std::string_view text, const PropertySource& property) {
    std::size_t i = std::size_t{property.value_span.offset} + property.value_span.length;
    while (i < text.size() && text[i] != ';') {
        if (text[i] == '#')
            while (i < text.size() && text[i] != '\n') ++i;
        else
            ++i;
    }
    return {property.name_span.offset, i < text.size() ? i + 1 : i};
}

bool ends_its_line(std::string_view text, std::size_t offset) {
    std::size_t i = offset;
    while (i < text.size() && is_blank(text[i])) ++i;
    return i == text.size() || text[i] == '\n' || text[i] == '#';
}

std::size_t next_line_start(std::string_view text, std::size_t offset) {
    const std::size_t newline = text.find('\n', offset);
    return newline == std::string_view::npos ? text.size() : newline + 1;
}

bool has_own_lines(std::string_view text, Range range) {
    return starts_its_line(text, range.begin) && ends_its_line(text, range.end);
}

TextEdit removal(std::string_view text, Range range, bool collapse_blank_lines) {
    if (has_own_lines(text, range)) {
        std::size_t begin = line_start(text, range.begin);
        std::size_t end = next_line_start(text, range.end);
        if (collapse_blank_lines && begin > 0 &&
            blank_line_at(text, previous_line_start(text, begin))) {
            if (blank_line_at(text, end))
                end = next_line_start(text, end);
            else if (first_char_of_line(text, end) == '}' || end == text.size())
                begin = previous_line_start(text, begin);
        }
        return {begin, end - begin, ""};
    }
    std::size_t begin = range.begin;
    std::size_t end = range.end;
    if (end < text.size() && is_blank(text[end]))
        ++end;
    else if (begin > 0 && is_blank(text[begin - 1]))
        --begin;
    return {begin, end - begin, ""};
}

std::optional<std::size_t> first_item(const SceneSource& source, const BlockSource& block) {
    std::optional<std::size_t> first;
    const auto own = properties_of(source, block);
    const auto nested = children_of(source, block);
    if (!own.empty()) first = own.front().name_span.offset;
    if (!nested.empty() && (!first || nested.front().keyword_span.offset < *first))
        first = nested.front().keyword_span.offset;
    return first;
}

TextEdit insertion_before_close(std::string_view text, std::size_t close,
                                std::optional<std::size_t> first_item,
                                const std::vector<std::string>& lines, bool blank_line_before) {
    if (starts_its_line(text, close)) {
        std::string indent;
        if (first_item && starts_its_line(text, *first_item))
            indent = std::string(line_indent(text, *first_item));
        else
            indent = std::string(line_indent(text, close)) + "    ";
        std::string inserted = blank_line_before ? "\n" : "";
        inserted += indented_lines(lines, indent);
        return {line_start(text, close), 0, std::move(inserted)};
    }
    // Insertions at the same brace follow one another: each brings the one
    // space it needs on the side the brace's own spacing does not give, so
    // that several make `a; b; c; }` or `a; b; c;}`, never two spaces.
    if (close > 0 && is_blank(text[close - 1])) return {close, 0, inline_text(lines) + " "};
    std::string inserted = " ";
    inserted.append(inline_text(lines));
    return {close, 0, std::move(inserted)};
}

TextEdit insertion_after(std::string_view text, Range range, const std::vector<std::string>& lines,
                         bool blank_line_before) {
    if (has_own_lines(text, range)) {
        const std::size_t at = next_line_start(text, range.end);
        std::string inserted =
            at == text.size() && (text.empty() || text.back() != '\n') ? "\n" : "";
        if (blank_line_before) inserted += "\n";
        inserted += indented_lines(lines, line_indent(text, range.begin));
        return {at, 0, inserted};
    }
    std::string inserted = " ";
    inserted += inline_text(lines);
    return {range.end, 0, std::move(inserted)};
}

TextEdit insertion_before(std::string_view text, Range range,
                          const std::vector<std::string>& lines) {
    if (has_own_lines(text, range))
        return {line_start(text, range.begin), 0,
                indented_lines(lines, line_indent(text, range.begin))};
    std::string inserted = inline_text(lines);
    inserted += ' ';
    return {range.begin, 0, std::move(inserted)};
}

bool set_apart_by_blank_lines(std::string_view text, Range range) {
    if (blank_line_at(text, next_line_start(text, range.end))) return true;
    std::size_t start = line_start(text, range.begin);
    while (start > 0) {
        start = previous_line_start(text, start);
        const char first = first_char_of_line(text, start);
        if (first == '\n') return true;
        if (first != '#') return false;
    }
    return false;
}

}  // namespace jt::edit

#include "model_reader/model_messages.hpp"

#include <algorithm>
#include <string_view>

namespace jt {

namespace {

bool starts_with(std::span<const std::uint8_t> bytes, std::initializer_list<std::uint8_t> head) {
    return bytes.size() >= head.size() && std::equal(head.begin(), head.end(), bytes.begin());
}

bool is_zip(std::span<const std::uint8_t> bytes) {
    return starts_with(bytes, {'P', 'K', 3, 4}) || starts_with(bytes, {'P', 'K', 5, 6});
}

// Assimp prints a bad number's text with each byte outside ' '..'~' as '?'
// (ai_str_toprintable), at most 200 of them.
bool printed_as(std::uint8_t byte, char shown) {
    if (shown == '?') return byte == '?' || byte < 0x20 || byte > 0x7E;
    return byte == static_cast<std::uint8_t>(shown);
}

// A byte of a word or a number: the quoted text never starts inside one,
// since the readers copy a whole word before they parse it.
bool inside_word(std::uint8_t byte) {
    return (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') ||
           (byte >= '0' && byte <= '9') || byte == '_' || byte == '.' || byte == '-' || byte == '+';
}

// Where the text Assimp quoted starts in the file: the first place it matches
// that does not start inside a word ('x' is not the x of "usemtl tex").
std::size_t find_printed(std::span<const std::uint8_t> bytes, std::string_view shown) {
    if (shown.empty() || shown.size() > bytes.size()) return std::string_view::npos;
    for (std::size_t at = 0; at + shown.size() <= bytes.size(); ++at) {
        if (at > 0 && inside_word(bytes[at - 1])) continue;
        std::size_t k = 0;
        while (k < shown.size() && printed_as(bytes[at + k], shown[k])) ++k;
        if (k == shown.size()) return at;
    }
    return std::string_view::npos;
}

// "Cannot parse string "TEXT" as a real number: ...": where TEXT starts, as
// line, column and byte, and its first word. TEXT is looked for in the model
// first, then in the material libraries it read (the reader parses a library
// where the model names it, so a failure may lie in either).
std::string located_number(const std::string& reason, std::span<const std::uint8_t> bytes,
                           std::span<const ReadAlongside> libraries) {
    constexpr std::string_view kHead = "Cannot parse string \"";
    constexpr std::string_view kTail = "\" as a real number";
    const std::size_t head = reason.find(kHead);
    const std::size_t tail = reason.rfind(kTail);
    if (head == std::string::npos || tail == std::string::npos || tail < head + kHead.size())
        return "";
    const std::string_view shown =
        std::string_view(reason).substr(head + kHead.size(), tail - head - kHead.size());
    if (shown.empty()) {
        // The reader copied the word after the last number of a line: none.
        std::string where = "a line of the file";
        for (std::size_t i = 0; i < libraries.size(); ++i)
            where.append(i == 0 ? " or of its material library '" : ", '")
                .append(libraries[i].name)
                .append("'");
        return where.append(" ends where a number was expected");
    }
    std::string in;
    std::size_t at = find_printed(bytes, shown);
    for (std::size_t i = 0; at == std::string_view::npos && i < libraries.size(); ++i) {
        at = find_printed(libraries[i].bytes, shown);
        if (at != std::string_view::npos) {
            bytes = libraries[i].bytes;
            in = "its material library '" + libraries[i].name + "', ";
        }
    }
    if (at == std::string_view::npos) return "";
    const auto before = bytes.subspan(0, at);
    const std::size_t line =
        1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const auto line_start = std::find(before.rbegin(), before.rend(), '\n');
    const std::size_t column = static_cast<std::size_t>(line_start - before.rbegin()) + 1;
    std::size_t word = 0;
    while (word < shown.size() && word < 40 && shown[word] != ' ' && shown[word] != '?') ++word;
    // Appended, not chained from a literal: GCC 12 warns falsely (-Wrestrict).
    std::string where(in);
    where.append("line ");
    where.append(std::to_string(line)).append(", column ").append(std::to_string(column));
    where.append(" (byte ").append(std::to_string(at)).append("): a number was expected, not ");
    if (word == 0) {
        // Spaces (or line ends and tabs, shown as '?') before a number: the
        // importer did not skip them.
        std::size_t at_word = 0;
        while (at_word < shown.size() && (shown[at_word] == ' ' || shown[at_word] == '?'))
            ++at_word;
        if (at_word == 0 || at_word == shown.size()) return where.append("nothing");
        std::size_t end = at_word;
        while (end < shown.size() && end - at_word < 40 && shown[end] != ' ' && shown[end] != '?')
            ++end;
        return where.append("the white space before '")
            .append(shown.substr(at_word, end - at_word))
            .append("' (the model reader does not skip it there)");
    }
    return where.append("'").append(shown.substr(0, word)).append("'");
}

}  // namespace

std::string wide_text_problem(std::span<const std::uint8_t> bytes) {
    const char* encoding = nullptr;
    if (starts_with(bytes, {0xFF, 0xFE, 0, 0}) || starts_with(bytes, {0, 0, 0xFE, 0xFF}))
        encoding = "UTF-32";
    else if (starts_with(bytes, {0xFF, 0xFE}) || starts_with(bytes, {0xFE, 0xFF}))
        encoding = "UTF-16";
    if (!encoding) return "";
    return std::string("the file is ") + encoding +
           " text (it starts with a byte order mark), which the model reader does not read: "
           "save it as UTF-8";
}

std::string unread_format_problem(std::span<const std::uint8_t> head, bool reads_vrml,
                                  bool reads_m3d) {
    constexpr std::string_view kConvert =
        ", which the model reader does not read: convert it to "
        "glTF 2.0, OBJ or PLY";
    if (!reads_vrml && starts_with(head, {'#', 'V', 'R', 'M', 'L'}))
        return std::string("the file is VRML").append(kConvert);
    // Binary Model 3D starts "3DMO", its text form "3dmodel".
    if (!reads_m3d &&
        (starts_with(head, {'3', 'D', 'M', 'O'}) || starts_with(head, {'3', 'd', 'm', 'o', 'd'})))
        return std::string("the file is Model 3D (.m3d, .a3d)").append(kConvert);
    return "";
}

std::string import_failure(const std::string& reason, std::span<const std::uint8_t> bytes,
                           std::span<const ReadAlongside> libraries) {
    if (std::string located = located_number(reason, bytes, libraries); !located.empty())
        return located;
    if (starts_with(bytes, {0x1F, 0x8B}))
        return "the file is gzip-compressed, which the model reader does not read: unpack it first";
    if (reason.rfind("Failed to open file", 0) == 0) {
        // Assimp's words when the zip archive a 3MF file is cannot be opened.
        if (!is_zip(bytes)) return "the file is not a zip archive, as a 3MF file must be";
        return "its zip archive cannot be read: it is cut short or damaged";
    }
    if (is_zip(bytes))
        return "the file is a zip archive (a zipped AMF?), which the model reader opens only as "
               "3MF: unzip it first";
    return reason;
}

}  // namespace jt

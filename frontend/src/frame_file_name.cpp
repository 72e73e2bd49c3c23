#include "jtracer/frontend/frame_file_name.hpp"

#include <cstdio>

namespace jt::frontend {

namespace {

// 'text', built by appending (GCC 12's -Wrestrict misreads "'" + string).
std::string quoted(std::string_view text) {
    std::string out(1, '\'');
    out.append(text);
    out += '\'';
    return out;
}

std::string padded(int frame, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%0*d", digits, frame);
    return text;
}

// At the % that starts a field, `rest` after it: the field's length and
// width, or an error.
Expected<int> read_field(std::string_view rest, std::size_t& length) {
    if (!rest.empty() && rest[0] == 'd') {
        length = 1;
        return 0;
    }
    if (rest.size() >= 3 && rest[0] == '0' && rest[1] >= '0' && rest[1] <= '9' && rest[2] == 'd') {
        if (rest[1] == '0') return Error{"'%00d' asks for no digits; write %01d to %09d"};
        length = 3;
        return rest[1] - '0';
    }
    if (rest.size() >= 2 && rest[0] == '0' && rest[1] == 'd')
        return Error{"'%0d' asks for no digits; write %01d to %09d"};
    // Quote what printf would take as the field: its flags, width and length
    // (`%4d`, `%010d`, `%ld`), then the conversion letter, and no more.
    std::size_t end = 0;
    while (end < rest.size() && end < 8 &&
           std::string_view("0123456789.+-# 'hljzt").find(rest[end]) != std::string_view::npos)
        ++end;
    // The conversion character whole: a UTF-8 one is several bytes.
    if (end < rest.size()) ++end;
    while (end < rest.size() && (static_cast<unsigned char>(rest[end]) & 0xC0) == 0x80) ++end;
    std::string field(1, '%');
    field.append(rest.substr(0, end));
    return Error{quoted(field) +
                 " is not a frame number field: write %d, %01d to %09d, or %% for a percent sign"};
}

}  // namespace

Expected<FrameNamePattern> parse_frame_name_pattern(std::string_view pattern) {
    FrameNamePattern result;
    bool found = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        std::string& out = found ? result.after : result.before;
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        std::size_t length = 0;
        Expected<int> digits = read_field(pattern.substr(i + 1), length);
        if (!digits) return digits.error();
        if (found)
            return Error{quoted(pattern) +
                         " has two frame number fields; a sequence needs exactly one"};
        found = true;
        result.digits = *digits;
        i += length;
    }
    if (!found)
        return Error{quoted(pattern) +
                     " has no frame number field: with --frames, name the files as "
                     "shot-%04d.png (%d or %01d to %09d; %% for a percent sign)"};
    return result;
}

std::string frame_file_name(const FrameNamePattern& pattern, int frame) {
    return pattern.before + padded(frame, pattern.digits) + pattern.after;
}

std::string numbered_file_name(std::string_view filename, int frame) {
    const std::size_t slash = filename.find_last_of('/');
    const std::size_t component = slash == std::string_view::npos ? 0 : slash + 1;
    std::size_t dot = filename.find_last_of('.');
    if (dot == std::string_view::npos || dot < component) dot = filename.size();
    return std::string(filename.substr(0, dot)) + "-" + padded(frame, 4) +
           std::string(filename.substr(dot));
}

}  // namespace jt::frontend

#include "jtracer/value_text.hpp"

#include "language/diagnostic_sink.hpp"
#include "language/lexer.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace jt {

std::string number_text(double value) {
    if (value == 0.0) return "0";  // also -0, which means the same here
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

double rounded_to_scale(double value, double scale) {
    if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(value)) return value;
    const double exponent = std::floor(std::log10(scale)) - 2.0;
    const double r = exponent < 0.0
                         ? std::round(value * std::pow(10.0, -exponent)) / std::pow(10.0, -exponent)
                         : std::round(value / std::pow(10.0, exponent)) * std::pow(10.0, exponent);
    return r == 0.0 ? 0.0 : r;  // never -0
}

Vec3 rounded_to_scale(const Vec3& v, double scale) {
    return {rounded_to_scale(v.x, scale), rounded_to_scale(v.y, scale),
            rounded_to_scale(v.z, scale)};
}

double ui_rounded(double value) {
    if (!std::isfinite(value)) return value;
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", kUiDigits, value);
    return std::strtod(text, nullptr);
}

Vec3 ui_rounded(const Vec3& value) {
    return {ui_rounded(value.x), ui_rounded(value.y), ui_rounded(value.z)};
}

std::string vector_text(const Vec3& v) {
    // Appended piece by piece: `"<" + std::string&&` trips GCC 12's -Wrestrict.
    std::string out = "<";
    out.append(number_text(v.x)).append(", ").append(number_text(v.y)).append(", ");
    return out.append(number_text(v.z)).append(">");
}

bool is_writable_string(std::string_view text) {
    for (char c : text)
        if (c < 0x20 || c > 0x7e || c == '"') return false;
    return true;
}

std::string string_text(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    return out.append(1, '"').append(text).append(1, '"');
}

std::string edited_vector_text(std::string_view written, const Vec3& value) {
    // The written vector's tokens: '<' number ',' number ',' number '>', with
    // anything the lexer skips (spaces, comments) between them.
    lang::DiagnosticSink sink;
    lang::Lexer lexer(written, sink);
    std::array<lang::Token, 7> tokens;
    for (lang::Token& token : tokens) lexer.next(token);
    lang::Token after;
    lexer.next(after);
    constexpr std::array<lang::TokenKind, 7> shape{lang::TokenKind::less,   lang::TokenKind::number,
                                                   lang::TokenKind::comma,  lang::TokenKind::number,
                                                   lang::TokenKind::comma,  lang::TokenKind::number,
                                                   lang::TokenKind::greater};
    bool plain = after.kind == lang::TokenKind::end && tokens[0].offset == 0;
    for (std::size_t i = 0; i < shape.size(); ++i) plain = plain && tokens[i].kind == shape[i];
    if (!plain) return vector_text(value);
    std::string out;
    std::size_t copied = 0;  // bytes of `written` already in `out`
    for (int k = 0; k < 3; ++k) {
        const lang::Token& number = tokens[1 + 2 * static_cast<std::size_t>(k)];
        if (number.number == value[k]) continue;
        out.append(written.substr(copied, number.offset - copied)).append(number_text(value[k]));
        copied = number.offset + number.length;
    }
    return out.append(written.substr(copied));
}

}  // namespace jt

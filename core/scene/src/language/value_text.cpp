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
    // The written vector's tokens: '<' component ',' component ',' component
    // '>', a component a number with at most one sign before it, and anything
    // the lexer skips (spaces, comments) between them. Anything else (an
    // expression) is written anew.
    lang::DiagnosticSink sink;
    lang::Lexer lexer(written, sink);
    lang::Token token;
    lexer.next(token);
    if (token.kind != lang::TokenKind::less || token.offset != 0) return vector_text(value);
    struct Component {
        std::size_t offset, end;
        double number;
    };
    std::array<Component, 3> parts{};
    for (std::size_t k = 0; k < 3; ++k) {
        lexer.next(token);
        if (k > 0) {
            if (token.kind != lang::TokenKind::comma) return vector_text(value);
            lexer.next(token);
        }
        const std::size_t start = token.offset;
        double sign = 1.0;
        if (token.kind == lang::TokenKind::minus || token.kind == lang::TokenKind::plus) {
            sign = token.kind == lang::TokenKind::minus ? -1.0 : 1.0;
            lexer.next(token);
        }
        if (token.kind != lang::TokenKind::number) return vector_text(value);
        parts[k] = {start, token.offset + token.length, sign * token.number};
    }
    lexer.next(token);
    if (token.kind != lang::TokenKind::greater) return vector_text(value);
    lexer.next(token);
    if (token.kind != lang::TokenKind::end) return vector_text(value);
    std::string out;
    std::size_t copied = 0;  // bytes of `written` already in `out`
    for (std::size_t k = 0; k < 3; ++k) {
        const Component& c = parts[k];
        if (c.number == value[static_cast<int>(k)]) continue;
        out.append(written.substr(copied, c.offset - copied))
            .append(number_text(value[static_cast<int>(k)]));
        copied = c.end;
    }
    return out.append(written.substr(copied));
}

}  // namespace jt

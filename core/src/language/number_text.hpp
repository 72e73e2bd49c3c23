#pragma once
// Numbers as text that reads back to exactly the same double.

#include <glm/vec3.hpp>

#include <charconv>
#include <string>
#include <string_view>

namespace jt::lang {

// Shortest text that std::from_chars reads back as exactly `value`; finite values only.
inline std::string number_text(double value) {
    if (value == 0.0) return "0";  // also -0, which means the same here
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

// "<1, 0.5, 0>": a vector as .jts text.
inline std::string vector_text(const glm::dvec3& v) {
    std::string out = "<";
    out.append(number_text(v.x)).append(", ").append(number_text(v.y)).append(", ");
    return out.append(number_text(v.z)).append(">");
}

// 'word' in single quotes, as messages cite names. (Built with append: GCC 12
// warns falsely on "literal" + std::string&&.)
inline std::string quote(std::string_view word) {
    std::string out;
    out.reserve(word.size() + 2);
    out.append(1, '\'').append(word).append(1, '\'');
    return out;
}

}  // namespace jt::lang

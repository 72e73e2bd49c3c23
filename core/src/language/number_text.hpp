#pragma once
// Numbers as text that reads back to exactly the same double.

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

// 'word' in single quotes, as messages cite names. (Built with append: GCC 12
// warns falsely on "literal" + std::string&&.)
inline std::string quote(std::string_view word) {
    std::string out;
    out.reserve(word.size() + 2);
    out.append(1, '\'').append(word).append(1, '\'');
    return out;
}

}  // namespace jt::lang

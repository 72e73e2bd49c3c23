#pragma once
// How messages cite a name or a word: in single quotes.

#include <string>
#include <string_view>

namespace jt::lang {

// 'word' in single quotes. (Built with append: GCC 12 warns falsely on
// "literal" + std::string&&.)
inline std::string quote(std::string_view word) {
    std::string out;
    out.reserve(word.size() + 2);
    out.append(1, '\'').append(word).append(1, '\'');
    return out;
}

}  // namespace jt::lang

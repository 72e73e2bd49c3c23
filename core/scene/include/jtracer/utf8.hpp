#pragma once
// One UTF-8 character read from a text. The scene reader's check that a text
// is UTF-8, its messages naming a character, and the viewer's check of what
// its text widget can hold all decode by this one rule.

#include <cstddef>
#include <optional>
#include <string_view>

namespace jt {

struct Utf8Character {
    char32_t code = 0;
    std::size_t length = 0;  // bytes, 1 to 4
};

// The character whose bytes start at `at`: one well-formed UTF-8 sequence,
// or nothing for a stray continuation byte, an overlong form, a surrogate, a
// code past U+10FFFF or a sequence the text's end cuts off. Inline: the
// reader asks for every byte past ASCII of a scene's text.
inline std::optional<Utf8Character> utf8_character_at(std::string_view text, std::size_t at) {
    if (at >= text.size()) return std::nullopt;
    const auto lead = static_cast<unsigned char>(text[at]);
    if (lead < 0x80) return Utf8Character{lead, 1};
    std::size_t length = 0;
    char32_t least = 0;  // below this, the sequence is an overlong form
    if ((lead & 0xE0) == 0xC0) {
        length = 2, least = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3, least = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4, least = 0x10000;
    } else {
        return std::nullopt;
    }
    if (at + length > text.size()) return std::nullopt;
    char32_t code = lead & (0x7Fu >> length);
    for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<unsigned char>(text[at + k]);
        if ((next & 0xC0) != 0x80) return std::nullopt;
        code = (code << 6) | (next & 0x3Fu);
    }
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return std::nullopt;
    return Utf8Character{code, length};
}

}  // namespace jt

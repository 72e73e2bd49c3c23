#pragma once
// What must hold for any input, checked by the fuzz targets and replayed by
// tests/hardening on every saved regression input. Each check returns an
// empty string when the invariants hold, else which one broke and how.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace jt::fuzz {

// Parses `text`, validates when parsing succeeded, and checks: every
// diagnostic lies within the text (or is unlocated) and formats; a scene
// without errors serializes to text that parses back, without errors, to an
// equal scene, and serializing that gives the same text again.
std::string check_scene_text(std::string_view text);

// Decodes `bytes` as a BMP and checks: either a message and no claim of an
// image, or an image of consistent size that encodes and decodes back equal.
std::string check_bmp_bytes(std::span<const std::uint8_t> bytes);

}  // namespace jt::fuzz

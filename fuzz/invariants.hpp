#pragma once
// What must hold for any input, checked by the fuzz targets and replayed by
// tests/hardening on every saved regression input. Each check returns an
// empty string when the invariants hold, else which one broke and how.

#include "jtracer/diagnostics.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt::fuzz {

// Parses `text`, validates when parsing succeeded, and checks: every
// diagnostic lies within the text (or is unlocated) and formats; a scene
// without errors serializes to text that parses back, without errors, to an
// equal scene, and serializing that gives the same text again; the same for
// the serializer that keeps the text's names (source_serializer.hpp).
std::string check_scene_text(std::string_view text);

// Empty when every diagnostic has a message and lies within `text` (at most one
// column past the end of its line) or is about the file as a whole (line 0).
std::string check_diagnostics_within(const std::vector<Diagnostic>& diagnostics,
                                     std::string_view text);

// Decodes `bytes` as a BMP and checks: either a message and no claim of an
// image, or an image of consistent size that encodes and decodes back equal.
std::string check_bmp_bytes(std::span<const std::uint8_t> bytes);

// Decodes `bytes` as an image map (PNG, JPEG or BMP through stb_image) and
// checks: either a message, or a texture within the size cap whose texel
// count matches its size and whose every value is finite, in [0, 1].
std::string check_texture_bytes(std::span<const std::uint8_t> bytes);

// A model input's first byte picks the file's extension, which is how Assimp
// picks its importer: model_extensions[byte % size]; the rest is the file.
inline constexpr std::array<const char*, 5> model_extensions{"obj", "ply", "stl", "gltf", "glb"};

// Writes the model input `bytes` to a file of its own, in a folder of its own,
// reads it as a mesh would (read_model, through Assimp, confined to that
// folder) and checks: either a message, or a model within the size caps whose
// normals and texture coordinates are parallel to its positions, whose
// positions are finite and whose triangles name existing vertices.
std::string check_model_bytes(std::span<const std::uint8_t> bytes);

// For the fuzz targets: a broken invariant is printed and aborts, so that
// libFuzzer keeps the input.
void abort_if_broken(const std::string& broken);

}  // namespace jt::fuzz

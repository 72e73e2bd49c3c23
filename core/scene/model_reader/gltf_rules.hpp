#pragma once
// Cases Assimp 5.2 (Debian 12's libassimp5) mishandles, found by
// fuzz/model_fuzzer, checked here from the file's own JSON before Assimp reads
// it, and refused with what is wrong:
// - it reads an accessor's elements without checking that they lie inside its
//   buffer view: an animation accessor that claimed more bytes than its view
//   held had it read past the end of its buffer (a heap overflow). Every
//   accessor, sparse part, buffer view and .glb buffer is checked against what
//   holds it;
// - it follows a skin's inverseBindMatrices without checking that there is one
//   (glTF lets a skin leave them out): a null pointer, the program dies;
// - its JSON reader takes text that is not JSON (bytes that are not UTF-8, for
//   one), so that the checks above would not see what it reads: a .gltf's text,
//   or a .glb's JSON chunk, must parse as JSON;
// - it names a glTF 1.0 file's problem by the first member 1.0 lays out
//   otherwise ('Member "version" was not of type "string"'): a file that says
//   it is glTF 1 is refused as such.
// It also counts the triangles the file's mesh primitives declare, which tells
// how many Assimp dropped (it leaves out faces whose indices are out of range,
// with no more than a log line), and its materials.

#include <cstdint>
#include <span>
#include <string>

namespace jt {

struct GltfCheck {
    // "" when `bytes` are not a glTF file (JSON or binary .glb) or break none
    // of the rules above; else which rule, and where.
    std::string problem;
    // The triangles of every mesh primitive of a triangle mode (TRIANGLES,
    // TRIANGLE_STRIP, TRIANGLE_FAN), counted from its indices or positions.
    std::uint64_t declared_triangles = 0;
    // How many materials the file declares: Assimp gives a primitive without
    // one a material of its own, numbered after them.
    std::uint64_t materials = 0;
};
GltfCheck check_gltf(std::span<const std::uint8_t> bytes);

}  // namespace jt

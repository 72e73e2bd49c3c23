#pragma once
// A case Assimp 5.2 (Debian 12's libassimp5) mishandles, found by
// fuzz/model_fuzzer: it reads a glTF accessor's elements without checking that
// they lie inside the accessor's buffer view, so that a file whose animation
// accessor claims more bytes than its view holds had it read past the end of
// its buffer (a heap overflow). Every glTF file's accessors, buffer views and
// buffers are checked here first, from the file's own JSON, and such a file is
// refused.

#include <cstdint>
#include <span>
#include <string>

namespace jt {

// "" when `bytes` are not a glTF 2.0 file (JSON or binary .glb), or its JSON
// does not parse (Assimp then reports it), or every accessor lies inside its
// buffer view and every view inside its buffer; else which one does not.
std::string gltf_bounds_problem(std::span<const std::uint8_t> bytes);

}  // namespace jt

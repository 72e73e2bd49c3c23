#pragma once
// The language's named limits (docs/language.md §4). Every check of these
// values, in the parser, the validator, the render job, the command-line flags
// and the viewer's fields, uses these names.

#include <cstddef>

namespace jt {

// Widest and tallest image a scene may ask for (0 means "not set"). Images
// read back (BMPs, region records) are held to the same bound.
inline constexpr int kMaxImageSide = 65535;

// The samples extension: rays per pixel.
inline constexpr int kMinSamples = 1;
inline constexpr int kMaxSamples = 1024;

// A soft light's shadow rays per shading point (docs/language.md §14.1).
inline constexpr int kMinShadowSamples = 1;
inline constexpr int kMaxShadowSamples = 1024;

// Generated smooth normals (docs/language.md §14.4) compare the triangles that
// meet at one position pairwise. A model may take this many comparisons, plus
// this many for each corner of its triangles (a real one needs a few dozen a
// corner), so that triangles of many directions around one point cannot hang
// a render.
inline constexpr std::size_t kSmoothNormalComparisons = std::size_t{1} << 24;
inline constexpr std::size_t kSmoothNormalComparisonsPerCorner = 64;

// Deeper recurse_depth values are clamped here, with a warning; the tracer
// keeps one entry per bounce on its stack, so this also bounds that stack.
inline constexpr int kMaxRecurseDepth = 256;

// The largest magnitude of any number a scene holds (a position, a radius, a
// scale, an intensity...). Secondary rays start 1e-9 of the distances involved
// off their surface (docs/language.md §8.5), so past 1e9 a surface a unit from
// the camera can no longer be told from its own lift, and a value this large
// next to unit-sized ones renders as noise. A scene made larger or smaller as
// a whole keeps its image; only the numbers written are held to this bound.
inline constexpr double kMaxMagnitude = 1e9;

// Parentheses, calls and vector literals inside one another in one value
// (docs/language.md §15.3). The expression parser recurses once per level, so
// this bounds its stack whatever the input.
inline constexpr int kMaxExpressionNesting = 256;

// Includes inside one another (docs/language.md §15.6): the main file has
// depth 0, and a file may be opened at depth 32 at most. The parser recurses
// once per level, so this also bounds its stack.
inline constexpr int kMaxIncludeDepth = 32;

// Readings of included files in one scene, counting every reading of a file
// included several times. Nesting alone would let a few small files that each
// include the next twice be read 2^32 times; past this the scene is refused.
inline constexpr std::size_t kMaxIncludeReadings = 4096;

// --frames N: at most a million frames, 11 hours of film at 25 per second;
// enough for any sequence, and a frame number always fits a file name.
inline constexpr int kMaxFrames = 1000000;

}  // namespace jt

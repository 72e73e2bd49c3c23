#pragma once
// Whole-scene checks that no single property can make (docs/language.md §4.9).
//
// Run after parsing and after any overrides (the CLI's --width/--height/--camera,
// the viewer's edits), so that the checks see the values that will render.

#include "jtracer/chunk_runner.hpp"
#include "jtracer/diagnostics.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <vector>

namespace jt {

// The options change the work, never the diagnostics.
struct ValidateOptions {
    // When given, a large scene's primitives are checked in pieces on its
    // threads; the diagnostics are the same, in the same order, either way.
    ChunkRunner run_chunks = {};
    // The caller's word that the primitives are exactly as the parser made
    // them (values from code or edits: false). The parser checked every value
    // it read against its range (the same rules, schema.hpp), so only the
    // properties whose default is out of range (`file` of a mesh: left
    // unwritten, never read) are checked again.
    bool primitives_as_parsed = false;
};

// Errors: no camera; width or height 0; an image whose BMP would pass 4 GiB;
// a camera whose look_at equals its position or whose up is parallel to its
// view direction; values out of their allowed range (for scenes built in code).
// Warnings: a camera aspect differing from width/height by over 1%; an
// active_camera naming no camera; a transform that leaves its primitive out (a
// scale with a zero component anywhere in the list, or magnitudes past the
// range of doubles: the renderer's own rule); no scene block.
// Each is located at the property or block concerned when `source` has it,
// at line 0 otherwise. `source` may be empty (a scene built in code).
std::vector<Diagnostic> validate_scene(const Scene& scene, const SceneSource& source,
                                       const ValidateOptions& options = {});

// The camera a render uses: the one named by settings.active_camera, else the
// first; -1 when there is none.
int active_camera_index(const Scene& scene);

// Size in bytes of the 24-bit BMP of a width x height image (header included).
unsigned long long bmp_file_size(int width, int height);

// Whether a width x height image fits in a BMP file (4 GiB at most): the
// largest image JTracer renders, whatever the output format.
bool fits_in_bmp(int width, int height);

}  // namespace jt

#pragma once
// validate_scene's findings with what they are about, for check_scene
// (scene_file.hpp): a scene loaded without its source map is parsed again to
// locate them, and only findings about primitives need the primitives' records.

#include "jtracer/diagnostics.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"
#include "jtracer/validate.hpp"

#include <string_view>
#include <vector>

namespace jt::lang {

struct Validation {
    std::vector<Diagnostic> diagnostics;  // as validate_scene returns them
    bool about_primitives = false;        // whether any concerns a primitive
};

Validation validate_scene_parts(const Scene& scene, const SceneSource& source,
                                const ValidateOptions& options = {});

// The source map of `text` without the primitives' records (SceneSource::
// primitives stays empty, so validate_scene leaves their findings unlocated),
// and without keeping the primitives themselves: for a million spheres this
// costs a parse's time but neither a scene's memory nor a full map's.
SceneSource source_without_primitives(std::string_view text, const ParseOptions& options);

}  // namespace jt::lang

#pragma once
// `jtracer-cli --list-cameras scene.jts`, hidden from --help: the scene's camera
// names, one a line on stdout, for the shell completions of --camera.

#include <string>

namespace jt::cli {

// Prints the cameras the parser found, even in a scene with errors (a scene
// being edited still completes). Returns 0, or 3 when the file cannot be read.
int list_cameras(const std::string& scene_path);

}  // namespace jt::cli

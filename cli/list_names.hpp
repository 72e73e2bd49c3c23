#pragma once
// `jtracer-cli --list-cameras scene.jts` and `--list-defines scene.jts`,
// hidden from --help: the scene's camera names, or the names it defines
// (`define NAME = ...`), one a line on stdout, for the shell completions of
// --camera and --define.

#include <string>

namespace jt::cli {

// Each prints what the parser found, even in a scene with errors (a scene
// being edited still completes). Returns 0, or 3 when the file cannot be read.
int list_cameras(const std::string& scene_path);
int list_defines(const std::string& scene_path);

}  // namespace jt::cli

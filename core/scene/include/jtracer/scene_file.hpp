#pragma once
// Loading a .jts file: reading it with clear I/O errors, parsing, validating.
// The one way every program loads a scene: the command-line renderers (through
// frontend/'s set_up_frame) and the viewer (on its loader thread) do this:
//
//   jt::Expected<jt::LoadedScene> loaded = jt::load_scene_file(path);
//   if (!loaded) { report loaded.error().message; stop; }
//   ... apply --width/--height/--camera to loaded->parsed.scene ...
//   auto diagnostics = jt::check_scene(*loaded);   // parse + validation
//   std::cerr << jt::format_diagnostics(diagnostics, *loaded);
//   if (jt::has_errors(diagnostics)) stop;

#include "jtracer/diagnostics.hpp"
#include "jtracer/error.hpp"
#include "jtracer/file_stamp.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/validate.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

// Scene files larger than this are refused rather than read into memory.
inline constexpr std::uintmax_t max_scene_file_bytes = 1ull << 30;

// Reads a whole file. On failure the error says which file and why, e.g.
// "cannot read 'a.jts': no such file", "'scenes' is a directory, not a file".
Expected<std::string> read_text_file(const std::filesystem::path& path,
                                     std::uintmax_t max_bytes = max_scene_file_bytes);

struct LoadedScene {
    std::string path;      // as given: the FILE of FILE:LINE:COL diagnostics
    std::string text;      // the file's contents; empty when given back
    ParseResult parsed;    // scene, source spans (included files too) and parse diagnostics
    ParseOptions options;  // what it was parsed with
    // TextKeeping::given_back_when_large gave the text back: a message that
    // quotes it reads the file again, if `stamp` says it is the same file.
    bool text_given_back = false;
    FileStamp stamp;  // of the file when it was read
};

// What load_scene_file keeps of the file's text.
enum class TextKeeping {
    whole,
    // A text of smallest_text_given_back or more, parsed without the source
    // map, is given back to the system as the parse passes it, so that the
    // text and its scene are never held whole together (a million spheres'
    // render: 139 MB of text). For a caller that needs only the scene and
    // the diagnostics: check_scene and format_diagnostics read the file
    // again when a message has to be located or quoted.
    given_back_when_large,
};

inline constexpr std::size_t smallest_text_given_back = std::size_t{64} << 20;

// Reads and parses, with `options.main_file` set to `path` when empty (so
// includes are read from its folder); fails only when the file cannot be read (mistakes in the
// text are diagnostics). Does not validate: apply any overrides to
// `parsed.scene` first, then call check_scene.
Expected<LoadedScene> load_scene_file(const std::filesystem::path& path, ParseOptions options = {},
                                      TextKeeping keeping = TextKeeping::whole);

// The same for a text already read (a pipe's, which cannot be read twice, or
// one given in memory), parsed as the file at `path` would be: named `path`
// in diagnostics, its includes and assets found in its folder. Fails only
// when the machine runs out of memory parsing it. The stamp stays empty.
Expected<LoadedScene> load_scene_text(std::string text, const std::filesystem::path& path,
                                      ParseOptions options = {},
                                      TextKeeping keeping = TextKeeping::whole);

struct CheckOptions {
    // False: warnings about a scene loaded without its source map stay at line
    // 0 rather than cost another parse to locate, for a caller that drops
    // them (a quiet command line). Errors are always located.
    bool locate_warnings = true;
    // How validate_scene works (its threads, what it may take as checked).
    ValidateOptions validation = {};
};

// The parse diagnostics followed by validate_scene's (validation runs only when
// parsing found no errors, so that one mistake does not cascade). A scene
// loaded without its source map is validated without it, and only when that
// finds something is the text parsed again to say where (keeping the
// primitives' records only when a finding concerns a primitive).
std::vector<Diagnostic> check_scene(const LoadedScene& loaded, CheckOptions options = {});

// Every diagnostic formatted by format_diagnostic, concatenated; `files`
// are the included files (SceneSource::files) a diagnostic may be in.
std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics,
                               std::string_view filename, std::string_view source,
                               std::span<const SourceFile> files = {});

// The same for a loaded scene: named as given, with its included files. A
// text given back is read again to quote it, and left unquoted (with a note
// saying why) if the file changed since.
std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics,
                               const LoadedScene& loaded);

}  // namespace jt

#pragma once
// .jts text -> Scene + diagnostics. A pure function: it never throws and never
// crashes, whatever the bytes (docs/language.md §2-§4).

#include "jtracer/diagnostics.hpp"
#include "jtracer/error.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

// One `--define NAME=VALUE` of a front end (docs/language.md §15.2): VALUE is
// written as in a file (`2`, `<1, 0, 0>`, `"out.png"`, `2 * pi`).
struct Define {
    std::string name;
    std::string value;
    bool operator==(const Define&) const = default;
};

// An included file read: its identity (absolute, symlinks resolved) and text.
struct IncludedText {
    std::string canonical;
    std::string text;
};

// Reads the file an `include` names, at most `max_bytes` of it; the error says
// which file and why ("cannot read 'a.jts': no such file").
using IncludeReader =
    std::function<Expected<IncludedText>(const std::string& path, std::uintmax_t max_bytes)>;

// The reader parse_scene uses by default: the file system, through the scene
// loader's read_text_file.
Expected<IncludedText> read_include_file(const std::string& path, std::uintmax_t max_bytes);

// Where a primitive was read, and whether any of its values (its own, its
// material's, its transform's, or a named material's it uses) read `clock`.
struct PrimitiveReading {
    std::uint32_t file = 0;     // SourcePos::file of its keyword
    std::uint32_t keyword = 0;  // the keyword's offset in that file's text
    std::uint32_t resume = 0;   // the offset of the token after its '}'
    SourcePos resume_pos;       // and that token's position
    bool reads_clock = false;
};

// The same texts parsed, without errors, at another clock: a frame sequence's previous frame
// (docs/language.md §15.4). Its primitives that read no `clock` are moved out
// of it into the new scene instead of being read again: in a scene where only
// a camera, a light or a few objects move, a frame reads little of the text.
struct EarlierParse {
    std::string text;                        // the main text it read
    std::vector<SourceFile> files;           // the included texts it read
    std::vector<Primitive> primitives;       // the scene's: the new parse takes the array
    std::vector<PrimitiveReading> readings;  // parallel to `primitives`
};

// How the messages about ParseOptions::defines and ::clock name them: in the
// words the front end's user gives them with. The defaults are this API's
// own names; jtracer-cli's are its flags (frontend/render_flags.hpp:
// "--define", "--clock"), the Python module's its arguments ("defines",
// "clock=").
struct ValueNames {
    // What sets the defines: "'r' is set by --define; this definition is ignored".
    std::string_view defines = "ParseOptions::defines";
    // One define, its name between these: "--define r", "defines['r']".
    std::string_view define_before = "define ";
    std::string_view define_after = "";
    // What sets the clock: "clock cannot be defined; set it with --clock".
    std::string_view clock = "ParseOptions::clock";

    std::string define(std::string_view name) const;
};

struct ParseOptions {
    // False: leave ParseResult::source empty. A tool that only renders needs
    // the source map only to locate validation findings, and for a million
    // spheres the map costs more than the scene (see check_scene).
    bool source_map = true;
    // Names set before the main file is read, in command-line order (a later
    // one of the same name wins, with a warning). The file's own definition
    // of such a name is then ignored, with a note.
    std::vector<Define> defines = {};
    // The value of `clock` (docs/language.md §15.4).
    double clock = 0.0;
    // How diagnostics name `defines` and `clock`.
    ValueNames value_names = {};
    // The main file's path as given (docs/language.md §15.6): `include`
    // paths are relative to its folder, and a diagnostic in an included file
    // is named from it ("scenes/a.jts" for `include "a.jts";` in
    // "scenes/main.jts"). Empty for a text of no file: includes are then
    // relative to the working directory.
    std::string main_file = {};
    // How included files are read; empty: read_include_file. The fuzzer
    // confines it to files of its own.
    IncludeReader read_include = {};
    // Threads that may read a large scene block, each a part of it
    // (language/scene_parts.hpp); 0: one a hardware thread. The result is the
    // same with any number.
    unsigned threads = 0;
    // Fill ParseResult::primitive_readings (for a later parse at another clock).
    bool record_primitive_readings = false;
    // Called now and then, on the parsing thread, with an offset of the main
    // text before which the parse will not read again: the caller of a huge
    // text may give its memory back behind it (load_scene_file does). Called
    // only while one thread reads the main text's scene block.
    std::function<void(std::size_t offset)> text_passed = {};
    // Take the primitives that read no `clock` from this earlier parse. Used
    // only without the source map (a taken primitive has no records), and
    // only while the texts read are the earlier parse's own, byte for byte.
    // Diagnostics inside a taken primitive are not repeated.
    EarlierParse* earlier = nullptr;
    // False: read every property's name and ':' as tokens, also where the
    // parser reads a run of them without (a generator's one-line blocks). The
    // result is the same either way: the tests compare the two.
    bool plain_properties = true;
};

// Splits and checks one `--define` argument "NAME=VALUE": NAME a name that is
// not reserved (nor `clock`), VALUE a string literal or an expression of
// numbers, `pi` and `clock`. The error says what is wrong, without the
// option; `names` says what sets the clock instead.
Expected<Define> parse_define(std::string_view argument, const ValueNames& names = {});

// The error of a checked `--define`'s value evaluated at `clock` ("at column
// 2: division by zero: 1 / 0"), or nullopt when it evaluates there.
// parse_define accepts a value of the clock that fails at clock 0 (1 / clock):
// a front end asks this at each clock it renders.
std::optional<std::string> define_error_at(const Define& define, double clock);

struct ParseResult {
    Scene scene;
    SceneSource source;                   // empty when parsed with source_map = false
    std::vector<Diagnostic> diagnostics;  // in the order found
    bool out_of_memory = false;           // parsing stopped for want of memory (one diagnostic)
    // Some value that was evaluated named `clock` (in the file or in a
    // --define): false means the scene is the same at every clock.
    bool reads_clock = false;
    // How many parts of the scene block other threads read (ParseOptions::threads);
    // the rest of the result is the same whatever it is.
    std::size_t scene_parts_taken = 0;
    // With ParseOptions::record_primitive_readings: one per primitive of `scene`.
    std::vector<PrimitiveReading> primitive_readings;
    bool ok() const { return !has_errors(diagnostics); }
};

// Lexes and parses; reports every error it can recover from (up to a cap).
ParseResult parse_scene(std::string_view text, ParseOptions options = {});

}  // namespace jt

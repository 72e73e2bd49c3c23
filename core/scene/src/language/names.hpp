#pragma once
// The names a scene defines (docs/language.md §15.2): `define NAME = VALUE;`
// and named materials share one table, filled in reading order, so that a name
// is visible from the end of its definition on.

#include "jtracer/diagnostics.hpp"
#include "jtracer/scene.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace jt::lang {

// A number, a vector/colour or a string: what an expression gives.
struct ExprValue {
    enum class Kind { number, vector, string };
    Kind kind = Kind::number;
    double number = 0.0;
    Vec3 vector{0.0};
    std::string_view text;  // a string's contents (in the scene text or in a NameTable)
};

struct Symbol {
    enum class Kind { value, material };
    Kind kind = Kind::value;
    ExprValue value;       // a value's (a string's text lives in `text`)
    std::string text;      // a string value's contents
    Material material;     // a named material's properties
    SourcePos defined_at;  // the name in the file; line 0: set by --define
    bool from_command_line = false;
    bool defined_in_file = false;  // a --define's name the file defines too
    bool bad = false;              // its definition had an error (reported there): uses say nothing
    bool reads_clock = false;      // its value named `clock`, directly or through other names
    std::uint32_t definition = 0;  // its index in SceneSource::definitions
};

// The statements of language 1.3 (docs/language.md §15).
inline constexpr std::string_view kDefineKeyword = "define";
inline constexpr std::string_view kIncludeKeyword = "include";

// Words that may not be defined: the language's keywords, `pi`, `clock` and
// the functions of docs/language.md §15.3.
bool is_reserved_name(std::string_view name);

// One of the schema's block keywords (sphere, material, ...).
bool is_block_keyword(std::string_view word);

class NameTable {
  public:
    const Symbol* find(std::string_view name) const;
    Symbol* find(std::string_view name);
    // Adds `name`; the symbol is returned for the caller to fill. A string
    // value's `value.text` must be set through set_string.
    Symbol& add(std::string_view name);
    static void set_string(Symbol& symbol, std::string text);
    // Every name defined so far, for did-you-mean.
    std::vector<std::string_view> names() const;
    bool empty() const { return symbols_.empty(); }
    // After an included file could not be read, its names are missing: a use
    // of an unknown name is then no longer reported (docs/language.md §15.6).
    bool reports_unknown() const { return reports_unknown_; }
    void stop_reporting_unknown() { reports_unknown_ = false; }

  private:
    bool reports_unknown_ = true;
    std::map<std::string, Symbol, std::less<>> symbols_;  // nodes stay put: views into them last
};

}  // namespace jt::lang

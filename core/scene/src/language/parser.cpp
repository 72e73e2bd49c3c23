// parse_scene (jtracer/parser.hpp): the checks of the whole text, then the
// parser (scene_parser.hpp) set up, run, and its result taken.

#include "jtracer/parser.hpp"

#include "io/reserve_records.hpp"
#include "language/count_hints.hpp"
#include "language/lexer.hpp"
#include "language/quote.hpp"
#include "language/scene_parser.hpp"
#include "language/validation.hpp"

#include <cstdint>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <utility>

namespace jt {
namespace lang {

SceneParser::SceneParser(std::string_view text, const ParseOptions& options, bool primitives)
    : text_(text),
      lexer_(text, sink_),
      reader_(sink_),
      include_(options),
      expressions_(*this, sink_, names_, options.clock),
      source_map_(options.source_map),
      keep_primitives_(primitives),
      record_readings_(options.record_primitive_readings && primitives),
      earlier_(options.earlier && !options.source_map && primitives && options.earlier->text == text
                   ? options.earlier
                   : nullptr),
      options_(options),
      reports_text_passed_(static_cast<bool>(options.text_passed)),
      plain_properties_(options.plain_properties) {
    if (keep_primitives_) {
        const BraceAndColonCount count = count_braces_and_colons(text);
        primitive_hint_ = primitive_count_hint(text, count);
        property_hint_ = property_count_hint(text, count);
        if (source_map_) {
            reserve_records(result_.source.properties, property_hint_);
            reserve_records(result_.source.children, primitive_hint_);
        }
    }
    set_command_line_names(options);
    lexer_.next(*cur_);
    lexer_.next(*next_);
}

SceneParser::SceneParser(std::string_view text, const ParseOptions& options, const NameTable& names,
                         std::size_t begin)
    : text_(text),
      lexer_(text, sink_),
      reader_(sink_),
      include_(options),
      names_(names),
      expressions_(*this, sink_, names_, options.clock),
      source_map_(options.source_map),
      keep_primitives_(true),
      record_readings_(false),
      earlier_(nullptr),
      options_(options),
      plain_properties_(options.plain_properties) {
    lexer_.resume_at(begin, position_of(text, begin));
    lexer_.next(*cur_);
    lexer_.next(*next_);
}

ParseResult SceneParser::run() {
    parse_file();
    for (const auto& [name, symbol] : command_line_)
        if (!symbol->defined_in_file && sink_.accepts_warnings())
            sink_.warning(
                {}, options_.value_names.define(name) + ": the scene defines no " + quote(name));
    result_.diagnostics = sink_.take();
    result_.reads_clock = result_.reads_clock || expressions_.read_clock();
    if (!source_map_) result_.source = {};
    // Kept with or without the map: diagnostics quote the included texts.
    result_.source.files = include_.take_files();
    result_.source.unread_includes = include_.take_unread();
    return std::move(result_);
}

}  // namespace lang

SceneSource lang::source_without_primitives(std::string_view text, const ParseOptions& options) {
    ParseOptions with_map = options;
    with_map.source_map = true;
    return lang::SceneParser(text, with_map, false).run().source;
}

ParseResult parse_scene(std::string_view text, ParseOptions options) {
    try {
        std::size_t bad = lang::find_invalid_text_byte(text);
        if (bad != std::string_view::npos) {
            ParseResult result;
            std::string what = text[bad] == '\0' ? "a NUL byte" : "a byte that is not UTF-8 text";
            result.diagnostics.push_back({Severity::error, lang::position_of(text, bad),
                                          "the file is not a text file: it contains " + what});
            return result;
        }
        if (text.size() >= std::numeric_limits<std::uint32_t>::max()) {
            ParseResult result;
            result.diagnostics.push_back(
                {Severity::error, {}, "the scene text is too large: 4 GiB or more"});
            return result;
        }
        return lang::SceneParser(text, options).run();
    } catch (const std::bad_alloc&) {
        ParseResult result;
        result.out_of_memory = true;
        result.diagnostics.push_back(
            {Severity::error,
             {},
             "out of memory: the scene is too large for the memory available"});
        return result;
    } catch (const std::exception& e) {
        ParseResult result;
        result.diagnostics.push_back(
            {Severity::error, {}, std::string("the scene could not be read: ") + e.what()});
        return result;
    }
}

}  // namespace jt

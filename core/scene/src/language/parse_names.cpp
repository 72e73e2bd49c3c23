// Names (docs/language.md §15.2): `define NAME = VALUE;`, named materials
// `material NAME { ... }` and the values of --define, one table for all,
// filled in reading order so that a name is visible from its definition on.

#include "jtracer/schema.hpp"
#include "language/block_body.hpp"
#include "language/define_value.hpp"
#include "language/quote.hpp"
#include "language/scene_parser.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace jt::lang {

namespace {

// A definition cut short before its value still defines its name, as a bad
// one: its uses then say nothing more than the error already reported, where
// "unknown name" would send the reader looking for a definition that is there.
void add_bad_name(NameTable& names, const Token& name, Symbol::Kind kind) {
    Symbol& symbol = names.add(name.text);
    symbol.kind = kind;
    symbol.defined_at = name.pos;
    symbol.bad = true;
}

}  // namespace

void SceneParser::set_command_line_names(const ParseOptions& options) {
    for (const Define& define : options.defines) {
        // Over-cautious for a string that holds the word; never wrong.
        if (define.value.find("clock") != std::string::npos) result_.reads_clock = true;
        ExprValue value;
        std::string error;
        if (!evaluate_define_value(define.value, options.clock, value, error)) {
            sink_.error(
                {}, options.value_names.define(define.name) + "=" + define.value + ": " + error);
            continue;
        }
        Symbol* symbol = names_.find(define.name);
        if (symbol) {
            if (sink_.accepts_warnings())
                sink_.warning({}, options.value_names.define(define.name) +
                                      " is given more than once; the last value is used");
        } else {
            symbol = &names_.add(define.name);
            command_line_.emplace_back(define.name, symbol);
        }
        symbol->from_command_line = true;
        symbol->reads_clock = define.value.find("clock") != std::string::npos;
        symbol->value = value;
        if (value.kind == ExprValue::Kind::string)
            NameTable::set_string(*symbol, std::string(value.text));
    }
}

bool SceneParser::claim_name(const Token& name, bool& overridden) {
    overridden = false;
    if (is_reserved_name(name.text)) {
        sink_.error(name.pos, quote(name.text) +
                                  " is reserved (a keyword, a function, pi or clock) and "
                                  "cannot be defined");
        return false;
    }
    Symbol* existing = names_.find(name.text);
    if (!existing) return true;
    if (existing->from_command_line && !existing->defined_in_file) {
        existing->defined_in_file = true;
        existing->defined_at = name.pos;
        overridden = true;
        return true;
    }
    std::string message = quote(name.text) + " is defined twice: it was first defined at " +
                          include_.where(existing->defined_at, name.pos);
    if (name.pos.file != 0) message += "; read again here" + include_.chain(name.pos.file);
    sink_.error(name.pos, std::move(message));
    return false;
}

void SceneParser::bare_assignment(bool top_level) {
    const Token name = *cur_;
    std::string message = "'";
    message += name.text;
    message += " = ...'";
    if (top_level)
        message += " needs the keyword 'define': write 'define ";
    else
        message +=
            " defines nothing here: names are defined at the top level, outside every "
            "block, with 'define ";
    message += name.text;
    message += " = ...;'";
    sink_.error(name.pos, std::move(message));
    // The name counts as defined, badly, so that its uses are not reported
    // again as unknown names.
    if (!is_reserved_name(name.text) && !names_.find(name.text))
        add_bad_name(names_, name, Symbol::Kind::value);
    skip_statement();
}

void SceneParser::parse_define() {
    const std::size_t keyword_end = cur_->offset + cur_->length;
    advance();
    if (!at(TokenKind::word)) {
        // A name the lexer refused ('define Σ = 1;') was reported there.
        if (!at(TokenKind::bad_value) && !reading_->skipped_between(keyword_end, cur_->offset))
            sink_.error(cur_->pos, "expected a name after 'define', got " + describe(*cur_));
        skip_statement();
        return;
    }
    const Token name = *cur_;
    bool overridden = false;
    const bool claimed = claim_name(name, overridden);
    advance();
    if (!at(TokenKind::equals)) {
        sink_.error(cur_->pos, "expected '=' after 'define " + std::string(name.text) + "', got " +
                                   describe(*cur_));
        if (claimed && !overridden) add_bad_name(names_, name, Symbol::Kind::value);
        skip_statement();
        return;
    }
    advance();
    const std::uint64_t clock_reads = expressions_.clock_reads();
    Value value = read_value(!overridden);
    if (value.form == Value::Form::none) {
        sink_.error(cur_->pos, "expected a value after 'define " + std::string(name.text) +
                                   " =', got " + describe(*cur_));
        if (claimed && !overridden) add_bad_name(names_, name, Symbol::Kind::value);
        skip_statement();
        return;
    }
    const bool glued = value.form != Value::Form::bad && glued_to(value.end);
    const bool name_beside =
        value.form != Value::Form::bad && !glued && !cut_short(value) && beside(value.end);
    const bool good = value.form != Value::Form::bad && !cut_short(value) && !glued && !name_beside;
    if (claimed && !overridden) {
        Symbol& symbol = names_.add(name.text);
        symbol.defined_at = name.pos;
        symbol.definition = static_cast<std::uint32_t>(result_.source.definitions.size());
        symbol.bad = !good;
        symbol.reads_clock = expressions_.clock_reads() > clock_reads;
        if (value.form == Value::Form::number) {
            symbol.value.kind = ExprValue::Kind::number;
            symbol.value.number = value.number;
        } else if (value.form == Value::Form::vector) {
            symbol.value.kind = ExprValue::Kind::vector;
            symbol.value.vector = value.vector;
        } else if (value.form == Value::Form::string) {
            NameTable::set_string(symbol, std::string(value.text));
        }
    }
    if (overridden) {
        sink_.note(name.pos, quote(name.text) + " is set by " +
                                 std::string(options_.value_names.defines) +
                                 "; this definition is ignored");
    }
    if (source_map_ && claimed) {
        result_.source.definitions.push_back(
            {std::string(name.text), span_of(name), value.span, value.origin, std::nullopt});
    }
    if (glued || name_beside)
        sink_.error(value.end, "expected ';' after the value of 'define " + std::string(name.text) +
                                   "'" + std::string(glued ? glued_hint : beside_hint));
    if (!good) {
        skip_statement();
        return;
    }
    if (at(TokenKind::semicolon)) {
        advance();
        return;
    }
    sink_.error(value.end, "expected ';' after the value of 'define " + std::string(name.text) +
                               "'" + std::string(comparison_after()));
    if (!at(TokenKind::word) && !at(TokenKind::rbrace)) skip_statement();
}

void SceneParser::parse_named_material() {
    BlockSource block;
    block.keyword = schema_of<Material>().keyword;
    block.keyword_span = span_of(*cur_);
    advance();
    if (!at(TokenKind::word)) {
        sink_.error(cur_->pos, "expected a name or '{' after 'material', got " + describe(*cur_));
        skip_statement();
        return;
    }
    const Token name = *cur_;
    bool overridden = false;
    bool claimed = claim_name(name, overridden);
    if (overridden) {
        // A --define holds a value of that name: a material cannot replace it.
        sink_.error(name.pos, quote(name.text) + " is set by " +
                                  std::string(options_.value_names.defines) +
                                  "; a material cannot have its name");
        claimed = false;
    }
    advance();
    if (!at(TokenKind::lbrace)) {
        sink_.error(cur_->pos, "expected '{' after 'material " + std::string(name.text) +
                                   "', got " + describe(*cur_));
        if (claimed) add_bad_name(names_, name, Symbol::Kind::material);
        skip_statement();
        return;
    }
    block.open_brace = static_cast<std::uint32_t>(cur_->offset);
    advance();
    Material material;
    const std::size_t errors_before = error_count();
    const std::uint64_t clock_reads = expressions_.clock_reads();
    read_properties(block, 0, [&](OpenBlock& open) {
        parse_body(
            block, kNoBlocks, [&](const Property& p) { reader_.apply(material, open, p); },
            [&] { block_in_property_block(block); });
    });
    if (!claimed) return;
    finishes_.share(material.finish);
    Symbol& symbol = names_.add(name.text);
    symbol.kind = Symbol::Kind::material;
    symbol.material = material;
    symbol.defined_at = name.pos;
    symbol.bad = error_count() != errors_before;
    symbol.reads_clock = expressions_.clock_reads() > clock_reads;
    symbol.definition = static_cast<std::uint32_t>(result_.source.definitions.size());
    if (source_map_) {
        result_.source.definitions.push_back(
            {std::string(name.text), span_of(name), {}, ValueOrigin::literal, block.properties});
    }
}

}  // namespace jt::lang

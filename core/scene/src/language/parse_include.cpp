// Include (docs/language.md §15.6): the included file's statements are read
// where the `include` stands, with a lexer of their own, and reading resumes
// after its ';' once they end.

#include "language/scene_parser.hpp"

#include "jtracer/value_text.hpp"

#include <optional>
#include <string>
#include <utility>

namespace jt::lang {

// A name where the path should stand: the path is a string literal, never a
// name's value (§15.6), so the hint spells out the literal to write, the
// name's own string when it has one.
std::string SceneParser::include_path_hint(const Token& token) const {
    if (token.kind != TokenKind::word) return "";
    const Symbol* symbol = names_.find(token.text);
    std::string example = "\"FILE.jts\"";
    if (symbol != nullptr && symbol->kind == Symbol::Kind::value &&
        symbol->value.kind == ExprValue::Kind::string && is_writable_string(symbol->text))
        example = string_text(symbol->text);
    return " (an include takes a string literal, not a name: write 'include " + example + ";')";
}

bool SceneParser::enter_include(IncludeResume& resume) {
    advance();
    if (!at(TokenKind::string)) {
        if (!at(TokenKind::bad_value))
            sink_.error(cur_->pos,
                        "expected the path of a file in double quotes after "
                        "'include', got " +
                            describe(*cur_) + include_path_hint(*cur_));
        skip_statement();
        return false;
    }
    const Token path = *cur_;
    advance();
    if (at(TokenKind::semicolon)) {
        advance();
    } else {
        sink_.error(
            {path.pos.line, path.pos.column + static_cast<int>(path.length), path.pos.file},
            "expected ';' after 'include \"" + std::string(path.text.substr(0, 40)) + "\"'");
    }
    bool unreadable = false;
    const std::optional<IncludeStack::Opened> opened =
        include_.open(path.text, path.pos, sink_, unreadable);
    if (!opened) {
        if (unreadable) names_.stop_reporting_unknown();
        return false;
    }
    // An included file that changed since the earlier parse: its offsets
    // say nothing of what it holds now.
    if (earlier_ && (opened->file > earlier_->files.size() ||
                     earlier_->files[opened->file - 1].text != opened->text))
        earlier_ = nullptr;
    if (included_directive_.line == 0 && reading_ != &lexer_)
        included_directive_ = reading_->directive_comment();
    resume.tokens = {*cur_, *next_};
    resume.text = text_;
    resume.lexer = reading_;
    Lexer& lexer = resume.included.emplace(opened->text, sink_, opened->file);
    reading_ = &lexer;
    text_ = opened->text;
    lexer.next(*cur_);
    lexer.next(*next_);
    return true;
}

void SceneParser::leave_include(IncludeResume& resume) {
    if (included_directive_.line == 0) included_directive_ = reading_->directive_comment();
    include_.close();
    *cur_ = resume.tokens[0];
    *next_ = resume.tokens[1];
    reading_ = resume.lexer;
    text_ = resume.text;
}

std::string SceneParser::directive_comment(SourcePos from) const {
    SourcePos directive = lexer_.directive_comment();
    if (directive.line == 0) directive = included_directive_;
    if (directive.line == 0) directive = reading_->directive_comment();
    return directive.line == 0 ? std::string() : include_.line_column_from(directive, from);
}

void SceneParser::rebase_file_name(Property& property) {
    if (property.value.form != Value::Form::string || property.name_span.pos.file == 0 ||
        !names_a_file(property.name))
        return;
    std::string rebased = include_.rebased_asset(property.value.text, property.name_span.pos.file);
    if (!rebased.empty()) property.value.text = rebased_names_.emplace_back(std::move(rebased));
}

}  // namespace jt::lang

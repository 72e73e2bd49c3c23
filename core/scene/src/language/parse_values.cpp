// Values and properties (docs/language.md §3.2, §15.3): a value is read by
// the expression reader, except the plain numbers and vectors most values
// are, which take short paths around it; a property is NAME ':' value ';'.

#include "language/block_body.hpp"
#include "language/scene_parser.hpp"

#include <cstdint>
#include <string>

namespace jt::lang {
namespace {

// Whether the token can start a value: anything else is "expected a value".
bool starts_value(TokenKind kind) {
    switch (kind) {
        case TokenKind::number:
        case TokenKind::string:
        case TokenKind::word:
        case TokenKind::less:
        case TokenKind::lparen:
        case TokenKind::plus:
        case TokenKind::minus:
        case TokenKind::bad_value:
            return true;
        default:
            return false;
    }
}

}  // namespace

Value SceneParser::read_value(bool evaluate) {
    Value v;
    if (!starts_value(cur_->kind)) return v;  // none; nothing consumed
    if (cur_->kind == TokenKind::number && next_->kind == TokenKind::semicolon) {
        v.form = Value::Form::number;
        v.number = cur_->number;
        v.text = cur_->text;
        v.span = span_of(*cur_);
        v.end = {cur_->pos.line, cur_->pos.column + static_cast<int>(cur_->length), cur_->pos.file};
        advance();
        return v;
    }
    // So does a vector of plain numbers, the other most common value.
    if (cur_->kind == TokenKind::less && evaluate) {
        Vec3 vector;
        if (const std::size_t end = reading_->plain_vector(cur_->offset, vector)) {
            const auto length = static_cast<std::uint32_t>(end - cur_->offset);
            v.form = Value::Form::vector;
            v.vector = vector;
            v.span = {static_cast<std::uint32_t>(cur_->offset), length, cur_->pos};
            v.end = {cur_->pos.line, cur_->pos.column + static_cast<int>(length), cur_->pos.file};
            reading_->skip_to(end);
            reading_->next(*cur_);
            reading_->next(*next_);
            return v;
        }
    }
    const ParsedValue parsed = expressions_.read(evaluate);
    v.span = parsed.span;
    v.end = parsed.end;
    v.origin = parsed.origin;
    if (!parsed.ok) {
        v.form = Value::Form::bad;
        return v;
    }
    switch (parsed.value.kind) {
        case ExprValue::Kind::number:
            v.form = Value::Form::number;
            v.number = parsed.value.number;
            if (parsed.origin == ValueOrigin::literal)
                v.text = text_.substr(v.span.offset, v.span.length);
            break;
        case ExprValue::Kind::vector:
            v.form = Value::Form::vector;
            v.vector = parsed.value.vector;
            break;
        case ExprValue::Kind::string:
            v.form = Value::Form::string;
            v.text = parsed.value.text;
            break;
    }
    return v;
}

bool SceneParser::read_plain_value(Value& v) {
    if (!read_plain_value_in_place(v)) return false;
    reading_->next(*cur_);
    reading_->next(*next_);
    return true;
}

bool SceneParser::read_property(Property& property, bool try_plain, std::string_view keyword) {
    property.name = cur_->text;
    property.name_span = span_of(*cur_);
    if (try_plain && next_->kind == TokenKind::colon && read_plain_value(property.value))
        return true;
    advance();
    if (!at(TokenKind::colon)) {
        sink_.error(cur_->pos, "expected ':' after '" + std::string(property.name) + "', got " +
                                   describe(*cur_));
        skip_statement();
        return false;
    }
    advance();
    if (!keyword.empty() && !block_has_property(keyword, property.name)) {
        // A misspelt or misplaced name ('fox: r * 2;', 'material: shiny;' in
        // a light): the name is the mistake to report, where the block's
        // reader does, not what evaluating its value would say (an unknown
        // name, a material used as a value), which would hide it.
        property.value = Value{};
        property.value.form = Value::Form::bad;
        skip_statement();
        return true;
    }
    property.value = read_value();
    rebase_file_name(property);
    if (property.value.form == Value::Form::none) {
        sink_.error(cur_->pos, "expected a value after '" + std::string(property.name) +
                                   ":', got " + describe(*cur_));
        skip_statement();
        return false;
    }
    if (property.value.form == Value::Form::bad || cut_short(property.value)) {
        skip_statement();
        return false;
    }
    if (at(TokenKind::semicolon)) {
        advance();
        return true;
    }
    const bool glued = glued_to(property.value.end);
    const bool name_beside = !glued && beside(property.value.end);
    std::string message = "expected ';' after the value of '" + std::string(property.name) + "'";
    if (glued) message += glued_hint;
    if (name_beside) message += beside_hint;
    message += comparison_after();
    sink_.error(property.value.end, std::move(message));
    if (glued || name_beside) {
        skip_statement();
        return false;
    }
    // A name or '}' next is most likely the next line: carry on from there.
    if (!at(TokenKind::word) && !at(TokenKind::rbrace)) skip_statement();
    return true;
}

}  // namespace jt::lang

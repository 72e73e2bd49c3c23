// `--define NAME=VALUE` (docs/language.md §15.2): the value is read as a file
// would read it, with no names but `pi` and `clock`.

#include "jtracer/parser.hpp"
#include "language/define_value.hpp"
#include "language/expression.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"
#include "language/quote.hpp"

#include <array>
#include <optional>

namespace jt {
namespace lang {

namespace {

class LexerCursor final : public TokenCursor {
  public:
    LexerCursor(std::string_view text, DiagnosticSink& sink) : lexer_(text, sink) {
        lexer_.next(tokens_[0]);
        lexer_.next(tokens_[1]);
    }
    const Token& cur() const override { return tokens_[at_]; }
    const Token& peek() const override { return tokens_[1 - at_]; }
    void advance() override {
        lexer_.next(tokens_[at_]);
        at_ = 1 - at_;
    }

  private:
    Lexer lexer_;
    std::array<Token, 2> tokens_;
    int at_ = 0;
};

// "at column 3: division by zero: 1 / 0"
std::string first_error(const std::vector<Diagnostic>& diagnostics) {
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Severity::error) continue;
        std::string message = d.message;
        // The value is all the text there is: its end is no file's.
        if (const std::size_t end = message.rfind("the end of the file");
            end != std::string::npos && end + 19 == message.size())
            message.replace(end, 19, "the end of the value");
        return d.pos.line > 0 ? "at column " + std::to_string(d.pos.column) + ": " + message
                              : message;
    }
    return "not a value";
}

// Reads `text` as one whole value; evaluates it at `clock` unless that is
// nullopt (then only its syntax and names are checked). `names_clock` tells
// whether an evaluated value named `clock`.
bool read_define_value(std::string_view text, std::optional<double> clock, ExprValue& value,
                       std::string& error, bool& names_clock) {
    if (find_invalid_text_byte(text) != std::string_view::npos) {
        error = "the value is not text";
        return false;
    }
    DiagnosticSink sink;
    LexerCursor tokens(text, sink);
    const NameTable none;
    ExpressionReader reader(tokens, sink, none, clock.value_or(0.0));
    if (tokens.cur().kind == TokenKind::end) {
        error = "the value is empty";
        return false;
    }
    const ParsedValue parsed = reader.read(clock.has_value());
    names_clock = reader.read_clock();
    if (parsed.ok && tokens.cur().kind != TokenKind::end) {
        sink.error(
            tokens.cur().pos,
            "expected the end of the value, got " + describe(tokens.cur()) +
                (tokens.cur().kind == TokenKind::semicolon ? " (the value takes no ';')" : ""));
    }
    std::vector<Diagnostic> found = sink.take();
    if (!parsed.ok || has_errors(found)) {
        error = first_error(found);
        return false;
    }
    value = parsed.value;
    return true;
}

}  // namespace

bool evaluate_define_value(std::string_view text, double clock, ExprValue& value,
                           std::string& error) {
    bool names_clock = false;
    return read_define_value(text, clock, value, error, names_clock);
}

bool check_define_value(std::string_view text, std::string& error) {
    ExprValue value;
    bool names_clock = false;
    if (read_define_value(text, 0.0, value, error, names_clock)) return true;
    // A value of the clock may fail at clock 0 alone (1 / clock): the clock of
    // the render is not known here, and the parse at that clock reports it.
    std::string syntax;
    bool unused = false;
    return names_clock && read_define_value(text, std::nullopt, value, syntax, unused);
}

}  // namespace lang

std::string ValueNames::define(std::string_view name) const {
    std::string text(define_before);
    text.append(name).append(define_after);
    return text;
}

std::optional<std::string> define_error_at(const Define& define, double clock) {
    lang::ExprValue value;
    std::string error;
    if (lang::evaluate_define_value(define.value, clock, value, error)) return std::nullopt;
    return error;
}

Expected<Define> parse_define(std::string_view argument, const ValueNames& names) {
    const std::size_t equals = argument.find('=');
    if (equals == std::string_view::npos)
        return Error{"expected NAME=VALUE, like r=2 or 'c=<1, 0, 0>', got '" +
                     std::string(argument) + "'"};
    Define define{std::string(argument.substr(0, equals)),
                  std::string(argument.substr(equals + 1))};
    const std::string_view name = define.name;
    auto is_start = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    };
    auto is_part = [&](char c) { return is_start(c) || (c >= '0' && c <= '9'); };
    bool good = !name.empty() && is_start(name[0]);
    for (char c : name) good = good && is_part(c);
    if (!good)
        return Error{"'" + define.name +
                     "' is not a name (letters, digits and '_', not starting with a digit)"};
    if (name == "clock")
        return Error{"clock cannot be defined; set it with " + std::string(names.clock)};
    if (lang::is_reserved_name(name))
        return Error{"'" + define.name +
                     "' is reserved (a keyword, a function or pi) and cannot be defined"};
    std::string error;
    if (!lang::check_define_value(define.value, error))
        return Error{"the value of " + define.name + ": " + error};
    return define;
}

}  // namespace jt

#pragma once
// Values written as expressions (docs/language.md §15.3), evaluated left to
// right as they are parsed, each step on a value stack, with the first
// evaluation error reported only once the value parsed whole.
//
// Only parentheses, calls and vector literals recurse, and at most
// kMaxExpressionNesting deep; sign chains and operator chains are loops, and
// values wait on a heap stack, so no input can exhaust the call stack.

#include "jtracer/source_map.hpp"
#include "language/diagnostic_sink.hpp"
#include "language/lexer.hpp"
#include "language/names.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace jt::lang {

// The token stream an expression is read from (the parser's).
class TokenCursor {
  public:
    virtual const Token& cur() const = 0;
    virtual const Token& peek() const = 0;
    virtual void advance() = 0;
    // Where the text read so far has a POV-Ray directive ("#include",
    // "#declare", "#local") that this language reads as a comment, for the
    // hint of an unknown name at `from`: "LINE:COL", or "FILE:LINE:COL" in
    // another file; "" when it has none.
    virtual std::string directive_comment(SourcePos from) const {
        (void)from;
        return {};
    }

  protected:
    ~TokenCursor() = default;
};

struct ParsedValue {
    bool ok = false;  // false: an error was reported
    ExprValue value;
    ValueOrigin origin = ValueOrigin::literal;
    TextSpan span;                // the whole value as written
    SourcePos end;                // just past it
    bool number_spelled = false;  // a lone number token: `span` holds its spelling
};

// True for the names of the functions an expression may call (sin, dot, ...).
bool is_function_name(std::string_view name);

class ExpressionReader {
  public:
    ExpressionReader(TokenCursor& tokens, DiagnosticSink& sink, const NameTable& names,
                     double clock)
        : tokens_(tokens), sink_(sink), names_(names), clock_(clock) {}

    // Reads the value at the cursor up to (not including) the token after it.
    // With `evaluate` false it is only parsed (a definition overridden by
    // --define). On a syntax error nothing past the error is consumed.
    ParsedValue read(bool evaluate = true);

    // True once a value read for evaluation has named `clock`: a scene
    // whose values never do is the same at every frame.
    bool read_clock() const { return clock_reads_ > 0; }
    // How many times values read for evaluation named `clock` or a name
    // whose value did: a part of the text whose reading leaves it unchanged
    // is the same at every frame.
    std::uint64_t clock_reads() const { return clock_reads_; }
    // Counts a reading of `clock` made elsewhere (a named material's use).
    void note_clock_read() { ++clock_reads_; }

    // One step of evaluation, in postfix order.
    struct Op {
        enum class Code : std::uint8_t { push, sign, group, add, sub, mul, div, call, vector };
        Code code = Code::push;
        std::uint8_t function = 0;  // call: an index into the function table
        bool negate = false;        // sign: minus (an even run of minus signs is plus)
        std::uint32_t count = 0;    // call: the arguments; push: the index of the constant
        SourcePos pos;              // the operator, the function's name, '(' or '<'
    };
    // A value with where it starts: errors about it as an operand point there.
    struct Slot {
        ExprValue value;
        SourcePos pos;
    };

  private:
    bool parse_sum(int depth);
    bool parse_product(int depth);
    bool parse_signed(int depth);
    bool parse_primary(int depth);
    bool parse_call(int depth);
    bool parse_vector(int depth);
    bool open_level(int depth);
    void push(Op op, const ExprValue& value);
    void take();  // advances, remembering where the consumed token ended
    // Runs one step as soon as it is parsed, left to right; the first
    // failure is held until the value has been parsed whole.
    void apply(const Op& op, const ExprValue* value = nullptr);

    TokenCursor& tokens_;
    DiagnosticSink& sink_;
    const NameTable& names_;
    double clock_;
    std::vector<Slot> stack_;  // as deep as the nesting, not as long as the value
    std::size_t operations_ = 0;
    bool evaluating_ = true;
    bool failed_ = false;
    Diagnostic failure_;
    std::uint32_t end_offset_ = 0;
    SourcePos end_pos_;
    bool literal_ = true;
    std::uint64_t clock_reads_ = 0;
    bool single_name_ = false;
};

}  // namespace jt::lang

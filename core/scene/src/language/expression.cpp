#include "language/expression.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/schema.hpp"
#include "language/quote.hpp"
#include "language/suggest.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace jt::lang {

namespace {

using Op = ExpressionReader::Op;
using Kind = ExprValue::Kind;

enum class Function : std::uint8_t {
    sin,
    cos,
    tan,
    asin,
    acos,
    atan2,
    sqrt,
    abs,
    floor,
    min,
    max,
    pow,
    length,
    normalize,
    dot,
    cross
};

struct FunctionSpec {
    std::string_view name;
    Function function;
    std::uint32_t min_args;
    std::uint32_t max_args;  // 0: no upper bound
    bool vectors;            // takes vectors (length, normalize, dot, cross), else numbers
};

constexpr std::array<FunctionSpec, 16> kFunctions{{
    {"sin", Function::sin, 1, 1, false},
    {"cos", Function::cos, 1, 1, false},
    {"tan", Function::tan, 1, 1, false},
    {"asin", Function::asin, 1, 1, false},
    {"acos", Function::acos, 1, 1, false},
    {"atan2", Function::atan2, 2, 2, false},
    {"sqrt", Function::sqrt, 1, 1, false},
    {"abs", Function::abs, 1, 1, false},
    {"floor", Function::floor, 1, 1, false},
    {"min", Function::min, 2, 0, false},
    {"max", Function::max, 2, 0, false},
    {"pow", Function::pow, 2, 2, false},
    {"length", Function::length, 1, 1, true},
    {"normalize", Function::normalize, 1, 1, true},
    {"dot", Function::dot, 2, 2, true},
    {"cross", Function::cross, 2, 2, true},
}};

const FunctionSpec* find_function(std::string_view name) {
    for (const FunctionSpec& f : kFunctions)
        if (f.name == name) return &f;
    return nullptr;
}

constexpr double kPi = std::numbers::pi;

bool finite(const ExprValue& v) {
    if (v.kind == Kind::number) return std::isfinite(v.number);
    if (v.kind == Kind::vector)
        return std::isfinite(v.vector.x) && std::isfinite(v.vector.y) && std::isfinite(v.vector.z);
    return true;
}

ExprValue number(double x) {
    return {Kind::number, x, Vec3{0.0}, {}};
}
ExprValue vector(Vec3 v) {
    return {Kind::vector, 0.0, v, {}};
}

std::string shown(const ExprValue& v) {
    switch (v.kind) {
        case Kind::number:
            return value_text(v.number);
        case Kind::vector:
            return value_text(v.vector);
        default: {
            // Appended, not concatenated: GCC 12 warns (-Wrestrict) about "\"" + s.
            std::string out(1, '"');
            out.append(v.text.substr(0, 40));
            out += '"';
            return out;
        }
    }
}

std::string kind_name(const ExprValue& v) {
    switch (v.kind) {
        case Kind::number:
            return "the number " + shown(v);
        case Kind::vector:
            return "the vector " + shown(v);
        default:
            return "the string " + shown(v);
    }
}

double dot3(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

}  // namespace

bool is_function_name(std::string_view name) {
    return find_function(name) != nullptr;
}

void ExpressionReader::take() {
    const Token& t = tokens_.cur();
    end_offset_ = static_cast<std::uint32_t>(t.offset + t.length);
    end_pos_ = {t.pos.line, t.pos.column + static_cast<int>(t.length), t.pos.file};
    tokens_.advance();
}

bool ExpressionReader::open_level(int depth) {
    if (depth < kMaxExpressionNesting) return true;
    sink_.error(tokens_.cur().pos, "expressions nest too deeply: at most " +
                                       std::to_string(kMaxExpressionNesting) +
                                       " parentheses, calls and vectors inside one another");
    return false;
}

void ExpressionReader::push(Op op, const ExprValue& value) {
    apply(op, &value);
}

ParsedValue ExpressionReader::read(bool evaluate_it) {
    operations_ = 0;
    stack_.clear();
    evaluating_ = evaluate_it;
    failed_ = false;
    literal_ = true;
    single_name_ = false;
    ParsedValue out;
    const Token& first = tokens_.cur();
    out.span = {static_cast<std::uint32_t>(first.offset), 0, first.pos};
    const bool lone_number = first.kind == TokenKind::number;
    if (!parse_sum(0)) return out;
    out.span.length = end_offset_ - out.span.offset;
    out.end = end_pos_;
    out.origin = single_name_ && operations_ == 1 ? ValueOrigin::name
                 : literal_                       ? ValueOrigin::literal
                                                  : ValueOrigin::expression;
    out.number_spelled = lone_number && operations_ == 1;
    if (failed_) {
        sink_.error(failure_.pos, std::move(failure_.message));
        return out;
    }
    // A string value is one string literal or one name, nothing else
    // (docs/language.md §15.3); arithmetic on one fails above, and this is
    // the rest: a string in parentheses.
    if (evaluate_it && stack_.back().value.kind == Kind::string && operations_ != 1) {
        sink_.error(out.span.pos,
                    "parentheses hold numbers and vectors, not a string: write the string, or "
                    "the name of one, alone");
        return out;
    }
    out.ok = true;
    if (evaluate_it) out.value = stack_.back().value;
    return out;
}

bool ExpressionReader::parse_sum(int depth) {
    if (!parse_product(depth)) return false;
    for (;;) {
        const TokenKind k = tokens_.cur().kind;
        if (k != TokenKind::plus && k != TokenKind::minus) return true;
        Op op;
        op.code = k == TokenKind::plus ? Op::Code::add : Op::Code::sub;
        op.pos = tokens_.cur().pos;
        literal_ = false;
        take();
        if (!parse_product(depth)) return false;
        apply(op);
    }
}

bool ExpressionReader::parse_product(int depth) {
    if (!parse_signed(depth)) return false;
    for (;;) {
        const TokenKind k = tokens_.cur().kind;
        if (k != TokenKind::star && k != TokenKind::slash) return true;
        Op op;
        op.code = k == TokenKind::star ? Op::Code::mul : Op::Code::div;
        op.pos = tokens_.cur().pos;
        literal_ = false;
        take();
        if (!parse_signed(depth)) return false;
        apply(op);
    }
}

bool ExpressionReader::parse_signed(int depth) {
    // A run of signs is counted, not recursed into.
    Op sign;
    sign.code = Op::Code::sign;
    std::size_t signs = 0;
    while (tokens_.cur().kind == TokenKind::plus || tokens_.cur().kind == TokenKind::minus) {
        if (signs == 0) sign.pos = tokens_.cur().pos;
        if (tokens_.cur().kind == TokenKind::minus) sign.negate = !sign.negate;
        ++signs;
        take();
    }
    if (signs > 1 || (signs == 1 && tokens_.cur().kind != TokenKind::number)) literal_ = false;
    if (!parse_primary(depth)) return false;
    if (signs > 0) apply(sign);
    return true;
}

bool ExpressionReader::parse_primary(int depth) {
    const Token& t = tokens_.cur();
    Op op;
    op.pos = t.pos;
    switch (t.kind) {
        case TokenKind::number:
            push(op, number(t.number));
            take();
            return true;
        case TokenKind::string:
            push(op, {Kind::string, 0.0, Vec3{0.0}, t.text});
            take();
            return true;
        case TokenKind::lparen: {
            if (!open_level(depth)) return false;
            literal_ = false;
            Op group;
            group.code = Op::Code::group;
            group.pos = t.pos;
            take();
            if (!parse_sum(depth + 1)) return false;
            if (tokens_.cur().kind != TokenKind::rparen) {
                sink_.error(tokens_.cur().pos,
                            "expected ')' or an operator, got " + describe(tokens_.cur()));
                return false;
            }
            take();
            apply(group);
            return true;
        }
        case TokenKind::less:
            return parse_vector(depth);
        case TokenKind::word:
            break;
        case TokenKind::bad_value:  // already reported
            return false;
        default:
            sink_.error(t.pos,
                        "expected a value (a number, a name, '(' or '<'), got " + describe(t));
            return false;
    }
    const std::string_view word = t.text;
    if (word == "pi" || word == "clock") {
        literal_ = false;
        if (word == "clock" && evaluating_) ++clock_reads_;
        push(op, number(word == "pi" ? kPi : clock_));
        take();
        return true;
    }
    if (find_function(word)) return parse_call(depth);
    const Symbol* symbol = names_.find(word);
    if (!symbol && tokens_.peek().kind == TokenKind::lparen) {
        // A call of a function there is not (a slip, or another language's
        // name: POV-Ray's vlength, vnormalize): no file can define a
        // function, so this is said whatever includes went unread.
        std::vector<std::string_view> functions;
        for (const FunctionSpec& f : kFunctions) functions.push_back(f.name);
        std::string message = "unknown function " + quote(word.substr(0, 40));
        if (std::string_view near = nearest_name(word, functions); !near.empty())
            message += "; did you mean " + quote(near) + "?";
        message += " (functions:";
        for (std::size_t i = 0; i < functions.size(); ++i)
            message += (i == 0 ? " " : ", ") + std::string(functions[i]);
        sink_.error(t.pos, message + ")");
        return false;
    }
    if (!symbol && is_block_keyword(word)) {
        // A keyword is never a name, so this is said even when an unread
        // include might have defined others. 'define m = material { ... }'
        // is how POV-Ray's '#declare' names a material.
        sink_.error(t.pos, word == schema_of<Material>().keyword
                               ? quote(word) +
                                     " is a block, not a value: a material is named with "
                                     "'material NAME { ... }' at the top level and used in a "
                                     "primitive with 'material: NAME;'"
                               : quote(word) +
                                     " is a block keyword, not a value (a number, a "
                                     "vector, a string or a defined name)");
        return false;
    }
    if (!symbol) {
        if (!names_.reports_unknown()) return false;
        const std::vector<std::string_view> known = names_.names();
        std::string message = "unknown name " + quote(word.substr(0, 40)) +
                              " (names must be defined before they are used)";
        if (std::string_view near = nearest_name(word, known); !near.empty())
            message += "; did you mean " + quote(near) + "?";
        std::string lower;
        for (char c : word) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        if (lower == "nan" || lower == "inf" || lower == "infinity")
            message += "; numbers must be finite";
        // POV-Ray's colour keywords: `color rgb <1, 0, 0>` is `<1, 0, 0>` here.
        for (std::string_view pov : {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb"})
            if (lower == pov)
                message += "; POV-Ray's " + quote(word.substr(0, 40)) +
                           " is not written here: a colour is the vector <r, g, b> alone, like "
                           "<1, 0.5, 0>";
        // POV-Ray's '#include "colors.inc"' or '#declare R = 1;' is a
        // comment here, which is why its names are unknown.
        if (const std::string directive = tokens_.directive_comment(t.pos); !directive.empty())
            message += "; POV-Ray's #include and #declare are comments here, as at " + directive +
                       ": write include \"FILE\"; and define NAME = VALUE;";
        sink_.error(t.pos, std::move(message));
        return false;
    }
    if (symbol->bad) return false;  // its definition's error was reported there
    if (symbol->kind == Symbol::Kind::material) {
        sink_.error(t.pos, quote(word) +
                               " is a material, not a value: a primitive uses it with "
                               "'material: " +
                               std::string(word) + ";'");
        return false;
    }
    literal_ = false;
    single_name_ = true;
    if (symbol->reads_clock && evaluating_) ++clock_reads_;
    push(op, symbol->value);
    take();
    return true;
}

bool ExpressionReader::parse_call(int depth) {
    const Token& name = tokens_.cur();
    Op call;
    call.code = Op::Code::call;
    call.pos = name.pos;
    const FunctionSpec* f = find_function(name.text);
    call.function = static_cast<std::uint8_t>(f - kFunctions.data());
    literal_ = false;
    take();
    if (tokens_.cur().kind != TokenKind::lparen) {
        sink_.error(tokens_.cur().pos, quote(f->name) +
                                           " is a function: expected '(' after it, got " +
                                           describe(tokens_.cur()));
        return false;
    }
    if (!open_level(depth)) return false;
    take();
    for (;;) {
        if (!parse_sum(depth + 1)) return false;
        ++call.count;
        if (tokens_.cur().kind == TokenKind::comma) {
            take();
            continue;
        }
        if (tokens_.cur().kind == TokenKind::rparen) break;
        sink_.error(tokens_.cur().pos, "expected ',' or ')' in the arguments of " + quote(f->name) +
                                           ", got " + describe(tokens_.cur()));
        return false;
    }
    take();
    apply(call);
    return true;
}

bool ExpressionReader::parse_vector(int depth) {
    if (!open_level(depth)) return false;
    Op op;
    op.code = Op::Code::vector;
    op.pos = tokens_.cur().pos;
    if (depth > 0) literal_ = false;
    take();
    for (int k = 0; k < 3; ++k) {
        if (k > 0) {
            if (tokens_.cur().kind != TokenKind::comma) {
                std::string message =
                    "a vector takes three numbers separated by commas, like <0, 1, 0>; "
                    "expected ',' but got " +
                    describe(tokens_.cur());
                // POV-Ray users' habit of writing a product without '*'.
                if (tokens_.cur().kind == TokenKind::word)
                    message +=
                        " (a name after a value does not multiply it: '2pi' and '2 pi' are "
                        "written '2 * pi')";
                sink_.error(tokens_.cur().pos, std::move(message));
                return false;
            }
            take();
        }
        if (!parse_sum(depth + 1)) return false;
    }
    if (tokens_.cur().kind != TokenKind::greater) {
        sink_.error(tokens_.cur().pos,
                    "a vector takes exactly three numbers, like <0, 1, 0>; expected '>' but got " +
                        describe(tokens_.cur()));
        return false;
    }
    take();
    apply(op);
    return true;
}

void ExpressionReader::apply(const Op& op, const ExprValue* value) {
    ++operations_;
    if (!evaluating_ || failed_) return;
    std::vector<Slot>& stack = stack_;  // reused: no allocation per value once warm
    // Held until the value is parsed whole: a syntax error after it wins.
    auto fail = [&](SourcePos pos, std::string message) {
        failed_ = true;
        failure_ = {Severity::error, pos, std::move(message)};
    };
    auto not_string = [&](const Slot& s) {
        if (s.value.kind != Kind::string) return true;
        fail(s.pos, "a string cannot be used in arithmetic, got " + kind_name(s.value));
        return false;
    };
    {
        switch (op.code) {
            case Op::Code::push:
                stack.push_back({*value, op.pos});
                return;
            case Op::Code::group:
                stack.back().pos = op.pos;
                return;
            case Op::Code::sign: {
                Slot& s = stack.back();
                if (!not_string(s)) return;
                if (op.negate) {
                    if (s.value.kind == Kind::number)
                        s.value.number = -s.value.number;
                    else
                        s.value.vector =
                            Vec3{-s.value.vector.x, -s.value.vector.y, -s.value.vector.z};
                }
                s.pos = op.pos;
                return;
            }
            case Op::Code::vector: {
                const std::size_t base = stack.size() - 3;
                Vec3 v{0.0};
                double* parts[3] = {&v.x, &v.y, &v.z};
                for (std::size_t k = 0; k < 3; ++k) {
                    const Slot& c = stack[base + k];
                    if (c.value.kind != Kind::number)
                        return fail(c.pos, "each component of a vector must be a number, got " +
                                               kind_name(c.value));
                    *parts[k] = c.value.number;
                }
                stack.resize(base);
                stack.push_back({vector(v), op.pos});
                return;
            }
            case Op::Code::call: {
                const FunctionSpec& f = kFunctions[op.function];
                const std::size_t base = stack.size() - op.count;
                const std::string name = quote(f.name);
                if (op.count < f.min_args || (f.max_args != 0 && op.count > f.max_args)) {
                    std::string wanted = f.max_args == 0 ? "at least " + std::to_string(f.min_args)
                                                         : std::to_string(f.min_args);
                    return fail(op.pos, name + " takes " + wanted + " argument" +
                                            (f.min_args == 1 && f.max_args == 1 ? "" : "s") +
                                            ", got " + std::to_string(op.count));
                }
                for (std::size_t k = base; k < stack.size(); ++k) {
                    const ExprValue& a = stack[k].value;
                    const Kind want = f.vectors ? Kind::vector : Kind::number;
                    if (a.kind != want)
                        return fail(op.pos, name + " takes " + (f.vectors ? "vectors" : "numbers") +
                                                ", got " + kind_name(a) + " as argument " +
                                                std::to_string(k - base + 1));
                }
                const ExprValue& a = stack[base].value;
                const ExprValue* b = op.count > 1 ? &stack[base + 1].value : nullptr;
                // The call as evaluated, for messages only: made when one is.
                auto args = [&] {
                    std::string s;
                    for (std::size_t k = base; k < stack.size(); ++k)
                        s += (k > base ? ", " : "") + shown(stack[k].value);
                    return std::string(f.name) + "(" + s + ")";
                };
                ExprValue r;
                switch (f.function) {
                    case Function::sin:
                        r = number(std::sin((a.number * kPi) / 180.0));
                        break;
                    case Function::cos:
                        r = number(std::cos((a.number * kPi) / 180.0));
                        break;
                    case Function::tan:
                        r = number(std::tan((a.number * kPi) / 180.0));
                        break;
                    case Function::asin:
                    case Function::acos:
                        if (!(a.number >= -1.0 && a.number <= 1.0))
                            return fail(op.pos, args() + ": the argument must be in [-1, 1]");
                        r = number(((f.function == Function::asin ? std::asin(a.number)
                                                                  : std::acos(a.number)) *
                                    180.0) /
                                   kPi);
                        break;
                    case Function::atan2: {
                        double d = 0.0;
                        if (a.number != 0.0 || b->number != 0.0) {
                            d = (std::atan2(a.number, b->number) * 180.0) / kPi;
                            if (d == -180.0) d = 180.0;  // the range is (-180, 180]
                        }
                        r = number(d);
                        break;
                    }
                    case Function::sqrt:
                        if (a.number < 0.0)
                            return fail(op.pos, args() + ": the square root of a negative number");
                        r = number(std::sqrt(a.number));
                        break;
                    case Function::abs:
                        r = number(std::fabs(a.number));
                        break;
                    case Function::floor:
                        r = number(std::floor(a.number));
                        break;
                    case Function::min:
                    case Function::max: {
                        double best = a.number;
                        for (std::size_t k = base + 1; k < stack.size(); ++k) {
                            const double x = stack[k].value.number;
                            if (f.function == Function::min ? x < best : x > best) best = x;
                        }
                        r = number(best);
                        break;
                    }
                    case Function::pow:
                        r = number(std::pow(a.number, b->number));
                        break;
                    case Function::length: {
                        const double d = dot3(a.vector, a.vector);
                        if (!std::isfinite(d))
                            return fail(op.pos, args() +
                                                    " is not finite: its squared length "
                                                    "overflows");
                        r = number(std::sqrt(d));
                        break;
                    }
                    case Function::normalize: {
                        const double d = dot3(a.vector, a.vector);
                        const Vec3& v = a.vector;
                        if (v.x == 0.0 && v.y == 0.0 && v.z == 0.0)
                            return fail(op.pos, args() + ": the zero vector has no direction");
                        if (d == 0.0)
                            return fail(op.pos, args() +
                                                    " is not finite: its squared length "
                                                    "underflows to 0");
                        const double s = 1.0 / std::sqrt(d);
                        if (!std::isfinite(d) || !std::isfinite(s))
                            return fail(op.pos, args() +
                                                    " is not finite: the length is out of "
                                                    "range");
                        r = vector(Vec3{a.vector.x * s, a.vector.y * s, a.vector.z * s});
                        break;
                    }
                    case Function::dot:
                        r = number(dot3(a.vector, b->vector));
                        break;
                    case Function::cross: {
                        const Vec3& u = a.vector;
                        const Vec3& w = b->vector;
                        r = vector(Vec3{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z,
                                        u.x * w.y - u.y * w.x});
                        break;
                    }
                }
                if (!finite(r)) return fail(op.pos, args() + " is not finite");
                stack.resize(base);
                stack.push_back({r, op.pos});
                return;
            }
            default:
                break;
        }
        // A binary operation: the right operand is on top.
        const Slot right = stack.back();
        stack.pop_back();
        Slot& left = stack.back();
        if (!not_string(left) || !not_string(right)) return;
        const ExprValue& a = left.value;
        const ExprValue& b = right.value;
        const char* symbol = op.code == Op::Code::add   ? "+"
                             : op.code == Op::Code::sub ? "-"
                             : op.code == Op::Code::mul ? "*"
                                                        : "/";
        auto written = [&] { return shown(a) + " " + symbol + " " + shown(b); };
        const bool va = a.kind == Kind::vector, vb = b.kind == Kind::vector;
        ExprValue r;
        switch (op.code) {
            case Op::Code::add:
            case Op::Code::sub: {
                if (va != vb)
                    return fail(op.pos,
                                "cannot " +
                                    std::string(op.code == Op::Code::add ? "add" : "subtract") +
                                    " a number and a vector: " + written());
                const double s = op.code == Op::Code::add ? 1.0 : -1.0;
                if (va) {
                    r = s > 0 ? vector(Vec3{a.vector.x + b.vector.x, a.vector.y + b.vector.y,
                                            a.vector.z + b.vector.z})
                              : vector(Vec3{a.vector.x - b.vector.x, a.vector.y - b.vector.y,
                                            a.vector.z - b.vector.z});
                } else {
                    r = number(s > 0 ? a.number + b.number : a.number - b.number);
                }
                break;
            }
            case Op::Code::mul:
                if (va && vb)
                    return fail(op.pos,
                                "cannot multiply two vectors (use dot or cross): " + written());
                if (va)
                    r = vector(
                        Vec3{a.vector.x * b.number, a.vector.y * b.number, a.vector.z * b.number});
                else if (vb)
                    r = vector(
                        Vec3{a.number * b.vector.x, a.number * b.vector.y, a.number * b.vector.z});
                else
                    r = number(a.number * b.number);
                break;
            default:  // div
                if (vb) return fail(op.pos, "cannot divide by a vector: " + written());
                // number_text writes -0 as 0; the divisor keeps its sign, which
                // tells which of two zeros the reader wrote or computed.
                if (b.number == 0.0)
                    return fail(op.pos, "division by zero: " + shown(a) + " / " +
                                            (std::signbit(b.number) ? "-0" : "0"));
                r = va ? vector(Vec3{a.vector.x / b.number, a.vector.y / b.number,
                                     a.vector.z / b.number})
                       : number(a.number / b.number);
                break;
        }
        if (!finite(r)) return fail(op.pos, "the result of " + written() + " is not finite");
        left.value = r;
    }
}

}  // namespace jt::lang

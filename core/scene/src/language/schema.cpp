#include "jtracer/schema.hpp"

#include "jtracer/value_text.hpp"
#include "language/quote.hpp"

#include <algorithm>
#include <cmath>

namespace jt {

std::string value_text(int value) {
    return std::to_string(value);
}
std::string value_text(double value) {
    return number_text(value);
}
std::string value_text(const Vec3& value) {
    return vector_text(value);
}

std::string value_text(const std::optional<Vec3>& value) {
    return value ? vector_text(*value) : std::string();
}

std::string value_text(const std::optional<double>& value) {
    return value ? number_text(*value) : std::string();
}

std::string value_text(const std::string& value) {
    // There are no escapes: what cannot stand in quotes becomes '_'.
    std::string written = value;
    for (char& c : written)
        if (!is_writable_string(std::string_view(&c, 1))) c = '_';
    return string_text(written);
}

std::string_view kind_description(ValueKind kind) {
    switch (kind) {
        case ValueKind::whole:
            return "a whole number like 640";
        case ValueKind::number:
            return "a number like 1.5";
        case ValueKind::vector:
            return "a vector like <0, 1, 0>";
        case ValueKind::colour:
            return "a colour like <1, 0.5, 0>";
        case ValueKind::string:
            return "a string like \"name\"";
    }
    return "a value";
}

RangeCheck<double> check_range(const ValueRange& range, double value) {
    if (!std::isfinite(value)) return {RangeVerdict::outside, value};
    if (value < range.low || (range.low_open && value == range.low))
        return range.clamp_low ? RangeCheck<double>{RangeVerdict::clamped, range.low}
                               : RangeCheck<double>{RangeVerdict::outside, value};
    if (value > range.high || (range.high_open && value == range.high))
        return range.clamp_high ? RangeCheck<double>{RangeVerdict::clamped, range.high}
                                : RangeCheck<double>{RangeVerdict::outside, value};
    return {RangeVerdict::inside, value};
}

RangeCheck<Vec3> check_range(const ValueRange& range, const Vec3& value) {
    // Every component strictly between the bounds (so finite, and not NaN):
    // inside, as most vectors are, without the bound-by-bound checks.
    auto between = [&](double x) { return range.low < x && x < range.high; };
    if (between(value.x) && between(value.y) && between(value.z)) {
        if (range.nonzero && value == Vec3(0.0)) return {RangeVerdict::outside, value};
        return {RangeVerdict::inside, value};
    }
    RangeCheck<Vec3> result{RangeVerdict::inside, value};
    for (int k = 0; k < 3; ++k) {
        const RangeCheck<double> component = check_range(range, value[k]);
        result.value[k] = component.value;
        result.verdict = std::max(result.verdict, component.verdict);
    }
    if (range.nonzero && value == Vec3(0.0)) result.verdict = RangeVerdict::outside;
    return result;
}

RangeVerdict check_range(const ValueRange& range, std::string_view value) {
    if (range.nonempty && value.empty()) return RangeVerdict::outside;
    if (!range.choices.empty() &&
        std::find(range.choices.begin(), range.choices.end(), value) == range.choices.end())
        return RangeVerdict::outside;
    return RangeVerdict::inside;
}

std::string range_rule(const ValueRange& range, ValueKind kind, std::string_view unit) {
    if (range.nonzero) return "must not be the zero vector";
    if (range.nonempty) return "must not be empty";
    if (!range.choices.empty()) {
        std::string rule = "must be ";
        for (std::size_t i = 0; i < range.choices.size(); ++i) {
            if (i > 0) rule += i + 1 == range.choices.size() ? " or " : ", ";
            rule.append(1, '"').append(range.choices[i]).append(1, '"');
        }
        return rule;
    }
    // Only the bounds past which a value is an error; clamping bounds are not rules.
    const bool low = !range.clamp_low;
    const bool high = !range.clamp_high;
    const std::string l = number_text(range.low), h = number_text(range.high);
    std::string u;  // built with append: GCC 12 warns falsely on "literal" + std::string&&
    if (!unit.empty()) u.append(1, ' ').append(unit);
    if (low && high) {
        if (range.low_open && range.high_open)
            return "must be between " + l + " and " + h + u + " (exclusive)";
        if (range.low_open) return "must be greater than " + l + " and at most " + h + u;
        if (range.high_open) return "must be at least " + l + " and less than " + h + u;
        return (kind == ValueKind::whole ? "must be a whole number from " : "must be from ") + l +
               " to " + h + u;
    }
    if (low)
        return range.low_open ? "must be greater than " + l + u : "must be " + l + u + " or more";
    if (high)
        return range.high_open ? "must be less than " + h + u : "must be " + h + u + " or less";
    return "must be finite";
}

namespace schema_detail {

bool is_finite(double value) {
    return std::isfinite(value);
}
bool is_finite(const Vec3& v) {
    return all_finite(v);
}

std::string not_finite_message(std::string_view name, std::string_view got) {
    return lang::quote(name) + " must be finite, got " + std::string(got);
}

std::string out_of_range_message(std::string_view name, const ValueRange& range, ValueKind kind,
                                 std::string_view unit, std::string_view got) {
    std::string message = lang::quote(name) + " " + range_rule(range, kind, unit);
    if (!got.empty()) message.append(", got ").append(got);
    return message;
}

std::string past_clamp_message(std::string_view name, const ValueRange& range, ValueKind kind,
                               std::string_view got, std::string_view clamped_to) {
    std::string message = lang::quote(name) + " " + std::string(got);
    if (kind == ValueKind::colour) {
        message += " is outside the colour range [" + number_text(range.low) + ", " +
                   number_text(range.high) + "]";
        if (!clamped_to.empty()) message.append(": clipped to ").append(clamped_to);
        return message;
    }
    const std::string l = number_text(range.low), h = number_text(range.high);
    if (range.clamp_low && range.clamp_high)
        message += " is outside " + l + ".." + h;
    else if (range.clamp_high)
        message += " is more than " + h;
    else
        message += " is less than " + l;
    if (!clamped_to.empty()) message.append(": clamped to ").append(clamped_to);
    return message;
}

}  // namespace schema_detail

}  // namespace jt

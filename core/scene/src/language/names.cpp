#include "language/names.hpp"

#include "jtracer/schema.hpp"
#include "language/expression.hpp"

#include <algorithm>
#include <array>

namespace jt::lang {

namespace {

// The language 1.3 statements, beside the block keywords the schema lists.
constexpr std::array<std::string_view, 5> kReservedWords{"clock", "pi", kIncludeKeyword,
                                                         kDefineKeyword, "material"};

}  // namespace

bool is_block_keyword(std::string_view word) {
    const auto keywords = block_keywords();
    return std::find(keywords.begin(), keywords.end(), word) != keywords.end();
}

bool is_reserved_name(std::string_view name) {
    if (std::find(kReservedWords.begin(), kReservedWords.end(), name) != kReservedWords.end())
        return true;
    return is_block_keyword(name) || is_function_name(name);
}

const Symbol* NameTable::find(std::string_view name) const {
    auto it = symbols_.find(name);
    return it == symbols_.end() ? nullptr : &it->second;
}

Symbol* NameTable::find(std::string_view name) {
    auto it = symbols_.find(name);
    return it == symbols_.end() ? nullptr : &it->second;
}

Symbol& NameTable::add(std::string_view name) {
    return symbols_.try_emplace(std::string(name)).first->second;
}

void NameTable::set_string(Symbol& symbol, std::string text) {
    symbol.text = std::move(text);
    symbol.value.kind = ExprValue::Kind::string;
    symbol.value.text = symbol.text;
}

std::vector<std::string_view> NameTable::names() const {
    std::vector<std::string_view> out;
    out.reserve(symbols_.size());
    for (const auto& [name, symbol] : symbols_) out.push_back(name);
    return out;
}

}  // namespace jt::lang

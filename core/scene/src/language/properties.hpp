#pragma once
// Reading one property's value into the scene model: kind checks, ranges,
// int truncation, colour clipping, duplicate warnings (docs/language.md §3.2-§4).
// What each block accepts comes from the schema (jtracer/schema.hpp).

#include "jtracer/scene.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/source_map.hpp"
#include "language/diagnostic_sink.hpp"

#include <cstddef>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace jt::lang {

// A value read and evaluated (docs/language.md §15.3): a literal, a name or
// an expression, already checked for everything but the property's kind.
struct Value {
    enum class Form { none, bad, number, vector, string };
    Form form = Form::none;
    double number = 0.0;
    Vec3 vector{0.0};
    std::string_view text;  // a string's contents, or a literal number's spelling ("-1.50")
    TextSpan span;          // the whole value as written
    SourcePos end;          // just past the value
    ValueOrigin origin = ValueOrigin::literal;
};

struct Property {
    std::string_view name;
    TextSpan name_span;
    Value value;
};

// The first line of each property name a block has set, for repeat warnings.
// A block knows a handful of names at most, so they live inline: a million
// spheres must not cost a million heap allocations here.
class FirstLines {
  public:
    // Provided, so that a value-initialised FirstLines (an OpenBlock's) is not
    // zeroed first: a block is opened for every primitive and its material,
    // and clearing the entries cost more than reading most blocks' names.
    FirstLines() noexcept {}

    // The line where `name` was first set, or 0. Both inline: they run for
    // every property, and a call each was 3% of a parse.
    int find(std::string_view name) const {
        for (std::size_t i = 0; i < count_; ++i)
            if (same_name({inline_[i].name, inline_[i].size}, name)) return inline_[i].line;
        for (const auto& [known, line] : more_)
            if (same_name(known, name)) return line;
        return 0;
    }
    void add(std::string_view name, int line) {
        if (count_ < inline_capacity)
            inline_[count_++] = {name.data(), name.size(), line};
        else
            more_.emplace_back(name, line);
    }

  private:
    struct Entry {  // trivial, so the array is left unwritten until used
        const char* name;
        std::size_t size;
        int line;
    };
    static constexpr std::size_t inline_capacity = 12;
    Entry inline_[inline_capacity];  // the first count_ are set
    std::size_t count_ = 0;
    std::vector<std::pair<std::string_view, int>> more_;  // never used by known names
};

// A block being read: its source record, where its property records are
// collected until its '}', and the names it has set.
struct OpenBlock {
    BlockSource& source;
    std::vector<PropertySource>& properties;
    FirstLines first_lines{};
};

// Applies well-formed properties to the part of the scene they belong to,
// reporting unknown names, wrong kinds and values out of range, and records
// each applied property in the block's source.
// Whether a block with this keyword has a property of this name (or alias).
// `cameras` and `scene` have none; a keyword of no block with properties
// answers true, leaving the name to that block's reader.
bool block_has_property(std::string_view keyword, std::string_view name);

class PropertyReader {
  public:
    explicit PropertyReader(DiagnosticSink& sink) : sink_(sink) {}

    void apply(RenderSettings& settings, OpenBlock& block, const Property& p);
    void apply(Camera& camera, OpenBlock& block, const Property& p);
    void apply(Shape& shape, OpenBlock& block, const Property& p);
    void apply(Material& material, OpenBlock& block, const Property& p);
    void apply(PointLight& light, OpenBlock& block, const Property& p);
    void apply(std::vector<TransformOp>& transforms, OpenBlock& block, const Property& p);

  private:
    template <class Block>
    void apply_block(Block& target, OpenBlock& block, const Property& p);
    // Reads the value into the member `spec` sets in `target`; false (reported)
    // when it is of the wrong kind or outside the property's range.
    template <class Block>
    bool read(const PropertySpec<Block>& spec, const Property& p, Block& target);
    void kind_error(const Property& p, ValueKind expected);
    void unknown_property(const Property& p, std::string_view keyword,
                          std::span<const std::string_view> names);
    // Records the property in `block` under `as_name`, which must be in static
    // storage (one of the known names); warns when the block already set it.
    void record(OpenBlock& block, const Property& p, std::string_view as_name, bool warn_repeat);

    DiagnosticSink& sink_;
};

}  // namespace jt::lang

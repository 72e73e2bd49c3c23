// The scene block: its primitives and lights, read into arrays sized once
// from the counts made before the parse, with the pages of a large one
// faulted in beside it; primitives of equal finishes share one, and those
// that read no `clock` are taken from an earlier parse (ParseOptions::earlier).

#include "io/page_warmer.hpp"
#include "io/reserve_records.hpp"
#include "jtracer/schema.hpp"
#include "language/block_body.hpp"
#include "language/scene_parser.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace jt::lang {
namespace {

// How often ParseOptions::text_passed hears of the parse's progress: often
// enough that little is held behind it, rarely enough to cost nothing.
constexpr std::size_t text_passed_step = std::size_t{4} << 20;

// The default shape a primitive keyword opens, or nullopt for another word.
template <std::size_t I = 0>
inline std::optional<Shape> shape_of_keyword(std::string_view word) {
    if constexpr (I == std::variant_size_v<Shape>) {
        return std::nullopt;
    } else {
        using Alternative = ShapeAlternative<I>;
        if (same_name(word, schema_of<Alternative>().keyword)) return Shape(Alternative{});
        return shape_of_keyword<I + 1>(word);
    }
}

}  // namespace

void SceneParser::parse_scene() {
    BlockSource block;
    SceneChildren children;
    if (!open_block(block)) return;
    // Only the first scene block gets the hint: it was counted over the whole text.
    std::size_t hint = std::exchange(primitive_hint_, 0);
    // The earlier parse's primitives stay where they are, each replaced
    // by the one read at its index unless taken: a frame holds one array.
    if (earlier_) children.primitives = std::move(earlier_->primitives);
    // A large array's fresh pages are faulted in beside the parse (io/page_warmer.hpp).
    PageWarmer warmer;
    if (children.primitives.empty()) {
        reserve_records(children.primitives, hint);
        warmer.start(children.primitives.data(),
                     children.primitives.capacity() * sizeof(Primitive));
    }
    if (source_map_) reserve_records(children.primitive_sources, hint);
    ScenePartThreads parts;
    // The warmer already has a second core faulting in the scene's array,
    // the most of a huge scene's parse: parts would write it twice (their
    // own arrays, then the scene's), which measured slower on a million spheres.
    if (hint > 0 && !warmer.warming()) start_scene_parts(parts, hint);
    // Threads reading parts read ahead of this one, and a part not taken
    // is read again here: no text may be given back while they run.
    if (!parts.empty()) reports_text_passed_ = false;
    parse_body(
        block, scene_blocks(), [&](const Property& p) { only_blocks(block, scene_blocks(), p); },
        [&] {
            if (!take_scene_part(parts, children)) parse_scene_child(children, warmer);
        });
    parts.stop();
    if (result_.source.scene) {
        sink_.warning(
            block.keyword_span.pos,
            "another 'scene' block: only the last one is used, so the one at " +
                include_.line_from(result_.source.scene->keyword_span.pos, block.keyword_span.pos) +
                " is ignored");
    }
    std::vector<Primitive>& primitives = children.primitives;
    primitives.erase(primitives.begin() + static_cast<std::ptrdiff_t>(children.placed),
                     primitives.end());
    warmer.finish(primitives.data(), primitives.size() * sizeof(Primitive));
    result_.scene.primitives = std::move(primitives);
    result_.primitive_readings = std::move(children.readings);
    result_.scene.lights = std::move(children.lights);
    result_.source.primitives = std::move(children.primitive_sources);
    result_.source.lights = std::move(children.light_sources);
    result_.source.scene = std::move(block);
}

void SceneParser::parse_scene_child(SceneChildren& into, PageWarmer& warmer) {
    std::string_view kind = cur_->text;
    if (same_name(kind, schema_of<PointLight>().keyword)) {
        BlockSource light_block;
        PointLight light;
        if (!parse_property_block(light_block, 0, light)) return;
        into.lights.push_back(light);
        into.light_sources.push_back(std::move(light_block));
    } else if (std::optional<Shape> shape = shape_of_keyword(kind)) {
        if (take_earlier(into.primitives, into.placed, into.readings)) return;
        const std::uint32_t file = cur_->pos.file;
        const auto keyword = static_cast<std::uint32_t>(cur_->offset);
        const std::uint64_t clock_reads = expressions_.clock_reads();
        Primitive primitive;
        primitive.shape = std::move(*shape);
        BlockSource primitive_block;
        if (!open_block(primitive_block, keyword_of(primitive.shape), /*behind=*/true)) return;
        in_primitive_ = true;
        primitive.material.finish = take_scratch_finish();
        read_properties(primitive_block, 0,
                        [&](OpenBlock& open) { parse_primitive_body(primitive, open); });
        in_primitive_ = false;
        if (!keep_primitives_) return;
        share_finish(primitive.material);
        if (into.placed < into.primitives.size())
            into.primitives[into.placed] = std::move(primitive);
        else
            into.primitives.push_back(std::move(primitive));
        ++into.placed;
        warmer.filled(into.placed * sizeof(Primitive));
        report_text_passed();
        if (source_map_) into.primitive_sources.push_back(primitive_block);
        if (record_readings_)
            into.readings.push_back({file, keyword, static_cast<std::uint32_t>(cur_->offset),
                                     cur_->pos, expressions_.clock_reads() > clock_reads});
    } else {
        unknown_block("in '" + std::string(kSceneKeyword) + "'", scene_statements());
    }
}

bool SceneParser::take_earlier(std::vector<Primitive>& primitives, std::size_t& placed,
                               std::vector<PrimitiveReading>& readings) {
    if (!earlier_ || placed >= earlier_->readings.size() || placed >= primitives.size())
        return false;
    const PrimitiveReading& reading = earlier_->readings[placed];
    if (reading.reads_clock || reading.file != cur_->pos.file || reading.keyword != cur_->offset)
        return false;
    ++placed;
    if (record_readings_) readings.push_back(reading);
    reading_->resume_at(reading.resume, reading.resume_pos);
    reading_->next(*cur_);
    reading_->next(*next_);
    return true;
}

void SceneParser::report_text_passed() {
    if (!reports_text_passed_ || reading_ != &lexer_ || cur_->pos.file != 0 ||
        cur_->offset < next_text_passed_)
        return;
    next_text_passed_ = cur_->offset + text_passed_step;
    options_.text_passed(cur_->offset);
}

inline Shared<Finish> SceneParser::take_scratch_finish() {
    if (scratch_finish_.unique())
        scratch_finish_.edit() = Finish{};
    else
        scratch_finish_ = Shared<Finish>(Finish{});
    return std::move(scratch_finish_);
}

inline void SceneParser::share_finish(Material& material) {
    Shared<Finish> read = material.finish;
    finishes_.share(material.finish);
    if (!material.finish.shares_with(read)) scratch_finish_ = std::move(read);
}

}  // namespace jt::lang

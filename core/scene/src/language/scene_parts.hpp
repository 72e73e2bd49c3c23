#pragma once
// Where a large scene block may be read by several threads at once.
//
// A scene block is a list of primitives and lights, each read alone from the
// names defined before the block: a part of the list can be read on a thread
// of its own. Where a part begins is only guessed here, from the keywords
// before a '{'; the parser takes a part's reading only once its own reading reaches that
// offset as the next block of the scene, and only if the part gave not one
// diagnostic. Otherwise it reads on itself, so the result is always the one
// a single reading gives.

#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <atomic>
#include <cstddef>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

namespace jt::lang {

// A scene block shorter than this is read by one thread: starting another
// costs more than it saves (a MiB is about 7,000 spheres, 3-4 ms to read).
inline constexpr std::size_t kSceneBytesPerPart = std::size_t{1} << 20;
// More parts than this gain little: the merge and the page faults of the
// scene's arrays are not shared among threads.
inline constexpr unsigned kMaxSceneParts = 8;

// How many parts to read the `bytes` after a scene block's '{' in, with at
// most `threads` threads (0: one a hardware thread).
unsigned scene_part_count(std::size_t bytes, unsigned threads);

// Offsets where parts 2..`parts` of the text after `from` might begin, one
// at or after each k/`parts` of it: a primitive's or a light's keyword, then
// '{'. Any such word may be in a comment, a string or a block where it means
// nothing: the parser checks. Fewer when the text has none there; increasing.
std::vector<std::size_t> guess_scene_part_starts(std::string_view text, std::size_t from,
                                                 unsigned parts);

// The primitives and lights of a scene block, as read so far.
struct SceneChildren {
    std::vector<Primitive> primitives;
    std::vector<PointLight> lights;
    std::vector<BlockSource> primitive_sources, light_sources;
    std::vector<PrimitiveReading> readings;
    std::size_t placed = 0;  // primitives read (an earlier parse's may follow them)
};

// What a thread made of one part of a large scene block.
struct ScenePart {
    std::size_t begin = 0;  // the offset of its first block's keyword
    std::size_t end = 0;    // it ends at the first block's keyword at or past this
    bool usable = false;    // read without a diagnostic to a place where a part may end
    SceneChildren children;
    // Its primitives in arrays of a mapping each, the last in `children`: the
    // parser moves them into the scene's array one at a time, freeing each,
    // so that the part adds at most one to the peak.
    std::vector<std::vector<Primitive>> filled;
    std::vector<PropertySource> properties;  // its blocks' records, from index 0
    std::vector<BlockSource> nested;         // its primitives' material and transform blocks
    bool reads_clock = false;
    std::size_t stop = 0;  // the token it ended at: the next part's keyword or the block's '}'
    SourcePos stop_pos;
};

// A part's primitives are kept in arrays of about 32 MiB: each its own
// mapping (io/reserve_records.hpp), given back to the system when freed.
inline constexpr std::size_t kPartArrayPrimitives = (std::size_t{32} << 20) / sizeof(Primitive);

// The threads reading the parts of a scene block after the first, which the
// parser reads itself.
class ScenePartThreads {
  public:
    ScenePartThreads() = default;
    ScenePartThreads(const ScenePartThreads&) = delete;
    ScenePartThreads& operator=(const ScenePartThreads&) = delete;
    ~ScenePartThreads() { stop(); }

    template <class Read>
    void start(std::vector<ScenePart> parts, Read read) {
        parts_ = std::move(parts);
        threads_.reserve(parts_.size());
        for (ScenePart& part : parts_) {
            try {
                threads_.emplace_back([&part, read] { read(part); });
            } catch (const std::system_error&) {
                // No thread to be had: the parser reads the rest itself.
                parts_.resize(threads_.size());
                break;
            }
        }
    }
    // The part that begins at `offset`, read to its end, or nullptr. Parts that
    // begin before it are dropped: the reading went past where they begin, so
    // their guessed starts were not blocks of the scene.
    ScenePart* take_at(std::size_t offset) {
        while (next_ < parts_.size() && parts_[next_].begin < offset) ++next_;
        if (next_ == parts_.size() || parts_[next_].begin != offset) return nullptr;
        threads_[next_].join();
        return &parts_[next_++];
    }
    // Tells the threads still reading that their parts will not be taken, and waits.
    void stop() {
        cancelled_.store(true, std::memory_order_relaxed);
        for (std::thread& t : threads_)
            if (t.joinable()) t.join();
    }
    const std::atomic<bool>& cancelled() const { return cancelled_; }
    bool empty() const { return next_ == parts_.size(); }

  private:
    std::vector<ScenePart> parts_;  // never grown once threads hold their parts
    std::vector<std::thread> threads_;
    std::size_t next_ = 0;
    std::atomic<bool> cancelled_ = false;
};

}  // namespace jt::lang

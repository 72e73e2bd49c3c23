#include "jtracer/render_job.hpp"

#include "render/prepared_frame.hpp"
#include "render/prepared_scene.hpp"
#include "render/render_passes.hpp"

#include "jtracer/validate.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <mutex>

namespace jt {

namespace {

PixelRect clip_region(const RenderOptions& o) {
    PixelRect full{0, 0, std::max(o.width, 0), std::max(o.height, 0)};
    if (!o.region) return full;
    return {std::clamp(o.region->x0, 0, full.x1), std::clamp(o.region->y0, 0, full.y1),
            std::clamp(o.region->x1, 0, full.x1), std::clamp(o.region->y1, 0, full.y1)};
}

// Lowers the OS priority of every thread that enters the arena (on Linux the
// nice value belongs to the thread). Nothing else changes, so the pixels are
// the same. An unprivileged process cannot raise a nice value again: the
// oneTBB workers stay lowered for the rest of the process.
class BackgroundPriority : public tbb::task_scheduler_observer {
  public:
    static constexpr int nice_value = 10;

    explicit BackgroundPriority(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
        observe(true);
    }
    ~BackgroundPriority() override { observe(false); }
    void on_scheduler_entry(bool) override {
        errno = 0;
        const int current = getpriority(PRIO_PROCESS, 0);
        if (errno == 0 && current < nice_value) setpriority(PRIO_PROCESS, 0, nice_value);
    }
};

}  // namespace

struct RenderJob::State {
    std::shared_ptr<const PreparedFrame> frame;  // null without a scene
    RenderOptions options;
    PixelRect region;
    std::vector<RenderPass> passes;
    std::uint64_t total_work = 0;
    tbb::task_arena arena;
    std::optional<BackgroundPriority> background;  // observes `arena`, so declared after it
    // Running sums of clamped samples, one colour a pixel of the region; only
    // when samples > 1.
    std::vector<Colour> sums;

    std::atomic<bool> cancel_requested{false};
    std::atomic<std::uint64_t> rays{0};
    std::atomic<std::uint64_t> work_done{0};

    mutable std::mutex image_mutex;  // guards image and dirty
    Image8 image;                    // the region's pixels only: a small region needs little memory
    bool image_taken = false;        // by take_image(): no pixels are left
    std::optional<PixelRect> dirty;

    // Tiles of pass `tiles_pass` already published. A pass cancelled part way
    // keeps them, so that resume() renders only the rest.
    std::vector<std::uint8_t> tiles_done;
    std::size_t tiles_pass = SIZE_MAX;
    std::uint64_t work_before_pass = 0;

    mutable std::mutex progress_mutex;  // guards the fields below
    std::size_t next_pass = 0;
    int samples_done = 0;
    double seconds = 0.0;  // in finished or cancelled passes
    std::optional<std::chrono::steady_clock::time_point> pass_started;  // while one runs
    bool cancelled = false;

    // False when cancelled before the tile was whole (nothing of it is kept).
    bool run_tile(const RenderPass& pass, const PixelRect& tile);
    void publish(const PixelRect& tile, const std::vector<std::uint8_t>& rgb);

    std::size_t sum_index(int x, int y) const {
        return static_cast<std::size_t>(y - region.y0) * static_cast<std::size_t>(region.width()) +
               static_cast<std::size_t>(x - region.x0);
    }
    // The full-size image, black outside the region; image_mutex held.
    Image8 full_image() const {
        if (image_taken) return Image8();
        // The whole frame: a plain copy, without zeroing megabytes first.
        if (region == PixelRect{0, 0, options.width, options.height}) return image;
        Image8 full(options.width, options.height);  // not a copy: see Image8's constructor
        const std::size_t row_bytes = static_cast<std::size_t>(region.width()) * 3;
        for (int y = region.y0; y < region.y1; ++y)
            std::copy_n(image.pixel(0, y - region.y0), row_bytes, full.pixel(region.x0, y));
        return full;
    }
};

void RenderJob::State::publish(const PixelRect& tile, const std::vector<std::uint8_t>& rgb) {
    std::lock_guard lock(image_mutex);
    const std::size_t row_bytes = static_cast<std::size_t>(tile.width()) * 3;
    for (int y = tile.y0; y < tile.y1; ++y)
        std::copy_n(&rgb[static_cast<std::size_t>(y - tile.y0) * row_bytes], row_bytes,
                    image.pixel(tile.x0 - region.x0, y - region.y0));
    dirty = holding_both(dirty, tile);
}

bool RenderJob::State::run_tile(const RenderPass& pass, const PixelRect& tile) {
    if (cancel_requested.load(std::memory_order_relaxed)) return false;
    TileBuffer out(tile);
    // The new sums stay in the tile until it is whole: a tile cancelled part
    // way leaves `sums` as they were, so its pass can run again after resume().
    const bool accumulate = !sums.empty() && pass.block == 1;
    if (accumulate && pass.sample_begin > 0) {
        out.sums.resize(static_cast<std::size_t>(tile.width()) * tile.height());
        for (int y = tile.y0; y < tile.y1; ++y)
            std::copy_n(&sums[sum_index(tile.x0, y)], tile.width(),
                        &out.sums[out.index(tile.x0, y)]);
    }
    std::uint64_t tile_rays = 0;
    const bool whole = trace_tile(*frame, pass, out, cancel_requested, tile_rays);
    rays.fetch_add(tile_rays, std::memory_order_relaxed);
    if (!whole) return false;
    if (accumulate)
        for (int y = tile.y0; y < tile.y1; ++y)
            std::copy_n(&out.sums[out.index(tile.x0, y)], tile.width(),
                        &sums[sum_index(tile.x0, y)]);
    publish(tile, out.rgb);
    return true;
}

RenderJob::RenderJob(std::shared_ptr<const PreparedScene> scene, RenderOptions options)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    options = frame_options(options);
    s.options = options;
    s.region = clip_region(options);
    if (scene) {
        s.frame = prepare_frame(std::move(scene), options);
        s.passes = plan_passes(s.region, options.samples, options.previews);
    }
    for (const RenderPass& p : s.passes) s.total_work += p.work;
    if (options.threads > 0) s.arena.initialize(options.threads);
    if (options.background) s.background.emplace(s.arena);
    s.image = Image8(s.region.width(), s.region.height());
    if (options.samples > 1 && !s.region.empty())
        s.sums.assign(static_cast<std::size_t>(s.region.width()) * s.region.height(), Colour(0.0));
}

RenderJob::~RenderJob() = default;

bool RenderJob::run_pass() {
    State& s = *state_;
    std::size_t index;
    {
        std::lock_guard lock(s.progress_mutex);
        if (s.cancelled || s.next_pass >= s.passes.size()) return false;
        index = s.next_pass;
        s.pass_started = std::chrono::steady_clock::now();
    }
    const RenderPass& pass = s.passes[index];
    const std::vector<PixelRect> tiles = cut_tiles(s.region, pass.block, tile_blocks);
    if (s.tiles_pass != index) {  // a fresh pass, not one resumed after a cancel
        s.tiles_pass = index;
        s.tiles_done.assign(tiles.size(), 0);
        s.work_before_pass = s.work_done.load();
    }
    s.arena.execute([&] {
        // Built by the first full-resolution pass, off the thread that made
        // the job, on the job's threads, and before the pass's tiles run
        // (prepared_frame.hpp says why).
        if (pass.block == 1) static_cast<void>(s.frame->view_table());
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    if (s.tiles_done[i]) continue;
                    if (!s.run_tile(pass, tiles[i])) return;
                    s.tiles_done[i] = 1;
                    // Work in rays of this pass, spread evenly over its tiles.
                    const PixelRect& t = tiles[i];
                    std::uint64_t units =
                        pass.block > 1
                            ? static_cast<std::uint64_t>((t.width() + pass.block - 1) /
                                                         pass.block) *
                                  static_cast<std::uint64_t>((t.height() + pass.block - 1) /
                                                             pass.block)
                            : static_cast<std::uint64_t>(t.width()) * t.height() *
                                  static_cast<std::uint64_t>(pass.sample_end - pass.sample_begin);
                    s.work_done.fetch_add(units, std::memory_order_relaxed);
                }
            },
            tbb::simple_partitioner());
    });
    std::lock_guard lock(s.progress_mutex);
    s.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - *s.pass_started).count();
    s.pass_started.reset();
    if (s.cancel_requested.load()) {
        s.cancelled = true;
        return false;
    }
    // Exact bookkeeping once the pass is whole (tile rounding may differ).
    s.work_done.store(s.work_before_pass + pass.work);
    if (pass.block == 1) s.samples_done = pass.sample_end;
    s.next_pass = index + 1;
    return true;
}

void RenderJob::run() {
    while (run_pass()) {
    }
}

void RenderJob::cancel() {
    state_->cancel_requested.store(true);
}

void RenderJob::resume() {
    State& s = *state_;
    std::lock_guard lock(s.progress_mutex);
    s.cancel_requested.store(false);
    s.cancelled = false;
}

RenderProgress RenderJob::progress() const {
    const State& s = *state_;
    RenderProgress p;
    std::lock_guard lock(s.progress_mutex);
    p.pass_count = static_cast<int>(s.passes.size());
    p.finished = s.next_pass >= s.passes.size() && !s.cancelled;
    std::size_t current = std::min(s.next_pass, s.passes.empty() ? 0 : s.passes.size() - 1);
    p.pass = static_cast<int>(current);
    if (!s.passes.empty()) p.pass_name = s.passes[current].name;
    p.fraction = s.total_work == 0 ? (p.finished ? 1.0 : 0.0)
                                   : std::min(1.0, static_cast<double>(s.work_done.load()) /
                                                       static_cast<double>(s.total_work));
    if (p.finished) p.fraction = 1.0;
    p.samples_done = s.samples_done;
    p.rays = s.rays.load();
    p.seconds = s.seconds;
    if (s.pass_started)
        p.seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - *s.pass_started)
                .count();
    p.cancelled = s.cancelled || s.cancel_requested.load();
    return p;
}

std::optional<PixelRect> RenderJob::fetch_updates(Image8& display) {
    State& s = *state_;
    std::lock_guard lock(s.image_mutex);
    if (s.image_taken) return std::nullopt;
    if (display.width != s.options.width || display.height != s.options.height ||
        display.rgb.size() != static_cast<std::size_t>(s.options.width) * s.options.height * 3) {
        display = s.full_image();
        s.dirty.reset();
        return PixelRect{0, 0, s.options.width, s.options.height};
    }
    if (!s.dirty) return std::nullopt;
    PixelRect r = *s.dirty;
    s.dirty.reset();
    const std::size_t row_bytes = static_cast<std::size_t>(r.width()) * 3;
    for (int y = r.y0; y < r.y1; ++y)
        std::copy_n(s.image.pixel(r.x0 - s.region.x0, y - s.region.y0), row_bytes,
                    display.pixel(r.x0, y));
    return r;
}

Image8 RenderJob::image() const {
    std::lock_guard lock(state_->image_mutex);
    return state_->full_image();
}

Image8 RenderJob::take_image() {
    State& s = *state_;
    std::lock_guard lock(s.image_mutex);
    Image8 taken = s.region == PixelRect{0, 0, s.options.width, s.options.height}
                       ? std::move(s.image)
                       : s.full_image();
    s.image = Image8();
    s.image_taken = true;
    s.dirty.reset();
    return taken;
}

Image8 RenderJob::region_image() const {
    std::lock_guard lock(state_->image_mutex);
    return state_->image;
}

const RenderOptions& RenderJob::options() const {
    return state_->options;
}

Image8 render_image(std::shared_ptr<const PreparedScene> scene, RenderOptions options) {
    options.previews = false;
    RenderJob job(std::move(scene), options);
    job.run();
    return job.take_image();
}

RenderOptions render_options_for(const Scene& scene) {
    RenderOptions options;
    options.width = scene.settings.width;
    options.height = scene.settings.height;
    options.samples = scene.settings.samples;
    options.camera = active_camera_index(scene);
    return options;
}

int find_camera(const Scene& scene, std::string_view name) {
    if (name.empty()) return -1;
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == name) return static_cast<int>(i);
    return -1;
}

}  // namespace jt

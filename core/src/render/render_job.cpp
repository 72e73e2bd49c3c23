#include "jtracer/render_job.hpp"

#include "render/camera_rays.hpp"
#include "render/prepared_scene.hpp"
#include "render/render_passes.hpp"
#include "render/sample_pattern.hpp"
#include "render/trace.hpp"

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

constexpr int tile_blocks = 32;  // a tile is 32 x 32 rays

double clamp01(double c) {
    return c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0;
}

Colour clamp01(const Colour& c) {
    return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
}

PixelRect unite(const std::optional<PixelRect>& a, const PixelRect& b) {
    if (!a) return b;
    return {std::min(a->x0, b.x0), std::min(a->y0, b.y0), std::max(a->x1, b.x1),
            std::max(a->y1, b.y1)};
}

PixelRect clip_region(const RenderOptions& o) {
    PixelRect full{0, 0, std::max(o.width, 0), std::max(o.height, 0)};
    if (!o.region) return full;
    return {std::clamp(o.region->x0, 0, full.x1), std::clamp(o.region->y0, 0, full.y1),
            std::clamp(o.region->x1, 0, full.x1), std::clamp(o.region->y1, 0, full.y1)};
}

// Camera rays through a camera that cannot form a frame (no camera, look_at
// equal to position) come out non-finite, and trace_ray turns them into the
// background rather than NaN.
CameraFrame frame_for(const PreparedScene& scene, const RenderOptions& o) {
    Camera camera;
    if (o.camera >= 0 && o.camera < static_cast<int>(scene.cameras.size()))
        camera = scene.cameras[static_cast<std::size_t>(o.camera)];
    else
        camera.look_at = camera.position;
    return camera_frame(camera, std::max(o.width, 1), std::max(o.height, 1));
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

// The quantized pixels of one tile, row by row, before they are published.
struct TileBuffer {
    PixelRect rect;
    std::vector<std::uint8_t> rgb;
    std::vector<Colour> sums;  // the tile's new running sums, when the job accumulates

    explicit TileBuffer(const PixelRect& r)
        : rect(r), rgb(static_cast<std::size_t>(r.width()) * r.height() * 3) {}
    void put(int x, int y, const Colour& c) {
        std::uint8_t* p = &rgb[(static_cast<std::size_t>(y - rect.y0) * rect.width() +
                                static_cast<std::size_t>(x - rect.x0)) *
                               3];
        p[0] = quantize_channel(c.x);
        p[1] = quantize_channel(c.y);
        p[2] = quantize_channel(c.z);
    }
};

}  // namespace

struct RenderJob::State {
    std::shared_ptr<const PreparedScene> scene;
    RenderOptions options;
    CameraFrame camera;
    // Shapes by direction around camera.position, for the primary rays; built
    // by the first full-resolution pass, off the thread that made the job.
    DirectionTable camera_table;
    std::once_flag camera_table_built;
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
    bool render_tile(const RenderPass& pass, const PixelRect& tile);
    // Both return false when cancelled part way.
    bool render_blocks(int block, const PixelRect& tile, TileBuffer& out, std::uint64_t& rays);
    bool render_samples(const RenderPass& pass, const PixelRect& tile, TileBuffer& out,
                        std::uint64_t& rays);
    void publish(const PixelRect& tile, const std::vector<std::uint8_t>& rgb);

    std::size_t sum_index(int x, int y) const {
        return static_cast<std::size_t>(y - region.y0) * static_cast<std::size_t>(region.width()) +
               static_cast<std::size_t>(x - region.x0);
    }
    // The full-size image, black outside the region; image_mutex held.
    Image8 full_image() const {
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
    dirty = unite(dirty, tile);
}

bool RenderJob::State::render_blocks(int b, const PixelRect& tile, TileBuffer& out,
                                     std::uint64_t& rays) {
    for (int by = tile.y0 / b * b; by < tile.y1; by += b) {
        if (cancel_requested.load(std::memory_order_relaxed)) return false;
        for (int bx = tile.x0 / b * b; bx < tile.x1; bx += b) {
            // The centre of the block, as far as the image reaches.
            double cx = bx + 0.5 * (std::min(bx + b, options.width) - bx);
            double cy = by + 0.5 * (std::min(by + b, options.height) - by);
            Colour c = trace_ray(*scene, camera.position, camera_direction(camera, cx, cy), 0.0,
                                 rays, &camera_table);
            for (int y = std::max(by, tile.y0); y < std::min(by + b, tile.y1); ++y)
                for (int x = std::max(bx, tile.x0); x < std::min(bx + b, tile.x1); ++x)
                    out.put(x, y, c);
        }
    }
    return true;
}

bool RenderJob::State::render_samples(const RenderPass& pass, const PixelRect& tile,
                                      TileBuffer& out, std::uint64_t& rays) {
    const bool accumulate = !sums.empty();
    // The new sums stay in the tile until it is whole: a tile cancelled part
    // way leaves `sums` as they were, so its pass can run again after resume().
    if (accumulate) out.sums.resize(static_cast<std::size_t>(tile.width()) * tile.height());
    for (int y = tile.y0; y < tile.y1; ++y) {
        if (cancel_requested.load(std::memory_order_relaxed)) return false;
        for (int x = tile.x0; x < tile.x1; ++x) {
            if (!accumulate) {
                out.put(
                    x, y,
                    trace_ray(*scene, camera.position, camera_direction(camera, x + 0.5, y + 0.5),
                              0.0, rays, &camera_table));
                continue;
            }
            // Each pixel belongs to one tile, so its running sum needs no lock,
            // and its samples add up in index order whatever the threads do.
            Colour sum = pass.sample_begin == 0 ? Colour(0.0) : sums[sum_index(x, y)];
            for (int k = pass.sample_begin; k < pass.sample_end; ++k) {
                SampleOffset o = sample_offset(k);
                sum += clamp01(trace_ray(*scene, camera.position,
                                         camera_direction(camera, x + o.x, y + o.y), 0.0, rays,
                                         &camera_table));
            }
            out.sums[static_cast<std::size_t>(y - tile.y0) * tile.width() + (x - tile.x0)] = sum;
            out.put(x, y, sum / static_cast<double>(pass.sample_end));
        }
    }
    if (accumulate)
        for (int y = tile.y0; y < tile.y1; ++y)
            std::copy_n(&out.sums[static_cast<std::size_t>(y - tile.y0) * tile.width()],
                        tile.width(), &sums[sum_index(tile.x0, y)]);
    return true;
}

bool RenderJob::State::render_tile(const RenderPass& pass, const PixelRect& tile) {
    if (cancel_requested.load(std::memory_order_relaxed)) return false;
    TileBuffer out(tile);
    std::uint64_t tile_rays = 0;
    bool whole = pass.block > 1 ? render_blocks(pass.block, tile, out, tile_rays)
                                : render_samples(pass, tile, out, tile_rays);
    rays.fetch_add(tile_rays, std::memory_order_relaxed);
    if (whole) publish(tile, out.rgb);
    return whole;
}

RenderJob::RenderJob(std::shared_ptr<const PreparedScene> scene, RenderOptions options)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    options.samples = std::clamp(options.samples, 1, 1024);
    options.width = std::max(options.width, 0);
    options.height = std::max(options.height, 0);
    s.scene = std::move(scene);
    s.options = options;
    s.region = clip_region(options);
    if (s.scene) {
        s.camera = frame_for(*s.scene, options);
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
    // Previews trace a few rays a block: for them the table (up to tens of ms
    // for thousands of shapes) would cost more than it saves and delay the
    // viewer's first picture. Passes run one at a time, so no tile reads the
    // table while it is built.
    if (pass.block == 1)
        std::call_once(s.camera_table_built, [&s] {
            const Geometry& g = *s.scene->geometry;
            s.camera_table = build_direction_table(
                g, s.camera.position, table_resolution(g.spheres.size() + g.shapes.size(), true));
        });
    const std::vector<PixelRect> tiles = cut_tiles(s.region, pass.block, tile_blocks);
    if (s.tiles_pass != index) {  // a fresh pass, not one resumed after a cancel
        s.tiles_pass = index;
        s.tiles_done.assign(tiles.size(), 0);
        s.work_before_pass = s.work_done.load();
    }
    s.arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    if (s.tiles_done[i]) continue;
                    if (!s.render_tile(pass, tiles[i])) return;
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
    return job.image();
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

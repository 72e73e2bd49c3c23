#include "jtracer/render_tile.hpp"

#include "jtracer/check.hpp"
#include "jtracer/limits.hpp"
#include "render/camera_rays.hpp"
#include "render/prepared_frame.hpp"
#include "render/prepared_scene.hpp"
#include "render/sample_pattern.hpp"
#include "render/sky_map.hpp"
#include "render/trace.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <optional>

namespace jt {

namespace {

double clamp01(double c) {
    return c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0;
}

Colour clamp01(const Colour& c) {
    return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
}

void put(TileBuffer& out, int x, int y, const Colour& c) {
    std::uint8_t* p = &out.rgb[out.index(x, y) * 3];
    p[0] = quantize_channel(c.x);
    p[1] = quantize_channel(c.y);
    p[2] = quantize_channel(c.z);
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

bool trace_blocks(const PreparedFrame& f, int b, TileBuffer& out, const std::atomic<bool>& cancel,
                  std::uint64_t& rays) {
    const PixelRect& tile = out.rect;
    const CameraFrame& camera = f.camera;
    for (int by = tile.y0 / b * b; by < tile.y1; by += b) {
        if (cancel.load(std::memory_order_relaxed)) return false;
        for (int bx = tile.x0 / b * b; bx < tile.x1; bx += b) {
            // The centre of the block, as far as the image reaches.
            double cx = bx + 0.5 * (std::min(bx + b, f.options.width) - bx);
            double cy = by + 0.5 * (std::min(by + b, f.options.height) - by);
            // Previews run before the view table is built: the BVH answers.
            // They show hard shadows and the pinhole image, which are quick.
            const PixelSample sample{static_cast<std::uint32_t>(bx), static_cast<std::uint32_t>(by),
                                     0, false};
            Colour c = trace_ray(*f.scene, camera.position, camera_direction(camera, cx, cy), 0.0,
                                 sample, rays);
            for (int y = std::max(by, tile.y0); y < std::min(by + b, tile.y1); ++y)
                for (int x = std::max(bx, tile.x0); x < std::min(bx + b, tile.x1); ++x)
                    put(out, x, y, c);
        }
    }
    return true;
}

bool trace_samples(const PreparedFrame& f, const RenderPass& pass, TileBuffer& out,
                   const std::atomic<bool>& cancel, std::uint64_t& rays) {
    const PixelRect& tile = out.rect;
    const CameraFrame& camera = f.camera;
    const ViewTable& table = f.view_table();
    // Where a block lists no shape and nothing unlisted could be met (no
    // planes, no triangles), its rays meet nothing: the background (or its
    // map), as trace_ray would find it, without its set-up.
    const Geometry& geometry = *f.scene->geometry;
    const bool open_sky = table.built && geometry.planes.empty() && !geometry.triangles;
    // The sphere the tile's last primary ray met first: its next ones mostly
    // meet it too.
    HitHint hint;
    auto trace = [&](double x, double y, const Vec3& direction, const PixelSample& sample) {
        if (!table.built) return trace_ray(*f.scene, camera.position, direction, 0.0, sample, rays);
        ListedShapes seen = shapes_seen(table, x, y);
        seen.hint = &hint;
        if (open_sky && seen.size() == 0) {
            ++rays;
            return miss_colour(*f.scene, direction);
        }
        return trace_ray(*f.scene, camera.position, direction, 0.0, sample, rays, &seen);
    };
    if (f.options.samples == 1) {
        // Without a sky map, the pixels of a block whose rays meet nothing
        // are all the background colour: no ray to aim or trace.
        const bool plain_sky = open_sky && !f.scene->background_map;
        std::array<std::uint8_t, 3> sky{};
        if (plain_sky) {
            const Colour& b = f.scene->settings.background;
            sky = {quantize_channel(b.x), quantize_channel(b.y), quantize_channel(b.z)};
        }
        // A row's directions first, in a loop of their own: their divisions
        // and square roots then overlap instead of each waiting its ray.
        std::vector<Vec3> directions(static_cast<std::size_t>(tile.width()));
        std::vector<int> traced(static_cast<std::size_t>(tile.width()));  // x of pixels to trace
        auto trace_row = [&](int y) {
            for (int x = tile.x0; x < tile.x1; ++x)
                directions[static_cast<std::size_t>(x - tile.x0)] =
                    camera_direction(camera, x + 0.5, y + 0.5);
            for (int x = tile.x0; x < tile.x1; ++x)
                put(out, x, y,
                    trace(x + 0.5, y + 0.5, directions[static_cast<std::size_t>(x - tile.x0)],
                          {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0}));
        };
        // A block's pixels of the row at a time, with one look-up for all:
        // the plain sky written at once, the rest traced as trace_row does.
        // The colour lives in locals: byte stores may alias any memory, so
        // values read through references would be read again.
        auto trace_row_under_plain_sky = [&](int y) {
            std::size_t count = 0;
            const std::uint8_t red = sky[0], green = sky[1], blue = sky[2];
            std::uint8_t* row = &out.rgb[out.index(tile.x0, y) * 3];
            for (int x = tile.x0; x < tile.x1;) {
                const int block_end = std::min(tile.x1, (x / view_block + 1) * view_block);
                if (shapes_seen(table, x + 0.5, y + 0.5).size() == 0) {
                    rays += static_cast<std::uint64_t>(block_end - x);
                    for (; x < block_end; ++x) {
                        std::uint8_t* p = row + 3 * static_cast<std::size_t>(x - tile.x0);
                        p[0] = red, p[1] = green, p[2] = blue;
                    }
                } else {
                    for (; x < block_end; ++x) traced[count++] = x;
                }
            }
            for (std::size_t k = 0; k < count; ++k)
                directions[k] = camera_direction(camera, traced[k] + 0.5, y + 0.5);
            for (std::size_t k = 0; k < count; ++k) {
                const int x = traced[k];
                put(out, x, y,
                    trace(x + 0.5, y + 0.5, directions[k],
                          {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0}));
            }
        };
        for (int y = tile.y0; y < tile.y1; ++y) {
            if (cancel.load(std::memory_order_relaxed)) return false;
            if (plain_sky)
                trace_row_under_plain_sky(y);
            else
                trace_row(y);
        }
        return true;
    }
    const bool has_lens = camera.aperture > 0.0;
    for (int y = tile.y0; y < tile.y1; ++y) {
        if (cancel.load(std::memory_order_relaxed)) return false;
        for (int x = tile.x0; x < tile.x1; ++x) {
            // A pixel's samples add up in index order, whatever the threads
            // and tiles do.
            Colour& sum = out.sums[out.index(x, y)];
            if (pass.sample_begin == 0) sum = Colour(0.0);
            for (int k = pass.sample_begin; k < pass.sample_end; ++k) {
                const SampleOffset o = sample_offset(k);
                const Vec3 d = camera_direction(camera, x + o.x, y + o.y);
                const PixelSample sample{static_cast<std::uint32_t>(x),
                                         static_cast<std::uint32_t>(y),
                                         static_cast<std::uint32_t>(k)};
                // A ray from off the camera's position: the view table, made
                // for rays from the position, cannot list what it meets.
                const std::optional<LensRay> lens =
                    has_lens ? lens_ray(camera, d, f.options.samples, sample.i, sample.j, sample.k)
                             : std::nullopt;
                sum += clamp01(
                    lens ? trace_ray(*f.scene, lens->origin, lens->direction, 0.0, sample, rays)
                         : trace(x + o.x, y + o.y, d, sample));
            }
            put(out, x, y, sum / static_cast<double>(pass.sample_end));
        }
    }
    return true;
}

}  // namespace

const ViewTable& PreparedFrame::view_table() const {
    std::call_once(table_built_, [this] { table_ = build_view_table(*scene->geometry, camera); });
    return table_;
}

bool trace_tile(const PreparedFrame& frame, const RenderPass& pass, TileBuffer& out,
                const std::atomic<bool>& cancel, std::uint64_t& rays) {
    if (frame.options.samples > 1 && pass.block == 1)
        out.sums.resize(static_cast<std::size_t>(out.rect.width()) * out.rect.height());
    return pass.block > 1 ? trace_blocks(frame, pass.block, out, cancel, rays)
                          : trace_samples(frame, pass, out, cancel, rays);
}

RenderOptions frame_options(RenderOptions options) {
    options.samples = std::clamp(options.samples, kMinSamples, kMaxSamples);
    options.width = std::max(options.width, 0);
    options.height = std::max(options.height, 0);
    return options;
}

std::shared_ptr<const PreparedFrame> prepare_frame(std::shared_ptr<const PreparedScene> scene,
                                                   const RenderOptions& options) {
    JT_DCHECK(scene != nullptr, "a frame is made of a prepared scene");
    auto frame = std::make_shared<PreparedFrame>();
    frame->options = frame_options(options);
    frame->camera = frame_for(*scene, frame->options);
    frame->scene = std::move(scene);
    return frame;
}

RenderedTile render_tile(const PreparedFrame& frame, const PixelRect& tile) {
    const PixelRect rect{
        std::clamp(tile.x0, 0, frame.options.width), std::clamp(tile.y0, 0, frame.options.height),
        std::clamp(tile.x1, 0, frame.options.width), std::clamp(tile.y1, 0, frame.options.height)};
    RenderedTile rendered;
    if (rect.empty()) return rendered;
    rendered.pixels = Image8(rect.width(), rect.height());
    const RenderPass every_sample{"", 1, 0, frame.options.samples, 0};
    const std::vector<PixelRect> pieces = cut_tiles(rect, 1, tile_blocks);
    const std::atomic<bool> never{false};
    std::atomic<std::uint64_t> rays{0};
    tbb::task_arena arena(frame.options.threads > 0 ? frame.options.threads
                                                    : tbb::task_arena::automatic);
    arena.execute([&] {
        static_cast<void>(frame.view_table());  // built here, outside the parallel loop
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, pieces.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    TileBuffer out(pieces[i]);
                    std::uint64_t piece_rays = 0;
                    trace_tile(frame, every_sample, out, never, piece_rays);
                    rays.fetch_add(piece_rays, std::memory_order_relaxed);
                    const PixelRect& p = pieces[i];
                    const std::size_t row_bytes = static_cast<std::size_t>(p.width()) * 3;
                    for (int y = p.y0; y < p.y1; ++y)
                        std::copy_n(&out.rgb[out.index(p.x0, y) * 3], row_bytes,
                                    rendered.pixels.pixel(p.x0 - rect.x0, y - rect.y0));
                }
            },
            tbb::simple_partitioner());
    });
    rendered.rays = rays.load();
    return rendered;
}

}  // namespace jt

#pragma once
// The progressive render job: the one way anything renders a scene.
//
// text -> Scene -> prepare_scene() -> PreparedScene -> RenderJob -> Image8
//
// A PreparedScene is the immutable, render-ready form of a Scene (world
// transforms, acceleration structure, shading data). It is shared by pointer
// between jobs, threads and the viewer. A RenderJob renders one image of it,
// pass by pass: coarse previews (1/8, 1/4, 1/2 resolution; 1/16 first for a
// large image, so that the first one takes a few milliseconds), then the full
// resolution at one sample per pixel, then further samples up to the target.
// The CLI runs a job with previews off; the viewer polls a job running on a
// thread of its own. Final pixels never depend on thread count, tile order or
// whether previews ran.
//
// The passes of a job with `samples` = N: "preview 1/16" (only when the 1/8
// pass would trace more than 4096 rays), "preview 1/8", "preview 1/4",
// "preview 1/2" (one ray per block, when previews are on), "1 sample" (the
// pixel centres), then "2 samples", "4 samples", ... doubling up to "N samples".
// Sample k of a pixel sits at a fixed R2-sequence offset (k = 0: the centre);
// a pixel shows the mean of its samples so far, each clamped to [0, 1].

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"
#include "jtracer/scene.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace jt {

struct PreparedScene;  // defined in the core's private headers

// Builds the render-ready scene. Primitives whose transform list has a scale
// with a zero component, or leaves the range of doubles, are left out (one rule,
// jtracer/affine.hpp's object_transform); the validator warns about them with
// their location.
//
// `previous` may be a scene prepared earlier: when the geometry of `scene`
// (shapes and transforms) equals the previous scene's, its acceleration
// structure is reused, so that material, light and settings edits are cheap.
// Fails only if Embree cannot start at all.
Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    const Scene& scene, std::shared_ptr<const PreparedScene> previous = nullptr);

// The same for a scene its caller gives up (a program that renders it once):
// its materials are moved, not copied, into the prepared scene, and its
// primitives freed before the BVH is built, so that a million spheres never
// hold their primitives (96 MB) and Embree's build (about 90 MB) at once. The
// image is the same to the byte.
Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    Scene&& scene, std::shared_ptr<const PreparedScene> previous = nullptr);

// The same for a scene shared with its caller, who never changes it (the
// viewer's scenes are const once made): kept, and when a copy of the
// materials would be large (past 16,384 runs of distinct ones) and no
// material has a pattern, each primitive's material is read where the scene
// holds it, without a copy of 100,000 distinct materials before the first
// preview. Null: as an empty scene.
Expected<std::shared_ptr<const PreparedScene>> prepare_scene(
    std::shared_ptr<const Scene> scene, std::shared_ptr<const PreparedScene> previous = nullptr);

// Prepares `scene` after an edit of `before`, the scene `previous` was
// prepared from. When the edit changed materials only (of one object or many),
// besides lights, cameras or settings, the result shares everything else with
// `previous` and only the changed objects' materials are gathered again, so
// that recolouring one object of a huge scene costs next to nothing. Any other
// edit, and any scene that reads files (image maps, background map, meshes,
// whose state on disk only prepare_scene checks), goes through
// prepare_scene(scene, previous). The image is the same either way.
Expected<std::shared_ptr<const PreparedScene>> prepare_scene_edit(
    const Scene& before, const Scene& scene, std::shared_ptr<const PreparedScene> previous);

// The same for a shared `scene` (as prepare_scene's above). When `previous`
// reads its materials in place, a material edit is patched by reading them in
// place from `scene` instead: nothing is gathered, and the result holds
// `scene`.
Expected<std::shared_ptr<const PreparedScene>> prepare_scene_edit(
    const Scene& before, std::shared_ptr<const Scene> scene,
    std::shared_ptr<const PreparedScene> previous);

struct RenderOptions {
    int width = 0;  // final image size in pixels, > 0
    int height = 0;
    int samples = 1;       // target samples per pixel, kMinSamples..kMaxSamples
    int camera = 0;        // index into Scene::cameras
    int threads = 0;       // 0: every core
    bool previews = true;  // run the preview passes (1/16,) 1/8, 1/4, 1/2 first
    // Run the job's threads at a lower OS priority (Linux nice 10), so that an
    // interactive thread sharing the cores (a viewer drawing its frames) keeps
    // its pace. The oneTBB workers stay lowered afterwards (an unprivileged
    // process cannot undo it), so a process should ask for it for all its jobs
    // or none.
    bool background = false;
    // Render only this window of the full image. The pixels inside are exactly
    // those of a full render; image() still has the full size, with the pixels
    // outside black, and region_image() has the window alone.
    std::optional<PixelRect> region;
};

// The options a scene's own settings ask for: its width, height and samples,
// through its active camera (validate.hpp's active_camera_index). Everything
// else keeps RenderOptions' defaults, for the caller to set.
RenderOptions render_options_for(const Scene& scene);

struct RenderProgress {
    int pass = 0;  // index of the pass running or next to run (the last one once finished)
    int pass_count = 0;
    std::string pass_name;   // "preview 1/16", "preview 1/8", ..., "1 sample", "4 samples"
    double fraction = 0.0;   // of the whole job's work, 0..1
    int samples_done = 0;    // full-resolution samples per pixel completed
    std::uint64_t rays = 0;  // camera, shadow and reflection rays traced so far
    double seconds = 0.0;    // wall time spent in run()
    bool finished = false;
    bool cancelled = false;
};

class RenderJob {
  public:
    RenderJob(std::shared_ptr<const PreparedScene> scene, RenderOptions options);
    ~RenderJob();
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    // Renders every remaining pass on the calling thread (its tiles go to the
    // oneTBB pool) and returns when finished or cancelled.
    void run();
    // Renders the next pass only; returns false when there was none left or it
    // was cancelled.
    bool run_pass();
    // Thread-safe; run() and run_pass() return within milliseconds.
    void cancel();
    // Undoes a cancel once run() or run_pass() has returned: the next run()
    // continues where the cancel stopped it. Passes and tiles already rendered
    // are kept; only the tiles the cancel interrupted are rendered again, so the
    // final image is the same as that of an uninterrupted job.
    void resume();

    // Thread-safe snapshot.
    RenderProgress progress() const;

    // Thread-safe. Copies the pixels that changed since the last call into
    // `display` (resized to the full image size on the first call; previews
    // fill whole blocks) and returns the bounding rectangle that changed, or
    // nothing when nothing did.
    std::optional<PixelRect> fetch_updates(Image8& display);

    // The image as it stands: final once progress().finished.
    Image8 image() const;
    // The image, moved out of the job instead of copied: for a shell that is
    // done with a finished or cancelled job and wants its megabytes once. The
    // job keeps no pixels afterwards (image(), region_image() and
    // fetch_updates() see none), so take it last.
    Image8 take_image();
    // Only the pixels of the region (the whole image without one), as an image
    // of the region's size, row 0 at the region's bottom. The job keeps only
    // these, so a small region of a huge frame needs little memory.
    Image8 region_image() const;

    const RenderOptions& options() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

// Renders straight to the final pass on the calling thread (tiles to oneTBB)
// and returns the image: a RenderJob with previews off, run to the end.
Image8 render_image(std::shared_ptr<const PreparedScene> scene, RenderOptions options);

// The index of the camera called `name`, or -1. (The camera a scene renders by
// default is validate.hpp's active_camera_index.)
int find_camera(const Scene& scene, std::string_view name);

}  // namespace jt

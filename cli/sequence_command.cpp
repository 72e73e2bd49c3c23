#include "sequence_command.hpp"

#include "existing_output.hpp"
#include "interruptible_render.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/frontend/memory_budget.hpp"
#include "jtracer/frontend/scene_sequence.hpp"
#include "jtracer/frontend/sequence_progress.hpp"
#include "jtracer/region_file.hpp"

#include <chrono>
#include <iostream>

namespace jt::cli {

namespace {

using namespace jt::frontend;
using Clock = std::chrono::steady_clock;

// What stays of a sequence stopped at frame `index`, `kept` frames before it
// already there (--skip-existing).
std::string written_before(const FrameRange& range, int index, int kept) {
    if (index == range.first) return "no frame was written";
    return frames_there(range.first, index, kept);
}

}  // namespace

int run_sequence(const Options& o) {
    SceneSequence sequence("jtracer-cli", o, o.region);
    if (o.region_output) sequence.fingerprint_frames();
    if (!o.check_only)
        if (std::optional<std::string> clash = sequence.output_clash()) {
            std::cerr << *clash;
            return exit_usage;
        }
    const FrameRange range = sequence.range();
    const int total = range.last - range.first + 1;
    ProgressDisplay display(progress_style_for_stderr(o.progress, o.quiet));
    const auto start = Clock::now();
    int kept_frames = 0;  // already there (--skip-existing)
    catch_interrupts();
    for (int index = range.first; index <= range.last; ++index) {
        // A signal during the last frame's write let it finish: stop before
        // preparing the next frame, which can take long (a large mesh).
        if (interrupting_signal() != 0) {
            display.finish();
            return report_interrupt(written_before(range, index, kept_frames).c_str());
        }
        // A frame already there is known once its set-up names its file and
        // size, before the scene is prepared for it.
        auto skip = [&](const SequenceFrame& f) {
            if (!o.skip_existing) return false;
            display.finish();
            return keep_existing_output(o, f.output,
                                        wanted_output(o, f.render, f.format, f.fingerprint),
                                        " (frame " + std::to_string(f.index) + ")");
        };
        const SequenceFrame frame = sequence.frame(index, !o.check_only, skip);
        if (!frame.message.empty()) {
            display.finish();
            std::cerr << frame.message;
        }
        if (frame.exit_code != exit_ok) return frame.exit_code;
        if (index == range.first)
            if (std::optional<std::string> refused = region_output_refusal(o, frame.output)) {
                display.finish();
                std::cerr << *refused;
                return exit_usage;
            }
        if (frame.skipped) {
            ++kept_frames;
            continue;
        }
        if (o.check_only) continue;
        if (index == range.first && !o.quiet) {
            display.finish();
            std::cerr << format_warning(o, frame.output);
        }
        if (Expected<void> fits = check_render_memory(frame.render, o.region_output); !fits) {
            display.finish();
            std::cerr << "jtracer-cli: " << fits.error().message << "; "
                      << written_before(range, index, kept_frames) << "\n";
            return exit_io_error;
        }
        // Each frame's file may be in a folder of its own (-o 'f%d/shot.png').
        if (Expected<void> writable = check_atomic_write(frame.output); !writable) {
            display.finish();
            std::cerr << "jtracer-cli: " << writable.error().message << "; "
                      << written_before(range, index, kept_frames) << "\n";
            return exit_io_error;
        }
        RenderJob job(frame.prepared, frame.render);
        const int done = index - range.first;
        const bool rendered = render_interruptibly(job, display, [&](const RenderProgress& p) {
            const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
            return sequence_progress(p, done, total, seconds);
        });
        if (!rendered) {
            display.finish();
            return report_interrupt(written_before(range, index, kept_frames).c_str());
        }
        const Expected<void> written =
            o.region_output ? write_region_bmp(frame.output, job.region_image(),
                                               region_placement(o, frame.render, frame.fingerprint))
                            : write_image(frame.output, job.take_image(), frame.format);
        display.finish();
        if (!written) {
            std::cerr << "jtracer-cli: " << written.error().message << "; "
                      << written_before(range, index, kept_frames) << "\n";
            return exit_io_error;
        }
        if (!o.quiet)
            std::cerr << "wrote " << frame.output << " (frame " << index << ", clock "
                      << shortest_decimal(frame.clock) << "): "
                      << render_summary(frame.render.width, frame.render.height,
                                        frame.render.samples, job.progress(), o.region)
                      << "\n";
    }
    display.finish();
    if (o.check_only && !o.quiet)
        std::cerr << o.scene_path << ": no errors in frames " << range.first << ".." << range.last
                  << "\n";
    if (!o.quiet && !o.check_only && total > 1) {
        std::cerr << sequence_summary(total, total - kept_frames, kept_frames,
                                      std::chrono::duration<double>(Clock::now() - start).count());
    }
    return exit_ok;
}

}  // namespace jt::cli

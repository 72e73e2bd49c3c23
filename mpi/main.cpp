// jtracer-mpi: one frame, or each frame of a sequence (--frames) in turn,
// rendered by every rank of an MPI job. Every rank reads and prepares the
// scene itself (only the file name travels, in argv); rank 0 hands out tiles
// on demand, renders tiles itself in between, and alone writes each image,
// atomically, once every tile is in. This file orders the steps and makes
// sure every rank ends the same way.

#include "coordinator.hpp"
#include "cpu_affinity.hpp"
#include "mpi_options.hpp"
#include "roll_call.hpp"
#include "work_tiles.hpp"
#include "worker.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/existing_output.hpp"
#include "jtracer/frontend/frame_setup.hpp"
#include "jtracer/frontend/progress.hpp"
#include "jtracer/frontend/region_flags.hpp"
#include "jtracer/frontend/render_fingerprint.hpp"
#include "jtracer/frontend/scene_sequence.hpp"
#include "jtracer/frontend/sequence_progress.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/region.hpp"
#include "jtracer/region_file.hpp"

#include <mpi.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace jt::mpi;
using jt::frontend::FrameSetup;
using Clock = std::chrono::steady_clock;

std::string host_name() {
    std::array<char, MPI_MAX_PROCESSOR_NAME> name{};
    int length = 0;
    MPI_Get_processor_name(name.data(), &length);
    return std::string(name.data(), static_cast<std::size_t>(length));
}

// OpenMPI's mpirun, told to end a job whose machine dropped off the network,
// waits for that machine's daemon for as long as TCP takes to give up (many
// minutes). When rank 0 is mpirun's own child (the usual layout: rank 0 on the
// machine mpirun runs on), a second SIGTERM within 5 seconds of the first
// makes mpirun end at once (the first only starts its abort). On a loaded
// machine mpirun may not have taken the first in before the second arrives,
// and two pending SIGTERMs are one: one a second, for as long as it lives (this
// rank's parent changes when it ends). An mpirun that still waits after five
// is killed: the daemons of the hosts still up then end their ranks
// themselves, having lost it.
void stop_local_launcher() {
    const pid_t parent = getppid();
    std::ifstream comm("/proc/" + std::to_string(parent) + "/comm");
    std::string name;
    std::getline(comm, name);
    if (name != "mpirun" && name != "mpiexec" && name != "orterun") return;
    // mpirun's abort ends its own children with SIGTERM: this rank must live to
    // send the second.
    std::signal(SIGTERM, SIG_IGN);
    for (int signals = 0; signals < 5 && getppid() == parent; ++signals) {
        kill(parent, SIGTERM);
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    if (getppid() == parent) kill(parent, SIGKILL);
}

// What a rank renders of one frame, and where rank 0 writes it.
struct RankFrame {
    RankSetUp mine;
    jt::RenderOptions render;
    std::string output;
    jt::ImageFormat format = jt::ImageFormat::bmp;
    double clock = 0.0;
    // What a region file (--region-output) records it was rendered from.
    std::optional<jt::RenderFingerprint> fingerprint;
};

// Reads, checks and prepares the scene (at frame `index` of a sequence): the
// same steps on every rank, each on its own machine.
RankFrame set_up_rank(const Options& o, jt::frontend::SceneSequence* sequence, int index) {
    RankFrame frame;
    RankSetUp& mine = frame.mine;
    std::shared_ptr<const jt::PreparedScene> scene;
    if (sequence) {
        jt::frontend::SequenceFrame set_up = sequence->frame(index);
        mine.exit_code = set_up.exit_code;
        mine.message = set_up.message;
        if (mine.exit_code != exit_ok) return frame;
        frame.render = set_up.render;
        frame.output = set_up.output;
        frame.format = set_up.format;
        frame.clock = set_up.clock;
        frame.fingerprint = set_up.fingerprint;
        scene = set_up.prepared;
    } else {
        FrameSetup setup = jt::frontend::set_up_frame("jtracer-mpi", o, o.region);
        mine.exit_code = setup.exit_code;
        mine.message = setup.message;
        if (setup.exit_code != exit_ok) return frame;
        // As jtracer-cli refuses it: the image would replace the scene file.
        if (jt::frontend::same_file(setup.output, o.scene_path)) {
            mine.exit_code = jt::frontend::exit_usage;
            mine.message = "jtracer-mpi: '" + setup.output +
                           "' is the scene file itself: the image would replace it; nothing "
                           "was written\n";
            return frame;
        }
        if (o.region_output)
            frame.fingerprint =
                jt::frontend::render_fingerprint(setup.scene, setup.render, o.clock.value_or(0.0));
        const jt::Expected<std::shared_ptr<const jt::PreparedScene>> prepared =
            jt::prepare_scene(std::move(setup.scene));
        if (!prepared) {
            mine.exit_code = exit_io_error;
            mine.message = "jtracer-mpi: " + prepared.error().message + "; nothing was written\n";
            return frame;
        }
        frame.render = setup.render;
        frame.output = setup.output;
        frame.format = setup.format;
        scene = *prepared;
    }
    // As jtracer-cli refuses it: a region file under a scene's filename.png.
    if (std::optional<std::string> refused =
            jt::frontend::region_output_refusal("jtracer-mpi", o, o, frame.output)) {
        mine.exit_code = exit_usage;
        mine.message = *refused;
        return frame;
    }
    // One frame a rank: the view table is built once, by the rank's first tile.
    mine.frame = jt::prepare_frame(scene, frame.render);
    mine.tiles = cut_work_tiles(
        frame.render.region.value_or(jt::PixelRect{0, 0, frame.render.width, frame.render.height}),
        o.tile_size);
    return frame;
}

// What stays of a run stopped at frame `index` (the only one without
// --frames), `rendered` frames before it written by this run and the others
// kept (--skip-existing).
std::string written_before(const jt::frontend::FrameRange& range, int index, int rendered) {
    if (index == range.first) return "nothing was written";
    return jt::frontend::frames_there(range.first, index, index - range.first - rendered);
}

// Rank 0 stops for SIGINT, SIGTERM or SIGHUP as jtracer-cli does, with its
// exit codes. Workers that still wait (for tiles, or for a frame they were
// told follows) cannot be told: only an abort ends them.
int stop_for_signal(int signal, const std::string& what, bool workers_wait) {
    std::cerr << "jtracer-mpi: interrupted by " << jt::frontend::signal_name(signal) << "; " << what
              << "\n";
    if (workers_wait) {
        std::cerr << std::flush;
        MPI_Abort(MPI_COMM_WORLD, 128 + signal);
    }
    return 128 + signal;
}

// Rank 0 ends a job it has lost a worker of: the others cannot be told.
[[noreturn]] void end_for_lost_rank(const LostRank& lost, const std::vector<std::string>& hosts,
                                    double rank_timeout, const char* outcome) {
    const std::string& host = hosts[static_cast<std::size_t>(lost.rank)];
    std::fprintf(stderr,
                 "jtracer-mpi: rank %d on %s stopped answering (nothing heard from it for %.1f s, "
                 "--rank-timeout %g)%s\n",
                 lost.rank, host.empty() ? "a host that never said its name" : host.c_str(),
                 lost.silence, rank_timeout, outcome);
    std::fflush(stderr);
    stop_local_launcher();
    std::_Exit(exit_io_error);
}

// Every rank's set-up verdict, as rank 0 heard it: a scene error is the same
// on every rank and rank 0 alone reports it; a worker that failed where rank 0
// did not (a file missing on its machine) is reported with its rank and host.
int agree_on_setup(const RankSetUp& own, const RollCall& call) {
    std::cerr << own.message;
    if (own.exit_code != exit_ok) return own.exit_code;
    for (std::size_t rank = 1; rank < call.exit_codes.size(); ++rank)
        if (call.exit_codes[rank] != exit_ok)
            std::cerr << "rank " << rank << " on " << call.hosts[rank] << ": "
                      << call.messages[rank];
    for (int code : call.exit_codes)
        if (code != exit_ok) return code;
    return exit_ok;
}

void print_stats(const CoordinatorResult& result, const std::vector<RankStats>& ranks,
                 std::size_t tiles, int tile_size, double total_seconds) {
    const double loop = result.seconds;
    const RankStats& r0 = ranks.front();
    std::fprintf(stderr,
                 "stats: %zu ranks, %zu tiles of %dx%d, %.3f s in all, %.3f s rendering loop\n",
                 ranks.size(), tiles, tile_size, tile_size, total_seconds, loop);
    std::fprintf(stderr,
                 "stats: %d tiles handed out a second time at the end, %d of them came back "
                 "first from the second rank\n",
                 result.second_copies, result.second_copies_won);
    std::fprintf(stderr,
                 "stats: rank 0 coordinator: waiting %.3f s (%.1f%%), merging %.3f s (%.1f%%), "
                 "%d tiles and %.2f MB received\n",
                 r0.wait_seconds, 100.0 * r0.wait_seconds / loop, r0.merge_seconds,
                 100.0 * r0.merge_seconds / loop, result.tiles_received,
                 static_cast<double>(result.bytes_received) / 1e6);
    for (std::size_t i = 0; i < ranks.size(); ++i) {
        const RankStats& s = ranks[i];
        std::fprintf(stderr,
                     "stats: rank %zu: %.0f tiles, rendering %.3f s (%.2f ms a tile), setup "
                     "%.3f s, waiting for work %.3f s\n",
                     i, s.tiles, s.render_seconds,
                     s.tiles > 0 ? 1000.0 * s.render_seconds / s.tiles : 0.0, s.setup_seconds,
                     i == 0 ? 0.0 : s.wait_seconds);
    }
}

// A worker: the frames rank 0 names, until it says no more.
int run_worker_frames(const Options& o, jt::frontend::SceneSequence* sequence, int rank) {
    int code = exit_ok;
    bool first = true;
    for (std::int32_t index = receive_frame_index(); index != no_more_frames;
         index = receive_frame_index()) {
        bool another_frame = false;
        code = run_worker(
            host_name(),
            [&] {
                RankFrame frame = set_up_rank(o, sequence, index);
                if (frame.mine.exit_code == exit_ok && first && !o.quiet)
                    if (auto warning =
                            narrow_affinity_warning(current_cpu_share(), rank, host_name()))
                        std::cerr << *warning << std::flush;
                return frame.mine;
            },
            another_frame);
        first = false;
        if (!another_frame) break;
    }
    return code;
}

// --skip-existing on rank 0, whose machine the images are written on: the
// frames from `from` on whose files are already there and complete, each said
// as jtracer-cli says it. The frames are set up (read at their clock) by a
// sequence of their own, without being prepared; one whose set-up fails is
// left to the render, which reports it.
class KeptFrames {
  public:
    explicit KeptFrames(const Options& o) : o_(o) {
        if (o.frames) {
            checker_.emplace("jtracer-mpi", o, o.region);
            if (o.region_output) checker_->fingerprint_frames();
        }
    }

    // The first frame from `from` to `last` that is to be rendered, or last + 1.
    int next_to_render(int from, int last) {
        if (!o_.skip_existing) return from;
        for (int index = from; index <= last; ++index) {
            if (!frame_is_kept(index)) return index;
            ++frames_kept;
        }
        return last + 1;
    }

    int frames_kept = 0;  // so far

  private:
    const Options& o_;
    std::optional<jt::frontend::SceneSequence> checker_;

    bool keep_output(const std::string& output, const jt::RenderOptions& render,
                     jt::ImageFormat format,
                     const std::optional<jt::RenderFingerprint>& fingerprint,
                     const std::string& what) const {
        // An output that is the scene file is refused by the set-up.
        if (jt::frontend::same_file(output, o_.scene_path)) return false;
        jt::frontend::WantedOutput wanted{render.width, render.height, format, std::nullopt};
        if (o_.region_output)
            wanted.placement = jt::frontend::region_placement(o_, render, fingerprint);
        return jt::frontend::keep_existing_output("jtracer-mpi", o_.quiet, output, wanted, what);
    }

    bool frame_is_kept(int index) {
        if (!checker_) {
            const FrameSetup setup = jt::frontend::set_up_frame("jtracer-mpi", o_, o_.region);
            if (setup.exit_code != exit_ok) return false;
            const std::optional<jt::RenderFingerprint> fingerprint =
                o_.region_output ? std::optional(jt::frontend::render_fingerprint(
                                       setup.scene, setup.render, o_.clock.value_or(0.0)))
                                 : std::nullopt;
            return keep_output(setup.output, setup.render, setup.format, fingerprint, "");
        }
        const jt::frontend::SequenceFrame frame =
            checker_->frame(index, false, [&](const jt::frontend::SequenceFrame& f) {
                return keep_output(f.output, f.render, f.format, f.fingerprint,
                                   " (frame " + std::to_string(f.index) + ")");
            });
        return frame.exit_code == exit_ok && frame.skipped;
    }
};

// What rank 0 says of a frame it wrote.
void report_frame(const Options& o, const RankFrame& frame, int index,
                  const CoordinatorResult& result, int ranks) {
    if (o.quiet) return;
    jt::RenderProgress summary;
    summary.rays = result.rays;
    summary.seconds = result.seconds;
    std::cerr << "wrote " << jt::frontend::shown_output(frame.output);
    if (o.frames)
        std::cerr << " (frame " << index << ", clock "
                  << jt::frontend::shortest_decimal(frame.clock) << ")";
    std::cerr << ": "
              << jt::frontend::render_summary(frame.render.width, frame.render.height,
                                              frame.render.samples, summary)
              << ", " << ranks << (ranks == 1 ? " rank" : " ranks") << "\n";
}

// As a render refuses it (and jtracer-cli --check): a region file under a
// scene's filename.png. Reported here; true when refused.
bool region_output_refused(const Options& o, const std::string& output) {
    const std::optional<std::string> refused =
        jt::frontend::region_output_refusal("jtracer-mpi", o, o, output);
    if (refused) std::cerr << *refused;
    return refused.has_value();
}

// --check, on rank 0: each frame set up (read at its clock and validated) as
// a render would set it up, and nothing more.
int check_scene(const Options& o) {
    if (!o.frames) {
        const FrameSetup setup = jt::frontend::set_up_frame("jtracer-mpi", o, o.region);
        std::cerr << setup.message;
        if (setup.exit_code != exit_ok) return setup.exit_code;
        if (region_output_refused(o, setup.output)) return exit_usage;
        if (!o.quiet) std::cerr << o.scene_path << ": no errors\n";
        return exit_ok;
    }
    jt::frontend::SceneSequence sequence("jtracer-mpi", o, o.region);
    const jt::frontend::FrameRange range = sequence.range();
    for (int index = range.first; index <= range.last; ++index) {
        const jt::frontend::SequenceFrame frame = sequence.frame(index, false);
        std::cerr << frame.message;
        if (frame.exit_code != exit_ok) return frame.exit_code;
        if (index == range.first && region_output_refused(o, frame.output)) return exit_usage;
    }
    if (!o.quiet)
        std::cerr << o.scene_path << ": no errors in frames " << range.first << ".." << range.last
                  << "\n";
    return exit_ok;
}

int run(int argc, char** argv, int rank, int ranks) {
    const auto start = Clock::now();
    ParsedOptions parsed = parse_options(argc, argv, rank == 0);
    if (parsed.exit_code) return *parsed.exit_code;
    const Options& o = parsed.options;
    // The other ranks have nothing to do: every rank would find the same.
    if (o.check_only) return rank == 0 ? check_scene(o) : exit_ok;
    // Only the file name travels: a pipe (a FIFO, /dev/stdin) gives its text
    // to the one rank that reads it first, and the others would wait for
    // theirs forever. Every rank sees the same and stops alike.
    if (ranks > 1 && jt::frontend::is_stream(o.scene_path)) {
        if (rank == 0)
            std::cerr << "jtracer-mpi: the scene '" << o.scene_path
                      << "' is a pipe or a device, which only one of the " << ranks
                      << " ranks could read: save it to a file at the same path on every "
                         "machine\nRun 'jtracer-mpi --help' for the options.\n";
        return exit_usage;
    }
    std::optional<jt::frontend::SceneSequence> sequence;
    if (o.frames) {
        sequence.emplace("jtracer-mpi", o, o.region);
        if (o.region_output) sequence->fingerprint_frames();
    }
    jt::frontend::SceneSequence* frames = sequence ? &*sequence : nullptr;
    const jt::frontend::FrameRange range =
        sequence ? sequence->range() : jt::frontend::FrameRange{};
    // As jtracer-cli: a frame of the range that would be written over the
    // scene file stops the job before any frame is, on every rank alike.
    if (sequence)
        if (std::optional<std::string> clash = sequence->output_clash()) {
            if (rank == 0) std::cerr << *clash;
            return exit_usage;
        }
    if (rank != 0) return run_worker_frames(o, frames, rank);

    // One display for the whole sequence, as jtracer-cli's: the bar or log goes
    // on from frame to frame and its time left is the sequence's.
    jt::frontend::ProgressDisplay display(
        jt::frontend::progress_style_for_stderr(o.progress, o.quiet));
    const int total = range.last - range.first + 1;
    const auto sequence_start = Clock::now();
    KeptFrames kept_frames(o);
    int rendered = 0;
    // The workers wait for the number of their next frame (tag_frame): at the
    // start, and after a frame whose stop said that another may follow.
    bool workers_wait = true;
    for (int index = kept_frames.next_to_render(range.first, range.last);;) {
        // A signal during the last frame's write let it finish: stop before
        // setting up the next frame, which can take long (a large mesh).
        const int signal = jt::frontend::stop_signal();
        const bool more = index <= range.last && signal == 0;
        if (workers_wait)
            for (int worker = 1; worker < ranks; ++worker)
                send_frame(worker, more ? index : no_more_frames);
        if (signal != 0)
            return stop_for_signal(signal, written_before(range, index, rendered), false);
        if (!more) break;
        const auto frame_start = Clock::now();
        RankFrame frame = set_up_rank(o, frames, index);
        // Rank 0 alone writes the image: a folder missing or not writable on
        // its machine is found before every rank renders a frame for nothing.
        if (frame.mine.exit_code == exit_ok)
            if (const jt::Expected<void> writable = jt::check_atomic_write(frame.output);
                !writable) {
                frame.mine.exit_code = exit_io_error;
                frame.mine.message +=
                    "jtracer-mpi: " + writable.error().message + "; " +
                    (o.frames ? written_before(range, index, rendered) : "nothing was rendered") +
                    "\n";
            }
        const RankSetUp& mine = frame.mine;
        const double setup_seconds =
            std::chrono::duration<double>(Clock::now() - frame_start).count();
        const RollCall call = call_the_roll(ranks, host_name(), mine.exit_code, o.rank_timeout);
        if (call.lost)
            end_for_lost_rank(
                *call.lost, call.hosts, o.rank_timeout,
                rendered == 0 ? "; nothing was written" : "; the frames before it were written");
        if (const int code = agree_on_setup(mine, call); code != exit_ok) {
            for (int worker = 1; worker < ranks; ++worker) send_stop(worker, false);
            return code;
        }
        if (rendered == 0) {
            if (!o.quiet) {
                // As jtracer-cli warns: -o shot.jpg is a BMP all the same.
                std::cerr << jt::frontend::format_warning("jtracer-mpi", o, frame.output);
                if (auto warning = narrow_affinity_warning(current_cpu_share(), 0, host_name()))
                    std::cerr << *warning << std::flush;
            }
            // Left to their defaults, SIGINT, SIGTERM and SIGHUP (a dropped
            // ssh connection) would end rank 0 in the middle of a write,
            // leaving the temporary file beside the image.
            jt::frontend::catch_stop_signals();
        }

        CoordinatorSettings settings;
        settings.ranks = ranks;
        settings.rank_timeout = o.rank_timeout;
        settings.on_progress = [&](const jt::RenderProgress& p) {
            if (!o.frames) return display.update(p);
            const double seconds =
                std::chrono::duration<double>(Clock::now() - sequence_start).count();
            display.update(jt::frontend::sequence_progress(p, index - range.first, total, seconds));
        };
        settings.another_frame = index < range.last;
        std::optional<jt::Expected<void>> written;
        CoordinatorResult result = run_coordinator(
            mine.frame, frame.render.width, frame.render.height, mine.tiles, settings,
            [] { return jt::frontend::stop_signal() != 0; },
            [&](const jt::Image8& image) {
                // A region file keeps the window's pixels alone and records
                // where they belong, for jtracer-merge.
                written =
                    o.region_output
                        ? jt::write_region_bmp(
                              frame.output, jt::crop_image(image, *frame.render.region),
                              jt::frontend::region_placement(o, frame.render, frame.fingerprint))
                        : jt::write_image(frame.output, image, frame.format);
                return static_cast<bool>(*written);
            });
        display.finish();
        if (result.lost)
            end_for_lost_rank(
                *result.lost, call.hosts, o.rank_timeout,
                written && *written ? " after the image was written" : "; nothing was written");
        // Short of every tile only when asked to stop (a lost rank ended the
        // job above); the workers still wait for tiles.
        if (!result.complete)
            return stop_for_signal(
                jt::frontend::stop_signal() != 0 ? jt::frontend::stop_signal() : SIGINT,
                written_before(range, index, rendered), ranks > 1);
        workers_wait = result.another_frame;
        result.stats.setup_seconds = setup_seconds;
        std::vector<RankStats> stats = result.rank_stats;
        stats.front() = result.stats;
        if (!*written) {
            std::cerr << "jtracer-mpi: "
                      << jt::frontend::shown_write_error(written->error().message) << "\n";
            return exit_io_error;
        }
        report_frame(o, frame, index, result, ranks);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (o.stats) print_stats(result, stats, mine.tiles.size(), o.tile_size, seconds);
        ++rendered;
        index = kept_frames.next_to_render(index + 1, range.last);
    }
    if (!o.quiet && o.frames && total > 1) {
        std::cerr << jt::frontend::sequence_summary(
            total, rendered, kept_frames.frames_kept,
            std::chrono::duration<double>(Clock::now() - sequence_start).count());
    }
    return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
    int provided = 0;
    // Only the main thread of a rank calls MPI; rank 0's rendering thread does not.
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    int code = exit_io_error;
    try {
        code = run(argc, argv, rank, ranks);
    } catch (const std::exception& e) {
        // Other ranks may be waiting on this one: only an abort ends them all.
        std::cerr << "jtracer-mpi: rank " << rank << ": " << e.what() << "; nothing was written\n";
        MPI_Abort(MPI_COMM_WORLD, exit_io_error);
    }
    MPI_Finalize();
    return code;
}

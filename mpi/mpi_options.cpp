#include "mpi_options.hpp"

#include "jtracer/frontend/existing_output.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace jt::mpi {

namespace {

// Whether a launcher (mpirun, mpiexec, srun) started this rank, rather than a
// user running jtracer-mpi alone; each sets its ranks' numbers in the
// environment.
bool started_by_launcher() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

}  // namespace

ParsedOptions parse_options(int argc, char** argv, bool speaks) {
    ParsedOptions parsed;
    Options& o = parsed.options;
    CLI::App app{
        "jtracer-mpi: renders a JTracer scene (.jts) over many machines with MPI; run it with "
        "mpirun."};
    app.footer(
        "Examples:\n"
        "  mpirun -np 4 jtracer-mpi scenes/showcase.jts -o shot.bmp --width 3840 --height 2160\n"
        "  mpirun --hostfile hosts -np 16 jtracer-mpi scene.jts --samples 16 --stats\n"
        "  mpirun -np 4 jtracer-mpi scenes/orbit.jts --frames 48 -o orbit-%04d.png\n"
        "  mpirun -np 4 jtracer-mpi --check scene.jts      only checks the scene, on rank 0\n"
        "  mpirun -np 4 jtracer-mpi scene.jts --region 0,0,1920,540 --region-output -o top.bmp\n"
        "\n"
        "Every rank reads the scene file itself (it must be at the same path on every\n"
        "machine). Rank 0 hands out tiles on demand, renders tiles itself in between, and\n"
        "alone writes the image (BMP, or PNG for a -o name ending in .png). With --frames,\n"
        "the ranks render the frames one after another, each over all of them.\n"
        "\n"
        "Exit codes: 0 ok, 1 errors in the scene, 2 bad command line, 3 file I/O errors;\n"
        "a rank that dies or an interrupt aborts the whole job (non-zero, nothing written).\n");
    frontend::add_version_flag(app, "jtracer-mpi");
    frontend::add_render_flags(app, o);
    frontend::add_region_flags(app, o);
    app.add_option("--tile-size", o.tile_size,
                   "Side of the square tiles handed out to the ranks, in pixels (default 128)")
        ->check(CLI::Range(16, 4096))
        ->type_name("N");
    app.add_flag("--stats", o.stats,
                 "After the render, print where the time went: the coordinator's waiting and "
                 "merging, and every rank's tiles");
    app.add_option("--rank-timeout", o.rank_timeout,
                   "Seconds without a word from a rank (every rank says something at least "
                   "once a second) after which rank 0 declares it lost and ends the job "
                   "(default 10)")
        ->check(CLI::Range(2.0, 3600.0))
        ->type_name("SECONDS");
    app.add_flag("--check", o.check_only,
                 "Only parse and validate the scene (each frame's, with --frames), on rank 0; "
                 "write nothing");
    app.add_flag("--skip-existing", o.skip_existing,
                 "Keep an image already there (on rank 0's machine) and complete instead of "
                 "rendering it again (with --frames, frame by frame): for rerunning a job after "
                 "a failure. Complete: every byte there and the frame's size; anything else is "
                 "rendered again");
    // Ranks other than 0 keep their (identical) words to themselves.
    std::ostringstream muted;
    std::ostream& out = speaks ? std::cout : muted;
    std::ostream& err = speaks ? std::cerr : muted;
    if (std::optional<int> code = frontend::parse_command_line(
            app, argc, argv, "jtracer-mpi",
            [&] {
                frontend::check_sequence_flags(o);
                // OpenMPI hands a rank a terminal of its own as standard
                // output and relays it, whatever the user redirected
                // mpirun's to: "is a terminal" would send them to redirect
                // what they already had.
                if (o.output_is_stdout && started_by_launcher() && ::isatty(STDOUT_FILENO))
                    throw CLI::ValidationError(
                        "-o/--output",
                        "- (standard output) cannot carry the image under mpirun, which passes "
                        "rank 0's standard output on through a terminal of its own, whatever "
                        "its own is redirected to: name a file (-o shot.bmp)");
                if (o.output)
                    if (auto refused = frontend::output_refusal(*o.output))
                        throw CLI::ValidationError("-o/--output", *refused);
                frontend::check_region_flags(o, o.output);
                if (o.skip_existing)
                    if (std::optional<std::string> why = frontend::region_skip_existing_refusal(o))
                        throw CLI::ValidationError("--skip-existing", *why);
                if (o.skip_existing && o.check_only)
                    throw CLI::ValidationError("--skip-existing",
                                               "not with --check, which writes nothing");
                if (o.skip_existing)
                    if (std::optional<std::string> why = frontend::skip_existing_refusal(o))
                        throw CLI::ValidationError("--skip-existing", *why);
            },
            out, err))
        parsed.exit_code = *code;
    return parsed;
}

}  // namespace jt::mpi

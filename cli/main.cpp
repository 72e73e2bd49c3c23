// jtracer-cli: scene file in, image file out. The work lives in the core; this
// file only orders the steps and maps failures to exit codes.

#include "diff_command.hpp"
#include "existing_output.hpp"
#include "info_command.hpp"
#include "interruptible_render.hpp"
#include "list_names.hpp"
#include "options.hpp"
#include "sequence_command.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/frontend/frame_setup.hpp"
#include "jtracer/frontend/memory_budget.hpp"
#include "jtracer/frontend/progress.hpp"
#include "jtracer/frontend/render_fingerprint.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/region_file.hpp"
#include "jtracer/render_job.hpp"

#include <chrono>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>

namespace {

using namespace jt::cli;
using namespace jt::frontend;

// Keeps a copy of what is written to std::cerr while it lives, so that
// --expect --junit can put a failed render's messages into the report that a
// CI page shows, where stderr is a log few open. The copy stops growing at a
// size no scene's messages reach.
class StderrCopy : public std::streambuf {
  public:
    StderrCopy() : stderr_(std::cerr.rdbuf(this)) {}
    ~StderrCopy() override { std::cerr.rdbuf(stderr_); }
    StderrCopy(const StderrCopy&) = delete;
    StderrCopy& operator=(const StderrCopy&) = delete;
    const std::string& text() const { return copy_; }

  protected:
    int overflow(int c) override {
        if (c == traits_type::eof()) return traits_type::not_eof(c);
        const char ch = static_cast<char>(c);
        keep(std::string_view(&ch, 1));
        return stderr_->sputc(ch);
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        keep(std::string_view(s, static_cast<std::size_t>(n)));
        return stderr_->sputn(s, n);
    }
    int sync() override { return stderr_->pubsync(); }

  private:
    static constexpr std::size_t kKept = 1 << 20;
    void keep(std::string_view text) {
        copy_.append(text.substr(0, kKept - std::min(kKept, copy_.size())));
    }
    std::streambuf* stderr_;
    std::string copy_;
};

ExpectOptions expect_options(const Options& o) {
    return {o.expect.value_or(""), o.tolerance, o.update, o.junit, o.scene_path, o.quiet};
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// `compared` is set once the render is compared with --expect's reference;
// `start`: when the run began, for the time --junit reports.
int run(const Options& o, Clock::time_point start, bool& compared) {
    FrameSetup setup = set_up_frame("jtracer-cli", o, o.region);
    std::cerr << setup.message;
    if (setup.exit_code != exit_ok) return setup.exit_code;
    if (std::optional<std::string> refused = region_output_refusal(o, setup.output)) {
        std::cerr << *refused;
        return exit_usage;
    }
    if (o.check_only) {
        if (!o.quiet) std::cerr << o.scene_path << ": no errors\n";
        return exit_ok;
    }
    const jt::RenderOptions& options = setup.render;
    const std::string& output = setup.output;
    if (!o.output)
        if (std::optional<std::string> clash = file_clash(o, output)) {
            std::cerr << "jtracer-cli: " << *clash << "; nothing was written\n";
            return exit_usage;
        }
    if (!o.quiet) std::cerr << format_warning(o, output);
    // A region file records what it was rendered from, for jtracer-merge.
    const std::optional<jt::RenderFingerprint> fingerprint =
        o.region_output
            ? std::optional(render_fingerprint(setup.scene, options, o.clock.value_or(0.0)))
            : std::nullopt;
    if (o.skip_existing &&
        keep_existing_output(o, output, wanted_output(o, options, setup.format, fingerprint)))
        return exit_ok;
    if (jt::Expected<void> fits = check_render_memory(options, o.region_output); !fits) {
        std::cerr << "jtracer-cli: " << fits.error().message << "; nothing was written\n";
        return exit_io_error;
    }
    if (jt::Expected<void> writable = jt::check_atomic_write(output); !writable) {
        std::cerr << "jtracer-cli: " << writable.error().message << "; nothing was rendered\n";
        return exit_io_error;
    }
    jt::Expected<std::shared_ptr<const jt::PreparedScene>> prepared =
        jt::prepare_scene(std::move(setup.scene));
    if (!prepared) {
        std::cerr << "jtracer-cli: " << prepared.error().message << "; nothing was written\n";
        return exit_io_error;
    }
    // Until the job exists a signal ends the process at once (nothing is written
    // yet); from here on it cancels the render, which stops within a tile.
    jt::RenderJob job(*prepared, options);
    catch_interrupts();
    ProgressDisplay display(progress_style_for_stderr(o.progress, o.quiet));
    const bool rendered = render_interruptibly(job, display);
    display.finish();
    if (!rendered) return report_interrupt("nothing was written");
    // A region file keeps only the region's pixels and records where they
    // belong. A whole image moves out of the job, which is done with, instead
    // of being copied.
    const jt::Image8 image = o.region_output ? jt::Image8() : job.take_image();
    const jt::Expected<void> written =
        o.region_output ? jt::write_region_bmp(output, job.region_image(),
                                               region_placement(o, options, fingerprint))
                        : jt::write_image(output, image, setup.format);
    if (!written) {
        std::cerr << "jtracer-cli: " << shown_write_error(written.error().message) << "\n";
        return exit_io_error;
    }
    if (!o.quiet)
        std::cerr << "wrote " << shown_output(output) << ": "
                  << render_summary(options.width, options.height, options.samples, job.progress(),
                                    o.region)
                  << "\n";
    if (o.expect) {
        compared = true;
        const jt::Image8 whole_frame = o.region_output ? job.image() : jt::Image8();
        return check_expected(o.region_output ? whole_frame : image, output, expect_options(o),
                              seconds_since(start));
    }
    return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string_view(argv[1]) == "diff")
        return run_diff_command(argc - 1, argv + 1);
    if (argc > 1 && std::string_view(argv[1]) == "info")
        return run_info_command(argc - 1, argv + 1);
    ParsedOptions parsed = parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    const Options& o = parsed.options;
    const Clock::time_point start = Clock::now();
    bool compared = false;
    int code = exit_io_error;
    std::optional<StderrCopy> messages;
    if (o.expect && o.junit) messages.emplace();
    try {
        if (o.list_cameras) return list_cameras(o.scene_path);
        if (o.list_defines) return list_defines(o.scene_path);
        if (o.frames) return run_sequence(o);
        // A report that cannot be written is found before the render, as an
        // output is: a CI job without its report folder learns it at once.
        if (o.expect && o.junit)
            if (jt::Expected<void> writable = jt::check_atomic_write(*o.junit); !writable) {
                std::cerr << "jtracer-cli: --junit: " << writable.error().message
                          << "; nothing was rendered\n";
                return exit_io_error;
            }
        code = run(o, start, compared);
    } catch (const std::bad_alloc&) {
        std::cerr << "jtracer-cli: out of memory (the scene or the image is too large for the "
                     "memory available); nothing was written\n";
    } catch (const std::exception& e) {
        std::cerr << "jtracer-cli: " << e.what() << "; nothing was written\n";
    }
    // --expect --junit: a render that failed is a test case in error.
    if (o.expect && !compared && code != exit_ok)
        return record_failed_render(expect_options(o), code, messages ? messages->text() : "",
                                    seconds_since(start));
    return code;
}

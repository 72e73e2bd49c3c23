#include "jtracer/frontend/scene_sequence.hpp"

#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/pipe_wait_notice.hpp"
#include "jtracer/scene_file.hpp"

#include <filesystem>

namespace jt::frontend {

SceneSequence::SceneSequence(std::string_view program, const RenderFlags& flags,
                             std::optional<FrameRegion> region)
    : program_(program), flags_(flags), region_(region), count_(flags.frames.value_or(1)) {
    range_ = flags.frame_range.value_or(FrameRange{0, count_ - 1});
    if (flags.output)
        if (Expected<FrameNamePattern> pattern = parse_frame_name_pattern(*flags.output))
            pattern_ = *pattern;
}

FrameSetup SceneSequence::set_up(double clock, bool& reads_clock) {
    RenderFlags flags = flags_;
    flags.clock = clock;
    ParseOptions options = parse_options_for(flags);
    options.record_primitive_readings = true;
    options.earlier = &earlier_;
    // A scene from a pipe (a named pipe, bash's <(...)) is read once: read
    // again, it would be empty, or wait for good for a writer that is gone.
    Expected<LoadedScene> read = [&] {
        if (piped_text_) return load_scene_text(*piped_text_, flags.scene_path, options);
        const PipeWaitNotice notice(program_, flags.scene_path);
        return load_scene_file(flags.scene_path, options);
    }();
    if (read && !piped_text_ && is_stream(flags.scene_path)) piped_text_ = read->text;
    earlier_.primitives = {};  // taken, or of other texts
    if (!read) {
        FrameSetup setup;
        setup.exit_code = exit_io_error;
        setup.message = program_ + ": " + read.error().message + "\n";
        return setup;
    }
    reads_clock = read->parsed.reads_clock;
    path_ = read->path;
    earlier_.text = read->text;
    earlier_.files = read->parsed.source.files;
    earlier_.readings = std::move(read->parsed.primitive_readings);
    // The primitives taken from the earlier parse are ones it made from the
    // same readings, so the whole scene is as a parse of this text makes it.
    return set_up_frame(program_, flags, std::move(*read), LoadedPrimitives::as_parsed, region_);
}

namespace {

std::string replaces_scene(std::string_view program, int index, const std::string& output) {
    return std::string(program) + ": frame " + std::to_string(index) + "'s file '" + output +
           "' is the scene file itself: the image would replace it";
}

}  // namespace

std::optional<std::string> SceneSequence::output_clash() const {
    if (!pattern_) return std::nullopt;
    // Only a name that ends as the scene's does can be it (as typed, or
    // through a link, which frame() still catches), so a long sequence asks
    // the file system about few names.
    const std::string scene_name = std::filesystem::path(flags_.scene_path).filename().string();
    for (int index = range_.first; index <= range_.last; ++index) {
        const std::string output = frame_file_name(*pattern_, index);
        if (output.ends_with(scene_name) && same_file(output, flags_.scene_path))
            return replaces_scene(program_, index, output) + "; no frame was written\n";
    }
    return std::nullopt;
}

std::string SceneSequence::unprinted(const std::vector<Diagnostic>& diagnostics) {
    std::string message;
    for (const Diagnostic& d : diagnostics) {
        std::string text = format_diagnostics({d}, path_, earlier_.text, earlier_.files);
        if (printed_.insert(text).second) message += text;
    }
    return message;
}

SequenceFrame SceneSequence::frame(int index, bool prepare,
                                   const std::function<bool(const SequenceFrame&)>& skip) {
    SequenceFrame frame;
    frame.index = index;
    frame.clock = frame_clock(index, count_);
    bool reads_clock = false;
    std::optional<FrameSetup> fresh;
    if (!fixed_) fresh = set_up(frame.clock, reads_clock);
    const FrameSetup& setup = fixed_ ? *fixed_ : *fresh;
    frame.exit_code = setup.exit_code;
    if (fresh) {
        // A usage or I/O failure is reported whole; diagnostics only once.
        const bool diagnostics_only =
            setup.exit_code == exit_ok || setup.exit_code == exit_scene_error;
        frame.message = diagnostics_only ? unprinted(setup.diagnostics) : setup.message;
        // The frame is named after an error, and after warnings no earlier
        // frame gave: in a scene that reads `clock` a warning may be of some
        // frames only, or name a value that changes from frame to frame.
        const bool new_warnings = setup.exit_code == exit_ok && !frame.message.empty();
        if ((setup.exit_code == exit_scene_error || new_warnings) && reads_clock)
            frame.message += "note: at frame " + std::to_string(index) +
                             " (clock = " + shortest_decimal(frame.clock) + ")\n";
    }
    if (setup.exit_code != exit_ok) return frame;
    frame.render = setup.render;
    frame.output =
        pattern_ ? frame_file_name(*pattern_, index) : numbered_file_name(setup.output, index);
    // The name typed on the command line decides, as for one image.
    frame.format = pattern_ ? format_from_extension(frame.output) : setup.format;
    if (same_file(frame.output, flags_.scene_path)) {
        frame.exit_code = exit_usage;
        frame.message += replaces_scene(program_, index, frame.output) + "; stopped before it\n";
        return frame;
    }
    if (fingerprints_) {
        // A scene the same at every clock is digested once.
        if (fixed_ && fixed_fingerprint_) {
            frame.fingerprint = fixed_fingerprint_;
            frame.fingerprint->clock = frame.clock;
        } else {
            frame.fingerprint = render_fingerprint(setup.scene, setup.render, frame.clock);
            if (!reads_clock) fixed_fingerprint_ = frame.fingerprint;
        }
    }
    frame.skipped = skip && skip(frame);
    if (prepare && !frame.skipped) {
        if (fixed_ && previous_) {
            frame.prepared = previous_;
        } else {
            Expected<std::shared_ptr<const PreparedScene>> prepared =
                prepare_scene(setup.scene, previous_);
            if (!prepared) {
                frame.exit_code = exit_io_error;
                frame.message += program_ + ": " + prepared.error().message + "\n";
                return frame;
            }
            frame.prepared = previous_ = *prepared;
        }
    }
    if (fresh && !reads_clock) fixed_ = std::move(*fresh);
    if (fresh && reads_clock) earlier_.primitives = std::move(fresh->scene.primitives);
    return frame;
}

}  // namespace jt::frontend

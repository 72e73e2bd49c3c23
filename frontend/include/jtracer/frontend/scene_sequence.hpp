#pragma once
// A scene rendered at the frames of a sequence (docs/language.md §15.4), each
// frame set up exactly as set_up_frame sets up a render at `--clock` of the
// frame's clock, so that a frame's bytes equal that render's.
//
// What it saves: a scene none of whose values names `clock` is the same at
// every frame, so it is read, checked and prepared once for the whole
// sequence. Any other is read again at every frame, but its primitives that
// read no `clock` are taken from the previous frame rather than read again
// (parser.hpp's EarlierParse), and it is prepared with the previous frame's
// scene at hand (its acceleration structure is reused when the geometry did
// not move; models and textures come from the shared caches, held meanwhile
// by the previous frame).

#include "jtracer/frontend/frame_file_name.hpp"
#include "jtracer/frontend/frame_setup.hpp"
#include "jtracer/frontend/render_fingerprint.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace jt::frontend {

struct SequenceFrame {
    int index = 0;
    double clock = 0.0;
    int exit_code = exit_ok;  // non-zero: stop with it; `message` says why
    // For stderr: the diagnostics no earlier frame printed (a warning that
    // every frame gives shows once), and after an error or such warnings of
    // a scene that reads `clock` the line "note: at frame F (clock = V)".
    std::string message;
    RenderOptions render;
    std::string output;  // this frame's file
    ImageFormat format = ImageFormat::bmp;
    // The render-ready scene; null unless asked for, and on failure.
    std::shared_ptr<const PreparedScene> prepared;
    // The caller's `skip` said that the frame's file is already there: not
    // prepared, to render no more.
    bool skipped = false;
    // What the frame is rendered from, when fingerprint_frames() asked.
    std::optional<RenderFingerprint> fingerprint;
};

class SceneSequence {
  public:
    // `flags.frames` must be set; flags.output, when set, is a valid pattern
    // (check_sequence_flags).
    SceneSequence(std::string_view program, const RenderFlags& flags,
                  std::optional<FrameRegion> region = std::nullopt);

    // The frames to render: --frame-range, or all of them.
    FrameRange range() const { return range_; }
    int count() const { return count_; }

    // Why -o's pattern cannot be used: a frame of the range would be written
    // over the scene file. Nothing when no frame's file is the scene's.
    std::optional<std::string> output_clash() const;

    // From now on each frame carries its fingerprint (for region files).
    void fingerprint_frames() { fingerprints_ = true; }

    // Sets up frame `index`, and prepares it when `prepare` (a failure to
    // prepare is exit_io_error; a frame whose file is the scene file itself
    // is exit_usage) and `skip`, asked once the frame is set up, does not say
    // that its file is already there (--skip-existing).
    SequenceFrame frame(int index, bool prepare = true,
                        const std::function<bool(const SequenceFrame&)>& skip = {});

  private:
    FrameSetup set_up(double clock, bool& reads_clock);
    std::string unprinted(const std::vector<Diagnostic>& diagnostics);

    std::string program_;
    RenderFlags flags_;
    std::optional<FrameRegion> region_;
    int count_ = 1;
    FrameRange range_;
    std::optional<FrameNamePattern> pattern_;
    // Set once a frame showed that the scene is the same at every clock:
    // every later frame renders this set-up and this prepared scene.
    std::optional<FrameSetup> fixed_;
    bool fingerprints_ = false;
    std::optional<RenderFingerprint> fixed_fingerprint_;  // fixed_'s, at any clock
    std::shared_ptr<const PreparedScene> previous_;
    std::set<std::string> printed_;  // formatted diagnostics already shown
    // The frame being set up: its path and texts, to format its diagnostics;
    // once it has rendered, its primitives, for the next frame to take.
    std::string path_;
    EarlierParse earlier_;
    // The text of a scene read from a pipe, which gives it only once.
    std::optional<std::string> piped_text_;
};

}  // namespace jt::frontend

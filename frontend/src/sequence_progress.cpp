#include "jtracer/frontend/sequence_progress.hpp"

#include "jtracer/frontend/progress.hpp"

#include <string>

namespace jt::frontend {

RenderProgress sequence_progress(const RenderProgress& frame, int done, int total, double seconds) {
    RenderProgress whole = frame;
    const double frames = total > 0 ? static_cast<double>(total) : 1.0;
    whole.fraction = (static_cast<double>(done) + frame.fraction) / frames;
    whole.seconds = seconds;
    whole.pass_name = "frame " + std::to_string(done + 1) + " of " + std::to_string(total);
    whole.finished = frame.finished && done + 1 == total;
    return whole;
}

std::string sequence_summary(int total, int written, int kept, double seconds) {
    const std::string time = format_duration(seconds);
    if (written == 0)
        return "kept all " + std::to_string(total) + " frames, already there (" + time + ")\n";
    return "wrote " + std::to_string(written) + (written == 1 ? " frame" : " frames") +
           (kept > 0 ? " and kept " + std::to_string(kept) + " already there" : std::string()) +
           " in " + time + "\n";
}

std::string frames_there(int first, int index, int kept) {
    const std::string frames = "frames " + std::to_string(first) + ".." + std::to_string(index - 1);
    const int written = index - first - kept;
    if (kept == 0) return frames + " were written";
    if (written == 0) return frames + " were kept, already there";
    return frames + " are there (" + std::to_string(written) + " written, " + std::to_string(kept) +
           " kept)";
}

}  // namespace jt::frontend

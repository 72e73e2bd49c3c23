#pragma once
// --skip-existing: whether an output already there holds what this run would
// write, so that a rerun after a lost node or a full disk renders only what is
// missing. A file is kept only when it is complete: a truncated or damaged
// one (a copy cut short, a disk that filled) is rendered again. Shared by
// jtracer-cli and jtracer-mpi, which keep and report files alike.

#include "jtracer/frontend/render_flags.hpp"

#include "jtracer/image_file.hpp"
#include "jtracer/region_file.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace jt::frontend {

// What the run would write to the file.
struct WantedOutput {
    int width = 0;  // the whole frame's
    int height = 0;
    ImageFormat format = ImageFormat::bmp;
    // A region file (--region-output): the record it must carry.
    std::optional<RegionPlacement> placement;
};

struct ExistingOutput {
    bool exists = false;  // something is there under the name
    bool keep = false;    // and it is what the run would write
    std::string why_not;  // when it exists but is not: why, for the message
};

// A whole image: the format its name asks for, every byte there (a PNG's
// chunks and their checksums, up to IEND; a BMP's size as its header says),
// decoded whole and of the frame's size. A region file: also its record's
// placement.
ExistingOutput check_existing_output(const std::string& path, const WantedOutput& wanted);

// --skip-existing for the file `path`: true when it is kept, said on stderr
// (unless `quiet`) as "kept PATH WHAT: already there and complete"; a file
// there that is not complete is said to be rendered again, and why, as
// "PROGRAM: note: ...".
bool keep_existing_output(std::string_view program, bool quiet, const std::string& path,
                          const WantedOutput& wanted, const std::string& what = "");

// Why --skip-existing means nothing for this output, or nothing: standard
// output or a device holds no earlier image to keep.
std::optional<std::string> skip_existing_refusal(const RenderFlags& flags);

}  // namespace jt::frontend

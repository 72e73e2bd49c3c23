// jtracer-merge: assembles the region files of one frame (written by
// `jtracer-cli --region ... --region-output`) into the whole image. Each part
// carries where it belongs (region_file.hpp), so the order and names of the
// parts do not matter.

#include "jtracer/atomic_file.hpp"
#include "jtracer/frontend/command_line.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/merge_regions.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

namespace {

using jt::frontend::exit_io_error;
using jt::frontend::exit_ok;
// 1 means parts that do not make one frame.
constexpr int exit_bad_parts = jt::frontend::exit_scene_error;

// A signal that ends the process during the write would leave the temporary
// file beside the frame: remove it, then end as the signal asks.
extern "C" void on_ending_signal(int signal) {
    jt::frontend::end_by_signal(signal);
}

void remove_the_temporary_file_on_signals() {
    jt::frontend::handle_stop_signals(on_ending_signal);
}

// Whether `path` is named as write_file_atomically names its temporary file,
// TARGET.tmp-XXXXXX: one left by a process killed during a write, which a
// glob such as `band*` picks up beside the parts.
bool is_unfinished_write(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    const std::size_t at = name.rfind(".tmp-");
    if (at == std::string::npos || at == 0 || name.size() - at != 11) return false;
    return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(at) + 5, name.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; });
}

int merge(const std::vector<std::string>& part_paths, const std::string& output, bool quiet) {
    // Found before the parts are read, as jtracer-cli finds it before the
    // render: the 64 bands of a 16k frame are gigabytes to read for nothing.
    if (const jt::Expected<void> writable = jt::check_atomic_write(output); !writable) {
        std::cerr << "jtracer-merge: " << writable.error().message << "; no part was read\n";
        return exit_io_error;
    }
    std::vector<jt::RegionPart> parts;
    for (const std::string& path : part_paths) {
        jt::Expected<jt::RegionPart> part = jt::read_region_bmp(path);
        if (!part) {
            std::cerr << "jtracer-merge: " << part.error().message << "; nothing was written\n";
            return exit_io_error;
        }
        parts.push_back(std::move(*part));
    }
    const jt::Expected<jt::Image8> frame = jt::merge_regions(parts);
    // Parts written before the fingerprint existed merge as they always did,
    // unchecked: say so, as a mix of renders is then the user's to rule out.
    if (frame && !quiet && std::none_of(parts.begin(), parts.end(), [](const jt::RegionPart& p) {
            return p.placement.fingerprint.has_value();
        }))
        std::cerr << "jtracer-merge: note: the parts carry no render fingerprint (written by an "
                     "older jtracer-cli): that they are parts of one render was not checked\n";
    if (!frame) {
        std::cerr << "jtracer-merge: " << frame.error().message << "; nothing was written\n";
        return exit_bad_parts;
    }
    if (const jt::Expected<void> written =
            jt::write_image(output, *frame, jt::format_from_extension(output));
        !written) {
        std::cerr << "jtracer-merge: " << jt::frontend::shown_write_error(written.error().message)
                  << "\n";
        return exit_io_error;
    }
    if (!quiet)
        std::cerr << "wrote " << jt::frontend::shown_output(output) << ": " << frame->width << "x"
                  << frame->height << " from " << parts.size() << " parts\n";
    return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> part_paths;
    std::string output;
    bool quiet = false;
    CLI::App app{
        "jtracer-merge: assembles region files written by 'jtracer-cli --region X0,Y0,X1,Y1 "
        "--region-output' into the whole frame."};
    app.footer(
        "Each part records its frame size and region, so any order works.\n"
        "\n"
        "Example:\n"
        "  jtracer-cli scene.jts --region 0,0,1920,540 --region-output -o parts/top.bmp\n"
        "  jtracer-cli scene.jts --region 0,540,1920,1080 --region-output -o parts/bottom.bmp\n"
        "  jtracer-merge -o frame.png parts/*.bmp\n"
        "\n"
        "Parts that overlap, leave a gap, reach out of the frame, belong to frames of\n"
        "different sizes or to different renders (each part records a fingerprint of its\n"
        "scene, samples, camera and clock) are refused and nothing is written.\n"
        "\n"
        "Exit codes: 0 ok, 1 parts that do not make one frame, 2 bad command line, 3 file I/O "
        "errors.\n");
    jt::frontend::add_version_flag(app, "jtracer-merge");
    app.add_option("-o,--output", output,
                   "The whole frame; a name ending in .png gives a PNG, anything else a BMP; - is "
                   "standard output (a BMP)")
        ->transform(jt::frontend::output_name, "", "")
        ->required()
        ->type_name("FILE");
    app.add_option("parts", part_paths, "The region files (BMP)")->required();
    app.add_flag("-q,--quiet", quiet, "No summary; errors still show");
    // The frame written over a part would lose that part for the next merge
    // (and a glob such as parts/*.bmp picks an earlier frame up as a part).
    auto checks = [&] {
        if (output.empty())
            throw CLI::ValidationError("-o/--output", "needs a file name, not an empty string");
        if (std::optional<std::string> refused = jt::frontend::output_refusal(output))
            throw CLI::ValidationError("-o/--output", *refused);
        for (const std::string& part : part_paths)
            if (jt::frontend::same_file(output, part))
                throw CLI::ValidationError("-o/--output", "'" + output + "' is also a part (" +
                                                              part + "): it would be replaced");
        for (std::size_t i = 0; i < part_paths.size(); ++i) {
            if (is_unfinished_write(part_paths[i]))
                throw CLI::ValidationError(
                    "'" + part_paths[i] +
                    "' is the temporary file of a write that never finished (its process was "
                    "killed before the rename): not a part; remove it, and render that part "
                    "again if its own file is missing");
            for (std::size_t j = i + 1; j < part_paths.size(); ++j)
                if (jt::frontend::same_file(part_paths[i], part_paths[j]))
                    throw CLI::ValidationError("'" + part_paths[i] + "' and '" + part_paths[j] +
                                               "' are the same file, given twice");
        }
    };
    if (std::optional<int> code =
            jt::frontend::parse_command_line(app, argc, argv, "jtracer-merge", checks))
        return *code;
    remove_the_temporary_file_on_signals();
    try {
        return merge(part_paths, output, quiet);
    } catch (const std::bad_alloc&) {
        std::cerr << "jtracer-merge: out of memory; nothing was written\n";
        return exit_io_error;
    }
}

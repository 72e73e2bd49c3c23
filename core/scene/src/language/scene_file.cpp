#include "jtracer/scene_file.hpp"

#include "io/file_bytes.hpp"
#include "io/huge_pages.hpp"
#include "io/link_cycle.hpp"
#include "io/text_give_back.hpp"
#include "jtracer/validate.hpp"
#include "language/quote.hpp"
#include "language/validation.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <system_error>

namespace jt {

namespace {

// The whole file; `stamp`, when asked for, is the stamp of the file opened
// (taken before reading it, so that a write during the read moves it).
Expected<std::string> read_text(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                FileStamp* stamp);

// The loaded file's text when it was given back: the file read again, or
// nullopt when it cannot be read or is no longer the file that was parsed.
std::optional<std::string> text_read_again(const LoadedScene& loaded) {
    FileStamp now;
    Expected<std::string> text = read_text(loaded.path, max_scene_file_bytes, &now);
    if (!text || now != loaded.stamp || text->size() != loaded.stamp.size) return std::nullopt;
    return std::move(*text);
}

Diagnostic text_changed_note(const LoadedScene& loaded, std::string_view what) {
    return {Severity::note,
            {},
            lang::quote(loaded.path) + " changed or went away after it was read, so " +
                std::string(what)};
}

}  // namespace

Expected<std::string> read_text_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
    return read_text(path, max_bytes, nullptr);
}

namespace {

// Standard input named as a file. Opening /dev/stdin again opens the pipe
// behind it anew, and a named pipe opened anew waits for a writer even when
// the one that filled it has gone and its text waits unread
// (`jtracer-cli /dev/stdin < fifo`): the descriptor already open is read.
bool names_standard_input(const std::filesystem::path& path) {
    return path == "/dev/stdin" || path == "/dev/fd/0" || path == "/proc/self/fd/0";
}

std::FILE* fdopen_standard_input() {
    const int descriptor = ::fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 0);
    if (descriptor < 0) return nullptr;
    std::FILE* file = ::fdopen(descriptor, "rb");
    if (file == nullptr) ::close(descriptor);
    return file;
}

Expected<std::string> read_text(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                FileStamp* stamp) {
    const std::string name = lang::quote(path.string());
    std::error_code ec;
    auto status = std::filesystem::status(path, ec);
    if (ec && ec == std::errc::too_many_symbolic_link_levels)
        return Error{"cannot read " + name + ": " + read_failure_reason(path, ELOOP)};
    if (ec || !std::filesystem::exists(status))
        return Error{"cannot read " + name + ": " + read_failure_reason(path, ENOENT)};
    if (std::filesystem::is_directory(status))
        return Error{name + " is a directory, not a scene file"};
    std::uintmax_t known_size = 0;  // 0: unknown (or empty)
    if (std::filesystem::is_regular_file(status)) {
        auto size = std::filesystem::file_size(path, ec);
        if (!ec) known_size = size;
        if (!ec && size > max_bytes)
            return Error{name + " is too large to read (" + std::to_string(size) +
                         " bytes; the limit is " + std::to_string(max_bytes) + ")"};
    }
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(
        names_standard_input(path) ? fdopen_standard_input() : std::fopen(path.c_str(), "rb"),
        &std::fclose);
    if (!f) return Error{"cannot read " + name + ": " + read_failure_reason(path, errno)};
    // A device other than a terminal never ends (/dev/zero, /dev/urandom) or is
    // no text: it would be read up to the limit, a gigabyte, before failing. A
    // terminal ends where its user types the end of input.
    struct stat opened {};
    if (::fstat(::fileno(f.get()), &opened) == 0 &&
        (S_ISBLK(opened.st_mode) || (S_ISCHR(opened.st_mode) && !::isatty(::fileno(f.get())))))
        return Error{name + " is a device, not a scene file"};
    if (stamp) *stamp = file_stamp(::fileno(f.get()));
    std::string text;
    // A regular file of known size is read in one go into a buffer of that
    // size: growing the string chunk by chunk would copy it and fault in twice
    // its pages. The loop below then only confirms the end (or reads on, if the
    // file grew meanwhile); pipes and other files of no known size start there.
    if (known_size > 0) {
        text.reserve(static_cast<std::size_t>(known_size));
        advise_huge_pages(text);
        text.resize(static_cast<std::size_t>(known_size));
        text.resize(std::fread(text.data(), 1, text.size(), f.get()));
    }
    char buffer[1 << 16];
    for (;;) {
        std::size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
        text.append(buffer, n);
        if (text.size() > max_bytes)
            return Error{name + " is too large to read (more than " + std::to_string(max_bytes) +
                         " bytes)"};
        if (n < sizeof buffer) break;
    }
    if (std::ferror(f.get())) {
        int error = errno;
        return Error{"cannot read " + name + ": " + read_failure_reason(path, error ? error : EIO)};
    }
    return text;
}

}  // namespace

Expected<LoadedScene> load_scene_file(const std::filesystem::path& path, ParseOptions options,
                                      TextKeeping keeping) {
    FileStamp stamp;
    Expected<std::string> text = read_text(path, max_scene_file_bytes, &stamp);
    if (!text) return text.error();
    Expected<LoadedScene> loaded = load_scene_text(std::move(*text), path, options, keeping);
    if (loaded) loaded->stamp = stamp;
    return loaded;
}

Expected<LoadedScene> load_scene_text(std::string text, const std::filesystem::path& path,
                                      ParseOptions options, TextKeeping keeping) {
    LoadedScene loaded;
    loaded.path = path.string();
    if (options.main_file.empty()) options.main_file = loaded.path;
    loaded.options = options;
    loaded.text = std::move(text);
    std::optional<TextGiveBack> give_back;
    if (keeping == TextKeeping::given_back_when_large && !options.source_map &&
        loaded.text.size() >= smallest_text_given_back) {
        give_back.emplace(loaded.text);
        options.text_passed = [&give_back](std::size_t offset) { give_back->passed(offset); };
    }
    loaded.parsed = parse_scene(loaded.text, options);
    if (give_back && give_back->gave_back()) {
        std::string().swap(loaded.text);  // not `= {}`, which keeps the buffer
        loaded.text_given_back = true;
    }
    // A machine's limit, not a mistake in the file: an I/O failure like any other.
    if (loaded.parsed.out_of_memory)
        return Error{"cannot read " + lang::quote(loaded.path) +
                     ": out of memory (the scene is too large for the memory available)"};
    loaded.parsed.scene.asset_folder = path.parent_path().string();
    return loaded;
}

std::vector<Diagnostic> check_scene(const LoadedScene& loaded, CheckOptions options) {
    std::vector<Diagnostic> all = loaded.parsed.diagnostics;
    if (!has_errors(all)) {
        lang::Validation found = lang::validate_scene_parts(
            loaded.parsed.scene, loaded.parsed.source, options.validation);
        const bool locate = !found.diagnostics.empty() && !loaded.options.source_map &&
                            (options.locate_warnings || has_errors(found.diagnostics));
        if (locate) {
            // Same text, same scene lists: the map lines up with the scene
            // (overrides applied to it change values, not the lists). Findings
            // about the settings, cameras or lights alone (an aspect that no
            // longer matches --width) need no record of the primitives.
            ParseOptions with_map = loaded.options;
            with_map.source_map = true;
            std::optional<std::string> again =
                loaded.text_given_back ? text_read_again(loaded) : std::nullopt;
            if (!loaded.text_given_back || again) {
                const std::string_view text = again ? *again : loaded.text;
                const SceneSource source = found.about_primitives
                                               ? parse_scene(text, with_map).source
                                               : lang::source_without_primitives(text, with_map);
                found.diagnostics = validate_scene(loaded.parsed.scene, source, options.validation);
            } else {
                found.diagnostics.push_back(
                    text_changed_note(loaded, "the messages above say no line"));
            }
        }
        for (Diagnostic& d : found.diagnostics) all.push_back(std::move(d));
    }
    return all;
}

std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics,
                               std::string_view filename, std::string_view source,
                               std::span<const SourceFile> files) {
    std::string out;
    for (const Diagnostic& d : diagnostics) out += format_diagnostic(d, filename, source, files);
    return out;
}

std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics,
                               const LoadedScene& loaded) {
    const std::span<const SourceFile> files = loaded.parsed.source.files;
    if (!loaded.text_given_back || diagnostics.empty())
        return format_diagnostics(diagnostics, loaded.path, loaded.text, files);
    if (std::optional<std::string> again = text_read_again(loaded))
        return format_diagnostics(diagnostics, loaded.path, *again, files);
    std::vector<Diagnostic> noted = diagnostics;
    noted.push_back(text_changed_note(loaded, "the messages above cannot quote it"));
    return format_diagnostics(noted, loaded.path, {}, files);
}

}  // namespace jt

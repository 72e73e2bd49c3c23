#include "language/include_stack.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/scene_file.hpp"
#include "language/lexer.hpp"
#include "language/quote.hpp"

#include <filesystem>
#include <system_error>

namespace jt {

Expected<IncludedText> read_include_file(const std::string& path, std::uintmax_t max_bytes) {
    // Opening a FIFO waits for a writer, possibly forever, and a socket or a
    // terminal is no file to include: only regular files (and folders, which
    // the reader names as such) go on to be read.
    std::error_code status_ec;
    const std::filesystem::file_status status = std::filesystem::status(path, status_ec);
    if (!status_ec && std::filesystem::exists(status) &&
        !std::filesystem::is_regular_file(status) && !std::filesystem::is_directory(status))
        return Error{lang::quote(path) + " is " +
                     (std::filesystem::is_fifo(status)     ? "a named pipe (FIFO)"
                      : std::filesystem::is_socket(status) ? "a socket"
                                                           : "a device") +
                     ", not a scene file"};
    Expected<std::string> text = read_text_file(path, max_bytes);
    if (!text) return text.error();
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::canonical(path, ec);
    if (ec) return Error{"cannot read " + lang::quote(path) + ": " + ec.message()};
    return IncludedText{canonical.string(), std::move(*text)};
}

namespace lang {

namespace {

namespace fs = std::filesystem;

// `path` joined to the folder of `of`, lexically; an absolute `path` as it is.
fs::path beside(const fs::path& of, const fs::path& path) {
    if (path.is_absolute()) return path;
    return of.parent_path() / path;
}

std::string normal(const fs::path& path) {
    return path.lexically_normal().generic_string();
}

std::string main_canonical(const ParseOptions& options) {
    if (options.main_file.empty()) return {};
    std::error_code ec;
    fs::path canonical = fs::canonical(options.main_file, ec);
    return ec ? std::string() : canonical.string();
}

}  // namespace

IncludeStack::IncludeStack(const ParseOptions& options)
    : main_name_(options.main_file.empty() ? "<text>" : options.main_file),
      main_path_(options.main_file),
      main_canonical_(main_canonical(options)),
      read_(options.read_include ? options.read_include : IncludeReader(read_include_file)),
      bytes_left_(max_scene_file_bytes) {}

std::optional<IncludeStack::Opened> IncludeStack::open(std::string_view path, SourcePos at,
                                                       DiagnosticSink& sink, bool& unreadable) {
    unreadable = false;
    if (path.empty()) {
        sink.error(at, "'include' takes the path of a file; this string is empty");
        return std::nullopt;
    }
    if (open_.size() + 1 > static_cast<std::size_t>(kMaxIncludeDepth)) {
        sink.error(at, "includes are nested too deeply: a file may be included at most " +
                           std::to_string(kMaxIncludeDepth) + " levels deep");
        return std::nullopt;
    }
    if (files_.size() >= kMaxIncludeReadings) {
        sink.error(at, "too many files included: a scene may read at most " +
                           std::to_string(kMaxIncludeReadings) + " (counting repeats)");
        return std::nullopt;
    }
    const fs::path written(path);
    const std::uint32_t from = at.file;
    const fs::path read_path =
        beside(from == 0 ? fs::path(main_path_) : fs::path(files_[from - 1].path), written);
    static_assert(max_scene_file_bytes == 1ull << 30, "the message below says 1 GiB");
    // The limit is the included files' together: said as such, with what the
    // files before took, not as a limit of this file's of an odd size.
    std::error_code size_ec;
    if (const std::uintmax_t size = fs::file_size(read_path, size_ec);
        !size_ec && size > bytes_left_) {
        unreadable = true;
        unread_.push_back(read_path.string());
        std::string message = quote(read_path.string()) + " is too large to include (" +
                              std::to_string(size) +
                              " bytes): the files a scene includes may hold 1 GiB (" +
                              std::to_string(max_scene_file_bytes) + " bytes) in all";
        if (bytes_left_ < max_scene_file_bytes)
            message += ", and the files included before it hold " +
                       std::to_string(max_scene_file_bytes - bytes_left_);
        sink.error(at, std::move(message));
        return std::nullopt;
    }
    Expected<IncludedText> read = read_(read_path.string(), bytes_left_);
    if (!read) {
        unreadable = true;
        unread_.push_back(read_path.string());
        std::string message = read.error().message;
        // A Windows habit: '\\' is a character of a file name here.
        if (path.find('\\') != std::string_view::npos)
            message += " (folders are separated by '/' on every platform)";
        sink.error(at, message);
        return std::nullopt;
    }
    const std::string shown = normal(beside(fs::path(name(from)), written));
    auto reading = [&](std::uint32_t file) {
        return file == 0 ? main_canonical_ : files_[file - 1].canonical;
    };
    bool cycle = !main_canonical_.empty() && read->canonical == main_canonical_;
    for (std::uint32_t file : open_) cycle = cycle || reading(file) == read->canonical;
    if (cycle) {
        sink.error(at, "an include cycle: " + quote(shown) +
                           " is already being read, so it would include itself");
        return std::nullopt;
    }
    bytes_left_ -= std::min<std::uintmax_t>(bytes_left_, read->text.size());
    const std::string relative =
        from == 0 ? normal(written) : normal(beside(fs::path(relative_[from - 1]), written));
    files_.push_back(
        {shown, read_path.string(), std::move(read->canonical), std::move(read->text), at});
    relative_.push_back(relative);
    const auto file = static_cast<std::uint32_t>(files_.size());
    // As for the main file: the error is at the first bad byte, in the
    // included file, so that a large file need not be searched for it. The
    // file is kept (not read) for the message to quote its line and name
    // its include chain, and for a viewer to watch it.
    const std::string_view text = files_.back().text;
    if (std::size_t bad = find_invalid_text_byte(text); bad != std::string_view::npos) {
        unreadable = true;
        SourcePos pos = position_of(text, bad);
        pos.file = file;
        sink.error(pos, std::string("the file is not a text file: it contains ") +
                            (text[bad] == '\0' ? "a NUL byte" : "a byte that is not UTF-8 text"));
        return std::nullopt;
    }
    open_.push_back(file);
    return Opened{file, files_.back().text};
}

void IncludeStack::close() {
    if (!open_.empty()) open_.pop_back();
}

std::string IncludeStack::rebased_asset(std::string_view path, std::uint32_t file) const {
    if (file == 0 || file > relative_.size()) return {};
    const fs::path written(path);
    const fs::path folder = fs::path(relative_[file - 1]).parent_path();
    if (written.is_absolute() || folder.empty()) return {};
    return normal(folder / written);
}

std::string_view IncludeStack::name(std::uint32_t file) const {
    if (file == 0 || file > files_.size()) return main_name_;
    return files_[file - 1].name;
}

std::string IncludeStack::location(SourcePos pos) const {
    return std::string(name(pos.file)) + ":" + std::to_string(pos.line) + ":" +
           std::to_string(pos.column);
}

std::string IncludeStack::line_from(SourcePos pos, SourcePos from) const {
    if (pos.file == from.file) return "line " + std::to_string(pos.line);
    return location(pos);
}

std::string IncludeStack::line_column_from(SourcePos pos, SourcePos from) const {
    if (pos.file == from.file) return std::to_string(pos.line) + ":" + std::to_string(pos.column);
    return location(pos);
}

std::string IncludeStack::chain(std::uint32_t file) const {
    std::string out;
    // Each step goes to an earlier file, so this ends at the main file.
    while (file > 0 && file <= files_.size()) {
        const SourcePos at = files_[file - 1].included_at;
        out += ", included from " + location(at);
        file = at.file;
    }
    return out;
}

std::string IncludeStack::where(SourcePos pos, SourcePos from) const {
    if (pos.file == 0) return line_column_from(pos, from);
    return location(pos) + chain(pos.file);
}

std::vector<SourceFile> IncludeStack::take_files() {
    return std::vector<SourceFile>(std::make_move_iterator(files_.begin()),
                                   std::make_move_iterator(files_.end()));
}

}  // namespace lang
}  // namespace jt

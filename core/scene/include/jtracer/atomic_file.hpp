#pragma once
// Writing a file so that readers only ever see the old file or the whole new
// one: the bytes go to a temporary file beside the target, which is then
// renamed over it (docs/language.md §10.3), or linked to its name when the
// file must be new. A failure leaves no file behind.

#include "jtracer/error.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

namespace jt {

// The file that writing to `path` replaces or creates: `path` itself, or,
// when it is a symbolic link, the file the chain of links ends at, which
// need not exist yet (a link to a render not made). A loop of links is left
// as it is, for the write to fail on.
std::filesystem::path file_behind_links(const std::filesystem::path& path);

// A symbolic link stays a link: the file behind it is the one written.
// On failure the error names the file and the reason ("cannot write
// 'out/x.bmp': No such file or directory"). A file replaced keeps its
// permissions; a new one is made 0644.
Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     std::span<const std::uint8_t> bytes);

// A file's bytes in pieces: each call returns the next one, an empty piece at
// the end. A piece stays valid until the next call.
using BytePieces = std::function<std::span<const std::uint8_t>()>;

// The same, for a file made piece by piece (a BMP's rows), which then needs no
// buffer of its whole size: megabytes of fresh memory cost more to fault in
// than to write.
Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     const BytePieces& next_piece);

// Whether write_file_atomically(target, ...) could write now, asked before
// long work so that a missing folder, a folder in the way or one without
// write permission is found before it, not after: the temporary file the
// write would make is made and removed. A device or pipe, written in place,
// passes. The error is the one the write would give.
Expected<void> check_atomic_write(const std::filesystem::path& target);

// Removes the temporary file of a write under way, if there is one, so that
// a program ended by a signal leaves none behind: for a signal handler, which
// then ends the process (the write, if it goes on, fails). Async-signal-safe.
// Writes on several threads at once are not covered: only the latest's file.
void remove_unfinished_file() noexcept;

// Writes a new file `target` and never replaces one: true when written, false
// when something is already there. The check and the creation are one step
// (link(2)), so a file that appears meanwhile is not overwritten either.
Expected<bool> write_new_file(const std::filesystem::path& target,
                              std::span<const std::uint8_t> bytes);

}  // namespace jt

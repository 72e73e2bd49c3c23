#pragma once
// Naming the symbolic links that loop. The system says only "Too many levels
// of symbolic links" (or, through std::filesystem::status, that the file is
// not there), which names none of the links the user has to mend.

#include <filesystem>
#include <optional>
#include <string>

namespace jt {

// The kernel gives up after 40 links in one lookup (ELOOP): a chain longer
// than that loops as far as any reader can tell.
inline constexpr int kMostLinksFollowed = 40;

// Where the symbolic link `link`, holding `target` (read_symlink's), leads:
// a relative target is taken from the link's own folder, as the kernel does,
// not from the working folder.
std::filesystem::path link_destination(const std::filesystem::path& link,
                                       const std::filesystem::path& target);

// "a cycle of symbolic links: 'a.jts' -> 'b.jts' -> 'a.jts'" for the first
// link of `path` (its folders' or its own) that leads back to itself, each
// named as it is written; nothing when no link of it loops.
std::optional<std::string> symbolic_link_cycle(const std::filesystem::path& path);

// The reason a file cannot be opened, from open's `error`: the cycle when
// the links of `path` loop (ELOOP), else strerror's words.
std::string open_failure_reason(const std::filesystem::path& path, int error);

}  // namespace jt

#pragma once
// Naming the symbolic links that loop. The system says only "Too many levels
// of symbolic links" (or, through std::filesystem::status, that the file is
// not there), which names none of the links the user has to mend.

#include <filesystem>
#include <optional>
#include <string>

namespace jt {

// "a cycle of symbolic links: 'a.jts' -> 'b.jts' -> 'a.jts'" for the first
// link of `path` (its folders' or its own) that leads back to itself, each
// named as it is written; nothing when no link of it loops.
std::optional<std::string> symbolic_link_cycle(const std::filesystem::path& path);

// The reason a file cannot be opened, from open's `error`: the cycle when
// the links of `path` loop (ELOOP), else strerror's words.
std::string open_failure_reason(const std::filesystem::path& path, int error);

}  // namespace jt

#include "io/link_cycle.hpp"

#include <cerrno>
#include <cstring>
#include <vector>

namespace jt {

namespace {

// The cycle reached by following `link` (a path to a symbolic link) link by
// link, or nothing when the chain ends.
std::optional<std::string> cycle_from(const std::filesystem::path& link) {
    std::vector<std::filesystem::path> places;  // absolute, lexically normal
    std::vector<std::string> shown;             // as written
    std::error_code error;
    std::filesystem::path at = std::filesystem::absolute(link, error).lexically_normal();
    if (error) return std::nullopt;
    shown.push_back(link.string());
    for (int step = 0; step <= kMostLinksFollowed; ++step) {
        for (std::size_t i = 0; i < places.size(); ++i)
            if (places[i] == at) {
                std::string text = "a cycle of symbolic links: ";
                for (std::size_t j = i; j < shown.size(); ++j)
                    text += (j == i ? "'" : " -> '") + shown[j] + "'";
                return text;
            }
        places.push_back(at);
        if (!std::filesystem::is_symlink(std::filesystem::symlink_status(at, error)))
            return std::nullopt;
        const std::filesystem::path target = std::filesystem::read_symlink(at, error);
        if (error) return std::nullopt;
        shown.push_back(target.string());
        at = link_destination(at, target);
    }
    return "more than " + std::to_string(kMostLinksFollowed) + " symbolic links in a row from '" +
           link.string() + "'";
}

}  // namespace

std::filesystem::path link_destination(const std::filesystem::path& link,
                                       const std::filesystem::path& target) {
    return (target.is_absolute() ? target : link.parent_path() / target).lexically_normal();
}

std::optional<std::string> symbolic_link_cycle(const std::filesystem::path& path) {
    // Each folder of the path in turn, then the file itself: a looping folder
    // link makes every file under it fail alike.
    std::filesystem::path prefix;
    for (const std::filesystem::path& part : path) {
        prefix /= part;
        std::error_code error;
        if (std::filesystem::is_symlink(std::filesystem::symlink_status(prefix, error)))
            if (std::optional<std::string> cycle = cycle_from(prefix)) return cycle;
    }
    return std::nullopt;
}

std::string open_failure_reason(const std::filesystem::path& path, int error) {
    if (error == ELOOP)
        if (std::optional<std::string> cycle = symbolic_link_cycle(path)) return *cycle;
    return std::strerror(error);
}

}  // namespace jt

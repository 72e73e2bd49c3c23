#include "io/file_bytes.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace jt {

std::string file_message(const std::filesystem::path& path, const std::string& message) {
    std::string s = "'";
    s += path.string();
    s += "': ";
    s += message;
    return s;
}

Expected<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path) {
    std::vector<std::uint8_t> bytes;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) return Error{"cannot read " + file_message(path, std::strerror(errno))};
    std::uint8_t buffer[65536];
    std::size_t n;
    errno = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
        bytes.insert(bytes.end(), buffer, buffer + n);
    // A directory opens but does not read (EISDIR): say so, not "read error".
    if (std::ferror(file.get()))
        return Error{"cannot read " +
                     file_message(path, errno != 0 ? std::strerror(errno) : "read error")};
    return bytes;
}

}  // namespace jt

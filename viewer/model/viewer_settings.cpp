#include "model/viewer_settings.hpp"

#include "model/image_files.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

namespace jt::view {

namespace {

constexpr std::string_view panel_width_key = "panel_width";

std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

}  // namespace

ViewerSettings read_viewer_settings(const std::filesystem::path& path) {
    ViewerSettings settings;
    if (path.empty()) return settings;
    // A settings file is a few short lines; a larger file is not ours.
    constexpr std::uintmax_t most_bytes = 64 * 1024;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > most_bytes) return settings;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        const std::string_view text = line;
        const auto equals = text.find('=');
        if (equals == std::string_view::npos) continue;
        if (trimmed(text.substr(0, equals)) != panel_width_key) continue;
        const std::string_view value = trimmed(text.substr(equals + 1));
        float width = 0.0f;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), width);
        if (ec == std::errc() && end == value.data() + value.size() && std::isfinite(width) &&
            width >= kLeastPanelWidth && width <= kMostPanelWidth)
            settings.panel_width = width;
    }
    return settings;
}

Expected<void> write_viewer_settings(const std::filesystem::path& path,
                                     const ViewerSettings& settings) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    char number[32];
    const auto [end, error] = std::to_chars(number, number + sizeof number, settings.panel_width);
    if (error != std::errc()) return Error{"cannot write the panel width"};
    std::string text = "# jtracer-view remembers these between runs\n";
    text += std::string(panel_width_key) + " = " + std::string(number, end) + "\n";
    return write_text_atomically(path, text);
}

std::filesystem::path config_folder() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "jtracer";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config" / "jtracer";
    return {};
}

std::filesystem::path default_settings_path() {
    const std::filesystem::path folder = config_folder();
    return folder.empty() ? folder : folder / "viewer-settings.txt";
}

}  // namespace jt::view

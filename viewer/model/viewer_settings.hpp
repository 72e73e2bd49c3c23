#pragma once
// What the viewer remembers about its window between runs (the panel's
// width), in a small "key = value" text file in the user's config folder.
// The file is written whole through a temporary file and a rename, so a crash
// never leaves it half written; a missing, unreadable or broken file (or
// line) gives the defaults for what it could not say, never an error.

#include "jtracer/error.hpp"

#include <filesystem>

namespace jt::view {

// The panel's width in font heights, so that it follows the font size.
constexpr float kDefaultPanelWidth = 30.0f;
// A width outside these is taken as broken: it would hide the panel or the image.
constexpr float kLeastPanelWidth = 10.0f;
constexpr float kMostPanelWidth = 200.0f;

struct ViewerSettings {
    float panel_width = kDefaultPanelWidth;
    bool operator==(const ViewerSettings&) const = default;
};

ViewerSettings read_viewer_settings(const std::filesystem::path& path);
// Creates the folder when needed.
Expected<void> write_viewer_settings(const std::filesystem::path& path,
                                     const ViewerSettings& settings);

// $XDG_CONFIG_HOME/jtracer, or ~/.config/jtracer; empty when neither is set.
std::filesystem::path config_folder();
// config_folder()/viewer-settings.txt, or empty.
std::filesystem::path default_settings_path();

}  // namespace jt::view

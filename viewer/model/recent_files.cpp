#include "model/recent_files.hpp"

#include "model/image_files.hpp"
#include "model/viewer_settings.hpp"

#include <algorithm>
#include <fstream>

namespace jt::view {

void RecentFiles::load(const std::filesystem::path& storage) {
    storage_ = storage;
    paths_.clear();
    if (storage_.empty()) return;
    std::ifstream in(storage_);
    std::string line;
    while (paths_.size() < capacity && std::getline(in, line))
        if (!line.empty() && std::find(paths_.begin(), paths_.end(), line) == paths_.end())
            paths_.push_back(line);
}

void RecentFiles::add(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    const std::string entry = (ec ? path : absolute).lexically_normal().string();
    std::erase(paths_, entry);
    paths_.insert(paths_.begin(), entry);
    if (paths_.size() > capacity) paths_.resize(capacity);
    if (storage_.empty()) return;
    std::filesystem::create_directories(storage_.parent_path(), ec);
    std::string text;
    for (const std::string& p : paths_) text += p + "\n";
    // A list we cannot save is no reason to fail.
    static_cast<void>(write_text_atomically(storage_, text));
}

std::filesystem::path default_recent_files_path() {
    const std::filesystem::path folder = config_folder();
    return folder.empty() ? folder : folder / "recent-scenes.txt";
}

}  // namespace jt::view

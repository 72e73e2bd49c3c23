#include "jtracer/model_cache.hpp"

#include "jtracer/file_stamp.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <system_error>
#include <utility>

namespace jt {

namespace {

// Models held after their last user lets go: enough for a scene's few
// distinct models between its validation and its render.
constexpr std::size_t kept_models = 4;

struct Entry {
    FileStamp stamp;
    std::weak_ptr<const Model> model;
};

struct Cache {
    std::mutex mutex;
    std::map<std::pair<std::string, std::string>, Entry> entries;
    std::deque<std::shared_ptr<const Model>> kept;  // most recent last
};

Cache& cache() {
    static Cache c;
    return c;
}

}  // namespace

Expected<std::shared_ptr<const Model>> shared_model(const std::filesystem::path& file,
                                                    const std::filesystem::path& folder) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(file, error);
    const FileStamp stamp = file_stamp(absolute);
    if (error || !stamp.exists) return read_model(file, folder).error();  // its own words
    const std::filesystem::path scene_folder = folder.empty() ? "." : folder;
    const auto key =
        std::pair(absolute.lexically_normal().string(),
                  std::filesystem::absolute(scene_folder, error).lexically_normal().string());
    Cache& c = cache();
    {
        std::lock_guard lock(c.mutex);
        auto found = c.entries.find(key);
        if (found != c.entries.end() && found->second.stamp == stamp)
            if (auto model = found->second.model.lock()) return model;
    }
    // Read outside the lock: two threads may read one file at once, and the
    // second result replaces the first; both are correct.
    Expected<Model> read = read_model(file, folder);
    if (!read) return read.error();
    auto model = std::make_shared<const Model>(std::move(*read));
    std::lock_guard lock(c.mutex);
    c.entries[key] = Entry{stamp, model};
    c.kept.push_back(model);
    if (c.kept.size() > kept_models) c.kept.pop_front();
    std::erase_if(c.entries, [](const auto& e) { return e.second.model.expired(); });
    return model;
}

void forget_model(const std::filesystem::path& file) {
    std::error_code error;
    const std::string absolute = std::filesystem::absolute(file, error).lexically_normal().string();
    Cache& c = cache();
    std::lock_guard lock(c.mutex);
    std::erase_if(c.entries, [&](const auto& e) {
        if (e.first.first != absolute) return false;
        if (auto model = e.second.model.lock()) std::erase(c.kept, model);
        return true;
    });
}

}  // namespace jt

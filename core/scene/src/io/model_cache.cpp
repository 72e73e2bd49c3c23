#include "jtracer/model_cache.hpp"

#include "io/stamped_cache.hpp"
#include "jtracer/file_stamp.hpp"

#include <string>
#include <system_error>
#include <tuple>
#include <utility>

namespace jt {

namespace {

// Models held after their last user lets go: enough for a scene's few
// distinct models between its validation and its render.
constexpr std::size_t kept_models = 4;

// The file, the scene's folder, and whether its materials were read.
using Key = std::tuple<std::string, std::string, bool>;

StampedCache<Key, Model>& cache() {
    static StampedCache<Key, Model> c(kept_models);
    return c;
}

}  // namespace

Expected<std::shared_ptr<const Model>> shared_model(const std::filesystem::path& file,
                                                    const std::filesystem::path& folder,
                                                    bool file_materials) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(file, error);
    const FileStamp stamp = file_stamp(absolute);
    if (error || !stamp.exists)
        return read_model(file, folder, file_materials).error();  // its own words
    const std::filesystem::path scene_folder = folder.empty() ? "." : folder;
    const Key key(absolute.lexically_normal().string(),
                  std::filesystem::absolute(scene_folder, error).lexically_normal().string(),
                  file_materials);
    return cache().get(key, stamp, [&] { return read_model(file, folder, file_materials); });
}

void forget_model(const std::filesystem::path& file) {
    std::error_code error;
    const std::string absolute = std::filesystem::absolute(file, error).lexically_normal().string();
    cache().forget([&](const Key& key) { return std::get<0>(key) == absolute; });
}

}  // namespace jt

#include "model_reader/confined_io_system.hpp"

#include "jtracer/model_file.hpp"

#include <cctype>
#include <system_error>

namespace jt {

namespace {

// Whether `path` is `folder` or lies below it; both canonical.
bool inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p)
        if (p == path.end() || *p != *f) return false;
    return true;
}

// An OBJ's `mtllib`: materials, which a mesh can be read without.
bool material_library(const char* file) {
    std::string ext = std::filesystem::path(file).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".mtl";
}

}  // namespace

ConfinedIOSystem::ConfinedIOSystem(std::filesystem::path folder,
                                   const std::filesystem::path& model) {
    std::error_code error;
    folder_ = std::filesystem::weakly_canonical(std::filesystem::absolute(folder, error), error);
    base_ = std::filesystem::absolute(model, error).parent_path();
}

std::filesystem::path ConfinedIOSystem::resolved(const char* file) const {
    const std::filesystem::path path(file);
    return path.is_relative() ? base_ / path : path;
}

std::string ConfinedIOSystem::shown(const char* file) const {
    // Assimp asks for most references as the model's folder joined to the
    // name the model writes (a glTF buffer's URI): that name is what the
    // user can find in the file.
    const std::string path(file), folder = base_.string() + "/";
    return path.starts_with(folder) ? path.substr(folder.size()) : path;
}

bool ConfinedIOSystem::allowed(const char* file) const {
    std::error_code error;
    const std::filesystem::path path = std::filesystem::weakly_canonical(resolved(file), error);
    const std::string name = shown(file);
    std::string why;
    if (error || folder_.empty() || !inside(path, folder_)) {
        why.append(material_library(file) ? "refers to the material library '" : "refers to '");
        why.append(name).append("', outside the folder '");
        why.append(folder_.string()).append("'");
    } else if (std::filesystem::is_directory(path, error)) {
        // Opening a folder succeeds on Linux and only its reading fails, for
        // which Assimp has nothing better to say than "File read error".
        why.append(material_library(file) ? "refers to the material library '" : "refers to '");
        why.append(name).append("', which is a folder");
    } else if (const std::uintmax_t size = std::filesystem::file_size(path, error);
               !error && size > kMaxModelFileBytes) {
        why.append("refers to '").append(name).append("', which is too large (");
        why.append(std::to_string(size));
        why.append(" bytes; at most ").append(std::to_string(kMaxModelFileBytes)).append(")");
    }
    if (why.empty()) return true;
    if (refusal_.empty()) refusal_ = std::move(why);
    return false;
}

bool ConfinedIOSystem::Exists(const char* file) const {
    if (leave_out_libraries_ && material_library(file)) return false;
    return allowed(file) && DefaultIOSystem::Exists(resolved(file).c_str());
}

bool ConfinedIOSystem::contains(const std::filesystem::path& file) const {
    std::error_code error;
    const std::filesystem::path path =
        std::filesystem::weakly_canonical(std::filesystem::absolute(file, error), error);
    return !error && !folder_.empty() && inside(path, folder_);
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
    // Reading only: a model never writes.
    if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;
    const bool library = material_library(file);
    if (library && leave_out_libraries_) return nullptr;
    const std::string refused_before = refusal_;
    const std::filesystem::path path = resolved(file);
    Assimp::IOStream* stream = allowed(file) ? DefaultIOSystem::Open(path.c_str(), mode) : nullptr;
    if (library && stream) libraries_.push_back(path);
    if (library && !stream && library_failure_.empty()) {
        if (refusal_ != refused_before)
            library_failure_ = "it " + refusal_;
        else
            library_failure_ =
                "its material library '" + shown(file) + "' cannot be read (" +
                (DefaultIOSystem::Exists(path.c_str()) ? "unreadable" : "no such file") + ")";
    }
    return stream;
}

}  // namespace jt

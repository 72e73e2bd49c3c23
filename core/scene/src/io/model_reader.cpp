#include "io/model_reader.hpp"

#include "jtracer/version.hpp"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace jt {

namespace {

// The folders the dynamic loader searches for what the program or library
// this code is part of needs, in its order: LD_LIBRARY_PATH's, its RUNPATH's,
// the system's. dlopen's own search would follow the RUNPATH of its caller,
// which is a sanitizer's runtime when that intercepts dlopen (GCC's ASan).
// Relative folders are left out: in the build tree CMake ends a RUNPATH with
// an empty entry, which would be the working folder.
std::vector<std::filesystem::path> search_folders() {
    dl_find_object self{};
    if (_dl_find_object(reinterpret_cast<void*>(&search_folders), &self) != 0) return {};
    Dl_serinfo size{};
    if (dlinfo(self.dlfo_link_map, RTLD_DI_SERINFOSIZE, &size) != 0) return {};
    const auto buffer = std::make_unique<std::max_align_t[]>(
        (size.dls_size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t));
    auto* info = reinterpret_cast<Dl_serinfo*>(buffer.get());
    *info = size;
    if (dlinfo(self.dlfo_link_map, RTLD_DI_SERINFO, info) != 0) return {};
    std::vector<std::filesystem::path> folders;
    for (unsigned i = 0; i < info->dls_cnt; ++i) {
        const std::filesystem::path folder(info->dls_serpath[i].dls_name);
        if (folder.is_absolute()) folders.push_back(folder.lexically_normal());
    }
    return folders;
}

Expected<const ModelReader*> open_model_reader() {
    const std::string failed = "cannot load the model reader";
    const std::vector<std::filesystem::path> folders = search_folders();
    std::filesystem::path path;
    for (const std::filesystem::path& folder : folders) {
        std::error_code error;
        if (std::filesystem::exists(folder / kModelReaderFile, error)) {
            path = folder / kModelReaderFile;
            break;
        }
    }
    if (path.empty()) {
        std::string where;
        for (const std::filesystem::path& folder : folders)
            where += (where.empty() ? "" : ", ") + folder.string();
        return Error{failed + ": " + kModelReaderFile + " is in none of the folders searched (" +
                     where + ")"};
    }
    // Local: the module's Assimp stays out of the program's own symbol scope.
    // Never closed: the models and textures it made may outlive any reader.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) return Error{failed + ": " + dlerror()};  // it names the file
    const std::string file = failed + " " + path.string() + ": ";
    auto entry = reinterpret_cast<ModelReaderEntry>(dlsym(module, kModelReaderEntry));
    if (!entry) return Error{file + dlerror()};
    const ModelReader* reader = entry();
    if (!reader || !reader->version) return Error{file + "it names no version"};
    if (reader->version != project_version)
        return Error{file + "it is from JTracer " + reader->version + ", this program from " +
                     std::string(project_version)};
    if (reader->layout != model_reader_layout())
        return Error{file + "it is from another build of JTracer " + reader->version +
                     " (its types differ from this program's)"};
    if (!reader->read) return Error{file + "it offers no reader"};
    return reader;
}

}  // namespace

Expected<const ModelReader*> model_reader() {
    static const Expected<const ModelReader*> reader = open_model_reader();
    return reader;
}

}  // namespace jt

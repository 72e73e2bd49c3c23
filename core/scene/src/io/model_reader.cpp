#include "io/model_reader.hpp"

#include "jtracer/version.hpp"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <memory>
#include <string>

namespace jt {

namespace {

// Where dlopen looked for the module, in order, for the message when it is
// not found: LD_LIBRARY_PATH's folders, the RUNPATH of the program or library
// this code is part of, then the system's.
std::string search_folders() {
    dl_find_object self{};
    if (_dl_find_object(reinterpret_cast<void*>(&search_folders), &self) != 0) return "";
    Dl_serinfo size{};
    if (dlinfo(self.dlfo_link_map, RTLD_DI_SERINFOSIZE, &size) != 0) return "";
    const auto buffer = std::make_unique<std::max_align_t[]>(
        (size.dls_size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t));
    auto* info = reinterpret_cast<Dl_serinfo*>(buffer.get());
    *info = size;
    if (dlinfo(self.dlfo_link_map, RTLD_DI_SERINFO, info) != 0) return "";
    std::string folders;
    for (unsigned i = 0; i < info->dls_cnt; ++i) {
        const Dl_serpath& folder = info->dls_serpath[i];
        folders += (folders.empty() ? "" : ", ") +
                   std::filesystem::path(folder.dls_name).lexically_normal().string();
    }
    return folders;
}

Expected<const ModelReader*> open_model_reader() {
    const std::string failed = "cannot load the model reader";
    // Local: the module's Assimp stays out of the program's own symbol scope.
    // Never closed: the models and textures it made may outlive any reader.
    void* module = dlopen(kModelReaderFile, RTLD_NOW | RTLD_LOCAL);
    if (!module) {
        std::string why = dlerror();
        // dlerror names the file it found, or the bare name when it found none.
        if (why.rfind(std::string(kModelReaderFile) + ":", 0) == 0)
            if (const std::string folders = search_folders(); !folders.empty())
                why += " (looked in " + folders + ")";
        return Error{failed + ": " + why};
    }
    std::string path = kModelReaderFile;
    if (link_map* map = nullptr; dlinfo(module, RTLD_DI_LINKMAP, &map) == 0 && map)
        path = std::filesystem::path(map->l_name).lexically_normal().string();
    auto entry = reinterpret_cast<ModelReaderEntry>(dlsym(module, kModelReaderEntry));
    if (!entry) return Error{failed + " " + path + ": " + dlerror()};
    const ModelReader* reader = entry();
    if (!reader || !reader->version) return Error{failed + " " + path + ": it names no version"};
    if (reader->version != project_version)
        return Error{failed + " " + path + ": it is from JTracer " + reader->version +
                     ", this program from " + std::string(project_version)};
    if (reader->layout != model_reader_layout())
        return Error{failed + " " + path + ": it is from another build of JTracer " +
                     reader->version + " (its types differ from this program's)"};
    if (!reader->read) return Error{failed + " " + path + ": it offers no reader"};
    return reader;
}

}  // namespace

Expected<const ModelReader*> model_reader() {
    static const Expected<const ModelReader*> reader = open_model_reader();
    return reader;
}

}  // namespace jt

#pragma once
// The model reader: read_model's work on a model file (Assimp, and the checks
// in front of it), built as a module of its own, libjtracer_model_reader.so
// (core/scene/model_reader/), that read_model opens with dlopen on the first
// model file it reads. A run whose scene names no model file never loads
// Assimp, whose 44,000 relocations took about a third of a 1x1 render
// (docs/benchmarks.md §2.3).
//
// The module and the program that opens it come from one build: C++ types
// cross between them, so the module's version and layout must be the
// program's.

#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/texture.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

// What the module exports: it is built with hidden visibility.
#define JT_MODEL_READER_EXPORT __attribute__((visibility("default")))

namespace jt {

// What the module uses of the program that opens it: its texture loader, so
// that a picture that is both an image map and a model's texture is decoded
// and held once (load_texture's cache), and no image codec is in the module.
// Both read a model's texture as stored (TextureLayout::as_stored): a JPEG's
// EXIF orientation, which turns an image map, does not turn it.
struct ModelReaderHost {
    Expected<std::shared_ptr<const Texture>> (*load_texture)(const std::filesystem::path& path);
    Expected<Texture> (*decode_texture)(std::span<const std::uint8_t> bytes);
};

// What the module offers. The program checks the first two members, the same
// in every build, before it reads the rest.
struct ModelReader {
    const char* version;   // project_version of its build
    std::uint64_t layout;  // model_reader_layout() of its build
    // read_model (jtracer/model_file.hpp).
    Expected<Model> (*read)(const std::filesystem::path& file, const std::filesystem::path& folder,
                            bool file_materials, const ModelReaderHost& host);
};

// The sizes of the types that cross between the module and the program, in
// one number. With the version it tells a module of another build, not one of
// the same version whose types changed and kept their sizes; it leaves out the
// git revision, which moves with every commit, so that a program built before
// the module's last relink in the same tree still reads models.
constexpr std::uint64_t model_reader_layout() {
    std::uint64_t hash = 14695981039346656037u;  // FNV-1a
    for (const std::size_t size :
         {sizeof(Model), sizeof(ModelPart), sizeof(ModelLeftOut), sizeof(Texture),
          sizeof(Expected<Model>), sizeof(Expected<Texture>),
          sizeof(Expected<std::shared_ptr<const Texture>>), sizeof(std::filesystem::path),
          sizeof(ModelReaderHost), sizeof(ModelReader)})
        hash = (hash ^ size) * 1099511628211u;
    return hash;
}

// The module's file name, looked for where the dynamic loader looks for the
// libraries of the program or library that opens it: LD_LIBRARY_PATH, its
// RUNPATH (jt_find_model_reader, core/CMakeLists.txt), the system's folders;
// and the one function it exports.
inline constexpr const char* kModelReaderFile = "libjtracer_model_reader.so";
inline constexpr const char* kModelReaderEntry = "jt_model_reader";
using ModelReaderEntry = const ModelReader* (*)();

// The module, opened on the first call; or, on every call, why it cannot be
// ("cannot load the model reader: REASON").
Expected<const ModelReader*> model_reader();

}  // namespace jt

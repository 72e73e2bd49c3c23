#pragma once
// The model reader: read_model's work on a model file (Assimp, and the checks
// in front of it), built as a module of its own, libjtracer_model_reader.so
// (core/scene/model_reader/), that read_model opens with dlopen on the first
// model file it reads. A run whose scene names no model file never loads
// Assimp, whose 44,000 relocations took half of a 1x1 render's start-up
// (docs/benchmarks.md §2.3).
//
// The module and the program that opens it come from one build: C++ types
// cross between them, so the module's version must be the program's.

#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/texture.hpp"

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
struct ModelReaderHost {
    Expected<std::shared_ptr<const Texture>> (*load_texture)(const std::filesystem::path& path);
    Expected<Texture> (*decode_texture)(std::span<const std::uint8_t> bytes);
};

// What the module offers.
struct ModelReader {
    const char* version;  // version_string() of its build; the first member in every build
    // read_model (jtracer/model_file.hpp).
    Expected<Model> (*read)(const std::filesystem::path& file, const std::filesystem::path& folder,
                            bool file_materials, const ModelReaderHost& host);
};

// The module's file name, found through the RUNPATH of the program or library
// that opens it (core/scene/CMakeLists.txt), and the one function it exports.
inline constexpr const char* kModelReaderFile = "libjtracer_model_reader.so";
inline constexpr const char* kModelReaderEntry = "jt_model_reader";
using ModelReaderEntry = const ModelReader* (*)();

// The module, opened on the first call; or, on every call, why it cannot be
// ("cannot load the model reader: REASON").
Expected<const ModelReader*> model_reader();

}  // namespace jt

#pragma once
// Where each part of a parsed Scene came from in its .jts text.
//
// Kept beside the Scene rather than inside it, so that the Scene stays a pure
// value. Used for located validation messages and by the viewer to write an
// edited value back into the file at its exact span, leaving every other byte
// (comments, order, formatting) as it was.

#include "jtracer/diagnostics.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace jt {

struct TextSpan {
    std::size_t offset = 0;  // byte offset into the text
    std::size_t length = 0;
    SourcePos pos;           // line:column of `offset`
    bool operator==(const TextSpan&) const = default;
};

struct PropertySource {
    std::string name;
    TextSpan name_span;
    TextSpan value_span;  // the value's own text, e.g. "<1, 0.5, 0>" or "2.0"
    bool operator==(const PropertySource&) const = default;
};

struct BlockSource {
    std::string keyword;    // "sphere", "material", "perspective_camera", ...
    TextSpan keyword_span;
    std::size_t open_brace = 0;   // offset of '{'
    std::size_t close_brace = 0;  // offset of '}'
    std::vector<PropertySource> properties;  // in file order, repeats included
    std::vector<BlockSource> children;       // material and transform blocks, in file order
    bool operator==(const BlockSource&) const = default;
};

struct SceneSource {
    std::optional<BlockSource> render_settings;  // the block in use (the last one)
    std::optional<BlockSource> scene;            // the block in use (the last one)
    std::vector<BlockSource> cameras;            // parallel to Scene::cameras
    std::vector<BlockSource> primitives;         // parallel to Scene::primitives
    std::vector<BlockSource> lights;             // parallel to Scene::lights
    bool operator==(const SceneSource&) const = default;
};

}  // namespace jt

#include "common/scenes.hpp"

#include "common/files.hpp"
#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

namespace jt::test {

std::filesystem::path source_path(const std::filesystem::path& relative) {
    return std::filesystem::path(JT_SOURCE_DIR) / relative;
}

Scene showcase_at(int width, int height) {
    ParseResult parsed = parse_scene(read_file(source_path("scenes/showcase.jts")));
    EXPECT_TRUE(parsed.ok());
    parsed.scene.settings.width = width;
    parsed.scene.settings.height = height;
    return parsed.scene;
}

}  // namespace jt::test

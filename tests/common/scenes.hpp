#pragma once
// Files of the source tree that tests read, and scenes made from them.

#include "jtracer/scene.hpp"

#include <filesystem>

namespace jt::test {

// `relative` inside the source tree, e.g. "scenes/showcase.jts".
std::filesystem::path source_path(const std::filesystem::path& relative);

// scenes/showcase.jts at another size.
Scene showcase_at(int width, int height);

}  // namespace jt::test

// Every scene in scenes/ rendered at 160x90 and compared with its reference in
// tests/references/ (PNG, looked at by eye before it was committed; the
// analytic tests and the differential test against the reference tracer
// check the rules the references rely on).
//
// A failing case keeps its render and a diff image under the build directory
// and prints where. To accept new renders after a deliberate change, run with
// JT_UPDATE_REFERENCES=1 and look at every changed PNG before committing it.

#include "jtracer/image_diff.hpp"
#include "jtracer/png.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace jt {
namespace {

namespace fs = std::filesystem;

constexpr int reference_width = 160;
constexpr int reference_height = 90;

const fs::path scenes_dir = fs::path(JT_SOURCE_DIR) / "scenes";
const fs::path references_dir = fs::path(JT_SOURCE_DIR) / "tests" / "references";

std::vector<std::string> every_scene() {
    std::vector<std::string> scenes;
    for (const auto& entry : fs::recursive_directory_iterator(scenes_dir))
        // A `parts` folder holds files that scenes include, not scenes.
        if (entry.is_regular_file() && entry.path().extension() == ".jts" &&
            entry.path().parent_path().filename() != "parts")
            scenes.push_back(fs::relative(entry.path(), scenes_dir).generic_string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

// "manual/sphere.jts" -> "manual_sphere"
std::string flat_name(std::string relative) {
    relative = fs::path(relative).replace_extension().generic_string();
    std::replace(relative.begin(), relative.end(), '/', '_');
    return relative;
}

class SceneReference : public testing::TestWithParam<std::string> {};

TEST_P(SceneReference, MatchesItsReferenceImage) {
    const std::string relative = GetParam();
    Expected<LoadedScene> read = load_scene_file(scenes_dir / relative);
    ASSERT_TRUE(read) << read.error().message;
    LoadedScene& loaded = *read;
    loaded.parsed.scene.settings.width = reference_width;
    loaded.parsed.scene.settings.height = reference_height;
    std::vector<Diagnostic> diagnostics = check_scene(loaded);
    ASSERT_FALSE(has_errors(diagnostics)) << format_diagnostics(diagnostics, loaded);

    const Scene& scene = loaded.parsed.scene;
    Image8 actual = render_image(prepare_scene(scene).value(), render_options_for(scene));

    const fs::path reference = references_dir / (flat_name(relative) + ".png");
    if (const char* update = std::getenv("JT_UPDATE_REFERENCES"); update && *update == '1') {
        const Expected<void> written = write_png(reference, actual);
        ASSERT_TRUE(written) << written.error().message;
        GTEST_SKIP() << "wrote " << reference;
    }
    const Expected<Image8> expected = read_png(reference);
    ASSERT_TRUE(expected) << expected.error().message << "\nno reference for " << relative
                          << "; create it with JT_UPDATE_REFERENCES=1";
    ImageDiff diff = diff_images(*expected, actual, 0);
    if (diff.pixels_over == 0 && diff.same_size) return;

    const fs::path artifacts = fs::path(JT_ARTIFACT_DIR);
    fs::create_directories(artifacts);
    const fs::path actual_path = artifacts / (flat_name(relative) + ".actual.png");
    const fs::path diff_path = artifacts / (flat_name(relative) + ".diff.png");
    // Only evidence for the failure below: a write that fails changes nothing.
    static_cast<void>(write_png(actual_path, actual));
    if (diff.same_size) static_cast<void>(write_png(diff_path, diff.image));
    ADD_FAILURE() << relative << " differs from " << reference << ": " << diff.pixels_over
                  << " pixels (" << diff.percent_over << "%), largest channel difference "
                  << diff.max_channel_difference << "\n  render: " << actual_path
                  << "\n  diff:   " << diff_path;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneReference, testing::ValuesIn(every_scene()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = flat_name(info.param);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
}  // namespace jt

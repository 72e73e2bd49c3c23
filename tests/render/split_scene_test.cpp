// scenes/split/main.jts, a scene split into files with `include`, renders to
// the same bytes as the same scene written as one file (docs/language.md §15.6).

#include "common/files.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt {
namespace {

namespace fs = std::filesystem;

// `text` with each line `include "X";` replaced by X's text, read from
// `folder`: the one-file scene, made without the parser's include.
std::string written_as_one_file(std::string text, const fs::path& folder) {
    for (std::size_t at; (at = text.find("include \"")) != std::string::npos;) {
        const std::size_t open = at + 9, close = text.find("\";", open);
        const std::string name = text.substr(open, close - open);
        const std::string included = test::read_file(folder / name);
        EXPECT_FALSE(included.empty()) << name;
        EXPECT_EQ(included.find("include \""), std::string::npos) << "one level only";
        text.replace(at, close + 2 - at, included);
    }
    return text;
}

TEST(SplitScene, RendersAsTheSameSceneWrittenAsOneFile) {
    const fs::path main = fs::path(JT_SOURCE_DIR) / "scenes" / "split" / "main.jts";
    Expected<LoadedScene> split = load_scene_file(main);
    ASSERT_TRUE(split) << split.error().message;
    ASSERT_EQ(format_diagnostics(check_scene(*split), *split), "");
    ASSERT_EQ(split->parsed.source.files.size(), 2u);

    const std::string one_file = written_as_one_file(split->text, main.parent_path());
    ParseResult flat = parse_scene(one_file);
    ASSERT_TRUE(flat.ok());
    EXPECT_TRUE(flat.source.files.empty());
    flat.scene.asset_folder = split->parsed.scene.asset_folder;
    EXPECT_TRUE(flat.scene == split->parsed.scene);

    for (Scene* scene : {&split->parsed.scene, &flat.scene}) {
        scene->settings.width = 160;
        scene->settings.height = 90;
    }
    const Image8 a = render_image(prepare_scene(split->parsed.scene).value(),
                                  render_options_for(split->parsed.scene));
    const Image8 b =
        render_image(prepare_scene(flat.scene).value(), render_options_for(flat.scene));
    ASSERT_EQ(a.rgb.size(), 160u * 90u * 3u);
    EXPECT_TRUE(a.rgb == b.rgb);
}

}  // namespace
}  // namespace jt

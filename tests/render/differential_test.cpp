// Differential test: random valid scenes (random_scene.hpp), rendered by the
// core through its real path (text -> parse -> validate -> prepare -> render)
// and by the independent brute-force tracer of reference_tracer.hpp.
//
// The comparison: every pixel the reference does not flag as numerically
// ambiguous must match to the byte; an ambiguous pixel must lie, channel by
// channel, within one level of the values the reference's variant rays gave;
// and a scene may have at most max(3, 1%) ambiguous pixels (more means the
// scene or the flagging has gone wrong, not that the render is right).
// The text must also parse back to the generated scene exactly, validate
// without errors, and warn once for each primitive a zero scale leaves out.
//
// Seeds: 0-299 by default (0-59 under the sanitizers). Any range by hand:
//   JT_DIFFERENTIAL_SEEDS=1000-4999 build/release/tests/render/render_tests
//   --gtest_filter='Differential.*'
// (one seed: JT_DIFFERENTIAL_SEEDS=1234). A failing seed prints its scene text
// and writes seed-N.jts, seed-N.core.png, seed-N.reference.png and
// seed-N.ambiguous.png (white: flagged) to <build>/tests/render/artifacts/differential/;
// JT_DIFFERENTIAL_KEEP=1 writes them for every seed, to look at.

#include "random_scene.hpp"
#include "reference_tracer.hpp"
#include "scene_builder.hpp"

#include "jtracer/parser.hpp"
#include "jtracer/png.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/validate.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t default_last_seed = 59;
#else
constexpr std::uint64_t default_last_seed = 299;
#endif

struct SeedRange {
    std::uint64_t first = 0, last = default_last_seed;
};

SeedRange seed_range() {
    SeedRange range;
    const char* text = std::getenv("JT_DIFFERENTIAL_SEEDS");
    if (!text || !*text) return range;
    std::string s(text);
    const std::size_t dash = s.find('-');
    range.first = std::stoull(s.substr(0, dash));
    range.last = dash == std::string::npos ? range.first : std::stoull(s.substr(dash + 1));
    return range;
}

struct Comparison {
    int mismatched = 0;    // unambiguous pixels whose bytes differ
    int out_of_range = 0;  // ambiguous pixels outside the variants' values
    int ambiguous = 0;
    std::string first_difference;
};

Comparison compare(const Image8& core, const reference::ReferenceImage& ref) {
    Comparison c;
    for (int y = 0; y < core.height; ++y) {
        for (int x = 0; x < core.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * core.width + x;
            const std::uint8_t* a = core.pixel(x, y);
            const std::uint8_t* b = ref.image.pixel(x, y);
            bool bad = false;
            if (ref.ambiguous[i]) {
                ++c.ambiguous;
                for (int k = 0; k < 3; ++k)
                    if (a[k] + 1 < ref.range[i][k] || a[k] > ref.range[i][3 + k] + 1) bad = true;
                if (bad) ++c.out_of_range;
            } else if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) {
                bad = true;
                ++c.mismatched;
            }
            if (bad && c.first_difference.empty()) {
                std::ostringstream s;
                s << "pixel (" << x << ", " << y << ") from the bottom left: core (" << +a[0]
                  << ", " << +a[1] << ", " << +a[2] << "), reference (" << +b[0] << ", " << +b[1]
                  << ", " << +b[2] << ")" << (ref.ambiguous[i] ? ", ambiguous" : "");
                c.first_difference = s.str();
            }
        }
    }
    return c;
}

int ambiguity_limit(const Image8& image) {
    return std::max(3, image.width * image.height / 100);
}

fs::path write_artifacts(std::uint64_t seed, const std::string& text, const Image8& core,
                         const reference::ReferenceImage& ref) {
    const fs::path dir = fs::path(JT_ARTIFACT_DIR) / "differential";
    fs::create_directories(dir);
    const std::string stem = "seed-" + std::to_string(seed);
    std::ofstream(dir / (stem + ".jts")) << text;
    // Artifacts only help to look: a failure to write one is not the test's.
    static_cast<void>(write_png(dir / (stem + ".core.png"), core));
    static_cast<void>(write_png(dir / (stem + ".reference.png"), ref.image));
    Image8 mask(core.width, core.height);
    for (int y = 0; y < core.height; ++y)
        for (int x = 0; x < core.width; ++x)
            if (ref.ambiguous[static_cast<std::size_t>(y) * core.width + x])
                std::fill_n(mask.pixel(x, y), 3, 255);
    static_cast<void>(write_png(dir / (stem + ".ambiguous.png"), mask));
    return dir / stem;
}

// What one seed's check found; `failure` empty when it passed.
struct SeedResult {
    int pixels = 0;
    int ambiguous = 0;
    std::string failure;
};

SeedResult check_seed(std::uint64_t seed) {
    SeedResult result;
    const RandomScene generated = random_scene(seed);
    const ParseResult parsed = parse_scene(generated.text);
    std::string problem;
    if (!parsed.ok())
        problem = "the text does not parse";
    else if (!(parsed.scene == generated.scene))
        problem = "the text parses to another scene";
    std::vector<Diagnostic> findings = validate_scene(parsed.scene, parsed.source);
    int zero_scale_warnings = 0;
    for (const Diagnostic& d : findings) {
        if (d.severity == Severity::error && problem.empty())
            problem = "validation error: " + d.message;
        if (d.message.find("zero component") != std::string::npos) ++zero_scale_warnings;
    }
    if (problem.empty() && zero_scale_warnings != generated.flattened)
        problem = std::to_string(zero_scale_warnings) + " zero-scale warnings for " +
                  std::to_string(generated.flattened) + " flattened primitives";
    if (!problem.empty()) {
        result.failure = "seed " + std::to_string(seed) + ": " + problem + "\n" + generated.text;
        return result;
    }

    const Scene& scene = parsed.scene;
    RenderOptions options;
    options.width = scene.settings.width;
    options.height = scene.settings.height;
    options.camera = active_camera_index(scene);
    const Image8 core = render_image(prepare_scene(scene).value(), options);
    const reference::ReferenceImage ref = reference::render(generated.scene);
    const Comparison c = compare(core, ref);
    result.pixels = core.width * core.height;
    result.ambiguous = c.ambiguous;
    const bool passed =
        c.mismatched == 0 && c.out_of_range == 0 && c.ambiguous <= ambiguity_limit(core);
    if (const char* keep = std::getenv("JT_DIFFERENTIAL_KEEP"); keep && *keep == '1')
        write_artifacts(seed, generated.text, core, ref);
    if (passed) return result;
    const fs::path stem = write_artifacts(seed, generated.text, core, ref);
    std::ostringstream s;
    s << "seed " << seed << ": " << c.mismatched << " pixels differ, " << c.out_of_range
      << " ambiguous pixels outside the reference's range, " << c.ambiguous
      << " ambiguous (at most " << ambiguity_limit(core) << ")\n  first: " << c.first_difference
      << "\n  images: " << stem.string() << ".{core,reference,ambiguous}.png\n"
      << generated.text;
    result.failure = s.str();
    return result;
}

TEST(Differential, RandomScenesRenderAsTheReferenceSays) {
    const SeedRange range = seed_range();
    int failed = 0;
    long long pixels = 0, ambiguous = 0;
    for (std::uint64_t seed = range.first; seed <= range.last; ++seed) {
        const SeedResult r = check_seed(seed);
        pixels += r.pixels;
        ambiguous += r.ambiguous;
        if (!r.failure.empty()) {
            ++failed;
            ADD_FAILURE() << r.failure;
        }
    }
    std::printf("differential: seeds %llu-%llu, %d failed; %lld pixels compared, %lld ambiguous\n",
                static_cast<unsigned long long>(range.first),
                static_cast<unsigned long long>(range.last), failed, pixels, ambiguous);
}

// The comparison can fail: a scene rendered with one light dimmed is caught.
TEST(Differential, ACoreThatShadesDifferentlyIsCaught) {
    for (std::uint64_t seed = 0;; ++seed) {
        RandomScene generated = random_scene(seed);
        if (generated.scene.lights.empty()) continue;
        const Scene scene = generated.scene;
        generated.scene.lights[0].intensity *= 0.97;
        RenderOptions options;
        options.width = scene.settings.width;
        options.height = scene.settings.height;
        options.camera = active_camera_index(scene);
        const Image8 core = render_image(prepare_scene(scene).value(), options);
        if (core == render_image(prepare_scene(generated.scene).value(), options)) continue;
        const Comparison c = compare(core, reference::render(generated.scene));
        EXPECT_GT(c.mismatched + c.out_of_range, 0) << "seed " << seed;
        return;
    }
}

}  // namespace
}  // namespace jt::test

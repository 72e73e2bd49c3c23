#pragma once
// A comparison's result for machines, from `jtracer-cli diff` and `--expect`:
// one JSON object (diff --json) and a JUnit XML file (--junit FILE), which CI
// systems show as a test case that passed or failed, with the figures.

#include "jtracer/error.hpp"
#include "jtracer/image_diff.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace jt::cli {

struct ImageSize {
    int width = 0;
    int height = 0;
};

// How a comparison ended.
enum class Verdict {
    within,   // within the tolerance
    outside,  // outside it, or the sizes differ
    updated,  // outside it, and --update wrote the render over the reference
    error,    // an image could not be read, or the render failed before the comparison
};

struct ComparisonReport {
    std::string name;           // the test case: the scene (--expect) or the image checked (diff)
    std::string expected_path;  // the reference
    std::string actual_path;    // the image compared with it
    std::optional<ImageSize> expected_size, actual_size;  // none: not read
    int threshold = 0;
    double max_percent = 0.0;
    std::optional<ImageDiff> diff;  // none: no comparison was made (an error)
    Verdict verdict = Verdict::error;
    std::string heat_map_path;  // the heat map written, or empty
    std::string error;          // with Verdict::error: what went wrong
    std::string text;           // the figures as the text report prints them
    std::string log;            // what the program printed on stderr, or empty
    double seconds = 0.0;       // what the comparison (or the render and it) took
};

// "within", "outside", "updated", "error"
const char* verdict_name(Verdict verdict);

// One JSON object on one line: the paths and sizes, the tolerance, the figures
// (psnr null for identical images: JSON has no infinity), the verdict, the
// heat map's path (null when none was written) and, on error, the message.
std::string comparison_json(const ComparisonReport& report);

// A JUnit XML file holding the comparison as one test case in a suite named
// `suite`: failed outside the tolerance (the message has the figures), an
// error when no comparison was made. Written atomically.
Expected<void> write_junit(const std::filesystem::path& path, const ComparisonReport& report,
                           const std::string& suite);

}  // namespace jt::cli

#include "comparison_report.hpp"

#include "jtracer/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>

namespace jt::cli {

namespace {

nlohmann::json image_json(const std::string& path, const std::optional<ImageSize>& size) {
    nlohmann::json image{{"path", path}, {"width", nullptr}, {"height", nullptr}};
    if (size) {
        image["width"] = size->width;
        image["height"] = size->height;
    }
    return image;
}

// The length of the UTF-8 sequence of a character XML 1.0 allows that starts
// at text[at], or 0 when the bytes there are no such sequence (a Latin-1 file
// name, a cut sequence, an overlong form, a surrogate, U+FFFE or U+FFFF).
std::size_t xml_character_length(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    std::uint32_t code = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        code = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        code = lead & 0x0Fu;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        code = lead & 0x07u;
    } else {
        return 0;
    }
    if (text.size() - at < length) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0u) != 0x80u) return 0;
        code = (code << 6) | (byte(at + i) & 0x3Fu);
    }
    const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < least[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF) ||
        code == 0xFFFE || code == 0xFFFF)
        return 0;
    return length;
}

// Text for XML attributes and content: the five special characters escaped,
// and what XML 1.0 does not allow in a UTF-8 file replaced: control
// characters other than tab and newline by '?', each byte that is not UTF-8 by
// U+FFFD (as the JSON has it), so that a CI system's parser reads the report
// whatever bytes a file name holds.
std::string xml_text(const std::string& text) {
    std::string out;
    for (std::size_t at = 0; at < text.size();) {
        const char c = text[at];
        if (static_cast<unsigned char>(c) >= 0x80) {
            const std::size_t length = xml_character_length(text, at);
            out += length ? text.substr(at, length) : std::string("\xEF\xBF\xBD");
            at += length ? length : 1;
            continue;
        }
        ++at;
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? '?' : c;
        }
    }
    return out;
}

// The failure's one-line message: the figures a CI page shows beside the test.
std::string failure_message(const ComparisonReport& r) {
    if (!r.diff || !r.diff->same_size) {
        auto size = [](const std::optional<ImageSize>& s) {
            return s ? std::to_string(s->width) + "x" + std::to_string(s->height)
                     : std::string("unread");
        };
        return "the sizes differ: " + size(r.actual_size) + " against " + size(r.expected_size) +
               " of " + r.expected_path;
    }
    char text[300];
    std::snprintf(text, sizeof text,
                  "max channel difference %d; %zu of %zu pixels over threshold %d (%.4f%%, "
                  "allowed %g%%); mean absolute error %.4f",
                  r.diff->max_channel_difference, r.diff->pixels_over, r.diff->pixels, r.threshold,
                  r.diff->percent_over, r.max_percent, r.diff->mean_absolute_error);
    return text;
}

}  // namespace

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::within:
            return "within";
        case Verdict::outside:
            return "outside";
        case Verdict::updated:
            return "updated";
        case Verdict::error:
            return "error";
    }
    return "error";
}

std::string comparison_json(const ComparisonReport& r) {
    nlohmann::json out{
        {"expected", image_json(r.expected_path, r.expected_size)},
        {"actual", image_json(r.actual_path, r.actual_size)},
        {"threshold", r.threshold},
        {"max_pixels", r.max_percent},
        {"verdict", verdict_name(r.verdict)},
        {"heat_map", r.heat_map_path.empty() ? nlohmann::json() : nlohmann::json(r.heat_map_path)},
    };
    if (r.diff) {
        const ImageDiff& d = *r.diff;
        out["same_size"] = d.same_size;
        if (d.same_size) {
            out["max_difference"] = d.max_channel_difference;
            out["pixels"] = d.pixels;
            out["pixels_over"] = d.pixels_over;
            out["percent_over"] = d.percent_over;
            out["mae"] = d.mean_absolute_error;
            out["psnr"] = std::isinf(d.psnr) ? nlohmann::json() : nlohmann::json(d.psnr);
        }
    }
    if (r.verdict == Verdict::error) out["error"] = r.error;
    // Paths are bytes, not always UTF-8 (a Latin-1 name): replaced, not thrown.
    return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

Expected<void> write_junit(const std::filesystem::path& path, const ComparisonReport& r,
                           const std::string& suite) {
    const bool failed = r.verdict == Verdict::outside;
    const bool error = r.verdict == Verdict::error;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f", r.seconds);
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites tests=\"1\" failures=\"" + std::to_string(failed) + "\" errors=\"" +
           std::to_string(error) + "\" time=\"" + seconds + "\">\n";
    xml += "  <testsuite name=\"" + xml_text(suite) + "\" tests=\"1\" failures=\"" +
           std::to_string(failed) + "\" errors=\"" + std::to_string(error) +
           "\" skipped=\"0\" time=\"" + seconds + "\">\n";
    xml += "    <testcase classname=\"" + xml_text(suite) + "\" name=\"" + xml_text(r.name) +
           "\" time=\"" + seconds + "\">\n";
    if (failed)
        xml += "      <failure type=\"outside tolerance\" message=\"" +
               xml_text(failure_message(r)) + "\">" + xml_text(r.text) + "</failure>\n";
    if (error)
        xml += "      <error type=\"error\" message=\"" + xml_text(r.error) + "\">" +
               xml_text(r.error) + "</error>\n";
    // A render that failed wrote nothing to compare.
    std::string out = "expected " + r.expected_path + ", actual " +
                      (r.actual_path.empty() ? "none (no render was written)" : r.actual_path) +
                      "\n" + r.text;
    if (!r.heat_map_path.empty()) out += "the differences are in " + r.heat_map_path + "\n";
    if (r.verdict == Verdict::updated) out += "updated " + r.expected_path + " with the render\n";
    xml += "      <system-out>" + xml_text(out) + "</system-out>\n";
    if (!r.log.empty()) xml += "      <system-err>" + xml_text(r.log) + "</system-err>\n";
    xml += "    </testcase>\n  </testsuite>\n</testsuites>\n";
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(xml.data());
    return write_file_atomically(path, std::span(bytes, xml.size()));
}

}  // namespace jt::cli

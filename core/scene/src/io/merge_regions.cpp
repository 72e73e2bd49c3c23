#include "jtracer/merge_regions.hpp"

#include <charconv>
#include <cstdint>
#include <optional>
#include <utility>

namespace jt {

namespace {

std::string size_text(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

std::string number_text(double value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::string("?");
}

std::string camera_text(const RenderFingerprint& f) {
    return f.camera_name.empty() ? "camera " + std::to_string(f.camera) + " (no name)"
                                 : "camera '" + f.camera_name + "'";
}

std::string digest_text(const std::array<std::uint8_t, 16>& digest) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < 6; ++i) {
        text += hex[digest[i] >> 4];
        text += hex[digest[i] & 15];
    }
    return text;
}

// Whether `part` was rendered as `first` was (region_file.hpp's fingerprint);
// the error names both files and every difference.
Expected<void> check_fingerprint(const RegionPart& part, const RegionPart& first) {
    const std::optional<RenderFingerprint>& p = part.placement.fingerprint;
    const std::optional<RenderFingerprint>& f = first.placement.fingerprint;
    if (!p && !f) return {};
    if (!p || !f) {
        const RegionPart& old = p ? first : part;
        const RegionPart& other = p ? part : first;
        return Error{
            old.name + " carries no render fingerprint (written by an older jtracer-cli), " +
            other.name + " does: whether they are parts of one render cannot be told; render " +
            old.name + " again"};
    }
    if (*p == *f) return {};
    std::string differences;
    auto add = [&](const std::string& what) {
        differences += differences.empty() ? "" : "; ";
        differences += what;
    };
    // Parts of two frames of one sequence differ in their clock, and so in
    // their content when the clock animates the scene: the clock comes first,
    // as the likelier cause.
    const bool clocks_differ = p->clock != f->clock;
    if (clocks_differ) add("clock " + number_text(p->clock) + " and " + number_text(f->clock));
    if (p->scene != f->scene)
        add("the scene's content differs (digest " + digest_text(p->scene) + "... and " +
            digest_text(f->scene) + "...: " +
            (clocks_differ ? "the clock animates it, or another scene, another version of it, "
                             "other defines or a file it names changed)"
                           : "another scene, another version of it, other defines "
                             "or a file it names changed)"));
    if (p->samples != f->samples)
        add("samples " + std::to_string(p->samples) + " and " + std::to_string(f->samples));
    if (p->camera != f->camera || p->camera_name != f->camera_name)
        add(camera_text(*p) + " and " + camera_text(*f));
    return Error{part.name + " and " + first.name +
                 " are parts of different renders: " + differences};
}

// Whether `part` is whole and fits the first part's frame.
Expected<void> check_part(const RegionPart& part, const RegionPart& first) {
    const RegionPlacement& p = part.placement;
    const RegionPlacement& f = first.placement;
    if (p.frame_width != f.frame_width || p.frame_height != f.frame_height)
        return Error{part.name + " is a part of a " + size_text(p.frame_width, p.frame_height) +
                     " frame, but " + first.name + " of a " +
                     size_text(f.frame_width, f.frame_height) + " one"};
    if (Expected<void> same = check_fingerprint(part, first); !same) return same.error();
    if (Expected<void> inside = check_region_in_frame(p.region, p.frame_width, p.frame_height);
        !inside)
        return Error{part.name + ": " + inside.error().message};
    if (part.pixels.width != p.region.width() || part.pixels.height != p.region.height())
        return Error{part.name + " holds " + size_text(part.pixels.width, part.pixels.height) +
                     " pixels, but declares the " + size_text(p.region.width(), p.region.height()) +
                     " region " + format_frame_region(p.region)};
    return {};
}

bool overlap(const FrameRegion& a, const FrameRegion& b) {
    return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}

// The first pixel, in reading order, that no part covers (parts known not to
// overlap and to lie in the frame).
std::optional<std::pair<int, int>> first_gap(const std::vector<RegionPart>& parts, int w, int h) {
    std::vector<std::uint8_t> covered(static_cast<std::size_t>(w) * h, 0);
    for (const RegionPart& part : parts) {
        const FrameRegion& r = part.placement.region;
        for (int y = r.top; y < r.bottom; ++y)
            std::fill_n(&covered[static_cast<std::size_t>(y) * w + r.left], r.width(), 1);
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (!covered[static_cast<std::size_t>(y) * w + x]) return std::pair{x, y};
    return std::nullopt;
}

}  // namespace

Expected<Image8> merge_regions(const std::vector<RegionPart>& parts) {
    if (parts.empty()) return Error{"no parts to merge"};
    for (const RegionPart& part : parts)
        if (Expected<void> fits = check_part(part, parts.front()); !fits) return fits.error();
    for (std::size_t i = 0; i < parts.size(); ++i)
        for (std::size_t j = i + 1; j < parts.size(); ++j)
            if (parts[i].name == parts[j].name)
                return Error{parts[i].name + " is given twice"};
            else if (overlap(parts[i].placement.region, parts[j].placement.region))
                return Error{parts[i].name + " (region " +
                             format_frame_region(parts[i].placement.region) + ") overlaps " +
                             parts[j].name + " (region " +
                             format_frame_region(parts[j].placement.region) + ")"};
    const int w = parts.front().placement.frame_width;
    const int h = parts.front().placement.frame_height;
    if (auto gap = first_gap(parts, w, h))
        return Error{"the parts leave a gap: no part covers pixel " + std::to_string(gap->first) +
                     "," + std::to_string(gap->second) + " (top-left origin) of the " +
                     size_text(w, h) + " frame"};
    Image8 frame(w, h);
    for (const RegionPart& part : parts) {
        PixelRect r = to_image_rect(part.placement.region, h);
        paste_image(frame, part.pixels, r.x0, r.y0);
    }
    return frame;
}

}  // namespace jt

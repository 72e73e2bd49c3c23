#pragma once
// Assembling region files (region_file.hpp) into the whole frame.

#include "jtracer/image.hpp"
#include "jtracer/region_file.hpp"

#include <string>
#include <vector>

namespace jt {

struct RegionPart {
    std::string name;  // for messages: the file it came from
    Image8 pixels;
    RegionPlacement placement;
};

// Pastes the parts into one frame. Refuses, with a message naming the parts
// at fault, parts of frames of different sizes, a part whose pixels differ in
// size from the region it declares or that reaches out of the frame, two parts
// that overlap, and parts that leave pixels of the frame uncovered. Returns an
// empty string on success (with `frame` filled), else the message.
std::string merge_regions(const std::vector<RegionPart>& parts, Image8& frame);

}  // namespace jt

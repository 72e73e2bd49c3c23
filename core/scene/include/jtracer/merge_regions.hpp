#pragma once
// Assembling region files (region_file.hpp) into the whole frame.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"
#include "jtracer/region_file.hpp"

#include <vector>

namespace jt {

// Pastes the parts into one frame. Refuses, with a message naming the parts
// at fault, parts of frames of different sizes or of different renders
// (their fingerprints differ, or only one of two has one), a part whose pixels differ in
// size from the region it declares or that reaches out of the frame, two parts
// that overlap, and parts that leave pixels of the frame uncovered.
Expected<Image8> merge_regions(const std::vector<RegionPart>& parts);

}  // namespace jt

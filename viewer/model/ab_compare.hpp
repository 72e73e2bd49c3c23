#pragma once
// A/B compare: a snapshot of the image (A) shown against the live render, side
// by side at a split line, alone, or as their per-pixel difference computed by
// the core's diff_images (the heat map jtracer-cli diff writes).

#include "model/app_state.hpp"

#include <string>

namespace jt::view {

// Keeps the image as it is now as A (replacing any earlier A).
void snapshot_a(AppState& state);
void clear_snapshot_a(CompareState& compare);

// Whether A can be shown against the image now: there is one, of the same size.
bool comparable(const CompareState& compare, const Image8& display);

// The column where the split view changes from A to live: image columns left
// of it show A, the others the live image.
int split_column(const CompareState& compare, const Image8& display);

// What the difference view shows, and its summary, as jtracer-cli diff
// compares A (expected) with the live image (actual).
struct CompareDifference {
    Image8 image;
    std::string summary;  // "max difference 37, 12.3% of pixels differ, PSNR 31.2 dB"
};
CompareDifference compare_difference(const CompareState& compare, const Image8& display);

}  // namespace jt::view

#pragma once
// Where within a pixel sample k lands: the R2 low-discrepancy sequence
// (Roberts 2018) started at the centre, so sample 0 is exactly the pixel centre
// and every prefix of the sequence is spread evenly. The same for every pixel,
// run and thread count.

#include <cmath>

namespace jt {

struct SampleOffset {
    double x = 0.5;
    double y = 0.5;
};

inline SampleOffset sample_offset(int k) {
    // 1/g and 1/g^2 for the plastic number g, the root of x^3 = x + 1.
    constexpr double a1 = 0.7548776662466927;
    constexpr double a2 = 0.5698402909980532;
    double x = 0.5 + a1 * k;
    double y = 0.5 + a2 * k;
    return {x - std::floor(x), y - std::floor(y)};
}

}  // namespace jt

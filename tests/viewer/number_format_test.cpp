// The number fields show a value inside the field's range as a number inside
// it: four significant digits rounded 179.98 in the fov field (held below
// 180) to "180", a value the field refuses.

#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "jtracer/schema.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace jt::view {
namespace {

std::string shown(float value, double min, double max) {
    char text[64];
    std::snprintf(text, sizeof text, number_format(value, min, max), static_cast<double>(value));
    return text;
}

FieldBounds fov_bounds() {
    for (const PropertySpec<Camera>& property : schema_of<Camera>().properties)
        if (property.name == "fov") return field_bounds(property.range);
    ADD_FAILURE() << "no fov property";
    return {};
}

TEST(NumberFormat, AValueInsideTheRangeNeverShowsAsOneOutsideIt) {
    const FieldBounds b = fov_bounds();
    ASSERT_LT(b.max, 180.0);
    EXPECT_EQ(shown(179.98f, b.min, b.max), "179.98");
    EXPECT_EQ(shown(60.0f, b.min, b.max), "60") << "four digits as before";
    EXPECT_EQ(shown(123.456f, b.min, b.max), "123.5");
    // Every float from 179.9 up to the bound, and the 20,000 from the low bound up.
    for (float v = 179.9f; v <= static_cast<float>(b.max); v = std::nextafter(v, 200.0f)) {
        if (v < b.min || v > b.max) continue;
        const float read = std::strtof(shown(v, b.min, b.max).c_str(), nullptr);
        ASSERT_LE(read, b.max) << v << " shows as " << shown(v, b.min, b.max);
    }
    float v = static_cast<float>(b.min);
    for (int i = 0; i < 20000; ++i, v = std::nextafter(v, 1.0f)) {
        if (v < b.min) continue;
        const float read = std::strtof(shown(v, b.min, b.max).c_str(), nullptr);
        ASSERT_GE(read, b.min) << v << " shows as " << shown(v, b.min, b.max);
    }
}

// Between the field's bound and an open bound of the language (a fov of
// 179.99 read from a file): shown as itself, never as the bound.
TEST(NumberFormat, AValueBeyondTheFieldsBoundShowsAsItself) {
    const FieldBounds b = fov_bounds();
    EXPECT_EQ(shown(179.99f, b.min, b.max), "179.99");
    EXPECT_EQ(shown(0.00005f, b.min, b.max), "5e-05");
    EXPECT_EQ(shown(2.5f, 0.0, 0.0), "2.5") << "no bounds: four digits";
}

}  // namespace
}  // namespace jt::view

#include "jtracer/vector_unit.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

TEST(VectorUnit, UnsetTakesTheBestTheCpuHas) {
    EXPECT_EQ(choose_vector_unit(nullptr, true).unit, VectorUnit::avx);
    EXPECT_EQ(choose_vector_unit(nullptr, false).unit, VectorUnit::sse2);
    EXPECT_TRUE(choose_vector_unit(nullptr, true).failure.empty());
}

TEST(VectorUnit, Sse2IsTakenOnEveryCpu) {
    for (const bool avx : {false, true}) {
        const VectorUnitChoice choice = choose_vector_unit("sse2", avx);
        EXPECT_EQ(choice.unit, VectorUnit::sse2);
        EXPECT_TRUE(choice.failure.empty());
    }
}

TEST(VectorUnit, AvxIsRefusedWithoutItAndNamesTheSetting) {
    EXPECT_EQ(choose_vector_unit("avx", true).unit, VectorUnit::avx);
    EXPECT_TRUE(choose_vector_unit("avx", true).failure.empty());
    EXPECT_EQ(choose_vector_unit("avx", false).failure, "JTRACER_SIMD='avx': this CPU has no AVX");
}

TEST(VectorUnit, AnUnknownValueSaysWhatIsExpected) {
    for (const char* value : {"", "AVX", "avx2", "sse4.2"}) {
        const std::string failure = choose_vector_unit(value, true).failure;
        EXPECT_NE(failure.find(std::string("JTRACER_SIMD='") + value + "'"), std::string::npos)
            << failure;
        EXPECT_NE(failure.find("expected sse2 or avx"), std::string::npos) << failure;
    }
}

TEST(VectorUnit, NamesAreTheVariablesSpelling) {
    EXPECT_STREQ(vector_unit_name(VectorUnit::sse2), "sse2");
    EXPECT_STREQ(vector_unit_name(VectorUnit::avx), "avx");
    for (const VectorUnit unit : {VectorUnit::sse2, VectorUnit::avx})
        EXPECT_EQ(choose_vector_unit(vector_unit_name(unit), true).unit, unit);
}

}  // namespace
}  // namespace jt

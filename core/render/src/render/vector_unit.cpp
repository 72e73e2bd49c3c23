#include "jtracer/vector_unit.hpp"

#include <cstdlib>
#include <cstring>

namespace jt {

namespace {

bool cpu_has_avx() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx");
#else
    return false;
#endif
}

}  // namespace

VectorUnitChoice choose_vector_unit(const char* requested, bool cpu_has_avx) {
    const VectorUnit best = cpu_has_avx ? VectorUnit::avx : VectorUnit::sse2;
    if (!requested) return {best, {}};
    const std::string setting = std::string(kVectorUnitVariable) + "='" + requested + "'";
    if (std::strcmp(requested, "sse2") == 0) return {VectorUnit::sse2, {}};
    if (std::strcmp(requested, "avx") == 0) {
        if (cpu_has_avx) return {VectorUnit::avx, {}};
        return {best, setting + ": this CPU has no AVX"};
    }
    return {best, setting +
                      ": expected sse2 or avx (or the variable unset: the best this CPU "
                      "has)"};
}

const VectorUnitChoice& vector_unit() {
    static const VectorUnitChoice choice =
        choose_vector_unit(std::getenv(kVectorUnitVariable), cpu_has_avx());
    return choice;
}

const char* vector_unit_name(VectorUnit unit) {
    return unit == VectorUnit::avx ? "avx" : "sse2";
}

}  // namespace jt

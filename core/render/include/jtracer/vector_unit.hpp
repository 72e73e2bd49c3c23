#pragma once
// Which vector instructions JTracer's own batched code runs on: AVX where the
// CPU has it, SSE2 (which every x86-64 CPU has) otherwise. Both give the same
// bytes, lane for lane; the environment variable JTRACER_SIMD picks one, so
// that a machine can prove it (tests/cli/isa_identity_test.sh), as
// JTRACER_EMBREE_CONFIG does for Embree's kernels (docs/distributed.md).

#include <string>

namespace jt {

inline constexpr const char* kVectorUnitVariable = "JTRACER_SIMD";

enum class VectorUnit { sse2, avx };

struct VectorUnitChoice {
    VectorUnit unit = VectorUnit::sse2;
    // Why the request cannot be met; empty when it can.
    std::string failure;
};

// What `requested` (the variable's value: "sse2", "avx", or null when it is
// unset) picks on a CPU that has AVX or not.
VectorUnitChoice choose_vector_unit(const char* requested, bool cpu_has_avx);

// The process's choice, made once from JTRACER_SIMD and the CPU.
const VectorUnitChoice& vector_unit();

// "sse2" or "avx": the variable's spelling.
const char* vector_unit_name(VectorUnit unit);

}  // namespace jt

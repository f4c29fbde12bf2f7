// Eight floats (or ints) worked on at once: the SIMD lanes of the photon walk, written with
// the GCC/Clang vector extensions so that the same code compiles to AVX-512 or AVX2 where
// the CPU has them and to pairs of SSE2 operations elsewhere. Scalar counterparts of every
// helper exist (float, bool) so that the warps in sampling.h and frame.h are written once,
// as templates over the number type, and shared by the scalar code and the lanes.
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace photon {

// Every helper here, and every shared template written for lanes, is always inlined: the
// lanes' kernels are compiled for AVX-512 and AVX2 as well as for the baseline CPU, and an
// out-of-line helper would run the baseline code, with a different way of passing vectors,
// from inside the wider ones.
#define PHOTON_LANES_INLINE inline __attribute__((always_inline))
// The same for a lambda inside a kernel, written after its parameters: its closure type is
// one for all three variants, so an out-of-line call operator would be compiled for the
// baseline CPU alone. GCC's inlining limits count per translation unit, so whether it
// inlines a plain lambda changed with what else a unity build put beside it, and an
// AVX-512 kernel then called the baseline body with vectors passed its own way (a crash).
#define PHOTON_LANES_LAMBDA __attribute__((always_inline))

// A kernel for lanes is written once, as an always-inline body; PHOTON_LANES_KERNEL makes
// from it an AVX-512 function, an AVX2 one and a baseline one, and calls the widest the CPU
// runs (asked once). Chosen by hand rather than with GCC's target_clones, whose ifunc
// resolvers run before the sanitizers' runtimes start.
//
// The kernels keep eight lanes under AVX-512 too: what they gain is its 64-bit multiply
// (PCG32's state update, emulated with three 32-bit multiplies under AVX2) and mask
// registers for the selects: the walk alone 5.5% faster than with AVX2. AVX-512 implies
// FMA, and GCC would fuse a * b + c into one rounding, so the engine is compiled with
// -ffp-contract=off: every variant gives the scalar code's bits (tests/test_photon_walk.cpp
// runs them all).
enum class LanesIsa { Baseline = 0, Avx2 = 1, Avx512 = 2 };
#if defined(__x86_64__)
// The widest instruction set the CPU (and the OS, which must save the wider registers)
// supports.
inline LanesIsa cpuLanesIsa() {
    static const LanesIsa isa = [] {
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
            __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw"))
            return LanesIsa::Avx512;
        return __builtin_cpu_supports("avx2") ? LanesIsa::Avx2 : LanesIsa::Baseline;
    }();
    return isa;
}
#else
inline LanesIsa cpuLanesIsa() { return LanesIsa::Baseline; }
#endif
inline std::atomic<int>& lanesIsaLimit() {
    static std::atomic<int> limit{static_cast<int>(LanesIsa::Avx512)};
    return limit;
}
// The instruction set the kernels run: the CPU's widest, unless limited.
inline LanesIsa lanesIsa() {
    return static_cast<LanesIsa>(std::min(static_cast<int>(cpuLanesIsa()), lanesIsaLimit().load(std::memory_order_relaxed)));
}
// Caps the instruction set of the kernels called from now on, so that tests can compare
// every variant on one machine.
inline void limitLanesIsa(LanesIsa widest) { lanesIsaLimit().store(static_cast<int>(widest), std::memory_order_relaxed); }

#if defined(__x86_64__)
#define PHOTON_LANES_KERNEL(name, body, params, args)                                                  \
    __attribute__((target("avx512f,avx512dq,avx512vl,avx512bw"))) static void name##Avx512 params { \
        body args;                                                                                  \
    }                                                                                               \
    __attribute__((target("avx2"))) static void name##Avx2 params { body args; }                   \
    static void name params {                                                                       \
        switch (lanesIsa()) {                                                                       \
            case LanesIsa::Avx512: return name##Avx512 args;                                        \
            case LanesIsa::Avx2: return name##Avx2 args;                                            \
            case LanesIsa::Baseline: break;                                                         \
        }                                                                                           \
        body args;                                                                                  \
    }
#else
#define PHOTON_LANES_KERNEL(name, body, params, args) \
    static void name params { body args; }
#endif

constexpr int kLanes = 8;
using FloatLanes = float __attribute__((vector_size(4 * kLanes)));
using IntLanes = int32_t __attribute__((vector_size(4 * kLanes)));  // masks: -1 true, 0 false
using UintLanes = uint32_t __attribute__((vector_size(4 * kLanes)));
using Uint64Lanes = uint64_t __attribute__((vector_size(8 * kLanes)));

// select(mask, a, b): a where mask holds, else b.
// The scalar select is done on the bits: GCC turns `m ? a : b` on floats into a branch,
// which the warps' coin-toss conditions would mispredict half the time.
PHOTON_LANES_INLINE float select(bool m, float a, float b) {
    uint32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    uint32_t mask = 0u - static_cast<uint32_t>(m);
    uint32_t r = (ia & mask) | (ib & ~mask);
    float out;
    std::memcpy(&out, &r, 4);
    return out;
}
PHOTON_LANES_INLINE FloatLanes select(IntLanes m, FloatLanes a, FloatLanes b) { return m ? a : b; }
PHOTON_LANES_INLINE IntLanes select(IntLanes m, IntLanes a, IntLanes b) { return m ? a : b; }

PHOTON_LANES_INLINE float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
PHOTON_LANES_INLINE FloatLanes safeSqrt(FloatLanes x) {
    x = x > 0.0f ? x : FloatLanes{};
    FloatLanes r;
    for (int i = 0; i < kLanes; ++i) r[i] = __builtin_sqrtf(x[i]);  // one vsqrtps
    return r;
}
PHOTON_LANES_INLINE FloatLanes absValue(FloatLanes x) {
    UintLanes bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits &= 0x7fffffffu;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}
// +1 or -1 with the sign of x (-0 counts as negative, like std::copysign(1, x)).
PHOTON_LANES_INLINE float signOf(float x) { return std::copysign(1.0f, x); }
PHOTON_LANES_INLINE FloatLanes signOf(FloatLanes x) {
    UintLanes bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = (bits & 0x80000000u) | 0x3f800000u;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}
PHOTON_LANES_INLINE float absValue(float x) { return std::fabs(x); }
PHOTON_LANES_INLINE float maxValue(float a, float b) { return std::max(a, b); }
PHOTON_LANES_INLINE FloatLanes maxValue(FloatLanes a, FloatLanes b) { return a > b ? a : b; }
// A constant of type F (a float, or the same float in every lane).
template <class F>
PHOTON_LANES_INLINE F broadcast(float v) {
    return F{} + v;
}

PHOTON_LANES_INLINE bool isFiniteLanes(float x) { return std::isfinite(x); }
PHOTON_LANES_INLINE IntLanes isFiniteLanes(FloatLanes x) {
    UintLanes bits;
    std::memcpy(&bits, &x, sizeof bits);
    return (bits & 0x7f800000u) != 0x7f800000u;
}

template <class T, class Lanes>
PHOTON_LANES_INLINE Lanes loadLanes(const T* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <class T, class Lanes>
PHOTON_LANES_INLINE void storeLanes(T* p, Lanes v) {
    std::memcpy(p, &v, sizeof v);
}

// A 3-vector of lanes: eight Vec3s, one per lane.
struct Vec3Lanes {
    FloatLanes x{}, y{}, z{};
};
PHOTON_LANES_INLINE Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PHOTON_LANES_INLINE Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PHOTON_LANES_INLINE Vec3Lanes operator*(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
PHOTON_LANES_INLINE Vec3Lanes operator*(const Vec3Lanes& a, FloatLanes s) { return {a.x * s, a.y * s, a.z * s}; }
PHOTON_LANES_INLINE FloatLanes dot(const Vec3Lanes& a, const Vec3Lanes& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PHOTON_LANES_INLINE FloatLanes maxComponent(const Vec3Lanes& a) { return maxValue(a.x, maxValue(a.y, a.z)); }
PHOTON_LANES_INLINE Vec3Lanes select(IntLanes m, const Vec3Lanes& a, const Vec3Lanes& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}

// PCG32 (rng.h's Rng) for eight streams at once: the same sequence a scalar Rng with the
// same state gives, so a photon's random numbers do not depend on which code consumes them.
// Only the lanes in `mask` advance.
PHOTON_LANES_INLINE FloatLanes uniformLanes(uint64_t* state, const uint64_t* increment, IntLanes mask) {
    Uint64Lanes old = loadLanes<uint64_t, Uint64Lanes>(state);
    Uint64Lanes inc = loadLanes<uint64_t, Uint64Lanes>(increment);
    Uint64Lanes advanced = old * 6364136223846793005ull + inc;
    Uint64Lanes wide = __builtin_convertvector(mask, Uint64Lanes);  // -1 sign-extends to all ones
    storeLanes(state, (advanced & wide) | (old & ~wide));
    UintLanes xorshifted = __builtin_convertvector(((old >> 18u) ^ old) >> 27u, UintLanes);
    UintLanes rot = __builtin_convertvector(old >> 59u, UintLanes);
    UintLanes bits = (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    return __builtin_convertvector(bits >> 8u, FloatLanes) * 0x1p-24f;
}

}  // namespace photon

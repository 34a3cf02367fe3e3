#pragma once
/// Lane types for packet tracing: a float, an int and a mask per lane, chosen
/// at build time — 16 lanes with AVX-512, 8 with AVX2, 4 with wasm SIMD (the
/// browser build, docs/web.md), 1 (plain C++) otherwise.
/// Every operation is the lane-wise IEEE operation (no FMA, no approximate
/// reciprocal), so a packet computes what the same code computes on floats.
/// Private to the core: the lane count depends on -march, so only targets
/// built with f2_opt may include this (docs/design.md, "Layers").
#include <cstdint>

#if defined(__AVX512F__) || defined(__AVX2__)
#include <immintrin.h>
#elif defined(__wasm_simd128__)
#include <wasm_simd128.h>
#endif

namespace f2::simd {

#if defined(__AVX512F__)

// The masked forms with an explicit source avoid GCC 12's false
// -Wmaybe-uninitialized on the unmasked intrinsics (which pass an undefined source).
inline constexpr int kWidth = 16;
inline constexpr const char* kIsaName = "AVX-512";

struct Mask {
    __mmask16 m;
};
struct Float {
    __m512 v;
    Float() = default;
    Float(__m512 x) : v(x) {}
    Float(float x) : v(_mm512_set1_ps(x)) {}
};
struct Int {
    __m512i v;
    Int() = default;
    Int(__m512i x) : v(x) {}
    Int(std::int32_t x) : v(_mm512_set1_epi32(x)) {}
};

inline Float operator+(Float a, Float b) { return _mm512_add_ps(a.v, b.v); }
inline Float operator-(Float a, Float b) { return _mm512_sub_ps(a.v, b.v); }
inline Float operator*(Float a, Float b) { return _mm512_mul_ps(a.v, b.v); }
inline Float operator/(Float a, Float b) { return _mm512_div_ps(a.v, b.v); }
inline Float operator-(Float a) { return _mm512_xor_ps(a.v, _mm512_set1_ps(-0.0f)); }
inline Float sqrt(Float a) { return _mm512_mask_sqrt_ps(a.v, 0xFFFF, a.v); }
inline Float abs(Float a) { return _mm512_abs_ps(a.v); }
/// a < b ? a : b, lane-wise (SSE semantics, which plain code mirrors).
inline Float min(Float a, Float b) { return _mm512_mask_min_ps(a.v, 0xFFFF, a.v, b.v); }
inline Float max(Float a, Float b) { return _mm512_mask_max_ps(a.v, 0xFFFF, a.v, b.v); }
inline Float floor(Float a) {
    return _mm512_mask_roundscale_ps(a.v, 0xFFFF, a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

inline Mask operator<(Float a, Float b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask operator<=(Float a, Float b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask operator>(Float a, Float b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ)}; }
inline Mask operator>=(Float a, Float b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ)}; }
inline Mask operator==(Float a, Float b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask operator==(Int a, Int b) { return {_mm512_cmpeq_epi32_mask(a.v, b.v)}; }
inline Mask operator<(Int a, Int b) { return {_mm512_cmplt_epi32_mask(a.v, b.v)}; }

inline Mask operator&(Mask a, Mask b) { return {__mmask16(a.m & b.m)}; }
inline Mask operator|(Mask a, Mask b) { return {__mmask16(a.m | b.m)}; }
inline Mask andNot(Mask a, Mask b) { return {__mmask16(a.m & ~b.m)}; }  ///< a and not b
inline bool any(Mask a) { return a.m != 0; }
inline bool none(Mask a) { return a.m == 0; }
inline int firstLane(Mask a) { return __builtin_ctz(a.m); }
inline std::uint32_t bits(Mask a) { return a.m; }
inline Mask allLanes() { return {0xFFFF}; }
inline Mask noLanes() { return {0}; }

/// mask ? a : b
inline Float select(Mask m, Float a, Float b) { return _mm512_mask_blend_ps(m.m, b.v, a.v); }
inline Int select(Mask m, Int a, Int b) { return _mm512_mask_blend_epi32(m.m, b.v, a.v); }

inline Float load(const float* p) { return _mm512_loadu_ps(p); }
inline void store(float* p, Float a) { _mm512_storeu_ps(p, a.v); }
inline void store(std::int32_t* p, Int a) { _mm512_storeu_si512(p, a.v); }
inline Int truncateToInt(Float a) { return _mm512_mask_cvttps_epi32(_mm512_setzero_si512(), 0xFFFF, a.v); }
inline Float toFloat(Int a) { return _mm512_mask_cvtepi32_ps(_mm512_setzero_ps(), 0xFFFF, a.v); }
inline Int bitsOf(Float a) { return _mm512_castps_si512(a.v); }
inline Float fromBits(Int a) { return _mm512_castsi512_ps(a.v); }
inline Int operator+(Int a, Int b) { return _mm512_add_epi32(a.v, b.v); }
inline Int operator-(Int a, Int b) { return _mm512_sub_epi32(a.v, b.v); }
inline Int operator&(Int a, Int b) { return _mm512_and_si512(a.v, b.v); }
inline Int operator|(Int a, Int b) { return _mm512_or_si512(a.v, b.v); }
inline Int shiftLeft23(Int a) { return _mm512_mask_slli_epi32(a.v, 0xFFFF, a.v, 23); }
inline Int shiftRight23(Int a) { return _mm512_mask_srli_epi32(a.v, 0xFFFF, a.v, 23); }

#elif defined(__AVX2__)

inline constexpr int kWidth = 8;
inline constexpr const char* kIsaName = "AVX2";

struct Mask {
    __m256 m;
};
struct Float {
    __m256 v;
    Float() = default;
    Float(__m256 x) : v(x) {}
    Float(float x) : v(_mm256_set1_ps(x)) {}
};
struct Int {
    __m256i v;
    Int() = default;
    Int(__m256i x) : v(x) {}
    Int(std::int32_t x) : v(_mm256_set1_epi32(x)) {}
};

inline Float operator+(Float a, Float b) { return _mm256_add_ps(a.v, b.v); }
inline Float operator-(Float a, Float b) { return _mm256_sub_ps(a.v, b.v); }
inline Float operator*(Float a, Float b) { return _mm256_mul_ps(a.v, b.v); }
inline Float operator/(Float a, Float b) { return _mm256_div_ps(a.v, b.v); }
inline Float operator-(Float a) { return _mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f)); }
inline Float sqrt(Float a) { return _mm256_sqrt_ps(a.v); }
inline Float abs(Float a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v); }
inline Float min(Float a, Float b) { return _mm256_min_ps(a.v, b.v); }
inline Float max(Float a, Float b) { return _mm256_max_ps(a.v, b.v); }
inline Float floor(Float a) { return _mm256_floor_ps(a.v); }

inline Mask operator<(Float a, Float b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask operator<=(Float a, Float b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask operator>(Float a, Float b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
inline Mask operator>=(Float a, Float b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
inline Mask operator==(Float a, Float b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask operator==(Int a, Int b) { return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(a.v, b.v))}; }
inline Mask operator<(Int a, Int b) { return {_mm256_castsi256_ps(_mm256_cmpgt_epi32(b.v, a.v))}; }

inline Mask operator&(Mask a, Mask b) { return {_mm256_and_ps(a.m, b.m)}; }
inline Mask operator|(Mask a, Mask b) { return {_mm256_or_ps(a.m, b.m)}; }
inline Mask andNot(Mask a, Mask b) { return {_mm256_andnot_ps(b.m, a.m)}; }
inline std::uint32_t bits(Mask a) { return std::uint32_t(_mm256_movemask_ps(a.m)); }
inline bool any(Mask a) { return bits(a) != 0; }
inline bool none(Mask a) { return bits(a) == 0; }
inline int firstLane(Mask a) { return __builtin_ctz(bits(a)); }
inline Mask allLanes() { return {_mm256_castsi256_ps(_mm256_set1_epi32(-1))}; }
inline Mask noLanes() { return {_mm256_setzero_ps()}; }

inline Float select(Mask m, Float a, Float b) { return _mm256_blendv_ps(b.v, a.v, m.m); }
inline Int select(Mask m, Int a, Int b) {
    return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(b.v), _mm256_castsi256_ps(a.v), m.m));
}

inline Float load(const float* p) { return _mm256_loadu_ps(p); }
inline void store(float* p, Float a) { _mm256_storeu_ps(p, a.v); }
inline void store(std::int32_t* p, Int a) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), a.v); }
inline Int truncateToInt(Float a) { return _mm256_cvttps_epi32(a.v); }
inline Float toFloat(Int a) { return _mm256_cvtepi32_ps(a.v); }
inline Int bitsOf(Float a) { return _mm256_castps_si256(a.v); }
inline Float fromBits(Int a) { return _mm256_castsi256_ps(a.v); }
inline Int operator+(Int a, Int b) { return _mm256_add_epi32(a.v, b.v); }
inline Int operator-(Int a, Int b) { return _mm256_sub_epi32(a.v, b.v); }
inline Int operator&(Int a, Int b) { return _mm256_and_si256(a.v, b.v); }
inline Int operator|(Int a, Int b) { return _mm256_or_si256(a.v, b.v); }
inline Int shiftLeft23(Int a) { return _mm256_slli_epi32(a.v, 23); }
inline Int shiftRight23(Int a) { return _mm256_srli_epi32(a.v, 23); }

#elif defined(__wasm_simd128__)

inline constexpr int kWidth = 4;
inline constexpr const char* kIsaName = "wasm SIMD";

struct Mask {
    v128_t m;
};
struct Float {
    v128_t v;
    Float() = default;
    Float(v128_t x) : v(x) {}
    Float(float x) : v(wasm_f32x4_splat(x)) {}
};
struct Int {
    v128_t v;
    Int() = default;
    Int(v128_t x) : v(x) {}
    Int(std::int32_t x) : v(wasm_i32x4_splat(x)) {}
};

inline Float operator+(Float a, Float b) { return wasm_f32x4_add(a.v, b.v); }
inline Float operator-(Float a, Float b) { return wasm_f32x4_sub(a.v, b.v); }
inline Float operator*(Float a, Float b) { return wasm_f32x4_mul(a.v, b.v); }
inline Float operator/(Float a, Float b) { return wasm_f32x4_div(a.v, b.v); }
inline Float operator-(Float a) { return wasm_f32x4_neg(a.v); }
inline Float sqrt(Float a) { return wasm_f32x4_sqrt(a.v); }
inline Float abs(Float a) { return wasm_f32x4_abs(a.v); }
// pmin(x, y) is y < x ? y : x: with the operands swapped, SSE's a < b ? a : b.
inline Float min(Float a, Float b) { return wasm_f32x4_pmin(b.v, a.v); }
inline Float max(Float a, Float b) { return wasm_f32x4_pmax(b.v, a.v); }
inline Float floor(Float a) { return wasm_f32x4_floor(a.v); }

inline Mask operator<(Float a, Float b) { return {wasm_f32x4_lt(a.v, b.v)}; }
inline Mask operator<=(Float a, Float b) { return {wasm_f32x4_le(a.v, b.v)}; }
inline Mask operator>(Float a, Float b) { return {wasm_f32x4_gt(a.v, b.v)}; }
inline Mask operator>=(Float a, Float b) { return {wasm_f32x4_ge(a.v, b.v)}; }
inline Mask operator==(Float a, Float b) { return {wasm_f32x4_eq(a.v, b.v)}; }
inline Mask operator==(Int a, Int b) { return {wasm_i32x4_eq(a.v, b.v)}; }
inline Mask operator<(Int a, Int b) { return {wasm_i32x4_lt(a.v, b.v)}; }

inline Mask operator&(Mask a, Mask b) { return {wasm_v128_and(a.m, b.m)}; }
inline Mask operator|(Mask a, Mask b) { return {wasm_v128_or(a.m, b.m)}; }
inline Mask andNot(Mask a, Mask b) { return {wasm_v128_andnot(a.m, b.m)}; }
inline std::uint32_t bits(Mask a) { return std::uint32_t(wasm_i32x4_bitmask(a.m)); }
inline bool any(Mask a) { return wasm_v128_any_true(a.m); }
inline bool none(Mask a) { return !wasm_v128_any_true(a.m); }
inline int firstLane(Mask a) { return __builtin_ctz(bits(a)); }
inline Mask allLanes() { return {wasm_i32x4_splat(-1)}; }
inline Mask noLanes() { return {wasm_i32x4_splat(0)}; }

inline Float select(Mask m, Float a, Float b) { return wasm_v128_bitselect(a.v, b.v, m.m); }
inline Int select(Mask m, Int a, Int b) { return wasm_v128_bitselect(a.v, b.v, m.m); }

inline Float load(const float* p) { return wasm_v128_load(p); }
inline void store(float* p, Float a) { wasm_v128_store(p, a.v); }
inline void store(std::int32_t* p, Int a) { wasm_v128_store(p, a.v); }
inline Int truncateToInt(Float a) { return wasm_i32x4_trunc_sat_f32x4(a.v); }
inline Float toFloat(Int a) { return wasm_f32x4_convert_i32x4(a.v); }
inline Int bitsOf(Float a) { return a.v; }
inline Float fromBits(Int a) { return a.v; }
inline Int operator+(Int a, Int b) { return wasm_i32x4_add(a.v, b.v); }
inline Int operator-(Int a, Int b) { return wasm_i32x4_sub(a.v, b.v); }
inline Int operator&(Int a, Int b) { return wasm_v128_and(a.v, b.v); }
inline Int operator|(Int a, Int b) { return wasm_v128_or(a.v, b.v); }
inline Int shiftLeft23(Int a) { return wasm_i32x4_shl(a.v, 23); }
inline Int shiftRight23(Int a) { return wasm_u32x4_shr(a.v, 23); }

#else  // portable fallback: one lane

inline constexpr int kWidth = 1;
inline constexpr const char* kIsaName = "scalar";

struct Mask {
    bool m;
};
struct Float {
    float v;
    Float() = default;
    Float(float x) : v(x) {}
};
struct Int {
    std::int32_t v;
    Int() = default;
    Int(std::int32_t x) : v(x) {}
};

inline Float operator+(Float a, Float b) { return a.v + b.v; }
inline Float operator-(Float a, Float b) { return a.v - b.v; }
inline Float operator*(Float a, Float b) { return a.v * b.v; }
inline Float operator/(Float a, Float b) { return a.v / b.v; }
inline Float operator-(Float a) { return -a.v; }
inline Float sqrt(Float a) { return __builtin_sqrtf(a.v); }
inline Float abs(Float a) { return __builtin_fabsf(a.v); }
inline Float min(Float a, Float b) { return a.v < b.v ? a.v : b.v; }
inline Float max(Float a, Float b) { return a.v > b.v ? a.v : b.v; }
inline Float floor(Float a) { return __builtin_floorf(a.v); }

inline Mask operator<(Float a, Float b) { return {a.v < b.v}; }
inline Mask operator<=(Float a, Float b) { return {a.v <= b.v}; }
inline Mask operator>(Float a, Float b) { return {a.v > b.v}; }
inline Mask operator>=(Float a, Float b) { return {a.v >= b.v}; }
inline Mask operator==(Float a, Float b) { return {a.v == b.v}; }
inline Mask operator==(Int a, Int b) { return {a.v == b.v}; }
inline Mask operator<(Int a, Int b) { return {a.v < b.v}; }

inline Mask operator&(Mask a, Mask b) { return {a.m && b.m}; }
inline Mask operator|(Mask a, Mask b) { return {a.m || b.m}; }
inline Mask andNot(Mask a, Mask b) { return {a.m && !b.m}; }
inline bool any(Mask a) { return a.m; }
inline bool none(Mask a) { return !a.m; }
inline int firstLane(Mask) { return 0; }
inline std::uint32_t bits(Mask a) { return a.m ? 1u : 0u; }
inline Mask allLanes() { return {true}; }
inline Mask noLanes() { return {false}; }

inline Float select(Mask m, Float a, Float b) { return m.m ? a : b; }
inline Int select(Mask m, Int a, Int b) { return m.m ? a : b; }

inline Float load(const float* p) { return *p; }
inline void store(float* p, Float a) { *p = a.v; }
inline void store(std::int32_t* p, Int a) { *p = a.v; }
inline Int truncateToInt(Float a) { return std::int32_t(a.v); }
inline Float toFloat(Int a) { return float(a.v); }
inline Int bitsOf(Float a) { return __builtin_bit_cast(std::int32_t, a.v); }
inline Float fromBits(Int a) { return __builtin_bit_cast(float, a.v); }
inline Int operator+(Int a, Int b) { return a.v + b.v; }
inline Int operator-(Int a, Int b) { return a.v - b.v; }
inline Int operator&(Int a, Int b) { return a.v & b.v; }
inline Int operator|(Int a, Int b) { return a.v | b.v; }
inline Int shiftLeft23(Int a) { return std::int32_t(std::uint32_t(a.v) << 23); }
inline Int shiftRight23(Int a) { return std::int32_t(std::uint32_t(a.v) >> 23); }

#endif

/// Lane i of a value (tests, debugging; not for hot loops).
inline float lane(Float a, int i) {
    alignas(64) float tmp[kWidth];
    store(tmp, a);
    return tmp[i];
}

/// The smallest and the largest lane (once per tile, not in hot loops).
inline float minLane(Float a) {
    alignas(64) float tmp[kWidth];
    store(tmp, a);
    float m = tmp[0];
    for (int i = 1; i < kWidth; ++i) m = tmp[i] < m ? tmp[i] : m;
    return m;
}
inline float maxLane(Float a) { return -minLane(-a); }

}  // namespace f2::simd

#pragma once
/// pow() for lanes, as exp2(n * log2(x)), accurate to about 1e-6 relative —
/// far below one level of an 8-bit channel (1/255).
#include "core/simd/simd.h"

namespace f2::simd {

/// log2 of a positive normal float.
inline Float log2Positive(Float x) {
    // x = 2^e * m with m in [1, 2), moved to [sqrt(1/2), sqrt(2)) so the series below converges fast.
    Int raw = bitsOf(x);
    Float e = toFloat(shiftRight23(raw) - Int(127));
    Float m = fromBits((raw & Int(0x007FFFFF)) | Int(0x3F800000));
    Mask big = m > Float(1.41421356f);
    m = select(big, m * Float(0.5f), m);
    e = select(big, e + Float(1.0f), e);
    // ln m = 2 atanh(z), z = (m - 1)/(m + 1), |z| < 0.172: five terms reach 1e-9.
    Float z = (m - Float(1.0f)) / (m + Float(1.0f));
    Float z2 = z * z;
    Float series =
        Float(1.0f) +
        z2 * (Float(1.0f / 3) + z2 * (Float(1.0f / 5) + z2 * (Float(1.0f / 7) + z2 * Float(1.0f / 9))));
    return e + z * series * Float(2.0f * 1.44269504088896341f);
}

/// 2^y for y clamped to [-126, 127].
inline Float exp2(Float y) {
    y = min(max(y, Float(-126.0f)), Float(127.0f));
    Float whole = floor(y + Float(0.5f));
    Float f = (y - whole) * Float(0.69314718055994531f);  // |f| <= 0.347: e^f by Taylor to degree 7
    Float p =
        Float(1.0f) +
        f * (Float(1.0f) +
             f * (Float(1.0f / 2) +
                  f * (Float(1.0f / 6) +
                       f * (Float(1.0f / 24) +
                            f * (Float(1.0f / 120) + f * (Float(1.0f / 720) + f * Float(1.0f / 5040)))))));
    Float scale = fromBits(shiftLeft23(truncateToInt(whole) + Int(127)));
    return p * scale;
}

/// x^n for x > 0 (lanes with x <= 0 give garbage: mask them).
inline Float powPositive(Float x, Float n) { return exp2(n * log2Positive(max(x, Float(1e-30f)))); }

}  // namespace f2::simd

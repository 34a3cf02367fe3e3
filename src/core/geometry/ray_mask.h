#pragma once
/// What rays do with a primitive besides hitting it: one byte of flags per
/// primitive of a frame (EvaluatedFrame::rayMask, Bvh::setRayMask). Most
/// scenes set none, and their mask is empty.
#include <cstdint>

namespace f2::ray_mask {

/// `/no_shadow` (SPEC 10.8): shadow rays pass through it; it is still seen.
inline constexpr std::uint8_t kCastsNoShadow = 1;
/// A `visible 0` key holds (SPEC 10.7): every ray passes through it.
inline constexpr std::uint8_t kHidden = 2;

}  // namespace f2::ray_mask

#pragma once
/// Lights beyond the first edition's ambient and directional ones: point and
/// spot lights, and the size that gives any light soft shadows
/// (docs/scene-language.md, "Point and spot lights", "Soft shadows").
/// Plain data, as the parser read it.
#include <cstdint>

#include "core/math/vec3.h"

namespace f2 {

/// The most shadow samples per side of a light's grid (256 shadow rays per
/// light and hit): beyond that a frame costs seconds, not milliseconds.
inline constexpr int kMaxShadowSamplesPerSide = 16;

/// A light's extent for soft shadows: a disc sampled by a fixed grid of
/// samplesPerSide x samplesPerSide points. samplesPerSide 0: a hard shadow.
struct SoftShadow {
    /// Point and spot lights: the disc's diameter (scene units); the sun: its
    /// angular radius (degrees).
    float size = 0;
    int samplesPerSide = 0;
    bool soft() const { return samplesPerSide > 0; }
    friend bool operator==(const SoftShadow&, const SoftShadow&) = default;
};

/// POV-Ray's fade_distance / fade_power: intensity * 2 / (1 + (d / distance)^power)
/// at distance d from the light. power 0: no falloff.
struct Fade {
    float distance = 0;
    float power = 0;
    bool fades() const { return power > 0; }
    friend bool operator==(const Fade&, const Fade&) = default;
};

/// A light without a name (SPEC 10.2): it stays where its numbers put it.
inline constexpr std::int32_t kStillLight = -1;

enum class LocalLightKind : std::uint8_t { Point, Spot };

/// `/point_light` or `/spot_light`: a light at a position.
struct LocalLight {
    LocalLightKind kind = LocalLightKind::Point;
    float intensity = 0;
    Vec3 position;
    // Spot lights only (POV-Ray's spotlight): the direction the light travels
    // along its axis, the cone's full-intensity and zero-intensity half-angles
    // (degrees) and the tightness exponent.
    Vec3 direction;
    float radius = 0, falloff = 0, tightness = 0;
    Fade fade;
    SoftShadow area;
    std::int32_t motion = kStillLight;  ///< SceneDesc::lightMotions index of a named light
};

}  // namespace f2

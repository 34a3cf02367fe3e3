#pragma once
/// The lights of a frame (EvaluatedFrame::lights, localLights and their
/// sample patterns) from the scene's light commands, and the geometry of the
/// soft-shadow discs that both shading paths share.
#include <cmath>

#include "core/anim/evaluated_frame.h"

namespace f2 {

/// Fills frame.ambient, lights, sunDirections, localLights and discPoints
/// from `scene` at time `t` (frames), keeping the vectors' capacity. Named
/// lights (SPEC 10.2) are moved by their pose and attachment and take their
/// keyed intensity.
void evaluateLights(const SceneDesc& scene, double t, EvaluatedFrame& frame);

/// The scene's ambient intensity at time t: the unnamed `/amb_light`s and the
/// named ones at their keyed intensity.
float ambientAt(const SceneDesc& scene, double t);

/// The frame a named light's numbers are read in at time t (SPEC 10.2):
/// worldFrom(its mount) · pose, or pose when it rides on nothing.
Transform lightFrameAt(const SceneDesc& scene, const LightMotion& motion, double t);

/// A light's intensity at time t: its `intensity` track (SPEC 10.3), never
/// below 0 (an overshooting easing would go there), else `written`.
float lightIntensityAt(const SceneDesc& scene, std::int32_t motion, float written, double t);

/// A light's position and direction in world space at time t: as written for
/// a light without a name, else through lightFrameAt.
struct PlacedLight {
    Vec3 position, direction;
};
PlacedLight placeLight(const SceneDesc& scene, std::int32_t motion, Vec3 position, Vec3 direction, double t);

/// The fixed pattern of an n x n soft-shadow grid on a unit-diameter disc,
/// appended to `out`: POV-Ray's `area_light ... n, n circular`, whose grid
/// point (i, j) is s = i/(n-1) - 1/2 + 0.001, t = j/(n-1) - 1/2 + 0.001, pushed
/// out to the circle through it: (s, t) * max(|s|, |t|) / |(s, t)|.
void appendDiscPattern(int n, std::vector<DiscPoint>& out);

/// Two axes of the disc of a light seen along `toLight` (unit): perpendicular
/// to it and to each other, unit length. POV-Ray's `orient`: a = toLight x z
/// (x y when toLight is within 0.01 of the z axis), b = toLight x a.
struct DiscAxes {
    Vec3 a, b;
};
inline DiscAxes discAxes(Vec3 toLight) {
    const bool nearZ = std::fabs(std::fabs(toLight.z) - 1.0f) < 0.01f;
    const Vec3 helper = nearZ ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    const Vec3 a = normalize(cross(toLight, helper));
    return {a, normalize(cross(toLight, a))};
}

/// POV-Ray's spotlight falloff: 1 inside the cone of `cosRadius`, 0 outside
/// that of `cosFalloff`, (3 - 2x) x^2 between, with x going from 0 to 1.
inline float spotFalloff(float cosFalloff, float cosRadius, float cosAngle) {
    if (cosAngle < cosFalloff) return 0.0f;
    if (cosAngle >= cosRadius) return 1.0f;
    const float x = (cosAngle - cosFalloff) / (cosRadius - cosFalloff);
    return (3.0f - 2.0f * x) * x * x;
}

/// What reaches a point at `distance` from `light` whose direction seen from
/// the light makes cosAngle with a spot's axis: intensity times the spot's
/// cone (cosAngle^tightness and spotFalloff) and fade. 0 outside a spot's cone.
inline float localLightIntensity(const LocalLightSample& light, float cosAngle, float distance) {
    float scale = 1.0f;
    if (light.spot) {
        if (!(cosAngle > 0.0f)) return 0.0f;
        if (light.tightness > 0) scale = std::pow(cosAngle, light.tightness);
        if (light.cosRadius > 0 && cosAngle < light.cosRadius)
            scale = scale * spotFalloff(light.cosFalloff, light.cosRadius, cosAngle);
    }
    if (light.fade.fades())
        scale = scale * (2.0f / (1.0f + std::pow(distance / light.fade.distance, light.fade.power)));
    return light.intensity * scale;
}

}  // namespace f2

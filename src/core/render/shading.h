#pragma once
/// Phong shading with one shadow ray per directional light (SPEC 3), and the
/// point, spot and soft lights of docs/rendering.md.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/render/checker.h"
#include "core/render/light_sampling.h"
#include "core/render/prepared_frame.h"

namespace f2 {

/// Shadow rays start this far off the surface, relative to the hit point's
/// magnitude, so a surface never shadows itself (float spacing grows with it).
inline constexpr float kShadowBias = 5e-5f;

inline float shadowOffset(Vec3 p) {
    Vec3 a = vabs(p);
    return kShadowBias * (1.0f + std::max(std::max(a.x, a.y), a.z));
}

/// Primary rays ignore hits nearer than this: with the eye exactly on a
/// surface, roots at t ~ 0 would otherwise fall either side of 0 by rounding
/// and speckle the image; this way they consistently count as behind the eye.
inline float primaryRayStart(Vec3 eye) { return shadowOffset(eye); }

/// Light terms are capped at the largest float before they meet a factor that
/// may be 0 (a black channel, a highlight's pow() that underflows): huge
/// materials and lights then saturate as they should, instead of 0 * inf = NaN
/// (a black pixel). Finite values pass unchanged, so images do not move.
inline constexpr float kMaxLight = std::numeric_limits<float>::max();

/// Where a ray's nearest hit is shaded from: the point, the normal turned to
/// face the viewer, and where its shadow rays start.
struct ShadingPoint {
    Vec3 position;
    Vec3 normal;          ///< unit, facing the viewer
    bool inside = false;  ///< the hit was seen from within its primitive
    /// Primitive the shadow rays skip: their own, except from the inside.
    std::uint32_t skip = Bvh::kNoPrimitive;
    Vec3 shadowOrigin;  ///< position lifted off the surface (kShadowBias)
};

inline ShadingPoint shadingPoint(const PreparedFrame& frame, const Ray& ray, const HitRecord& hit) {
    ShadingPoint s;
    s.position = ray.origin + ray.direction * hit.t;
    Vec3 n = primitiveNormal(frame.primitives[hit.primitive], s.position, hit.face);
    s.inside = dot(n, ray.direction) > 0;  // seen from within the primitive
    s.normal = s.inside ? -n : n;          // face the viewer
    // A shadow ray leaving a convex primitive's outside never meets it again,
    // so it skips that primitive; from the inside it must not.
    s.skip = s.inside ? Bvh::kNoPrimitive : hit.primitive;
    s.shadowOrigin = s.position + s.normal * shadowOffset(s.position);
    return s;
}

/// The sum shading starts from before any light: ka · ambient, plus a glow
/// (SPEC 10.8 `emit`), which adding 0 leaves bit for bit as it was.
inline float unlitSum(const Material& m, float ambient) { return m.ka * ambient + m.emission; }

/// One light's part in shading a point, as shadeHit() computed it.
struct LightTerm {
    std::size_t light = 0;       ///< PreparedFrame::lights, then localLights (index - lights.size())
    Vec3 toLight;                ///< unit, toward the light (its centre)
    float distance = kInfinity;  ///< to a point or spot light's centre
    float intensity = 0;         ///< what arrives, before shadows: after a spot's cone and fade
    float nDotL = 0;             ///< <= 0: the surface faces away, no shadow ray
    float visible = 1;           ///< fraction of the light's shadow samples that reach it
    std::uint32_t rays = 0;      ///< shadow rays cast
    bool shadowed = false;       ///< none did
    float diffuse = 0;           ///< intensity * visible * kd * N.L (0 unless lit)
    float specular = 0;          ///< intensity * visible * ks * (R.V)^n (0 unless lit and R.V > 0)
};

/// Adds a lit light's diffuse and specular terms (SPEC 3) to the sums.
inline void addPhong(LightTerm& term, const Material& m, Vec3 n, Vec3 toEye, float& diffuse,
                     float& specular) {
    const float intensity = term.intensity * term.visible;
    term.diffuse = intensity * m.kd * term.nDotL;
    diffuse += term.diffuse;
    Vec3 reflected = n * (2 * term.nDotL) - term.toLight;
    float rDotV = dot(reflected, toEye);
    if (rDotV > 0 && m.ks > 0) {
        term.specular = std::min(intensity * m.ks, kMaxLight) * std::pow(rDotV, m.n);
        specular += term.specular;
    }
}

/// Colour (0..1, unclamped) of the nearest hit `hit` of `ray`; onLight(term)
/// sees each light's LightTerm (the --pixel report); the shadow rays'
/// traversals add their work to `count` (TraversalCount: the cost view).
template <class OnLight, class Count>
inline Vec3 shadeHit(const PreparedFrame& frame, const Ray& ray, const HitRecord& hit, OnLight&& onLight,
                     Count& count) {
    const Surface& surface = frame.surfaces[hit.primitive];
    const Material& m = surface.material;
    const ShadingPoint s = shadingPoint(frame, ray, hit);
    const Vec3 n = s.normal;
    Vec3 toEye = -ray.direction;

    float diffuse = unlitSum(m, frame.ambient);
    float specular = 0;
    for (std::size_t i = 0; i < frame.lights.size(); ++i) {
        const LightSample& light = frame.lights[i];
        LightTerm term;
        term.light = i;
        term.toLight = light.toLight;
        term.intensity = light.intensity;
        term.nDotL = dot(n, light.toLight);
        if (term.nDotL > 0) {
            if (light.sampleCount == 0) {
                term.rays = 1;
                term.shadowed =
                    frame.bvh.occluded({s.shadowOrigin, light.toLight}, 0.0f, kInfinity, s.skip, count);
            } else {
                const SampledShadow shadow =
                    visibleSunSamples(frame, light, s.shadowOrigin, n, s.skip, count);
                term.rays = shadow.rays;
                term.visible = float(shadow.visible) / float(light.sampleCount);
                term.shadowed = shadow.visible == 0;
            }
            if (!term.shadowed) addPhong(term, m, n, toEye, diffuse, specular);
        }
        onLight(term);
    }
    for (std::size_t j = 0; j < frame.localLights.size(); ++j) {
        const LocalLightSample& light = frame.localLights[j];
        const LocalLightView view = viewLocalLight(light, s.shadowOrigin);
        LightTerm term;
        term.light = frame.lights.size() + j;
        term.toLight = view.toLight;
        term.distance = view.distance;
        term.nDotL = dot(n, view.toLight);
        if (term.nDotL > 0) {
            term.intensity = localLightIntensity(light, -dot(view.toLight, light.axis), view.distance);
            if (term.intensity > 0) {
                if (light.sampleCount == 0) {
                    term.rays = 1;
                    term.shadowed = localLightBlocked(frame, light, view, s.skip, count);
                } else {
                    const SampledShadow shadow =
                        visibleDiscSamples(frame, light, view, s.shadowOrigin, n, s.skip, count);
                    term.rays = shadow.rays;
                    term.visible = float(shadow.visible) / float(light.sampleCount);
                    term.shadowed = shadow.visible == 0;
                }
                if (!term.shadowed) addPhong(term, m, n, toEye, diffuse, specular);
            }
        }
        onLight(term);
    }
    const Vec3 outward = s.inside ? -n : n;
    const Vec3 color = surfaceColorAt(surface, frame.primitives[hit.primitive], s.position, outward,
                                      shadowOffset(s.position));
    return color * std::min(diffuse, kMaxLight) + Vec3{specular, specular, specular};
}

template <class OnLight>
inline Vec3 shadeHit(const PreparedFrame& frame, const Ray& ray, const HitRecord& hit, OnLight&& onLight) {
    NoTraversalCount none;
    return shadeHit(frame, ray, hit, onLight, none);
}

inline Vec3 shadeHit(const PreparedFrame& frame, const Ray& ray, const HitRecord& hit) {
    return shadeHit(frame, ray, hit, [](const LightTerm&) {});
}

/// floor(255 * clamp(v) + 0.5)
inline std::uint8_t toByte(float v) {
    v = std::clamp(v, 0.0f, 1.0f);  // NaN-safe: clamp keeps NaN, so test below
    return v == v ? std::uint8_t(std::floor(255.0f * v + 0.5f)) : 0;
}

}  // namespace f2

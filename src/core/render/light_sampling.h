#pragma once
/// Shadow tests of soft suns and of point and spot lights, single-ray
/// reference path (docs/rendering.md, "Point and spot lights", "Soft
/// shadows"). packet_light_sampling.h is the lane version, operation for
/// operation.
#include "core/anim/light_evaluation.h"
#include "core/render/prepared_frame.h"

namespace f2 {

/// Of a soft light's shadow samples: how many reach the light, and how many
/// shadow rays were cast (samples below the surface's horizon cast none).
struct SampledShadow {
    std::uint32_t visible = 0, rays = 0;
};

/// How many of a soft sun's sample directions reach it from the shadow
/// origin `origin` of a surface with normal `normal` (skipping `skip`): a
/// direction below the surface's horizon (N·L_k <= 0) does not.
template <class Count>
inline SampledShadow visibleSunSamples(const PreparedFrame& frame, const LightSample& light, Vec3 origin,
                                       Vec3 normal, std::uint32_t skip, Count& count) {
    SampledShadow shadow;
    for (std::uint32_t k = 0; k < light.sampleCount; ++k) {
        const Vec3 toSample = frame.sunDirections[light.firstSample + k];
        if (!(dot(normal, toSample) > 0)) continue;
        ++shadow.rays;
        if (!frame.bvh.occluded({origin, toSample}, 0.0f, kInfinity, skip, count)) ++shadow.visible;
    }
    return shadow;
}

/// Where a point or spot light is seen from a shadow origin.
struct LocalLightView {
    Vec3 toLight;    ///< unit, toward the light's centre
    float distance;  ///< to the light's centre
};

inline LocalLightView viewLocalLight(const LocalLightSample& light, Vec3 origin) {
    const Vec3 v = light.position - origin;
    const float distance = std::sqrt(dot(v, v));
    return {v / distance, distance};
}

/// Whether anything lies between a point or spot light's centre and
/// `origin`: one ray from the light toward the point (all the rays of a
/// packet then leave one place), ending at the point.
template <class Count>
inline bool localLightBlocked(const PreparedFrame& frame, const LocalLightSample& light,
                              const LocalLightView& view, std::uint32_t skip, Count& count) {
    return frame.bvh.occluded({light.position, -view.toLight}, 0.0f, view.distance, skip, count);
}

/// How many samples of a soft point or spot light's disc reach `origin`: the
/// disc faces the point (discAxes), and a sample below the surface's horizon
/// does not count. Rays go from each sample to the point.
template <class Count>
inline SampledShadow visibleDiscSamples(const PreparedFrame& frame, const LocalLightSample& light,
                                        const LocalLightView& view, Vec3 origin, Vec3 normal,
                                        std::uint32_t skip, Count& count) {
    const DiscAxes axes = discAxes(view.toLight);
    const Vec3 a = axes.a * light.diameter, b = axes.b * light.diameter;
    SampledShadow shadow;
    for (std::uint32_t k = 0; k < light.sampleCount; ++k) {
        const DiscPoint d = frame.discPoints[light.firstSample + k];
        const Vec3 sample = light.position + a * d.u + b * d.v;
        const Vec3 w = origin - sample;
        const float length = std::sqrt(dot(w, w));
        const Vec3 direction = w / length;
        if (!(dot(normal, direction) < 0)) continue;
        ++shadow.rays;
        if (!frame.bvh.occluded({sample, direction}, 0.0f, length, skip, count)) ++shadow.visible;
    }
    return shadow;
}

}  // namespace f2

#pragma once
/// A scene evaluated at one time: every primitive in world space with its
/// surface, and the lights. What animation produces; render adds the BVH
/// (PreparedFrame). Refilled in place each frame; its vectors keep their
/// capacity so steady-state frames do not allocate.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/anim/track.h"
#include "core/geometry/primitive.h"
#include "core/math/transform.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct AnimationProgram;  // animation_program.h

/// Shading inputs of one primitive.
struct Surface {
    Vec3 color;  ///< 0..1
    Material material;
    Vec3 checkerColor;         ///< 0..1, the second colour of `/checker`
    float checkerSize = 0.0f;  ///< the cells' side in the primitive's frame; 0: plain `color`
};

/// A directional light at this frame.
struct LightSample {
    Vec3 toLight;  ///< L = -normalize(direction of travel)
    float intensity;
    /// A soft sun: its shadow rays go toward EvaluatedFrame::sunDirections
    /// [firstSample, firstSample + sampleCount); 0 samples: one ray along toLight.
    std::uint32_t firstSample = 0, sampleCount = 0;
};

/// A point on a light's disc, each coordinate in [-1/2, 1/2] of its diameter.
struct DiscPoint {
    float u, v;
};

/// A point or spot light at this frame (SceneDesc::localLights, with the
/// values shading needs worked out once).
struct LocalLightSample {
    Vec3 position;
    float intensity = 0;
    bool spot = false;
    Vec3 axis;  ///< spot: unit direction the light travels
    float cosRadius = 0, cosFalloff = 0, tightness = 0;
    Fade fade;
    float diameter = 0;  ///< of the disc its soft shadows sample (0: hard)
    /// Soft shadows: EvaluatedFrame::discPoints [firstSample, firstSample + sampleCount).
    std::uint32_t firstSample = 0, sampleCount = 0;
};

/// Primitives are in scene order: object by object, each model's shapes in
/// their fixed order. That index is what breaks ties between equal hits.
struct EvaluatedFrame {
    std::vector<Primitive> primitives;
    std::vector<Surface> surfaces;  ///< parallel to primitives
    /// Object i's primitives are [firstPrimitive[i], firstPrimitive[i + 1]).
    std::vector<std::uint32_t> firstPrimitive;
    std::vector<LightSample> lights;
    std::vector<Vec3> sunDirections;  ///< unit, toward the samples of soft suns
    std::vector<LocalLightSample> localLights;
    /// Per primitive, its ray_mask flags (`/no_shadow`, hidden); empty when
    /// no primitive has one. Points into the program in `filledBy` (shadows
    /// alone never change), or into `rayMaskStorage` when visibility keys
    /// change it from frame to frame.
    std::span<const std::uint8_t> rayMask;
    std::vector<std::uint8_t> rayMaskStorage;
    std::vector<DiscPoint> discPoints;  ///< the sample patterns of soft point and spot lights
    float ambient = 0;
    Vec3 background;  ///< 0..1
    /// World root frames of attached objects (SPEC 9.2), indexed by object.
    std::vector<Transform> attachedRoots;
    /// Where the time falls in each key layout of the scene's animation
    /// (AnimationProgram::segmentsAt): scratch of the evaluation.
    std::vector<TrackSegment> segments;
    /// The time (frames) the evaluation is at: driven tracks (SPEC 10.7) read it.
    double time = 0;
    /// Every drive's value at `time` (AnimationProgram::evaluateDrives), one per
    /// AnimationProgram::drives: scratch of the evaluation.
    std::vector<double> driveValues;
    /// The program that filled this frame last: when it fills it again, the
    /// surfaces and the primitives of objects that never move are in place.
    std::shared_ptr<const AnimationProgram> filledBy;
};

}  // namespace f2

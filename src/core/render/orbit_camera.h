#pragma once
/// Look-around camera of the viewer and the web page: orbits a target point in front of the
/// scene's camera. Pure math (no Qt), so it is unit-tested on its own.
#include "core/render/camera.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// Distance along the camera's view direction to orbit around: the median
/// depth of the scene's objects in front of the eye, so the pivot sits inside
/// the picture rather than at the eye or far behind the subject.
float orbitTargetDistance(const SceneDesc& scene, const Camera& camera);

/// An orbit around `target`: the eye sits `distance` away, looking at the
/// target, turned by `yawDeg` about world +y and tilted down by `pitchDeg`.
/// Roll is dropped: orbiting keeps the horizon level.
class OrbitCamera {
   public:
    /// Starts exactly where `camera` looks, with the target `targetDistance`
    /// in front of its eye.
    static OrbitCamera fromCamera(const Camera& camera, float targetDistance);

    /// Drag: turn around the target (degrees). Pitch stays within +-kMaxPitchDeg
    /// so the view never flips over the pole.
    void orbit(float yawDeltaDeg, float pitchDeltaDeg);
    /// Wheel: multiply the eye-target distance by `factor` (< 1 moves closer).
    void zoom(float factor);

    /// The camera at this orbit position with `base`'s field of view and size.
    Camera apply(const Camera& base) const;
    /// The eye and rotation (degrees, SPEC 1) as `/camera` writes them.
    Pose pose() const;

    Vec3 target() const { return target_; }
    float distance() const { return distance_; }
    float yawDeg() const { return yawDeg_; }
    float pitchDeg() const { return pitchDeg_; }

    static constexpr float kMaxPitchDeg = 89.0f;
    static constexpr float kMinDistance = 1.0f;
    static constexpr float kMaxDistance = 1.0e6f;

   private:
    Vec3 target_;
    float distance_ = 500.0f;
    float yawDeg_ = 0.0f;
    float pitchDeg_ = 0.0f;
};

}  // namespace f2

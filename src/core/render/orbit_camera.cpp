#include "core/render/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math/transform.h"

namespace f2 {

namespace {
constexpr float kFallbackTargetDistance = 500.0f;  // cm: a few metres, the scale of our models
constexpr double kDegPerRad = 180.0 / kPi;
}  // namespace

float orbitTargetDistance(const SceneDesc& scene, const Camera& camera) {
    const Vec3 forward = camera.worldFromCamera.column(2);
    std::vector<float> depths;
    depths.reserve(scene.objects.size());
    for (const SceneObject& object : scene.objects) {
        float depth = dot(object.rest.position - camera.eye, forward);
        if (depth > OrbitCamera::kMinDistance) depths.push_back(depth);
    }
    if (depths.empty()) return kFallbackTargetDistance;
    auto middle = depths.begin() + std::ptrdiff_t(depths.size() / 2);
    std::nth_element(depths.begin(), middle, depths.end());
    return std::clamp(*middle, OrbitCamera::kMinDistance, OrbitCamera::kMaxDistance);
}

OrbitCamera OrbitCamera::fromCamera(const Camera& camera, float targetDistance) {
    OrbitCamera orbit;
    const Vec3 forward = normalize(camera.worldFromCamera.column(2));
    orbit.distance_ = std::clamp(targetDistance, kMinDistance, kMaxDistance);
    orbit.target_ = camera.eye + forward * orbit.distance_;
    // forward = Ry(yaw) * Rx(pitch) * (0,0,1) = (cos p sin y, -sin p, cos p cos y) (SPEC 1).
    orbit.pitchDeg_ = float(std::asin(std::clamp(double(-forward.y), -1.0, 1.0)) * kDegPerRad);
    orbit.pitchDeg_ = std::clamp(orbit.pitchDeg_, -kMaxPitchDeg, kMaxPitchDeg);
    orbit.yawDeg_ = float(std::atan2(double(forward.x), double(forward.z)) * kDegPerRad);
    return orbit;
}

void OrbitCamera::orbit(float yawDeltaDeg, float pitchDeltaDeg) {
    yawDeg_ = float(std::remainder(double(yawDeg_) + yawDeltaDeg, 360.0));
    pitchDeg_ = std::clamp(pitchDeg_ + pitchDeltaDeg, -kMaxPitchDeg, kMaxPitchDeg);
}

void OrbitCamera::zoom(float factor) {
    if (!(factor > 0.0f)) return;
    distance_ = std::clamp(distance_ * factor, kMinDistance, kMaxDistance);
}

Camera OrbitCamera::apply(const Camera& base) const {
    Camera c = base;
    c.worldFromCamera = rotationFromEulerDegrees(pitchDeg_, yawDeg_, 0.0);
    c.eye = target_ - c.worldFromCamera.column(2) * distance_;
    return c;
}

Pose OrbitCamera::pose() const { return {apply(Camera{}).eye, {pitchDeg_, yawDeg_, 0.0f}}; }

}  // namespace f2

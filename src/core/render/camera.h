#pragma once
/// The pinhole camera of SPEC 2.
#include <optional>

#include "core/anim/camera_motion.h"
#include "core/geometry/primitive.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct Camera {
    int width = 800, height = 600;
    float distance = 0.5f;  ///< eye-to-screen distance in screen widths
    Vec3 eye;
    Mat3 worldFromCamera;  ///< R: columns are right, up, forward

    static Camera fromDesc(const CameraDesc& desc) {
        return {desc.width, desc.height, float(desc.distance), desc.pose.position,
                rotationFromEulerDegrees(desc.pose.rotation)};
    }

    /// Same view at another image size; the horizontal field of view is kept.
    Camera resized(int w, int h) const {
        Camera c = *this;
        c.width = w;
        c.height = h;
        return c;
    }

    /// Ray through image point (x, y) in pixels from the top-left corner;
    /// the centre of pixel (i, j) is (i + 0.5, j + 0.5).
    Ray rayThrough(float px, float py) const {
        float x = px * inverseWidth() - 0.5f;
        float y = (0.5f - py * inverseHeight()) * aspect();
        return {eye, worldFromCamera * normalize(Vec3{x, y, distance})};
    }

    /// The image point (pixel coordinates as rayThrough) whose ray passes
    /// through world point `p`: the inverse of rayThrough. False if `p` is
    /// not in front of the eye.
    bool project(Vec3 p, float& px, float& py) const {
        const Vec3 c = worldFromCamera.transposed() * (p - eye);
        if (!(c.z > 0)) return false;
        px = (c.x / c.z * distance + 0.5f) * float(width);
        py = (0.5f - c.y / c.z * distance / aspect()) * float(height);
        return true;
    }

    /// The pyramid from the eye through the pixel rectangle [x0, x1] x [y0, y1]
    /// (pixel coordinates as rayThrough), widened by a pixel on every side so
    /// that rounding cannot leave one of its rays outside.
    Frustum pixelFrustum(int x0, int y0, int x1, int y1) const {
        const float left = float(x0 - 1), right = float(x1 + 1), top = float(y0 - 1), bottom = float(y1 + 1);
        const Vec3 corner[4] = {rayThrough(left, top).direction, rayThrough(right, top).direction,
                                rayThrough(right, bottom).direction, rayThrough(left, bottom).direction};
        const Vec3 centre = rayThrough(0.5f * (left + right), 0.5f * (top + bottom)).direction;
        Frustum f;
        for (int i = 0; i < 4; ++i) {
            Vec3 n = cross(corner[i], corner[(i + 1) % 4]);
            if (dot(n, centre) < 0) n = -n;  // inside is where the rays are
            f.normal[i] = n;
            f.offset[i] = -dot(n, eye);
        }
        return f;
    }

    // Reciprocals, so the per-ray work multiplies instead of divides (the packet
    // path uses the same three numbers, which keeps both paths bit-identical).
    float inverseWidth() const { return 1.0f / float(width); }
    float inverseHeight() const { return 1.0f / float(height); }
    float aspect() const { return float(height) / float(width); }
};

/// The scene's camera at time `t` (frames): keys, attachment and `/look_at`
/// applied (SPEC 9.1). Every front end renders and exports through this.
inline Camera cameraAt(const SceneDesc& scene, double t) {
    const Transform worldFromCamera = cameraFrameAt(scene, t);
    return {scene.camera.width, scene.camera.height, float(cameraDistanceAt(scene, t)),
            worldFromCamera.translation, worldFromCamera.linear};
}

/// What the frames of an animation are seen through: the scene's own camera
/// at each frame's time (cameraAt) at an image size, or one fixed camera (the
/// viewer's look-around).
struct FrameView {
    int width = 800, height = 600;
    std::optional<Camera> fixed;

    /// The scene's camera, frame by frame, at width x height.
    static FrameView sceneCamera(int w, int h) { return {w, h, std::nullopt}; }
    /// `camera` for every frame, at its own size.
    static FrameView fixedCamera(const Camera& camera) { return {camera.width, camera.height, camera}; }

    Camera at(const SceneDesc& scene, double t) const {
        return fixed ? *fixed : cameraAt(scene, t).resized(width, height);
    }
};

}  // namespace f2

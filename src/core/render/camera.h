#pragma once
/// The pinhole camera of SPEC 2.
#include "core/geometry/primitive.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct Camera {
    int width = 800, height = 600;
    float distance = 0.5f;  ///< eye-to-screen distance in screen widths
    Vec3 eye;
    Mat3 worldFromCamera;   ///< R: columns are right, up, forward

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

    // Reciprocals, so the per-ray work multiplies instead of divides (the packet
    // path uses the same three numbers, which keeps both paths bit-identical).
    float inverseWidth() const { return 1.0f / float(width); }
    float inverseHeight() const { return 1.0f / float(height); }
    float aspect() const { return float(height) / float(width); }
};

}  // namespace f2

#pragma once
/// Renders a frame through Embree: square tiles spread over TBB's threads,
/// each traced as blocks of pixels in one ray packet (rtcIntersect16/8/4),
/// shaded by SPEC 3's Phong formula with a packet of shadow rays per light
/// (rtcOccluded16/8/4).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/render/image.h"
#include "prims_file.h"
#include "user_shapes.h"

namespace f2::peer {

/// Rays cast in one frame.
struct RayCounts {
    std::uint64_t primary = 0, shadow = 0;
};

class PacketRenderer {
   public:
    /// `packetWidth` 4, 8 or 16 lanes (2x2, 4x2, 4x4 pixels); `tileSize` pixels a side.
    PacketRenderer(const PrimsFrame& frame, int packetWidth, int tileSize);

    /// Traces the whole image against `scene` (committed) into image().
    RayCounts render(const UserShapeScene& scene);

    const Image& image() const { return image_; }

    /// A primitive's colour (0..1) and Phong material.
    struct Surface {
        float colour[3];
        float ka, kd, ks, shininess;
    };
    struct Light {
        float toLight[3];  ///< unit, against the direction of travel
        float intensity;
    };

   private:
    template <int W>
    void renderTile(const UserShapeScene& scene, int tile, RayCounts& counts);

    int packetWidth_, tileSize_, tilesX_, tilesY_;
    float eye_[3], camera_[3][3], distance_;
    float primaryStart_;  ///< primary rays ignore hits nearer than this
    float ambient_;
    float background_[3];
    std::vector<Light> lights_;
    std::vector<Surface> surfaces_;
    Image image_;
};

/// SPEC 3: shadow rays leave this far off the surface, relative to the hit
/// point's largest coordinate, so a surface never shadows itself. The same
/// offset as f2's, so that both renderers take the same shadow decisions.
inline float surfaceOffset(float x, float y, float z) {
    constexpr float kBias = 5e-5f;
    return kBias * (1.0f + std::max(std::max(std::fabs(x), std::fabs(y)), std::fabs(z)));
}

}  // namespace f2::peer

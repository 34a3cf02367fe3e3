#include "packet_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace f2::peer {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kMaxTile = 64;
static_assert(sizeof(Rgb8) == 3, "image rows are copied as bytes");

/// Embree's packet entry points for W lanes (4, 8 or 16), and the block of
/// pixels a packet covers: 2x2, 4x2 or 4x4.
template <int W>
struct Packet {
    static constexpr int kColumns = W == 4 ? 2 : 4, kRows = W / kColumns;

    static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<W>& r) {
        if constexpr (W == 16)
            rtcIntersect16(valid, s, c, reinterpret_cast<RTCRayHit16*>(&r));
        else if constexpr (W == 8)
            rtcIntersect8(valid, s, c, reinterpret_cast<RTCRayHit8*>(&r));
        else
            rtcIntersect4(valid, s, c, reinterpret_cast<RTCRayHit4*>(&r));
    }
    static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayNt<W>& r) {
        if constexpr (W == 16)
            rtcOccluded16(valid, s, c, reinterpret_cast<RTCRay16*>(&r));
        else if constexpr (W == 8)
            rtcOccluded8(valid, s, c, reinterpret_cast<RTCRay8*>(&r));
        else
            rtcOccluded4(valid, s, c, reinterpret_cast<RTCRay4*>(&r));
    }
};

/// floor(255 * clamp(v, 0, 1) + 0.5), 0..255; NaN gives 0. Written as
/// selects and a truncation (the same as floor for a positive value), so
/// that it vectorises.
inline int toByte(float v) {
    v = v > 0.0f ? v : 0.0f;  // NaN too
    v = v < 1.0f ? v : 1.0f;
    return int(255.0f * v + 0.5f);
}

}  // namespace

namespace {

using Surface = PacketRenderer::Surface;

/// What the primary rays of a packet found, lane by lane: everything shading
/// needs, computed for all lanes at once (the shape and surface of each lane
/// gathered by its primitive), so that the loop vectorises however many
/// primitives the packet hit.
template <int W>
struct PacketSurfaces {
    alignas(64) float normal[3][W];  ///< unit, facing the viewer
    alignas(64) float origin[3][W];  ///< shadow rays start here, off the surface
    alignas(64) float colour[3][W];
    alignas(64) float kd[W], ks[W], shininess[W];
    alignas(64) float diffuse[W], specular[W];  ///< the sums of SPEC 3, ambient first
    alignas(64) unsigned skip[W];               ///< the primitive the shadow rays skip
    alignas(64) int hit[W];

    void fill(const int* valid, const RTCRayHitNt<W>& rays, const Shape* shapes, const Surface* surfaces,
              float ambient) {
        const float* eye[3] = {rays.ray.org_x, rays.ray.org_y, rays.ray.org_z};
        const float* dir[3] = {rays.ray.dir_x, rays.ray.dir_y, rays.ray.dir_z};
#pragma omp simd
        for (int lane = 0; lane < W; ++lane) {
            hit[lane] = (valid[lane] != 0) & (rays.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID);
            // Loads unconditional (GCC does not vectorise masked ones here);
            // lanes without a hit read primitive 0, and their values go unused.
            const unsigned hitPrim = rays.hit.primID[lane];
            const unsigned prim = hit[lane] ? hitPrim : 0;
            const Shape& s = shapes[prim];
            const Surface& surface = surfaces[prim];
            const float t = rays.ray.tfar[lane];
            const int face = int(rays.hit.u[lane]);
            float p[3], local[3], d[3];
            for (int i = 0; i < 3; ++i) {
                d[i] = dir[i][lane];
                p[i] = eye[i][lane] + d[i] * t;
                local[i] = p[i] - s.centre[i];
            }
            // The unit outward normal of the face hit: a sphere's from its
            // centre, a cylinder's side across its axis, a cap's or a box
            // face's along the axis of that face.
            const float along = local[0] * s.axes[1][0] + local[1] * s.axes[1][1] + local[2] * s.axes[1][2];
            const bool cylinder = s.kind == ShapeKind::Cylinder;
            float radial[3];
            for (int i = 0; i < 3; ++i) radial[i] = cylinder ? local[i] - s.axes[1][i] * along : local[i];
            const float scale =
                1.0f / std::sqrt(radial[0] * radial[0] + radial[1] * radial[1] + radial[2] * radial[2]);
            const int flatAxis = face == kCap ? 1 : face == kCurved ? 0 : face - kSlabX;
            // The face's axis picked with bit masks, not a select: GCC would turn
            // a select into masked gathers, which it does not vectorise.
            float axis[3];
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t pick0 = flatAxis == 0 ? ~0u : 0u, pick1 = flatAxis == 1 ? ~0u : 0u;
                axis[i] =
                    std::bit_cast<float>((std::bit_cast<std::uint32_t>(s.axes[0][i]) & pick0) |
                                         (std::bit_cast<std::uint32_t>(s.axes[1][i]) & pick1) |
                                         (std::bit_cast<std::uint32_t>(s.axes[2][i]) & ~(pick0 | pick1)));
            }
            const float sign =
                local[0] * axis[0] + local[1] * axis[1] + local[2] * axis[2] >= 0 ? 1.0f : -1.0f;
            float n[3];
            for (int i = 0; i < 3; ++i) n[i] = face == kCurved ? radial[i] * scale : sign * axis[i];
            // Seen from inside the shape: the normal faces the viewer, and the
            // shadow rays must not skip the shape they start in.
            const bool inside = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0;
            for (int i = 0; i < 3; ++i) n[i] = inside ? -n[i] : n[i];
            const float offset = surfaceOffset(p[0], p[1], p[2]);
            for (int i = 0; i < 3; ++i) {
                normal[i][lane] = hit[lane] ? n[i] : 0.0f;
                origin[i][lane] = p[i] + n[i] * offset;
                colour[i][lane] = surface.colour[i];
            }
            skip[lane] = inside ? UserShapeScene::kNoSkip : prim;
            kd[lane] = surface.kd;
            ks[lane] = surface.ks;
            shininess[lane] = surface.shininess;
            diffuse[lane] = surface.ka * ambient;
            specular[lane] = 0;
        }
    }
};

}  // namespace

PacketRenderer::PacketRenderer(const PrimsFrame& frame, int packetWidth, int tileSize)
    : packetWidth_(packetWidth), tileSize_(tileSize), distance_(frame.distance), ambient_(frame.ambient) {
    if (packetWidth != 4 && packetWidth != 8 && packetWidth != 16)
        throw std::invalid_argument("packet width must be 4, 8 or 16");
    if (tileSize < 4 || tileSize > kMaxTile || tileSize % 4 != 0)
        throw std::invalid_argument("tile size must be a multiple of 4 from 4 to 64");
    image_.resize(frame.width, frame.height);
    tilesX_ = (frame.width + tileSize - 1) / tileSize;
    tilesY_ = (frame.height + tileSize - 1) / tileSize;
    for (int row = 0; row < 3; ++row) {
        eye_[row] = frame.worldFromCamera.translation(row);
        for (int col = 0; col < 3; ++col) camera_[row][col] = frame.worldFromCamera.linear(row, col);
    }
    primaryStart_ = surfaceOffset(eye_[0], eye_[1], eye_[2]);
    for (int i = 0; i < 3; ++i) background_[i] = float(frame.background[i]) / 255.0f;
    for (const DirLight& light : frame.lights) {
        const float* d = light.direction;
        const float scale = 1.0f / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        lights_.push_back({{-(d[0] * scale), -(d[1] * scale), -(d[2] * scale)}, light.intensity});
    }
    for (const PrimRecord& p : frame.prims)
        surfaces_.push_back({{float(p.rgb[0]) / 255.0f, float(p.rgb[1]) / 255.0f, float(p.rgb[2]) / 255.0f},
                             p.ka,
                             p.kd,
                             p.ks,
                             p.shininess});
}

RayCounts PacketRenderer::render(const UserShapeScene& scene) {
    std::atomic<std::uint64_t> primary{0}, shadow{0};
    tbb::parallel_for(tbb::blocked_range<int>(0, tilesX_ * tilesY_, 1),
                      [&](const tbb::blocked_range<int>& range) {
                          RayCounts counts;
                          for (int tile = range.begin(); tile != range.end(); ++tile) {
                              switch (packetWidth_) {
                                  case 16:
                                      renderTile<16>(scene, tile, counts);
                                      break;
                                  case 8:
                                      renderTile<8>(scene, tile, counts);
                                      break;
                                  default:
                                      renderTile<4>(scene, tile, counts);
                                      break;
                              }
                          }
                          primary += counts.primary;
                          shadow += counts.shadow;
                      });
    return {primary.load(), shadow.load()};
}

template <int W>
void PacketRenderer::renderTile(const UserShapeScene& scene, int tile, RayCounts& counts) {
    using P = Packet<W>;
    const int width = image_.width, height = image_.height;
    const int x0 = (tile % tilesX_) * tileSize_, y0 = (tile / tilesX_) * tileSize_;
    const int x1 = std::min(x0 + tileSize_, width), y1 = std::min(y0 + tileSize_, height);
    // The camera of SPEC 2, with the same float operations as f2's.
    const float inverseWidth = 1.0f / float(width), inverseHeight = 1.0f / float(height);
    const float aspect = float(height) / float(width);

    // Pixels go to a tile-local buffer first: neighbouring tiles share cache
    // lines of the image, which threads would otherwise pass back and forth.
    alignas(64) std::uint8_t local[kMaxTile * kMaxTile * 3];

    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;

    for (int by = y0; by < y1; by += P::kRows) {
        for (int bx = x0; bx < x1; bx += P::kColumns) {
            // Primary rays of the block.
            alignas(64) RTCRayHitNt<W> rays;
            alignas(64) int valid[W];
#pragma omp simd
            for (int lane = 0; lane < W; ++lane) {
                const int px = bx + lane % P::kColumns, py = by + lane / P::kColumns;
                valid[lane] = (px < x1) & (py < y1) ? -1 : 0;
                const float x = (float(px) + 0.5f) * inverseWidth - 0.5f;
                const float y = (0.5f - (float(py) + 0.5f) * inverseHeight) * aspect;
                const float scale = 1.0f / std::sqrt(x * x + y * y + distance_ * distance_);
                const float vx = x * scale, vy = y * scale, vz = distance_ * scale;
                rays.ray.org_x[lane] = eye_[0];
                rays.ray.org_y[lane] = eye_[1];
                rays.ray.org_z[lane] = eye_[2];
                rays.ray.tnear[lane] = primaryStart_;
                rays.ray.dir_x[lane] = camera_[0][0] * vx + camera_[0][1] * vy + camera_[0][2] * vz;
                rays.ray.dir_y[lane] = camera_[1][0] * vx + camera_[1][1] * vy + camera_[1][2] * vz;
                rays.ray.dir_z[lane] = camera_[2][0] * vx + camera_[2][1] * vy + camera_[2][2] * vz;
                rays.ray.time[lane] = 0;
                rays.ray.tfar[lane] = kInf;
                rays.ray.mask[lane] = ~0u;
                rays.ray.id[lane] = 0;
                rays.ray.flags[lane] = 0;
                rays.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
                rays.hit.primID[lane] = RTC_INVALID_GEOMETRY_ID;
            }
            for (int lane = 0; lane < W; ++lane) counts.primary += valid[lane] != 0;
            P::intersect(valid, scene.handle(), &context, rays);

            // The surface each lane found, lifted off for its shadow rays.
            PacketSurfaces<W> surf;
            surf.fill(valid, rays, &scene.shape(0), surfaces_.data(), ambient_);

            // One packet of shadow rays per light, for the lanes it faces.
            for (const Light& light : lights_) {
                alignas(64) RTCRayNt<W> shadowRays;
                alignas(64) int lit[W];
                alignas(64) float nDotL[W];
                int active = 0;
#pragma omp simd reduction(+ : active)
                for (int lane = 0; lane < W; ++lane) {
                    nDotL[lane] = surf.normal[0][lane] * light.toLight[0] +
                                  surf.normal[1][lane] * light.toLight[1] +
                                  surf.normal[2][lane] * light.toLight[2];
                    lit[lane] = (surf.hit[lane] != 0) & (nDotL[lane] > 0) ? -1 : 0;
                    active += lit[lane] & 1;
                    shadowRays.org_x[lane] = surf.origin[0][lane];
                    shadowRays.org_y[lane] = surf.origin[1][lane];
                    shadowRays.org_z[lane] = surf.origin[2][lane];
                    shadowRays.tnear[lane] = 0;
                    shadowRays.dir_x[lane] = light.toLight[0];
                    shadowRays.dir_y[lane] = light.toLight[1];
                    shadowRays.dir_z[lane] = light.toLight[2];
                    shadowRays.time[lane] = 0;
                    shadowRays.tfar[lane] = kInf;
                    shadowRays.mask[lane] = ~0u;
                    shadowRays.id[lane] = surf.skip[lane];
                    shadowRays.flags[lane] = 0;
                }
                if (active == 0) continue;
                counts.shadow += unsigned(active);
                P::occluded(lit, scene.handle(), &context, shadowRays);

                // Lit lanes (facing the light, not in shadow) add its terms;
                // the highlight's power only where it is needed.
                alignas(64) float rDotV[W];
                alignas(64) int shiny[W];
                int anyShiny = 0;
#pragma omp simd reduction(| : anyShiny)
                for (int lane = 0; lane < W; ++lane) {
                    const bool reached = (lit[lane] != 0) & (shadowRays.tfar[lane] >= 0);
                    surf.diffuse[lane] += reached ? light.intensity * surf.kd[lane] * nDotL[lane] : 0.0f;
                    const float twice = 2 * nDotL[lane];
                    rDotV[lane] = (surf.normal[0][lane] * twice - light.toLight[0]) * -rays.ray.dir_x[lane] +
                                  (surf.normal[1][lane] * twice - light.toLight[1]) * -rays.ray.dir_y[lane] +
                                  (surf.normal[2][lane] * twice - light.toLight[2]) * -rays.ray.dir_z[lane];
                    shiny[lane] = reached & (rDotV[lane] > 0) & (surf.ks[lane] > 0);
                    anyShiny |= shiny[lane];
                }
                if (!anyShiny) continue;
                for (int lane = 0; lane < W; ++lane)
                    if (shiny[lane])
                        surf.specular[lane] +=
                            light.intensity * surf.ks[lane] * std::pow(rDotV[lane], surf.shininess[lane]);
            }

            // SPEC 3's sum, clamped and rounded to bytes (kept in ints, which
            // the vectoriser converts to in one step).
            alignas(64) int bytes[3][W];
#pragma omp simd
            for (int lane = 0; lane < W; ++lane) {
                for (int i = 0; i < 3; ++i) {
                    const float shaded = surf.colour[i][lane] * surf.diffuse[lane] + surf.specular[lane];
                    bytes[i][lane] = toByte(surf.hit[lane] ? shaded : background_[i]);
                }
            }
            for (int lane = 0; lane < W; ++lane) {
                if (valid[lane] == 0) continue;
                const int px = bx + lane % P::kColumns - x0, py = by + lane / P::kColumns - y0;
                std::uint8_t* out = &local[(py * tileSize_ + px) * 3];
                for (int i = 0; i < 3; ++i) out[i] = std::uint8_t(bytes[i][lane]);
            }
        }
    }
    for (int y = y0; y < y1; ++y)
        std::memcpy(&image_.at(x0, y), &local[(y - y0) * tileSize_ * 3], sizeof(Rgb8) * std::size_t(x1 - x0));
}

}  // namespace f2::peer

#pragma once
/// The body of a POV-Ray 3.7 scene (settings, background, camera, lights,
/// shapes) from what never changes — shape kinds and sizes, finishes, light
/// kinds — and the values that may change with time, given as SDL
/// expressions. The single-frame export (pov_export.h) gives them as numbers;
/// the animation export (pov_animation.h) as numbers where they hold over the
/// whole animation, else as clock-driven expressions. One writer, so the two
/// exports cannot drift apart.
#include <string>
#include <vector>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"
#include "io/frame_primitives.h"

namespace f2 {

/// A light's changing values: `location` and `pointAt` vectors, `intensity` a
/// float, `areaA`/`areaB` the area light's axes (soft lights only), `note` a
/// comment (suns: the direction they travel along).
struct PovLightValues {
    std::string location, pointAt, intensity, areaA, areaB, note;
};

/// A shape's changing values: `transform` a `matrix <…>` (or `transform {…}`),
/// `colour` a vector in 0..1, `ambient` a float, `visible` a float (0 or 1;
/// "1" writes no test, "0" leaves the shape out).
struct PovShapeValues {
    std::string transform, colour, ambient, visible;
};

/// Every changing value of a scene, in the order of scene.lights,
/// scene.localLights and the primitives. `ambient` is the scene's level, which
/// each shape's `ambient` (ka times it) carries.
struct PovValues {
    std::string eye, right, up, direction, ambient;
    std::vector<PovLightValues> suns, locals;
    std::vector<PovShapeValues> shapes;
};

/// The box directional lights are placed beyond (POV-Ray casts no shadow from
/// objects behind a light's location): the camera and every shape.
struct PovBounds {
    Vec3 lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
    void grow(const Camera& camera, const std::vector<PlacedPrimitive>& prims);
    Vec3 centre() const { return (lo + hi) * 0.5f; }
    float far() const { return length(hi - lo) * 2 + 1000; }
};

/// `<x, y, z>` (formatNumber).
std::string povVector(Vec3 v);

/// The values at time t (frames) as numbers: `prims` are framePrimitives at t
/// (with their hidden shapes when kept), `camera` the camera at t.
PovValues povValuesAt(const SceneDesc& scene, double t, const Camera& camera,
                      const std::vector<PlacedPrimitive>& prims, const PovBounds& bounds);

/// The scene after its header: `prims` give each shape's kind, size, label,
/// finish and pattern (their transforms and colours are taken from `values`).
std::string povSceneBody(const SceneDesc& scene, const std::vector<PlacedPrimitive>& prims,
                         const PovValues& values);

}  // namespace f2

#pragma once
/// The parsed scene: what the file says, before any animation is evaluated.
/// Produced by the parser, evaluated at a time by anim/frame_builder; plain
/// data, no behaviour.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math/vec3.h"

namespace f2 {

/// Position and rotation (degrees), the six numbers of a creating command or a key.
struct Pose {
    Vec3 position;
    Vec3 rotation;
    friend bool operator==(const Pose&, const Pose&) = default;
};

struct Color8 {
    std::uint8_t r = 200, g = 200, b = 200;
    friend bool operator==(const Color8&, const Color8&) = default;
};

/// Phong coefficients (SPEC 3), default `1 1 0.3 32`.
struct Material {
    float ka = 1.0f, kd = 1.0f, ks = 0.3f, n = 32.0f;
    friend bool operator==(const Material&, const Material&) = default;
};

struct Appearance {
    Color8 color;
    Material material;
};

enum class Interpolation : std::uint8_t { Linear, Ease, Spline };

struct Key {
    int frame = 0;
    Pose pose;
};

/// Key frames of one target (an object or one part), sorted by frame, unique frames.
struct Track {
    std::vector<Key> keys;
    Interpolation interpolation = Interpolation::Linear;
};

enum class ObjectKind : std::uint8_t { Sphere, Cylinder, Box, Robot, Human };

inline bool isModel(ObjectKind k) { return k == ObjectKind::Robot || k == ObjectKind::Human; }

/// Parts of a model (SPEC 5), in a fixed order used to index arrays.
enum class PartId : std::uint8_t { Body, Head, LHand, RHand };
inline constexpr int kPartCount = 4;
inline constexpr std::array<const char*, kPartCount> kPartNames = {"body", "head", "lhand", "rhand"};

/// One named object of the scene: a primitive, a robot or a human.
struct SceneObject {
    std::string name;
    ObjectKind kind = ObjectKind::Sphere;
    /// Sphere: (r, 0, 0); cylinder: (r, h, 0); box: (sx, sy, sz); models: unused.
    Vec3 size;
    Pose rest;
    /// Object's own key frames (absolute pose).
    Track track;
    /// Primitives use appearance[0]; models one per part (indexed by PartId).
    std::array<Appearance, kPartCount> appearance{};
    /// Models only: per-part key frames (offset and rotation about the pivot).
    std::array<Track, kPartCount> partTracks{};
};

struct CameraDesc {
    int width = 800, height = 600;
    double distance = 0.5;  ///< eye-to-screen distance in screen widths (SPEC 2)
    Pose pose;
};

struct DirectionalLight {
    float intensity = 0;
    Vec3 direction;  ///< the direction the light travels, as written
};

struct SceneDesc {
    CameraDesc camera;
    float ambient = 0;  ///< sum of all /amb_light
    std::vector<DirectionalLight> lights;
    Color8 background{0, 0, 0};
    int fps = 24;
    std::vector<SceneObject> objects;

    /// Last frame of the animation: the largest key frame of the scene (0 if none).
    int lastFrame() const;
    /// Number of primitives after expanding models (robot 6, human 4).
    std::size_t primitiveCount() const;
};

}  // namespace f2

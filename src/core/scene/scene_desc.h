#pragma once
/// The parsed scene: what the file says, before any animation is evaluated.
/// Produced by the parser, evaluated at a time by anim/frame_builder; plain
/// data, no behaviour (besides the cache of its animation compiled for
/// evaluation, SceneDesc::animation).
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math/vec3.h"
#include "core/scene/drive.h"
#include "core/scene/light_desc.h"

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

/// Phong coefficients (SPEC 3), default `1 1 0.3 32`, and the mirror
/// reflection coefficient of `/material`'s optional sixth argument (default 0:
/// no reflected ray; docs/rendering.md).
struct Material {
    float ka = 1.0f, kd = 1.0f, ks = 0.3f, n = 32.0f;
    float reflection = 0.0f;
    /// `emit e` (SPEC 10.8): e · C joins the colour whatever the lights, as
    /// POV-Ray's `finish { emission e }`.
    float emission = 0.0f;
    friend bool operator==(const Material&, const Material&) = default;
};

/// `/checker`: the second colour of a checker pattern and its cell size in
/// the primitive's own frame; size 0 = a plain colour (docs/rendering.md).
struct Checker {
    Color8 color{0, 0, 0};
    float size = 0.0f;
    friend bool operator==(const Checker&, const Checker&) = default;
};

struct Appearance {
    Color8 color;
    Material material;
    Checker checker;
    bool castsShadow = true;  ///< false after `/no_shadow` (SPEC 10.8): seen and reflected, no shadow
};

/// How a target moves from one key to the next (SPEC 6 and 9.3; back,
/// elastic, bounce and bezier are SPEC 10.4's).
enum class Interpolation : std::uint8_t {
    Linear,
    Ease,
    Spline,
    EaseIn,
    EaseOut,
    Step,
    Back,
    Elastic,
    Bounce,
    Bezier
};

/// The mode's word in the scene language ("linear", "ease_in", ...).
std::string_view interpolationName(Interpolation mode);

/// `bezier x1 y1 x2 y2` (SPEC 10.4): CSS's cubic-bezier, the curve from (0, 0)
/// to (1, 1) with control points (x1, y1) and (x2, y2), x1 and x2 in [0, 1].
struct BezierCurve {
    float x1 = 0, y1 = 0, x2 = 1, y2 = 1;
    friend bool operator==(const BezierCurve&, const BezierCurve&) = default;
};

/// A mode with what it needs: the curve, for `bezier` (unused by the others).
/// Converts from a plain mode, so `track.interpolation = Interpolation::Ease`.
struct Easing {
    Interpolation mode = Interpolation::Linear;
    BezierCurve curve{};

    Easing() = default;
    Easing(Interpolation m, BezierCurve c = {}) : mode(m), curve(c) {}  // NOLINT: implicit on purpose
    friend bool operator==(const Easing&, const Easing&) = default;
};

struct Key {
    /// The key's time in frames (SPEC 10.4: may be fractional, written in
    /// frames or seconds; seconds are converted with the scene's `/fps`).
    double time = 0;
    Pose pose;
    /// The key's own mode word (SPEC 9.3), if it has one: how the target moves
    /// from this key to the next. Without one the track's `interpolation` holds.
    std::optional<Easing> mode = std::nullopt;
};

/// Key frames of one target (an object, one part, a named light or the
/// camera), sorted by time, unique times. A property's track (SPEC 10.3:
/// colour, intensity, the camera's d) keeps its values in the keys'
/// `pose.position` (r g b, or the one value in x) and zero rotations, so
/// that it is interpolated exactly as a pose is.
struct Track {
    std::vector<Key> keys;
    Easing interpolation = Interpolation::Linear;  ///< `/interp`, for keys without a mode
    /// `/drive`s of its numbers (SPEC 10.7), which replace the keyed values; none: null.
    std::shared_ptr<const TrackDrives> drives;

    /// The mode of the segment that starts at key i.
    const Easing& modeAfter(std::size_t i) const { return keys[i].mode ? *keys[i].mode : interpolation; }
};

/// A primitive, or an instance of a model type (SPEC 10.1: the robot, the
/// human, or a `/model` of the scene).
enum class ObjectKind : std::uint8_t { Sphere, Cylinder, Box, Model };

/// "sphere", "cylinder", "box" or "model" (a model's own type name: typeNameOf, models.h).
constexpr std::string_view objectKindName(ObjectKind kind) {
    constexpr std::string_view kNames[] = {"sphere", "cylinder", "box", "model"};
    return kNames[static_cast<int>(kind)];
}

inline bool isModel(ObjectKind k) { return k == ObjectKind::Model; }

struct ModelType;  // scene/models.h

/// A frame something can ride on or look at (SPEC 9.1, 9.2): an object's root
/// frame, or the frame of one of its parts.
struct FrameRef {
    std::uint32_t object = 0;  ///< index in SceneDesc::objects
    int part = -1;             ///< index among its model's parts, or -1 for the object itself
    friend bool operator==(const FrameRef&, const FrameRef&) = default;
};

/// A change of ride (SPEC 10.7): `/attach <name> <target> at <time>`.
struct AttachChange {
    double time = 0;                ///< in frames
    std::optional<FrameRef> mount;  ///< none: `world`, the ride ends
};

/// One named object of the scene: a primitive, or an instance of a model.
struct SceneObject {
    std::string name;
    ObjectKind kind = ObjectKind::Sphere;
    /// An instance's type (kind Model); null for a primitive.
    std::shared_ptr<const ModelType> model;
    /// Sphere: (r, 0, 0); cylinder: (r, h, 0); box: (sx, sy, sz); models: unused.
    Vec3 size;
    Pose rest;
    /// Object's own key frames (absolute pose).
    Track track;
    /// One per primitive: a primitive's own, or each shape's of a model, in
    /// the model's order (SPEC 10.1: looks on the instance, a part or a shape).
    std::vector<Appearance> appearance = std::vector<Appearance>(1);
    /// Models only: each part's key frames (offset and rotation about the
    /// pivot), one per part of the model.
    std::vector<Track> partTracks;
    /// `/attach` (SPEC 9.2): the frame the object rides on from the start; its
    /// pose is then read in that frame.
    std::optional<FrameRef> attachedTo;
    /// `/attach <name> <target> at <t>` (SPEC 10.7), by increasing time (all
    /// distinct): from `time` on the object rides on `mount` (none: `world`).
    std::vector<AttachChange> attachChanges;

    /// Whether the object rides on something at some time: its root frame then
    /// comes from attachedRootFrames (anim/frame_builder.h).
    bool mayRide() const { return attachedTo || !attachChanges.empty(); }
};

/// The frame `object` rides on at time t (SPEC 9.2, 10.7): the latest
/// attachment whose time is <= t; none when it rides on nothing then.
inline std::optional<FrameRef> mountAt(const SceneObject& object, double t) {
    if (object.attachChanges.empty()) return object.attachedTo;
    const auto after = std::upper_bound(object.attachChanges.begin(), object.attachChanges.end(), t,
                                        [](double time, const AttachChange& c) { return time < c.time; });
    return after == object.attachChanges.begin() ? object.attachedTo : std::prev(after)->mount;
}

/// `/look_at` (SPEC 9.1): a fixed point, an object's origin or a part's shape centre.
struct LookAt {
    std::optional<FrameRef> target;  ///< none: the fixed `point`
    Vec3 point;
};

struct CameraDesc {
    int width = 800, height = 600;
    double distance = 0.5;  ///< eye-to-screen distance in screen widths (SPEC 2)
    Pose pose;              ///< `/camera`'s eye and rotation: the rest pose of `track`
    Track track;            ///< `/key t camera ...` (SPEC 9.1)
    Track zoom;             ///< `/key t camera d <d>` (SPEC 10.3): `distance` over time
    std::optional<FrameRef> attachedTo;
    std::optional<LookAt> lookAt;
};

struct DirectionalLight {
    float intensity = 0;
    Vec3 direction;  ///< the direction the light travels, as written (in its own frame when it moves)
    SoftShadow sun;  ///< `angle`: the sun's angular radius (degrees) and samples per side
    std::int32_t motion = kStillLight;  ///< SceneDesc::lightMotions index of a named light
};

/// A named `/amb_light` (SPEC 10.2): it has no pose, only its intensity track.
struct AmbientLight {
    float intensity = 0;
    std::uint32_t motion = 0;  ///< SceneDesc::lightMotions index
};

/// What a named light does over time (SPEC 10.2, 10.3). Its numbers (a
/// position, a direction) are read in its own frame: `pose` at time t, on
/// `attachedTo`'s frame when it rides on something.
struct LightMotion {
    std::string name;
    bool ambient = false;  ///< an `/amb_light`: no pose, no attachment
    Track track;           ///< pose keys; the identity at rest
    std::optional<FrameRef> attachedTo;
    Track intensity;  ///< `/key t <name> intensity <i>` (keys' position.x)
};

/// A property track of an object, a model part or a shape: `/key t <target>
/// colour r g b` (SPEC 10.3; keys' position: r g b, 0..255) or `/key t
/// <target> visible 0|1` (SPEC 10.7; keys' position.x, always a step).
struct TargetTrack {
    FrameRef target;
    int shape = -1;  ///< a shape of the model (`f2.head.leye`), else -1
    Track track;
};

/// `/caption` (SPEC 10.5): text drawn over the picture while `from <= t < to`.
struct Caption {
    double from = 0, to = 0;  ///< key times, in frames
    float x = 0, y = 0;       ///< the left end of its baseline, in fractions of the image (0 0: top left)
    float size = 0;           ///< the font's em, in fractions of the image height
    std::string text;         ///< valid UTF-8, escapes undone and `{ … }` expanded
    Color8 colour{255, 255, 255};

    bool shownAt(double t) const { return from <= t && t < to; }
};

struct AnimationProgram;  // anim/animation_program.h

/// Where a scene keeps the compiled form of its animation
/// (anim/animation_program.h), made by its first evaluation; thread-safe. A
/// copy starts empty: the objects of a scene must not change once it has been
/// evaluated, so a changed scene is a changed copy, compiled anew.
class AnimationCache {
   public:
    AnimationCache() = default;
    AnimationCache(const AnimationCache&) {}
    AnimationCache& operator=(const AnimationCache&) {
        set(nullptr);
        return *this;
    }
#if defined(__cpp_lib_atomic_shared_ptr)
    std::shared_ptr<const AnimationProgram> get() const { return program_.load(); }
    void set(std::shared_ptr<const AnimationProgram> program) const { program_.store(std::move(program)); }

   private:
    mutable std::atomic<std::shared_ptr<const AnimationProgram>> program_;
#else
    // libc++ 14 (the WebAssembly build) has no std::atomic<std::shared_ptr>.
    std::shared_ptr<const AnimationProgram> get() const {
        std::lock_guard lock(mutex_);
        return program_;
    }
    void set(std::shared_ptr<const AnimationProgram> program) const {
        std::lock_guard lock(mutex_);
        program_.swap(program);
    }

   private:
    mutable std::mutex mutex_;
    mutable std::shared_ptr<const AnimationProgram> program_;
#endif
};

struct SceneDesc {
    CameraDesc camera;
    float ambient = 0;                        ///< sum of the unnamed /amb_light
    std::vector<AmbientLight> namedAmbients;  ///< the named ones, whose intensity may be keyed
    std::vector<DirectionalLight> lights;
    std::vector<LocalLight> localLights;  ///< `/point_light` and `/spot_light`, in file order
    /// Named lights' names, poses and intensity tracks (SPEC 10.2), in file order.
    std::vector<LightMotion> lightMotions;
    /// Colour keys (SPEC 10.3): every whole object's track before any part's,
    /// and those before any shape's, so that applied in order the most
    /// specific target wins.
    std::vector<TargetTrack> colourTracks;
    /// Visibility keys (SPEC 10.7), in file order of their targets' first key.
    std::vector<TargetTrack> visibilityTracks;
    Color8 background{0, 0, 0};
    int fps = 24;
    std::vector<SceneObject> objects;
    /// The scene's own model types (`/model`, SPEC 10.1), in file order; the
    /// robot and the human are not among them (models.h).
    std::vector<std::shared_ptr<const ModelType>> models;
    /// Indices of the attached objects, each after the object it rides on
    /// when that one is attached too: the order in which to evaluate them.
    /// When `attachmentsChange`, every object that may ride, in index order
    /// (the order of the rides changes with time).
    std::vector<std::uint32_t> attachOrder;
    /// Some object has an `/attach … at` (SPEC 10.7).
    bool attachmentsChange = false;
    /// Every `/drive` (SPEC 10.7), in file order; each is also in its track (Track::drives).
    std::vector<std::shared_ptr<const Drive>> drives;
    /// `/caption`s in file order: drawn in that order over the traced picture.
    std::vector<Caption> captions;
    /// The objects' animation compiled for evaluation (anim/animation_program.h).
    AnimationCache animation;

    /// Last frame of the animation: the smallest whole number at or after the
    /// largest key time of the scene, a caption's times included (0 if none; SPEC 10.4).
    int lastFrame() const;
    /// Number of primitives after expanding models (robot 6, human 4: their shapes).
    std::size_t primitiveCount() const;
};

}  // namespace f2

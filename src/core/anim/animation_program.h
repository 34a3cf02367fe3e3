#pragma once
/// A scene's animation compiled for evaluation, once per scene (on its first
/// evaluation, then kept with it): what evaluating a frame reads, laid out
/// for that and nothing else.
///
/// The parser's SceneDesc is written for the language: one 300-byte
/// SceneObject per object, each track's keys in a heap block of its own.
/// Evaluation is bound by memory, so the program keeps
/// - the keys' poses of every animated track in one array, in scene order, so
///   that a frame streams through them;
/// - each distinct sequence of key frames and segment modes once (a key
///   layout): where a time falls among the keys is found once per layout and
///   frame (a grid of robots keyed alike has two layouts, whatever its size);
/// - a part's track that only turns about one axis as one angle per key
///   (TurnTrack): one channel to blend, one sine and cosine per frame;
/// - what does not move as constants: a root frame without keys (or with one)
///   as its transform, a part without keys (or with one) as its rotation
///   matrix, every surface (identical surfaces stored once).
/// Results are those of evaluateTrack, modelPartFrames and makePrimitive,
/// bit for bit (tests/unit/animation_program_test.cpp).
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/anim/evaluated_frame.h"
#include "core/anim/track.h"
#include "core/math/transform.h"
#include "core/scene/models.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct AnimationProgram {
    /// A track with two keys or more: its key layout and its first pose in `poses`.
    struct AnimatedTrack {
        std::uint32_t layout;
        std::uint32_t firstPose;
    };
    /// Keys `[first, first + count)` of `frames` and `modes`.
    struct KeyLayout {
        std::uint32_t first;
        std::uint32_t count;
    };
    /// A part's track of two keys or more that only turns about one axis: the
    /// other two angles are 0 and the offset is the same in every key (a
    /// swinging arm, a turning head). Its keys are stored as one angle each,
    /// and a frame blends that one channel and takes one sine and cosine.
    struct TurnTrack {
        std::uint32_t layout;
        std::uint32_t firstAngle;  ///< its keys' angles in `angles`
        std::uint32_t axis;        ///< 0: x, 1: y, 2: z
        Vec3 offset;               ///< every key's position
    };
    /// A track with drives (SPEC 10.7), evaluated as evaluateTrack does it:
    /// its keys (`track`, without its drives), then its drives
    /// `[firstDrive, firstDrive + driveCount)` of `drives`, at the frame's time.
    struct DrivenTrack {
        Track track;
        Pose rest;
        std::uint32_t firstDrive, driveCount;
    };
    /// One drive: the slot it replaces and its code, `[first, first + count)`
    /// of `driveCode`, which streams through the cache as `poses` does (a
    /// drive's code on the heap costs a cache miss or more per object).
    struct ProgramDrive {
        std::uint32_t slot, first, count, stackSize;
        double fps;
        /// Runs side by side with the drive before it (ExpressionCode::runLanes):
        /// both run in lanes and have the same shape, as the drives of a grid
        /// of objects written alike do.
        bool withPrevious = false;
    };
    /// A part's constant motion (no keys: rest, or one key): offset and rotation.
    struct ConstantMotion {
        Vec3 offset;
        Mat3 rotation;
        bool rotated = false;  ///< rotation angles not all zero (else no matrix product)
    };

    /// Where a root or a part gets its pose: `kAnimated | track index` or a
    /// constant (for a part: an index in `constantMotions`).
    static constexpr std::uint32_t kAnimated = 0x8000'0000u;
    /// Where a part gets its pose: `kTurning | index in turnTracks`.
    static constexpr std::uint32_t kTurning = 0x4000'0000u;
    /// Where a root or a part gets its pose: `kDriven | index in drivenTracks`.
    static constexpr std::uint32_t kDriven = 0x2000'0000u;
    /// A root frame taken from `EvaluatedFrame::attachedRoots` (SPEC 9.2).
    static constexpr std::uint32_t kAttached = 0x7fff'ffffu;
    /// A root frame that does not move: `constantRoots[object]`.
    static constexpr std::uint32_t kConstantRoot = 0;

    // Per object, in scene order.
    std::vector<ObjectKind> kinds;
    std::vector<const ModelType*> models;   ///< an instance's type (kept alive by `types`), else null
    std::vector<Vec3> sizes;                ///< as SceneObject::size
    std::vector<std::uint32_t> rootSource;  ///< kAnimated | track, kConstantRoot, kAttached
    std::vector<Transform> constantRoots;   ///< the root frame when kConstantRoot
    /// Models: where each part gets its pose (kAnimated | track, kTurning |
    /// turn, or a constant), the object's parts from `firstPartSource[object]`.
    std::vector<std::uint32_t> partSources;
    std::vector<std::uint32_t> firstPartSource;
    std::vector<std::uint32_t> firstSurface;    ///< the object's surfaces in `surfaces`, one per primitive
    std::vector<std::uint32_t> firstPrimitive;  ///< as EvaluatedFrame::firstPrimitive (objects + 1)
    std::vector<std::uint8_t> still;            ///< 1: neither the object nor a part of it ever moves
    /// The object's drives are [firstDrive[i], firstDrive[i + 1]) of `drives` (objects + 1).
    std::vector<std::uint32_t> firstDrive;

    // Shared tables.
    std::vector<AnimatedTrack> tracks;
    std::vector<Pose> poses;  ///< keys' poses, track after track in scene order
    std::vector<KeyLayout> layouts;
    std::vector<double> frames;  ///< key times (frames) of the layouts
    std::vector<Easing> modes;   ///< mode from each key to the next, of the layouts
    std::vector<TurnTrack> turnTracks;
    std::vector<float> angles;  ///< keys' angles of the turn tracks, track after track
    std::vector<ConstantMotion> constantMotions;
    std::vector<DrivenTrack> drivenTracks;
    std::vector<ProgramDrive> drives;
    std::vector<ExprInstruction> driveCode;
    std::vector<Surface> surfaces;
    /// The model types of the instances, so that `models` stay valid as long as the program.
    std::vector<std::shared_ptr<const ModelType>> types;
    /// Per primitive (frame order), ray_mask::kCastsNoShadow where `/no_shadow`
    /// (SPEC 10.8) reached it; empty when nothing in the scene uses it.
    std::vector<std::uint8_t> castsNoShadow;

    /// Compiles `scene` (its objects; the camera and lights are read per frame).
    static std::shared_ptr<const AnimationProgram> compile(const SceneDesc& scene);

    /// Where time t falls in every layout, into `segments` (one per layout).
    void segmentsAt(double t, std::vector<TrackSegment>& segments) const;

    /// Pose of animated track `track` with the layouts' `segments` of this frame.
    Pose trackPose(std::uint32_t track, const TrackSegment* segments) const {
        const AnimatedTrack& at = tracks[track];
        const Pose* keys = &poses[at.firstPose];
        return poseInSegment(segments[at.layout], [keys](std::uint32_t i) -> const Pose& { return keys[i]; });
    }

    /// Angle (degrees) of turn track `turn` with the layouts' `segments` of
    /// this frame: that channel of trackPose, bit for bit.
    float turnAngle(std::uint32_t turn, const TrackSegment* segments) const {
        const TurnTrack& track = turnTracks[turn];
        const TrackSegment& segment = segments[track.layout];
        const float* keys = &angles[track.firstAngle];
        if (segment.kind == TrackSegment::Kind::Hold) return keys[segment.p1];
        return float(
            blendInSegment(segment, keys[segment.p0], keys[segment.p1], keys[segment.p2], keys[segment.p3]));
    }

    /// An object's frames at this frame: its root frame (a primitive object's
    /// own frame) and, for a model, every part's (in `parts`, room for
    /// kMaxModelParts, given by the caller).
    struct ObjectFrames {
        Transform root;
        Transform* parts;
    };
    /// The frames of object i with this frame's `segments` and, if it is
    /// attached, `frame.attachedRoots[i]`; driven tracks at `frame.time` with
    /// `frame.driveValues`; its parts' into `parts`.
    ObjectFrames objectFrames(std::size_t i, const TrackSegment* segments, const EvaluatedFrame& frame,
                              Transform* parts) const;
    /// The values of drives [begin, end) at time t into values[begin, end):
    /// ExpressionCode::evaluate's, bit for bit, runs of alike drives side by
    /// side (ProgramDrive::withPrevious).
    void evaluateDrives(std::size_t begin, std::size_t end, double t, double* values) const;
    /// Pose of driven track `track` at time t with every drive's value in
    /// `values` (evaluateDrives): evaluateTrack's, bit for bit.
    Pose drivenPose(std::uint32_t track, double t, const double* values) const;
    /// Primitive `shape` (0 for a primitive object; a model's shapes in
    /// order) of object i whose frames are `frames`.
    Primitive objectPrimitive(std::size_t i, std::uint32_t shape, const ObjectFrames& frames) const {
        const ModelType* model = models[i];
        if (!model) return makePrimitive(shapeKindOf(kinds[i]), sizes[i], frames.root);
        const ModelShape& s = model->shapes[shape];
        return makePrimitive(s.kind, s.size, shapeFrame(frames.parts[s.part], s));
    }

    /// Writes the primitives and surfaces of objects [begin, end) into `frame`
    /// (sized by the caller, `driveValues` too), with this frame's `segments`
    /// and, for attached objects, `frame.attachedRoots`; their drives' values
    /// first into `frame.driveValues`. `refill`: the frame already holds this
    /// program's surfaces and still objects (EvaluatedFrame::filledBy), which
    /// are then not written again.
    void evaluateObjects(std::size_t begin, std::size_t end, const TrackSegment* segments, bool refill,
                         EvaluatedFrame& frame) const;
    /// The same, refilling a frame (EvaluatedFrame::filledBy: surfaces and
    /// still objects in place, also in `leaves`), each primitive i written
    /// both into `frame.primitives` and into leaves[leafOf[i]] (a BVH's leaf
    /// order), around the caches (streamingStore): for frames larger than them.
    void evaluateObjectsIntoLeaves(std::size_t begin, std::size_t end, const TrackSegment* segments,
                                   EvaluatedFrame& frame, std::span<const std::uint32_t> leafOf,
                                   std::span<Primitive> leaves) const;
};

/// `worldFromParent · translate(origin) · rotate(rotation)` (SPEC 5); no
/// rotation (null) makes no matrix product.
inline Transform childFrame(const Transform& worldFromParent, Vec3 origin, const Mat3* rotation) {
    return rotation ? worldFromParent * Transform{*rotation, origin} : worldFromParent.translated(origin);
}

/// The same with the rotation's angles (degrees): zero angles, as most parts
/// have in most frames, make no matrix.
inline Transform childFrame(const Transform& worldFromParent, Vec3 origin, Vec3 rotationDegrees) {
    if (rotationDegrees == Vec3{}) return worldFromParent.translated(origin);
    const Mat3 rotation = rotationFromEulerDegrees(rotationDegrees);
    return childFrame(worldFromParent, origin, &rotation);
}

/// The rotation of `degrees` about axis `axis` (0: x, 1: y, 2: z) alone:
/// rotationFromEulerDegrees with the other angles 0, bit for bit, for one
/// sine and cosine and a third of the products.
inline Mat3 turnMatrix(float degrees, std::uint32_t axis) {
    const SinCos turn = sinCosDegrees(degrees), none;
    return axis == 0   ? rotationFromSinCos(turn, none, none)
           : axis == 1 ? rotationFromSinCos(none, turn, none)
                       : rotationFromSinCos(none, none, turn);
}

/// childFrame for a rotation about one axis alone (turnMatrix).
inline Transform childFrameTurned(const Transform& worldFromParent, Vec3 origin, float degrees,
                                  std::uint32_t axis) {
    if (degrees == 0) return worldFromParent.translated(origin);
    const Mat3 rotation = turnMatrix(degrees, axis);
    return childFrame(worldFromParent, origin, &rotation);
}

/// The program of `scene`: compiled on the first call and kept with the scene
/// (SceneDesc::animation) for the next ones; thread-safe.
std::shared_ptr<const AnimationProgram> animationProgramOf(const SceneDesc& scene);

}  // namespace f2

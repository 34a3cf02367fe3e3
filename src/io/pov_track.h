#pragma once
/// A key-frame track (SPEC 6, 9.3, 10.4) written in POV-Ray's own language:
/// an `#if`/`#elseif` over its key intervals, each with f2's interpolation
/// as an SDL expression, so that POV-Ray evaluates the pose at any clock, as
/// track.h does.
#include <set>
#include <string>

#include "core/scene/models.h"

namespace f2 {

/// Whether povTrackPose writes `track` exactly: keys (every mode; `bezier`
/// inverts its curve by the same 30 bisection steps as f2, in an SDL
/// `#for`) and no drives (SPEC 10.7).
bool povEvaluates(const Track& track);

/// povEvaluates, or no keys and no drives: a track that holds its rest.
bool povEvaluatesOrStill(const Track& track);

/// SDL declaring `NAME_Position` and `NAME_Rotation` (degrees) as the pose of
/// `track` (at least one key, povEvaluates) at the frame time `F2_Frame`.
/// Numbers are written as they read back (formatNumber); f2 blends in double and stores floats.
std::string povTrackPose(const Track& track, const std::string& name);

/// Whether POV-Ray can move object `index` itself: its own and its parts'
/// tracks are povEvaluates or have neither keys nor drives, and it rides on
/// nothing or, for the whole animation (no `/attach … at`, SPEC 10.7), on
/// an object it can move (SPEC 9.2).
bool povEvaluatesMotion(const SceneDesc& scene, std::size_t index);

/// SDL declaring the poses of object `index`'s keyed tracks at `F2_Frame`
/// (povTrackPose, named `F2_ObjectN` and `F2_ObjectN_PartK`), and those of
/// the objects it rides on; each object once (`declared`).
std::string povObjectPoses(const SceneDesc& scene, std::size_t index, std::set<std::size_t>& declared);

/// The SDL transform of object `index`'s primitive `shape` (0 for a
/// primitive; a model's shape) from its canonical frame to the world, from
/// the poses povObjectPoses declares: as frame_builder.h composes it, shape
/// turn and centre, then each part's motion, rest rotation and pivot up to
/// the root, then the object's pose, then the same for the part and object
/// it rides on, and so on. `rotate <x, y, z>` is f2's Rz·Ry·Rx (SPEC 1).
std::string povShapeMotion(const SceneDesc& scene, std::size_t index, std::size_t shape);

/// SDL of the point `/look_at` names by `ref` (lookAtPoint: an object's
/// origin, or the centre of a part's main shape) carried through the same
/// steps, from the poses povObjectPoses declares for `ref.object`.
std::string povRefPoint(const SceneDesc& scene, FrameRef ref);

}  // namespace f2

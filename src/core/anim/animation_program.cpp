#include "core/anim/animation_program.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "core/geometry/ray_mask.h"
#include "core/scene/models.h"
#include "core/util/streaming_store.h"

namespace f2 {

namespace {
Vec3 toUnitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

/// Shading inputs of a primitive's or a model shape's look.
Surface surfaceOf(const Appearance& look) {
    return {toUnitColor(look.color), look.material, toUnitColor(look.checker.color), look.checker.size};
}

/// The bytes of a value, as a key for the tables that store equal things once
/// (padding bytes, if any, can only make two equal things be stored twice).
template <class T>
void appendBytes(std::string& key, const T& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// Compiles the scene's tracks into the program's tables.
class Compiler {
   public:
    explicit Compiler(AnimationProgram& program) : p_(program) {}

    /// kAnimated | track for two keys or more; else `kConstant` (no keys, or one).
    std::uint32_t animatedTrack(const Track& track) {
        if (track.keys.size() < 2) return 0;
        const auto index = std::uint32_t(p_.tracks.size());
        p_.tracks.push_back({layoutOf(track), std::uint32_t(p_.poses.size())});
        for (const Key& key : track.keys) p_.poses.push_back(key.pose);
        return AnimationProgram::kAnimated | index;
    }

    /// kTurning | turn track for a part track of two keys or more that only
    /// turns about one axis (AnimationProgram::TurnTrack); else 0.
    std::uint32_t turnTrack(const Track& track) {
        if (track.keys.size() < 2) return 0;
        const Pose& first = track.keys.front().pose;
        // A blend of equal values gives that value back, except -0 (-0 + 0 is
        // +0) and what is not finite: such offsets stay on the general path.
        for (int c = 0; c < 3; ++c) {
            const float offset = first.position[c];
            if (!std::isfinite(offset) || (std::signbit(offset) && offset == 0)) return 0;
        }
        std::uint32_t axis = 0;
        for (const Key& key : track.keys) {
            if (!(key.pose.position == first.position)) return 0;
            for (std::uint32_t c = 0; c < 3; ++c) {
                if (key.pose.rotation[int(c)] != 0) axis = c;
            }
        }
        // The other axes' angles are 0 (either sign, as sinCosDegrees takes them) in every key.
        for (const Key& key : track.keys) {
            for (std::uint32_t c = 0; c < 3; ++c) {
                if (c != axis && !(key.pose.rotation[int(c)] == 0)) return 0;
            }
        }
        const auto index = std::uint32_t(p_.turnTracks.size());
        p_.turnTracks.push_back({layoutOf(track), std::uint32_t(p_.angles.size()), axis, first.position});
        for (const Key& key : track.keys) p_.angles.push_back(key.pose.rotation[int(axis)]);
        return AnimationProgram::kTurning | index;
    }

    /// Index in constantMotions of a part's constant pose (rest, or its one key).
    std::uint32_t constantMotion(const Track& track) {
        const Pose pose = track.keys.empty() ? Pose{} : track.keys.front().pose;
        std::string key;
        appendBytes(key, pose);
        auto [it, added] = motionIndex_.try_emplace(std::move(key), std::uint32_t(p_.constantMotions.size()));
        if (added) {
            // As modelPartFrames computes it: no matrix for zero angles.
            const bool rotated = !(pose.rotation == Vec3{});
            p_.constantMotions.push_back(
                {pose.position, rotated ? rotationFromEulerDegrees(pose.rotation) : Mat3{}, rotated});
        }
        return it->second;
    }

    /// kDriven | index of a track with drives (SPEC 10.7), whose rest pose is `rest`.
    std::uint32_t drivenTrack(const Track& track, const Pose& rest) {
        const auto index = std::uint32_t(p_.drivenTracks.size());
        AnimationProgram::DrivenTrack driven{track, rest, std::uint32_t(p_.drives.size()), 0};
        driven.track.drives = nullptr;
        for (std::size_t slot = 0; slot < track.drives->bySlot.size(); ++slot) {
            const Drive* drive = track.drives->bySlot[slot].get();
            if (!drive) continue;
            const auto first = std::uint32_t(p_.driveCode.size());
            const std::span<const ExprInstruction> code = drive->code.instructions();
            if (code.empty()) {
                p_.driveCode.push_back({ExprOp::Push, ExprFunction::Sin, 0, 0, drive->code.evaluate({})});
            } else {
                p_.driveCode.insert(p_.driveCode.end(), code.begin(), code.end());
            }
            AnimationProgram::ProgramDrive programDrive{
                std::uint32_t(slot), first, std::uint32_t(p_.driveCode.size()) - first,
                std::uint32_t(std::max<std::size_t>(drive->code.stackSize(), 1)), double(drive->fps)};
            if (!p_.drives.empty()) {
                const AnimationProgram::ProgramDrive& previous = p_.drives.back();
                const std::span<const ExprInstruction> mine = codeOf(programDrive), theirs = codeOf(previous);
                programDrive.withPrevious = ExpressionCode::runsInLanes(mine, programDrive.stackSize) &&
                                            ExpressionCode::runsInLanes(theirs, previous.stackSize) &&
                                            ExpressionCode::sameShape(mine, theirs);
            }
            p_.drives.push_back(programDrive);
            ++driven.driveCount;
        }
        p_.drivenTracks.push_back(std::move(driven));
        return AnimationProgram::kDriven | index;
    }

    /// First index in `surfaces` of an object's surfaces (equal runs stored once).
    std::uint32_t surfaces(const SceneObject& object) {
        run_.clear();
        for (const Appearance& look : object.appearance) run_.push_back(surfaceOf(look));
        std::string key;
        for (const Surface& surface : run_) appendBytes(key, surface);
        auto [it, added] = surfaceIndex_.try_emplace(std::move(key), std::uint32_t(p_.surfaces.size()));
        if (added) p_.surfaces.insert(p_.surfaces.end(), run_.begin(), run_.end());
        return it->second;
    }

    /// The program's entry for an instance's type: kept alive with the program.
    const ModelType* type(const std::shared_ptr<const ModelType>& model) {
        if (!model) return nullptr;
        if (types_.insert(model.get()).second) p_.types.push_back(model);
        return model.get();
    }

   private:
    std::span<const ExprInstruction> codeOf(const AnimationProgram::ProgramDrive& drive) const {
        return {&p_.driveCode[drive.first], drive.count};
    }

    std::uint32_t layoutOf(const Track& track) {
        std::string key;
        for (std::size_t i = 0; i < track.keys.size(); ++i) {
            const Easing& easing = track.modeAfter(i);
            appendBytes(key, track.keys[i].time);
            appendBytes(key, easing.mode);  // field by field: Easing has padding
            appendBytes(key, easing.curve);
        }
        auto [it, added] = layoutIndex_.try_emplace(std::move(key), std::uint32_t(p_.layouts.size()));
        if (added) {
            p_.layouts.push_back({std::uint32_t(p_.frames.size()), std::uint32_t(track.keys.size())});
            for (std::size_t i = 0; i < track.keys.size(); ++i) {
                p_.frames.push_back(track.keys[i].time);
                p_.modes.push_back(track.modeAfter(i));
            }
        }
        return it->second;
    }

    AnimationProgram& p_;
    std::unordered_map<std::string, std::uint32_t> layoutIndex_, motionIndex_, surfaceIndex_;
    std::unordered_set<const ModelType*> types_;
    std::vector<Surface> run_;
};

}  // namespace

std::shared_ptr<const AnimationProgram> AnimationProgram::compile(const SceneDesc& scene) {
    auto program = std::make_shared<AnimationProgram>();
    AnimationProgram& p = *program;
    const std::size_t count = scene.objects.size();
    p.kinds.resize(count);
    p.models.resize(count);
    p.sizes.resize(count);
    p.rootSource.resize(count);
    p.constantRoots.resize(count);
    p.firstPartSource.resize(count);
    p.firstSurface.resize(count);
    p.firstPrimitive.resize(count + 1);
    p.still.resize(count);
    p.firstDrive.resize(count + 1);
    Compiler compiler(p);
    std::uint32_t primitives = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const SceneObject& object = scene.objects[i];
        p.kinds[i] = object.kind;
        p.models[i] = compiler.type(object.model);
        p.sizes[i] = object.size;
        p.firstPrimitive[i] = primitives;
        p.firstDrive[i] = std::uint32_t(p.drives.size());
        primitives += std::uint32_t(primitiveCountOf(object));
        if (object.mayRide()) {
            p.rootSource[i] = kAttached;
        } else if (object.track.drives) {
            p.rootSource[i] = compiler.drivenTrack(object.track, object.rest);
        } else if (const std::uint32_t track = compiler.animatedTrack(object.track)) {
            p.rootSource[i] = track;
        } else {
            // As objectFrame computes it from the rest pose or the one key.
            const Pose pose = object.track.keys.empty() ? object.rest : object.track.keys.front().pose;
            p.rootSource[i] = kConstantRoot;
            p.constantRoots[i] = Transform::fromPose(pose.position, pose.rotation);
        }
        bool still = p.rootSource[i] == kConstantRoot;
        p.firstPartSource[i] = std::uint32_t(p.partSources.size());
        for (const Track& track : object.partTracks) {
            std::uint32_t animated = track.drives ? compiler.drivenTrack(track, Pose{}) : 0;
            if (!animated) animated = compiler.turnTrack(track);
            if (!animated) animated = compiler.animatedTrack(track);
            p.partSources.push_back(animated ? animated : compiler.constantMotion(track));
            still = still && !animated;
        }
        p.still[i] = still;
        p.firstSurface[i] = compiler.surfaces(object);
    }
    p.firstPrimitive[count] = primitives;
    p.firstDrive[count] = std::uint32_t(p.drives.size());
    const auto shadowless = [](const Appearance& a) { return !a.castsShadow; };
    if (std::any_of(scene.objects.begin(), scene.objects.end(), [&](const SceneObject& o) {
            return std::any_of(o.appearance.begin(), o.appearance.end(), shadowless);
        })) {
        p.castsNoShadow.reserve(primitives);
        for (const SceneObject& object : scene.objects) {
            for (const Appearance& look : object.appearance)
                p.castsNoShadow.push_back(shadowless(look) ? ray_mask::kCastsNoShadow : 0);
        }
    }
    return program;
}

void AnimationProgram::evaluateDrives(std::size_t begin, std::size_t end, double t, double* values) const {
    std::array<std::array<double, 2>, ExpressionCode::kMaxLanes> inputs;
    std::array<ExprLane, ExpressionCode::kMaxLanes> lanes;
    std::size_t d = begin;
    while (d < end) {
        // The drive and the alike ones after it (up to kMaxLanes; a drive
        // withPrevious runs in lanes, and so does the one before it), or the drive alone.
        std::size_t n = 1;
        while (n < ExpressionCode::kMaxLanes && d + n < end && drives[d + n].withPrevious) ++n;
        for (std::size_t l = 0; l < n; ++l) {
            const ProgramDrive& drive = drives[d + l];
            inputs[l] = {t, t / drive.fps};  // as Drive::valueAt
            lanes[l] = {&driveCode[drive.first], inputs[l]};
        }
        const ProgramDrive& drive = drives[d];
        if (n == 1) {
            values[d] = ExpressionCode::run({&driveCode[drive.first], drive.count}, drive.stackSize,
                                            inputs[0], nullptr);
        } else {
            ExpressionCode::runLanes({lanes.data(), n}, drive.count, &values[d]);
        }
        d += n;
    }
}

Pose AnimationProgram::drivenPose(std::uint32_t track, double t, const double* values) const {
    const DrivenTrack& driven = drivenTracks[track];
    Pose pose = evaluateTrack(driven.track, t, driven.rest);
    for (std::uint32_t k = 0; k < driven.driveCount; ++k) {
        const std::uint32_t d = driven.firstDrive + k;
        setDrivenNumber(pose, int(drives[d].slot), values[d]);
    }
    return pose;
}

void AnimationProgram::segmentsAt(double t, std::vector<TrackSegment>& segments) const {
    segments.resize(layouts.size());
    for (std::size_t l = 0; l < layouts.size(); ++l) {
        const double* keyFrames = &frames[layouts[l].first];
        const Easing* keyModes = &modes[layouts[l].first];
        segments[l] = segmentAt(
            layouts[l].count, [keyFrames](std::uint32_t i) { return keyFrames[i]; },
            [keyModes](std::uint32_t i) -> const Easing& { return keyModes[i]; }, t);
    }
}

// Inlined into both loops below: a call per object measured slower.
[[gnu::always_inline]] inline AnimationProgram::ObjectFrames AnimationProgram::objectFrames(
    std::size_t i, const TrackSegment* segments, const EvaluatedFrame& frame, Transform* parts) const {
    ObjectFrames out;
    out.parts = parts;
    const std::uint32_t root = rootSource[i];
    if (root == kConstantRoot) {
        out.root = constantRoots[i];
    } else if (root == kAttached) {
        out.root = frame.attachedRoots[i];
    } else if (root & kDriven) {
        const Pose pose = drivenPose(root & ~kDriven, frame.time, frame.driveValues.data());
        out.root = Transform::fromPose(pose.position, pose.rotation);
    } else {
        const Pose pose = trackPose(root & ~kAnimated, segments);
        out.root = Transform::fromPose(pose.position, pose.rotation);
    }
    const ModelType* model = models[i];
    if (!model) return out;

    // Part frames, parents first (SPEC 5, 10.1), as modelPartFrames computes them.
    const std::uint32_t* sources = &partSources[firstPartSource[i]];
    const std::size_t count = model->parts.size();
    for (std::size_t index = 0; index < count; ++index) {
        const ModelPart& part = model->parts[index];
        const Transform& worldFromParent = part.parent < 0 ? out.root : parts[part.parent];
        const std::uint32_t source = sources[index];
        if (source & kTurning) {
            const TurnTrack& turn = turnTracks[source & ~kTurning];
            const float degrees = turnAngle(source & ~kTurning, segments);
            if (!part.rest) {
                parts[index] =
                    childFrameTurned(worldFromParent, part.pivot + turn.offset, degrees, turn.axis);
            } else {
                const Mat3 rotation = degrees == 0 ? Mat3{} : turnMatrix(degrees, turn.axis);
                parts[index] =
                    partFrame(worldFromParent, part, turn.offset, degrees == 0 ? nullptr : &rotation);
            }
        } else if (source & kDriven) {
            const Pose motion = drivenPose(source & ~kDriven, frame.time, frame.driveValues.data());
            const bool turned = !(motion.rotation == Vec3{});
            const Mat3 rotation = turned ? rotationFromEulerDegrees(motion.rotation) : Mat3{};
            parts[index] = partFrame(worldFromParent, part, motion.position, turned ? &rotation : nullptr);
        } else if (source & kAnimated) {
            const Pose motion = trackPose(source & ~kAnimated, segments);
            const bool turned = !(motion.rotation == Vec3{});
            const Mat3 rotation = turned ? rotationFromEulerDegrees(motion.rotation) : Mat3{};
            parts[index] = partFrame(worldFromParent, part, motion.position, turned ? &rotation : nullptr);
        } else {
            const ConstantMotion& motion = constantMotions[source];
            parts[index] =
                partFrame(worldFromParent, part, motion.offset, motion.rotated ? &motion.rotation : nullptr);
        }
    }
    return out;
}

void AnimationProgram::evaluateObjects(std::size_t begin, std::size_t end, const TrackSegment* segments,
                                       bool refill, EvaluatedFrame& frame) const {
    evaluateDrives(firstDrive[begin], firstDrive[end], frame.time, frame.driveValues.data());
    Transform parts[kMaxModelParts];
    for (std::size_t i = begin; i < end; ++i) {
        if (refill && still[i]) continue;
        const ObjectFrames frames = objectFrames(i, segments, frame, parts);
        const std::uint32_t first = firstPrimitive[i];
        Primitive* prims = &frame.primitives[first];
        const Surface* look = &surfaces[firstSurface[i]];
        const ModelType* model = models[i];
        if (!model) {
            *prims = makePrimitive(shapeKindOf(kinds[i]), sizes[i], frames.root);
            if (!refill) frame.surfaces[first] = *look;
            continue;
        }
        for (const ModelShape& shape : model->shapes)
            *prims++ = makePrimitive(shape.kind, shape.size, shapeFrame(parts[shape.part], shape));
        if (!refill) std::memcpy(&frame.surfaces[first], look, model->shapes.size() * sizeof(Surface));
    }
}

void AnimationProgram::evaluateObjectsIntoLeaves(std::size_t begin, std::size_t end,
                                                 const TrackSegment* segments, EvaluatedFrame& frame,
                                                 std::span<const std::uint32_t> leafOf,
                                                 std::span<Primitive> leaves) const {
    // A large frame does not fit in the caches: both copies are written around
    // them, without first reading each line from memory.
    evaluateDrives(firstDrive[begin], firstDrive[end], frame.time, frame.driveValues.data());
    Transform parts[kMaxModelParts];
    for (std::size_t i = begin; i < end; ++i) {
        if (still[i]) continue;
        const ObjectFrames frames = objectFrames(i, segments, frame, parts);
        const std::uint32_t first = firstPrimitive[i];
        const std::uint32_t count = firstPrimitive[i + 1] - first;
        for (std::uint32_t shape = 0; shape < count; ++shape) {
            const Primitive primitive = objectPrimitive(i, shape, frames);
            streamingStore(&leaves[leafOf[first + shape]], primitive);
            streamingStore(&frame.primitives[first + shape], primitive);
        }
    }
    streamingStoreFence();
}

std::shared_ptr<const AnimationProgram> animationProgramOf(const SceneDesc& scene) {
    std::shared_ptr<const AnimationProgram> program = scene.animation.get();
    // A scene given objects after its first evaluation is compiled again
    // (changing existing ones is not allowed: SceneDesc::animation).
    if (!program || program->kinds.size() != scene.objects.size()) {
        program = AnimationProgram::compile(scene);
        scene.animation.set(program);
    }
    return program;
}

}  // namespace f2

#include "core/anim/frame_builder.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "core/anim/animation_program.h"
#include "core/anim/light_evaluation.h"
#include "core/anim/track.h"
#include "core/scene/models.h"

namespace f2 {

namespace {
Vec3 toUnitColor(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

}  // namespace

Transform objectFrame(const SceneObject& object, double t) {
    Pose pose = evaluateTrack(object.track, t, object.rest);
    return Transform::fromPose(pose.position, pose.rotation);
}

namespace {
/// Part `index`'s frame on its parent's, with its animation at time t.
Transform partFrameAt(const SceneObject& object, std::size_t index, const Transform& worldFromParent,
                      double t) {
    const Pose motion = evaluateTrack(object.partTracks[index], t, Pose{});
    // As childFrame: zero angles make no matrix.
    const bool turned = !(motion.rotation == Vec3{});
    const Mat3 rotation = turned ? rotationFromEulerDegrees(motion.rotation) : Mat3{};
    return partFrame(worldFromParent, object.model->parts[index], motion.position,
                     turned ? &rotation : nullptr);
}
}  // namespace

std::vector<Transform> modelPartFrames(const SceneObject& object, const Transform& worldFromRoot, double t) {
    const std::vector<ModelPart>& parts = object.model->parts;
    std::vector<Transform> worldFromPart(parts.size());
    for (std::size_t index = 0; index < parts.size(); ++index) {
        const int parent = parts[index].parent;
        worldFromPart[index] =
            partFrameAt(object, index, parent < 0 ? worldFromRoot : worldFromPart[std::size_t(parent)], t);
    }
    return worldFromPart;
}

Transform modelPartFrame(const SceneObject& object, int part, const Transform& worldFromRoot, double t) {
    // The chain from the part up to the root, then its frames top down:
    // modelPartFrames' products for these parts, without a frame per part.
    std::array<int, kMaxModelParts> chain;
    std::size_t depth = 0;
    for (int p = part; p >= 0; p = object.model->parts[std::size_t(p)].parent) chain[depth++] = p;
    Transform world = worldFromRoot;
    while (depth > 0) world = partFrameAt(object, std::size_t(chain[--depth]), world, t);
    return world;
}

Transform worldFromRef(const SceneDesc& scene, FrameRef ref, double t) {
    // Bottom up: each level's frame in its parent's space, multiplied on the left.
    Transform world;
    bool first = true;
    for (std::optional<FrameRef> at = ref; at; at = mountAt(scene.objects[at->object], t)) {
        const SceneObject& object = scene.objects[at->object];
        const Transform root = objectFrame(object, t);
        const Transform level = at->part < 0 ? root : modelPartFrame(object, at->part, root, t);
        world = first ? level : level * world;
        first = false;
    }
    return world;
}

namespace {
/// attachedRootFrames when the rides change with time (SPEC 10.7), and so
/// does their order: from each object not yet done, climb the rides that
/// hold at t to the first holder done or riding on nothing, then evaluate
/// that chain top first. Each object once: linear in their number.
void changingRootFrames(const SceneDesc& scene, double t, std::vector<Transform>& roots) {
    // Per thread, reused: `done[i] == pass` marks object i evaluated in this call.
    thread_local std::vector<std::uint32_t> done, chain;
    thread_local std::uint32_t pass = 0;
    if (++pass == 0) {
        std::fill(done.begin(), done.end(), 0u);
        pass = 1;
    }
    const std::vector<SceneObject>& objects = scene.objects;
    if (done.size() < objects.size()) done.resize(objects.size(), 0u);
    for (std::uint32_t i : scene.attachOrder) {
        if (done[i] == pass) continue;
        chain.clear();
        for (std::uint32_t x = i;;) {
            chain.push_back(x);
            done[x] = pass;
            const std::optional<FrameRef> mount = mountAt(objects[x], t);
            if (!mount || !objects[mount->object].mayRide() || done[mount->object] == pass) break;
            x = mount->object;  // the parser saw to it that no ride closes a cycle at any time
        }
        for (std::size_t k = chain.size(); k-- > 0;) {
            const std::uint32_t y = chain[k];
            const SceneObject& object = objects[y];
            const std::optional<FrameRef> mount = mountAt(object, t);
            if (!mount) {
                roots[y] = objectFrame(object, t);
                continue;
            }
            const SceneObject& parent = objects[mount->object];
            const Transform parentRoot = parent.mayRide() ? roots[mount->object] : objectFrame(parent, t);
            const Transform worldFromMount =
                mount->part < 0 ? parentRoot : modelPartFrame(parent, mount->part, parentRoot, t);
            roots[y] = worldFromMount * objectFrame(object, t);
        }
    }
}
}  // namespace

void attachedRootFrames(const SceneDesc& scene, double t, std::vector<Transform>& roots) {
    if (scene.attachOrder.empty()) return;
    roots.resize(scene.objects.size());
    if (scene.attachmentsChange) {
        changingRootFrames(scene, t, roots);
        return;
    }
    for (std::uint32_t i : scene.attachOrder) {
        const SceneObject& object = scene.objects[i];
        const FrameRef mount = *object.attachedTo;
        const SceneObject& parent = scene.objects[mount.object];
        // The parent comes earlier in attachOrder when it is attached itself.
        const Transform parentRoot = parent.attachedTo ? roots[mount.object] : objectFrame(parent, t);
        const Transform worldFromMount =
            mount.part < 0 ? parentRoot : modelPartFrame(parent, mount.part, parentRoot, t);
        roots[i] = worldFromMount * objectFrame(object, t);
    }
}

Vec3 partShapeCentre(const SceneObject& object, int part, const Transform& worldFromPart) {
    const int shape = object.model->mainShapeOf(part);
    return shape < 0 ? worldFromPart.translation
                     : worldFromPart.applyToPoint(object.model->shapes[std::size_t(shape)].centre);
}

namespace {
// Objects per parallel work item: big enough to hide the hand-out cost.
constexpr std::size_t kObjectsPerChunk = 256;
}  // namespace

FrameEvaluation FrameEvaluation::begin(const SceneDesc& scene, double t, EvaluatedFrame& frame) {
    // The front ends refuse a time that is not a finite number (a NaN frame is
    // meaningless); the tracks still stay on their keys if one gets through.
    assert(std::isfinite(t));
    evaluateLights(scene, t, frame);
    frame.background = toUnitColor(scene.background);

    // Each object owns a fixed run of primitive slots, so objects can be
    // evaluated in any order, in parallel, straight into place.
    FrameEvaluation evaluation;
    evaluation.scene = &scene;
    evaluation.t = t;
    evaluation.program = animationProgramOf(scene);
    evaluation.refill = frame.filledBy == evaluation.program;
    frame.filledBy = nullptr;  // until the frame is whole again
    frame.firstPrimitive = evaluation.program->firstPrimitive;
    const std::size_t total = evaluation.program->firstPrimitive.back();
    frame.primitives.resize(total);
    frame.surfaces.resize(total);
    // Attached objects need their parents' frames first: one pass in order.
    attachedRootFrames(scene, t, frame.attachedRoots);
    // Where t falls among the keys, once per key layout.
    evaluation.program->segmentsAt(t, frame.segments);
    frame.time = t;
    frame.driveValues.resize(evaluation.program->drives.size());
    return evaluation;
}

namespace {
/// body(begin, end) for chunks of objects [0, count), on the pool when there is one.
template <class Body>
void forObjectChunks(std::size_t count, ThreadPool* pool, const Body& body) {
    auto chunk = [&](std::uint32_t c) {
        const std::size_t begin = c * kObjectsPerChunk;
        body(begin, std::min(count, begin + kObjectsPerChunk));
    };
    const auto chunks = std::uint32_t((count + kObjectsPerChunk - 1) / kObjectsPerChunk);
    if (pool) {
        pool->parallelFor(chunks, chunk);
    } else {
        for (std::uint32_t c = 0; c < chunks; ++c) chunk(c);
    }
}
}  // namespace

void FrameEvaluation::evaluateObjects(EvaluatedFrame& frame, ThreadPool* pool) const {
    forObjectChunks(program->kinds.size(), pool, [&](std::size_t begin, std::size_t end) {
        program->evaluateObjects(begin, end, frame.segments.data(), refill, frame);
    });
}

void FrameEvaluation::evaluateObjectsIntoLeaves(EvaluatedFrame& frame, std::span<const std::uint32_t> leafOf,
                                                std::span<Primitive> leaves, ThreadPool* pool) const {
    forObjectChunks(program->kinds.size(), pool, [&](std::size_t begin, std::size_t end) {
        program->evaluateObjectsIntoLeaves(begin, end, frame.segments.data(), frame, leafOf, leaves);
    });
}

void FrameEvaluation::finish(EvaluatedFrame& frame) && {
    applyColourTracks(*scene, t, frame);
    frame.rayMask = program->castsNoShadow;
    if (!scene->visibilityTracks.empty()) markHiddenShapes(*scene, t, frame);
    frame.filledBy = std::move(program);
}

void markHiddenShapes(const SceneDesc& scene, double t, EvaluatedFrame& frame) {
    std::vector<std::uint8_t>& mask = frame.rayMaskStorage;
    if (frame.rayMask.empty())
        mask.assign(frame.primitives.size(), 0);
    else
        mask.assign(frame.rayMask.begin(), frame.rayMask.end());
    forEachHiddenShape(scene, t, [&](std::size_t object, std::size_t shape) {
        mask[frame.firstPrimitive[object] + shape] |= ray_mask::kHidden;
    });
    frame.rayMask = mask;
}

void applyColourTracks(const SceneDesc& scene, double t, EvaluatedFrame& frame) {
    forEachKeyedColour(scene, t, [&](std::size_t object, std::size_t shape, Vec3 rgb) {
        frame.surfaces[frame.firstPrimitive[object] + shape].color = rgb / 255.0f;
    });
}

void evaluateFrame(const SceneDesc& scene, double t, EvaluatedFrame& frame, ThreadPool* pool) {
    FrameEvaluation evaluation = FrameEvaluation::begin(scene, t, frame);
    evaluation.evaluateObjects(frame, pool);
    std::move(evaluation).finish(frame);
}

}  // namespace f2

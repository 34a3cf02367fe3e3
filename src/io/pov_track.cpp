#include "io/pov_track.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "io/comment_text.h"
#include "io/frame_primitives.h"
#include "io/pov_scene_text.h"

namespace f2 {

namespace {
/// w(u) of track.h's interpolationWeight as SDL of `F2_U`, u in [0, 1).
std::string weight(const Easing& easing) {
    switch (easing.mode) {
        case Interpolation::Ease:
            return "F2_U * F2_U * (3 - 2 * F2_U)";
        case Interpolation::EaseIn:
            return "F2_U * F2_U * F2_U";
        case Interpolation::EaseOut:
            return "1 - (1 - F2_U) * (1 - F2_U) * (1 - F2_U)";
        case Interpolation::Back:
            // c1 = 1.70158, c3 = c1 + 1; exactly 0 at u = 0 (backFraction).
            return "(F2_U <= 0 ? 0 : 1 + 2.70158 * pow(F2_U - 1, 3) + 1.70158 * pow(F2_U - 1, 2))";
        case Interpolation::Elastic:
            return "(F2_U <= 0 ? 0 : pow(2, -10 * F2_U) * sin((10 * F2_U - 0.75) * 2 * pi / 3) + 1)";
        case Interpolation::Bounce:
            // n = 7.5625, d = 2.75: four parabolas (bounceFraction).
            return "(F2_U < 1 / 2.75 ? 7.5625 * F2_U * F2_U"
                   " : F2_U < 2 / 2.75 ? 7.5625 * pow(F2_U - 1.5 / 2.75, 2) + 0.75"
                   " : F2_U < 2.5 / 2.75 ? 7.5625 * pow(F2_U - 2.25 / 2.75, 2) + 0.9375"
                   " : 7.5625 * pow(F2_U - 2.625 / 2.75, 2) + 0.984375)";
        case Interpolation::Linear:
        case Interpolation::Spline:
        case Interpolation::Step:
        case Interpolation::Bezier:
            break;
    }
    return "F2_U";
}
/// bezierFraction's w(u) into `F2_W`: the same 30 halvings of s, so that
/// POV-Ray takes the same steps as f2.
std::string bezierWeight(const BezierCurve& c) {
    auto along = [](const std::string& s, float c1, float c2) {
        return "3 * (1 - " + s + ") * (1 - " + s + ") * " + s + " * " + formatNumber(c1) + " + 3 * (1 - " +
               s + ") * " + s + " * " + s + " * " + formatNumber(c2) + " + " + s + " * " + s + " * " + s;
    };
    return "  #declare F2_Lo = 0;\n  #declare F2_Hi = 1;\n  #for (F2_Step, 0, 29)\n"
           "    #declare F2_Mid = 0.5 * (F2_Lo + F2_Hi);\n"
           "    #declare F2_X = " +
           along("F2_Mid", c.x1, c.x2) +
           ";\n"
           "    #if (F2_X < F2_U)\n      #declare F2_Lo = F2_Mid;\n    #else\n      #declare F2_Hi = "
           "F2_Mid;\n"
           "    #end\n  #end\n"
           "  #declare F2_S = 0.5 * (F2_Lo + F2_Hi);\n"
           "  #declare F2_W = (F2_U <= 0 ? 0 : " +
           along("F2_S", c.y1, c.y2) + ");\n";
}
}  // namespace

bool povEvaluates(const Track& track) { return !track.drives && !track.keys.empty(); }

std::string povTrackPose(const Track& track, const std::string& name) {
    const std::vector<Key>& keys = track.keys;
    const std::string position = name + "_Position", rotation = name + "_Rotation";
    std::ostringstream out;
    auto hold = [&](const Pose& pose) {
        out << "  #declare " << position << " = " << povVector(pose.position) << ";\n  #declare " << rotation
            << " = " << povVector(pose.rotation) << ";\n";
    };
    // As segmentAt: the first key up to its time, [key i, key i + 1) between, the last from its time.
    out << "#if (F2_Frame <= " << formatNumber(keys[0].time) << ")\n";
    hold(keys[0].pose);
    const std::size_t last = keys.size() - 1;
    for (std::size_t i = 0; i < last; ++i) {
        const Easing& easing = track.modeAfter(i);
        out << "#elseif (F2_Frame < " << formatNumber(keys[i + 1].time) << ")\n";
        if (easing.mode == Interpolation::Step) {
            hold(keys[i].pose);  // until the next key
            continue;
        }
        out << "  #declare F2_U = (F2_Frame - " << formatNumber(keys[i].time) << ") / "
            << formatNumber(keys[i + 1].time - keys[i].time) << ";\n";
        auto blend = [&](const std::string& target, Vec3 Pose::*channel) {
            const Vec3 p1 = keys[i].pose.*channel, p2 = keys[i + 1].pose.*channel;
            if (easing.mode == Interpolation::Spline) {
                // Uniform Catmull-Rom (catmullRom), an end key standing in for a missing neighbour.
                const Vec3 p0 = keys[i == 0 ? i : i - 1].pose.*channel;
                const Vec3 p3 = keys[i + 1 < last ? i + 2 : i + 1].pose.*channel;
                out << "  #declare " << target << " = 0.5 * (2 * " << povVector(p1) << " + (" << povVector(p2)
                    << " - " << povVector(p0) << ") * F2_U + (2 * " << povVector(p0) << " - 5 * "
                    << povVector(p1) << " + 4 * " << povVector(p2) << " - " << povVector(p3)
                    << ") * F2_U * F2_U + (3 * " << povVector(p1) << " - " << povVector(p0) << " - 3 * "
                    << povVector(p2) << " + " << povVector(p3) << ") * F2_U * F2_U * F2_U);\n";
            } else {
                out << "  #declare " << target << " = " << povVector(p1) << " + (" << povVector(p2) << " - "
                    << povVector(p1) << ") * F2_W;\n";
            }
        };
        if (easing.mode == Interpolation::Bezier) {
            out << bezierWeight(easing.curve);
        } else if (easing.mode != Interpolation::Spline) {
            out << "  #declare F2_W = " << weight(easing) << ";\n";
        }
        blend(position, &Pose::position);
        blend(rotation, &Pose::rotation);
    }
    out << "#else\n";
    hold(keys[last].pose);
    out << "#end\n";
    return out.str();
}

bool povEvaluatesOrStill(const Track& track) {
    return (track.keys.empty() && !track.drives) || povEvaluates(track);
}

namespace {
std::string partName(const std::string& name, std::size_t part) {
    return name + "_Part" + std::to_string(part);
}

/// `F2_ObjectN`: the names of object N's poses.
std::string objectName(std::size_t object) { return "F2_Object" + std::to_string(object); }

/// A chain of `rotate` and `translate` steps, applied first to last: the
/// text of a transform, or a point carried through it.
struct Motion {
    struct Step {
        bool turn;  ///< rotate (degrees), else translate
        std::string by;
    };
    std::vector<Step> steps;

    void rotate(const std::string& by) { steps.push_back({true, by}); }
    void translate(const std::string& by) { steps.push_back({false, by}); }
    /// Leaving out zeros, as f2 makes no matrix of a zero turn.
    void place(Vec3 rotation, Vec3 position) {
        if (!(rotation == Vec3{})) rotate(povVector(rotation));
        if (!(position == Vec3{})) translate(povVector(position));
    }

    std::string transform() const {
        std::string text;
        for (const Step& s : steps) text += (s.turn ? " rotate " : " translate ") + s.by;
        return text;
    }
    std::string point(const std::string& start) const {
        std::string p = start;
        for (const Step& s : steps)
            p = s.turn ? "vrotate(" + p + ", " + s.by + ")" : "(" + p + " + " + s.by + ")";
        return p;
    }
};

/// worldFromRef: part `ref.part` (if any) on its parent up to the root
/// (partFrame: the motion's rotation, the rest rotation, the pivot plus the
/// motion's offset), the object's own pose (objectFrame), then the same for
/// what it rides on, level by level.
void refChain(const SceneDesc& scene, FrameRef ref, Motion& motion) {
    for (std::optional<FrameRef> at = ref; at;) {
        const SceneObject& object = scene.objects[at->object];
        const std::string name = objectName(at->object);
        for (int p = at->part; p >= 0; p = object.model->parts[std::size_t(p)].parent) {
            const ModelPart& part = object.model->parts[std::size_t(p)];
            const bool keyed = !object.partTracks[std::size_t(p)].keys.empty();
            if (keyed) motion.rotate(partName(name, std::size_t(p)) + "_Rotation");
            motion.place(part.restRotation, part.pivot);
            if (keyed) motion.translate(partName(name, std::size_t(p)) + "_Position");
        }
        if (object.track.keys.empty()) {
            motion.place(object.rest.rotation, object.rest.position);
        } else {
            motion.rotate(name + "_Rotation");
            motion.translate(name + "_Position");
        }
        at = object.attachedTo;
    }
}
}  // namespace

bool povEvaluatesMotion(const SceneDesc& scene, std::size_t index) {
    const SceneObject& object = scene.objects[index];
    if (!object.attachChanges.empty()) return false;  // rides that change (SPEC 10.7): per frame
    if (!povEvaluatesOrStill(object.track) ||
        !std::all_of(object.partTracks.begin(), object.partTracks.end(), povEvaluatesOrStill))
        return false;
    return !object.attachedTo || povEvaluatesMotion(scene, object.attachedTo->object);
}

std::string povObjectPoses(const SceneDesc& scene, std::size_t index, std::set<std::size_t>& declared) {
    std::string text;
    for (std::optional<std::size_t> o = index; o && declared.insert(*o).second;) {
        const SceneObject& object = scene.objects[*o];
        const std::string name = objectName(*o);
        text += "// " + commentText(object.name) + ": its keys\n";
        if (!object.track.keys.empty()) text += povTrackPose(object.track, name);
        for (std::size_t p = 0; p < object.partTracks.size(); ++p)
            if (!object.partTracks[p].keys.empty())
                text += povTrackPose(object.partTracks[p], partName(name, p));
        o = object.attachedTo ? std::optional<std::size_t>(object.attachedTo->object) : std::nullopt;
    }
    return text;
}

std::string povShapeMotion(const SceneDesc& scene, std::size_t index, std::size_t shape) {
    const SceneObject& object = scene.objects[index];
    Motion motion;
    int part = -1;
    if (object.model) {
        const ModelShape& s = object.model->shapes[shape];
        motion.place(s.rotation, s.centre);
        part = s.part;
    }
    refChain(scene, {std::uint32_t(index), part}, motion);
    return motion.transform();
}

std::string povRefPoint(const SceneDesc& scene, FrameRef ref) {
    // lookAtPoint: an object's origin, or the centre of a part's main shape.
    Vec3 start;
    if (ref.part >= 0) {
        const SceneObject& object = scene.objects[ref.object];
        const int shape = object.model->mainShapeOf(ref.part);
        if (shape >= 0) start = object.model->shapes[std::size_t(shape)].centre;
    }
    Motion motion;
    refChain(scene, ref, motion);
    return motion.point(povVector(start));
}

}  // namespace f2

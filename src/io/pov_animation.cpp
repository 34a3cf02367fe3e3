#include "io/pov_animation.h"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "io/comment_text.h"
#include "io/frame_primitives.h"
#include "io/pov_scene_text.h"
#include "io/pov_track.h"

namespace f2 {

namespace {
/// Merges the values of every frame into one SDL expression each: the
/// value itself when every frame has the same, else a look-up in an array of
/// every frame's value, declared in `declarations`.
class FrameMerger {
   public:
    explicit FrameMerger(const std::vector<PovValues>& frames) : frames_(frames) {}

    using Field = std::function<const std::string&(const PovValues&)>;

    /// `transform`: the values are `matrix <…>`, which an array holds as a `transform {}`.
    std::string expression(const std::string& name, const Field& field, bool transform = false) {
        const std::string& first = field(frames_[0]);
        const bool same = std::all_of(frames_.begin(), frames_.end(),
                                      [&](const PovValues& v) { return field(v) == first; });
        if (same) return first;
        ++arrays_;
        declarations_ << "#declare " << name << " = array[" << frames_.size() << "] {\n";
        for (std::size_t f = 0; f < frames_.size(); ++f) {
            declarations_ << "  "
                          << (transform ? "transform { " + field(frames_[f]) + " }" : field(frames_[f]))
                          << (f + 1 < frames_.size() ? ",\n" : "\n");
        }
        declarations_ << "};\n";
        return transform ? "transform { " + name + "[F2_K] }" : name + "[F2_K]";
    }

    /// Whether `field` has another value at some frame.
    bool varies(const Field& field) const {
        const std::string& first = field(frames_[0]);
        return std::any_of(frames_.begin(), frames_.end(),
                           [&](const PovValues& v) { return field(v) != first; });
    }

    /// A comment's value: the same at every frame, or a word saying it is not.
    std::string note(const Field& field) const {
        const std::string& first = field(frames_[0]);
        for (const PovValues& v : frames_)
            if (field(v) != first) return "(changes over the animation)";
        return first;
    }

    std::string declarations() const { return declarations_.str(); }
    std::size_t arrays() const { return arrays_; }

   private:
    const std::vector<PovValues>& frames_;
    std::ostringstream declarations_;
    std::size_t arrays_ = 0;
};

/// The camera's values in `v`: evaluated by POV-Ray from its keys (declared
/// in `tracks`; true) when it moves by keys alone (no ride, no `/look_at`,
/// no drive, no bezier), else as `merge` gives them.
bool povCamera(const SceneDesc& scene, int width, int height, FrameMerger& merge, std::ostringstream& tracks,
               PovValues& v) {
    const CameraDesc& camera = scene.camera;
    auto field = [](std::string PovValues::*member) {
        return [member](const PovValues& x) -> const std::string& { return x.*member; };
    };
    const bool moves = merge.varies(field(&PovValues::eye)) || merge.varies(field(&PovValues::right)) ||
                       merge.varies(field(&PovValues::direction));
    if (!moves || camera.attachedTo || camera.lookAt || !povEvaluatesOrStill(camera.track) ||
        !povEvaluatesOrStill(camera.zoom)) {
        v.eye = merge.expression("F2_Eye", field(&PovValues::eye));
        v.right = merge.expression("F2_Right", field(&PovValues::right));
        v.up = merge.expression("F2_Up", field(&PovValues::up));
        v.direction = merge.expression("F2_Direction", field(&PovValues::direction));
        return false;
    }
    // As povValuesAt: R·x^, R·y^·h/w, R·z^·d, vrotate being f2's Rz·Ry·Rx.
    const bool keyed = !camera.track.keys.empty();
    if (keyed) tracks << "// the camera: its keys\n" << povTrackPose(camera.track, "F2_Camera");
    const std::string rotation = keyed ? "F2_Camera_Rotation" : povVector(camera.pose.rotation);
    std::string distance = formatNumber(camera.distance);
    if (!camera.zoom.keys.empty()) {
        // cameraDistanceAt: never below a thousandth of the smallest key.
        double smallest = camera.zoom.keys.front().pose.position.x;
        for (const Key& k : camera.zoom.keys) smallest = std::min(smallest, double(k.pose.position.x));
        tracks << "// the camera's d: its keys\n" << povTrackPose(camera.zoom, "F2_Zoom");
        distance = "max(F2_Zoom_Position.x, " + formatNumber(smallest / 1000.0) + ")";
    }
    v.eye = keyed ? "F2_Camera_Position" : povVector(camera.pose.position);
    v.right = "vrotate(<1, 0, 0>, " + rotation + ")";
    v.up = "vrotate(<0, 1, 0>, " + rotation + ") * " + formatNumber(float(height) / float(width));
    v.direction = "vrotate(<0, 0, 1>, " + rotation + ") * " + distance;
    return true;
}

/// The `colour` and `visible` tracks (SPEC 10.3, 10.7) of each shape, as
/// frame_builder.h applies them: the last colour track that reaches it
/// wins; it is seen while all its visible tracks show it.
struct KeyedLooks {
    std::vector<const TargetTrack*> colour;               ///< per shape; null: none
    std::vector<std::vector<std::size_t>> visibleTracks;  ///< per shape: indices in scene.visibilityTracks

    KeyedLooks(const SceneDesc& scene, const std::vector<std::size_t>& firstOf, std::size_t shapes)
        : colour(shapes, nullptr), visibleTracks(shapes) {
        for (const TargetTrack& c : scene.colourTracks) {
            if (c.track.keys.empty() && !c.track.drives) continue;  // as forEachKeyedColour
            forEachShapeOf(scene, c.target, c.shape, [&](std::size_t shape, const ModelShape* inModel) {
                if (inModel && inModel->ownColor && c.shape < 0) return;
                colour[firstOf[c.target.object] + shape] = &c;
            });
        }
        for (std::size_t j = 0; j < scene.visibilityTracks.size(); ++j) {
            const TargetTrack& v = scene.visibilityTracks[j];
            forEachShapeOf(scene, v.target, v.shape, [&](std::size_t shape, const ModelShape*) {
                visibleTracks[firstOf[v.target.object] + shape].push_back(j);
            });
        }
    }
};

/// SDL of a colour track's 0..255 values as POV-Ray's 0..1: clamped and
/// rounded to whole levels, as framePrimitives does.
std::string colourOf(const std::string& pose) {
    std::string text = "<";
    for (const char* axis : {"x", "y", "z"}) {
        if (text.size() > 1) text += ", ";
        text += "floor(min(max(" + pose + "_Position." + axis + ", 0), 255) + 0.5)";
    }
    return text + "> / 255";
}
}  // namespace

bool povIniName(std::string_view name) {
    if (name.empty()) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
               c == '_' || c == '+' || c == '-';
    });
}

PovAnimation povAnimation(const SceneDesc& scene, int width, int height, const std::string& source,
                          const std::string& stem) {
    PovAnimation result;
    result.lastFrame = scene.lastFrame();
    const std::size_t count = std::size_t(result.lastFrame) + 1;

    // Every frame's shapes (hidden ones kept, so the list is the same at
    // every frame) and camera: a first pass for the box the suns stand
    // beyond, a second for the values (only frame 0's shapes are kept, for
    // what never changes: a long animation need not hold every frame's).
    const auto cameraAtFrame = [&](std::size_t f) {
        return cameraAt(scene, double(f)).resized(width, height);
    };
    PovBounds bounds;
    for (std::size_t f = 0; f < count; ++f)
        bounds.grow(cameraAtFrame(f), framePrimitives(scene, double(f), true));
    const std::vector<PlacedPrimitive> firstPrims = framePrimitives(scene, 0, true);
    std::vector<PovValues> frames(count);
    for (std::size_t f = 0; f < count; ++f)
        frames[f] =
            povValuesAt(scene, double(f), cameraAtFrame(f), framePrimitives(scene, double(f), true), bounds);

    FrameMerger merge(frames);
    PovValues v;
    std::ostringstream tracks;  // the key tracks POV-Ray evaluates
    result.cameraEvaluated = povCamera(scene, width, height, merge, tracks, v);
    auto lights = [&](const std::string& prefix, std::vector<PovLightValues> PovValues::*list,
                      std::size_t n) {
        std::vector<PovLightValues> out(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::string name = prefix + std::to_string(i) + "_";
            auto field = [&](std::string PovLightValues::*member) {
                return [list, i, member](const PovValues& x) -> const std::string& {
                    return (x.*list)[i].*member;
                };
            };
            out[i].location = merge.expression(name + "Location", field(&PovLightValues::location));
            out[i].pointAt = merge.expression(name + "PointAt", field(&PovLightValues::pointAt));
            out[i].intensity = merge.expression(name + "Intensity", field(&PovLightValues::intensity));
            out[i].areaA = merge.expression(name + "AreaA", field(&PovLightValues::areaA));
            out[i].areaB = merge.expression(name + "AreaB", field(&PovLightValues::areaB));
            out[i].note = merge.note(field(&PovLightValues::note));
        }
        return out;
    };
    v.suns = lights("F2_Sun", &PovValues::suns, scene.lights.size());
    v.locals = lights("F2_Light", &PovValues::locals, scene.localLights.size());
    // A shape whose object moves by its own keys alone (no ride, no drive,
    // no bezier) has them evaluated by POV-Ray (pov_track.h); other changing
    // values are read from their arrays.
    std::vector<std::size_t> objectOf, firstOf;  // each primitive's object, each object's first primitive
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        firstOf.push_back(objectOf.size());
        objectOf.insert(objectOf.end(), primitiveCountOf(scene.objects[o]), o);
    }
    std::size_t posed = scene.objects.size();  // the last object whose poses are declared
    const KeyedLooks looks(scene, firstOf, firstPrims.size());
    std::set<std::size_t> colourDeclared, visibleDeclared;  // tracks already written
    const std::size_t shapes = firstPrims.size();
    for (std::size_t i = 0; i < shapes; ++i) {
        const std::string name = "F2_Shape" + std::to_string(i) + "_";
        auto field = [i](std::string PovShapeValues::*member) {
            return [i, member](const PovValues& x) -> const std::string& { return x.shapes[i].*member; };
        };
        PovShapeValues& s = v.shapes.emplace_back();
        const std::size_t o = objectOf[i];
        const SceneObject& object = scene.objects[o];
        if (povEvaluatesMotion(object) && merge.varies(field(&PovShapeValues::transform))) {
            const std::string objectName = "F2_Object" + std::to_string(o);
            if (o != posed) {  // once per object, before its first moving shape
                tracks << "// " << commentText(object.name) << ": its keys\n"
                       << povObjectPoses(object, objectName);
                posed = o;
            }
            s.transform = "transform {" + povShapeMotion(object, i - firstOf[o], objectName) + " }";
            ++result.evaluated;
        } else {
            s.transform = merge.expression(name + "Transform", field(&PovShapeValues::transform), true);
        }
        const TargetTrack* colour = looks.colour[i];
        if (colour && povEvaluates(colour->track) && merge.varies(field(&PovShapeValues::colour))) {
            const std::size_t j = std::size_t(colour - scene.colourTracks.data());
            const std::string pose = "F2_Colour" + std::to_string(j);
            if (colourDeclared.insert(j).second)
                tracks << "// colour keys of " << commentText(firstPrims[i].label) << "...\n"
                       << povTrackPose(colour->track, pose);
            s.colour = colourOf(pose);
            ++result.evaluatedLooks;
        } else {
            s.colour = merge.expression(name + "Colour", field(&PovShapeValues::colour));
        }
        s.ambient = merge.expression(name + "Ambient", field(&PovShapeValues::ambient));
        const std::vector<std::size_t>& shown = looks.visibleTracks[i];
        const auto evaluable = [&](std::size_t j) {
            return povEvaluatesOrStill(scene.visibilityTracks[j].track);
        };
        if (merge.varies(field(&PovShapeValues::visible)) &&
            std::all_of(shown.begin(), shown.end(), evaluable)) {
            // visibleAt: keyed 0 or 1, shown from 0.5; a track without keys shows it.
            std::string all;
            for (std::size_t j : shown) {
                if (scene.visibilityTracks[j].track.keys.empty()) continue;
                const std::string pose = "F2_Visible" + std::to_string(j);
                if (visibleDeclared.insert(j).second)
                    tracks << "// visible keys of " << commentText(firstPrims[i].label) << "...\n"
                           << povTrackPose(scene.visibilityTracks[j].track, pose);
                all += (all.empty() ? "" : " & ") + pose + "_Position.x >= 0.5";
            }
            s.visible = all.empty() ? "1" : all;
            ++result.evaluatedLooks;
        } else {
            s.visible = merge.expression(name + "Visible", field(&PovShapeValues::visible));
        }
    }
    result.arrays = merge.arrays();

    const double fps = double(scene.fps);
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << "// " << commentText(source) << ", frames 0-" << result.lastFrame << " at " << scene.fps
        << " fps, exported by f2 (F2 Stage).\n"
        << "// Render every frame: cd <this directory> && povray " << stem
        << ".ini (+SFk +EFk: frame k only).\n"
        << "// clock is the time in seconds; keys below are evaluated at clock * fps, other values\n"
        << "// that change are read from their arrays at the nearest frame (docs/output.md).\n"
        << "// Coordinates are f2's: left-handed, y up, like POV-Ray's.\n"
        << "#version 3.7;\n\n"
        // f2's time in frames; within 1e-6 of a whole frame it is that frame,
        // so that a step key or an array lands on it despite the clock's rounding.
        << "#declare F2_Frame = clock * " << scene.fps << ";\n"
        << "#declare F2_Frame = (abs(F2_Frame - floor(F2_Frame + 0.5)) < 1e-6 ? floor(F2_Frame + 0.5) : "
           "F2_Frame);\n"
        << "#declare F2_K = min(max(floor(F2_Frame + 0.5), 0), " << result.lastFrame << ");\n\n"
        << merge.declarations() << "\n"
        << tracks.str() << "\n"
        << povSceneBody(scene, firstPrims, v);
    result.scene = out.str();

    std::ostringstream ini;
    ini.imbue(std::locale::classic());
    ini << "; " << commentText(source) << ": every frame, exported by f2 (F2 Stage).\n"
        << "; Run in this directory: povray " << stem << ".ini\n"
        << "Input_File_Name=" << stem << ".pov\n"
        << "Output_File_Name=" << stem << "_.png\n"
        << "Output_File_Type=N\n"
        << "Width=" << width << "\nHeight=" << height << "\n"
        << "Antialias=Off\nDisplay=Off\n"
        << "Initial_Frame=0\nFinal_Frame=" << result.lastFrame << "\n"
        << "Initial_Clock=0\nFinal_Clock=" << formatNumber(double(result.lastFrame) / fps) << "\n";
    result.ini = ini.str();
    return result;
}

}  // namespace f2

#pragma once
/// Building a scene from its commands (docs/design.md, "The front end"):
/// the meaning of each command of core/parse/language.h, read through the
/// CommandReader. One member function per command (dispatch()), grouped in
/// files by what they build: scene_builder.cpp (lines, names, targets),
/// scene_builder_lights.cpp (camera, lights, background, fps),
/// scene_builder_objects.cpp (primitives, instances, looks, captions),
/// scene_builder_models.cpp (`/model` blocks), scene_builder_keys.cpp
/// (keys, modes, drives, seconds) and scene_builder_attachments.cpp
/// (`/attach`, `/look_at`). Adding a command: a row in language.cpp, a case
/// in dispatch(), one member function here, its tests.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/parse/command_reader.h"
#include "core/parse/language.h"
#include "core/scene/models.h"

namespace f2::parsing {

struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

/// A command's target: an object, one part or shape of a model, the camera or a named light.
struct Target {
    std::size_t object = 0;
    int part = -1;        ///< index among the model's parts, or -1 for the object itself
    bool camera = false;  ///< the scene camera (SPEC 9.1); `object` and `part` unused
    int light = -1;       ///< a named light (SPEC 10.2): SceneDesc::lightMotions index; `object` unused
    int shape = -1;       ///< a shape of the model (`f2.head.leye`, SPEC 10.1), or -1
};

/// A key for the per-target books: object, part and shape in one number.
inline std::uint64_t slotOf(const Target& t) {
    return std::uint64_t(t.object) << 20 | std::uint64_t(t.part + 1) << 10 | std::uint64_t(t.shape + 1);
}

/// Whether a command accepts `camera` as its target.
enum class CameraTarget : bool { Refused, Accepted };
/// Whether a command accepts a named light as its target (SPEC 10.2).
enum class LightTarget : bool { Refused, Accepted };
/// Whether a command accepts a model's shape as its target (SPEC 10.1: looks and
/// colour or visible keys only).
enum class ShapeTarget : bool { Refused, Accepted };

/// What a track holds: the pose (none) or a property (SPEC 10.3).
using TrackProperty = std::optional<KeyProperty>;

/// Parse-time bookkeeping of one track: where each key came from, for the
/// duplicate-key warning. Parallel to Track::keys.
struct TrackBook {
    Target target;
    TrackProperty property;
    std::vector<Pos> origins;
    bool sorted = true;  ///< keys arrived in increasing frame order so far
    /// Keys whose time is still in seconds (SPEC 10.4), turned into frames at
    /// the end of the file, when `/fps` is known.
    std::vector<std::uint32_t> inSeconds;
};

/// An `/attach <name> <target> at <t>` (SPEC 10.7), kept until the end of
/// the file, when its time is in frames.
struct AttachChangeBook {
    std::uint32_t object = 0;
    KeyTime time;
    std::optional<FrameRef> mount;  ///< none: `world`
    std::string targetText;         ///< as written, for messages
    Pos command, timePos;
};

/// Parse-time bookkeeping of one object (its tracks' books are kept by
/// target: SceneBuilder::poseTrackBooks_ and the like).
struct ObjectBook {
    Pos defined;
    std::optional<Pos> attached;  ///< where its `/attach` is
    std::uint32_t loopNote =
        0;  ///< the loop pass it was defined in: SceneBuilder::loopNotes_ index + 1, 0 if none
};

/// A `/model` block being read (SPEC 10.1).
struct ModelBuild {
    std::shared_ptr<ModelType> type;
    Pos defined;                   ///< its `/model`
    Pos namePos;                   ///< its type's name there
    std::size_t errorsBefore = 0;  ///< errors reported before it: one inside makes "no shapes" a follow-on
    bool named = false;            ///< its name is valid and new: the type is registered at `/end`
    int nested = 0;                ///< `/model` lines inside it (each an error) whose `/end` is still to come
    IndexedModel indexed;
    /// Read again for an instance (SPEC 10.6): the type whose names it must give; not registered.
    std::shared_ptr<const ModelType> readFor;
};

/// What addObject needs of a creating command's line, taken before a model's
/// block is read again for the instance (SPEC 10.6) and the line is gone.
struct ObjectLine {
    std::string name;
    Pos namePos, command;
    TokenSpan nameSpan;
    std::uint32_t loopNote = 0;
};

/// A model type that instances may use: the robot, the human, or a `/model` of the file.
struct TypeBook {
    std::shared_ptr<const ModelType> type;
    std::optional<Pos> defined;  ///< none for the robot and the human
    /// Where its block's lines start, read again for an instance that sets a parameter (SPEC 10.6).
    SourceExpander::BlockStart start;
};

/// Parse-time bookkeeping of one named light (SPEC 10.2).
struct LightBook {
    Pos defined;
    std::uint32_t loopNote = 0;             ///< as ObjectBook::loopNote
    int poseBook = -1, intensityBook = -1;  ///< SceneBuilder::trackBooks_ indices, -1 if none
    std::optional<Pos> interp, attached;
};

/// Where a `/caption`'s times stand and whether they are in seconds: they
/// become frames at the end of the file, then `to` must follow `from`.
struct CaptionBook {
    Pos from, to;
    bool fromInSeconds = false, toInSeconds = false;
};

/// A `/key` of the camera, kept until the end of the file: a key without
/// numbers takes `/camera`'s pose, wherever `/camera` stands (SPEC 9.1).
struct CameraKey {
    KeyTime time;
    std::optional<Pose> pose;
    std::optional<Easing> mode;
    Pos origin;
};

/// The commands of the scene; /let, /repeat, /end and /include are run by the
/// SourceExpander before a line gets here.
class SceneBuilder final : public CommandReader {
   public:
    SceneBuilder(std::string_view fileName, const ParseLimits& limits, SymbolIndex* index)
        : CommandReader(fileName, limits), index_(index) {}

    /// `identity`: the main file's (device, inode), when it is a file.
    ParseResult run(std::string_view text,
                    std::optional<std::pair<std::uint64_t, std::uint64_t>> identity = std::nullopt);

   private:
    ParseResult finish();

    bool knowsCommand(std::string_view command) const override;

    /// The model type `/<type>` creates an instance of, or null.
    const TypeBook* typeOfCommand(std::string_view command) const;

    void parseLine();

    void unknownCommand(std::string_view head);

    void dispatch(CommandId command);
#ifdef F2_SCRATCH_COMMAND
    void parseScratch();
#endif
    /// The argument count of the line against its command's row of the
    /// language table (CommandSpec::counts), not counting `optionArgs`.
    bool expectCounts(int optionArgs = 0) { return expectArgs(command(command_).counts, optionArgs); }

    /// A name for a new object: valid and not yet used.
    bool newName(int i);

    /// The named light `name`, if it is one (SPEC 10.2).
    std::optional<int> lightNamed(std::string_view name) const;

    /// Tells the symbol index that `name` at `pos` names the light `light`.
    void noteLightUse(int light, Pos pos, std::string_view name);

    /// "the light 'lamp'" or "the ambient light 'sky'", for messages.
    std::string lightText(int light) const;

    /// Looks up an existing object by name; `token` is the whole argument, for the message;
    /// `cameraToo`: the command also takes `camera`, so it is a suggestion too ("Camera").
    std::optional<std::size_t> existing(std::string_view name, std::string_view token, Pos pos,
                                        bool cameraToo = false);

    /// The existing name closest to a mistyped one, in file order (then
    /// `camera` if `cameraToo`), within a total work budget for the whole file.
    std::string_view suggestName(std::string_view name, bool cameraToo);

    /// "body, head, lhand or rhand": the parts of a model, for messages.
    static std::string partList(const ModelType& model);

    /// Checks that the object is a model and `part` one of its parts.
    std::optional<int> partOf(std::size_t object, std::string_view part, Pos pos);

    /// Checks that `shape` is a shape on part `part` of the object's model.
    std::optional<int> shapeOf(std::size_t object, int part, std::string_view shape, Pos pos);

    /// Resolves `name` or `name.part` in argument i, or `camera` or a named
    /// light when the command takes them.
    std::optional<Target> target(int i, CameraTarget cameraUse = CameraTarget::Refused,
                                 LightTarget lightUse = LightTarget::Refused,
                                 ShapeTarget shapeUse = ShapeTarget::Refused);

    std::string targetName(Target t) const;

    /// The track of `t`'s pose, or of one of its properties (SPEC 10.3).
    Track& trackOf(Target t, TrackProperty property = std::nullopt);

    LightMotion& lightMotion(Target t) { return scene_.lightMotions[static_cast<std::size_t>(t.light)]; }

    LightBook& lightBook(Target t) { return lightBooks_[static_cast<std::size_t>(t.light)]; }

    /// The index of an object's or part's colour track (SPEC 10.3) or visibility
    /// track (10.7) in its list, made on its first key.
    std::size_t targetTrackIndex(Target t, KeyProperty property);

    void parseCamera();

    /// SPEC 7: at most maxLights light commands of every kind together.
    bool lightAllowed();

    void parseAmbLight();

    /// A light's direction (arguments first..first+2): not 0 0 0, and
    /// normalisable in float.
    Vec3 lightDirection(int first, bool& ok);

    /// The options a light command may end with: a word and its numbers.
    struct LightOptions {
        Fade fade;
        SoftShadow shadow;
        float tightness = 0;
        int nameArg = -1;  ///< the argument holding `name`'s word, -1 if unnamed
    };

    /// Reads the options after argument `first` (docs/scene-language.md,
    /// "Point and spot lights"); each of `allowed` at most once.
    bool lightOptions(int first, std::initializer_list<LightOption> allowed, LightOptions& out);

    /// A light command's arguments before its options (its row's count) are
    /// there and the light limit is not reached.
    bool lightArgsAllowed();

    /// The most arguments of a light command: /spot_light's 9 and its four
    /// options (tightness k, fade d p, size s n, name n). Every one is stored (kMaxStoredTokens).
    static constexpr int kMostLightArgs = 9 + 2 + 3 + 3 + 2;

    static_assert(kMostLightArgs + 1 <= kMaxStoredTokens);

    /// The largest angular radius of a soft sun (degrees): wider is no longer a sun.
    static constexpr float kMaxSunRadius = 45.0f;

    void parseDirLight();

    /// `/point_light <i> <x> <y> <z> [fade D P] [size S N]` and
    /// `/spot_light <i> <x> <y> <z> <dx> <dy> <dz> <radius> <falloff> [tightness T] [fade D P] [size S N]`
    void parseLocalLight(LocalLightKind kind);

    /// Makes the light named by argument `nameArg` (valid and new) a target of
    /// `/key`, `/interp` and `/attach` (SPEC 10.2); returns its lightMotions index.
    std::int32_t registerLight(int nameArg, bool ambient);

    void parseBackground();

    void parseFps();

    /// How many numbers give a primitive's size: 1 sphere, 2 cylinder, 3 box, 0 a model.
    static int sizeArgCount(ObjectKind kind);

    /// The size of a primitive from arguments first… (radius; radius and height; sides).
    Vec3 primitiveSize(ObjectKind kind, int first, bool& ok);

    /// A primitive (`type` null) or an instance of a model type (SPEC 10.1),
    /// with its parameters' values after the pose (SPEC 10.6).
    void parseObject(ObjectKind kind, const TypeBook* type = nullptr);

    static bool sameValues(const std::vector<ModelParam>& a, const std::vector<ModelParam>& b);

    /// The loop values of the line being read ("in /repeat k = 0") as an index
    /// into loopNotes_ + 1, shared by the objects of one pass; 0 outside loops.
    std::uint32_t definitionLoopNote();

    /// Adds the object named by argument 0, which is valid and new.
    void addObject(SceneObject object) { addObject(std::move(object), objectLine()); }

    void addObject(SceneObject object, ObjectLine line);

    /// The creating command's line (its name in argument 0), as addObject needs it.
    ObjectLine objectLine() {
        return {std::string(arg(0)), argPos(0), commandPos(), span(argPos(0), arg(0)), definitionLoopNote()};
    }

    /// Warnings about a scene that parses but is almost certainly not what was
    /// meant. Only for a scene without errors: a rejected scene is never shown.
    void warnAboutTheWholeScene();

    /// What a look command sets (SPEC 3, 10.1): a colour, which a shape painted
    /// in its model keeps unless the command names that shape, or the rest of
    /// the look, which reaches every shape of the target.
    enum class LookPart : bool { Colour, Other };

    /// The shapes' appearances a `/paint`-like command on `t` sets (SPEC 3, 10.1):
    /// a primitive's, a model's shape's, a part's shapes' or every shape's.
    template <class Set>
    void setAppearance(const Target& t, LookPart what, Set&& set) {
        SceneObject& o = scene_.objects[t.object];
        if (!o.model) return set(o.appearance[0]);
        if (t.shape >= 0) return set(o.appearance[std::size_t(t.shape)]);
        const std::vector<ModelShape>& shapes = o.model->shapes;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            if (t.part >= 0 && shapes[k].part != t.part) continue;
            if (what == LookPart::Colour && shapes[k].ownColor) continue;  // painted in its model
            set(o.appearance[k]);
        }
    }

    /// Where a look command's target is: a shape of the model being read
    /// (SPEC 10.1, `part.shape`), else a target of the scene.
    struct LookTarget {
        std::optional<Target> scene;
        ModelShape* modelShape = nullptr;
        explicit operator bool() const { return scene || modelShape; }
    };

    LookTarget lookTarget(int i);

    template <class Set>
    void setLook(const LookTarget& t, LookPart what, Set&& set) {
        if (t.modelShape) {
            set(t.modelShape->look);
            if (what == LookPart::Colour) t.modelShape->ownColor = true;
            return;
        }
        setAppearance(*t.scene, what, set);
    }

    void parsePaint();

    void parseMaterial();

    /// `/no_shadow <target>` (SPEC 10.8): the target casts no shadow.
    void parseNoShadow();

    /// `/checker <target> <r> <g> <b> <size>`: the second colour and cell size
    /// of a checker pattern (docs/rendering.md).
    void parseChecker();

    // Models (SPEC 10.1)
    /// `/model <type>`: starts reading a block; its lines go to parseModelLine
    /// up to the `/end` the expander pairs with it.
    void openModel();

    /// The `/model` line itself: the type's name and parameters.
    void readModelHeader(ModelBuild& build);

    /// The `<param> <default>` pairs after a `/model`'s type (SPEC 10.6), each
    /// set as a variable of the block; a bad one is reported and left out.
    std::vector<ModelParam> modelParams();

    /// The instance's values of its type's parameters (SPEC 10.6): the option
    /// words from argument `first` on, any order, each once; nullopt after an error.
    std::optional<std::vector<ModelParam>> instanceParams(const ModelType& type, int first);

    /// Reads `book`'s block again with an instance's parameter values (SPEC
    /// 10.6): the instance's own type, or null after an error in it.
    std::shared_ptr<const ModelType> readBlockFor(const TypeBook& book, const std::vector<ModelParam>& values,
                                                  const ObjectLine& line);

    /// Part and shape names of a block read again for an instance must be its type's (SPEC 10.6).
    bool sameNames(const ModelType& a, const ModelType& b);

    /// A line inside a `/model` block.
    void parseModelLine(std::string_view head);

    static std::string modelText(const ModelBuild& build) {
        return build.named ? quoteToken(build.type->name) : std::string("the model");
    }

    /// `/part <part> <parent> <px> <py> <pz> [<rx> <ry> <rz>]`.
    void parsePart();

    /// "unknown part 'b' of 'm' (expected a)": a part the block being read has not declared.
    std::string unknownBlockPart(std::string_view part) const;

    /// The `part.shape` in argument i names a shape of the model being read.
    std::optional<int> modelShapeArgument(int i);

    /// `/sphere|/cylinder|/box <part>.<shape> <size…> <cx> <cy> <cz> [<rx> <ry> <rz>]` in a model.
    void parseModelShape(ShapeKind kind, ObjectKind sized);

    /// The `/end` of a `/model` block: the type can be instanced from here on.
    void closeModel();

    void parseAnim();

    void parseInterp();

    /// "linear, ease, … or bounce": the language table's modes, for messages.
    static const std::string& modeWordList();

    /// The mode word in argument i (SPEC 9.3).
    std::optional<Interpolation> interpolationMode(int i);

    void parseKey();

    /// `/key <t> <target> <property> <values…> [<mode>]` (SPEC 10.3), the
    /// property's word in argument 2, `numbers` values after it, then the mode at `modeAt`.
    void parsePropertyKey(int numbers, int modeAt);

    /// `/drive <target> <channel> (<expression>)` (SPEC 10.7): the expression
    /// arrives compiled (SourceExpander); the drive goes into the track of the
    /// channel's property, beside its keys.
    void parseDrive();

    /// Whether `t` has channel `c` (SPEC 10.7): the pose's numbers where a
    /// pose is keyed, the others where keys of their property are allowed.
    bool hasChannel(Target t, DriveChannel c) const;

    /// What has channel `c`, for messages.
    static std::string channelTargets(DriveChannel c);

    /// The scene's `/fps` is known at the end of the file: every drive's `time` is read at it.
    void finishDrives();

    /// SPEC 10.3's table (and 10.7's `visible`): colour and visible on objects,
    /// parts and shapes, intensity on named lights, d on the camera.
    static bool hasProperty(Target t, KeyProperty property);

    /// "the camera", "the light 'lamp'", "the robot 'f2'", "the part 'f2.head'", for messages.
    std::string targetText(Target t) const;

    /// The mode word in argument i with the numbers after it up to argument
    /// `end` (SPEC 9.3; `bezier x1 y1 x2 y2`, SPEC 10.4).
    std::optional<Easing> easing(int i, int end);

    /// `/caption <from> <to> <x> <y> <size> "<text>" [colour <r> <g> <b>]` (SPEC 10.5).
    void parseCaption();

    /// The camera's keys, in file order, now that `/camera`'s pose is known.
    void addCameraKeys();

    int& trackBookIndex(Target t, TrackProperty property);

    /// `key.time` is `time.value`: frames, or seconds until convertSecondsToFrames.
    void addKey(Target t, TrackProperty property, KeyTime time, const Key& key, Pos origin);

    /// A time in seconds (at `origin`) in frames at the scene's `/fps`; beyond
    /// the frame limit an error there.
    double framesOfSeconds(double seconds, Pos origin);

    /// Keys and captions written in seconds become frames at the scene's
    /// `/fps`, wherever it stands (SPEC 10.4); then a caption must end after it starts.
    void convertSecondsToFrames();

    void parseLookAt();

    void parseAttach();

    /// The `/attach … at` changes (SPEC 10.7), their times now in frames, go
    /// to their objects, sorted; then one time per name, and no cycle in any
    /// interval between two changes: a cycle can only be closed by a ride
    /// that starts at the interval's start, so each change climbs the rides
    /// that hold then, from its new holder, looking for its own object.
    void checkAttachChanges();

    /// The change `b` closes a cycle at its time: told, and then taken as if
    /// the ride ended (one message per cycle).
    void reportRideCycle(const AttachChangeBook& b);

    // Attachment trees (see setParent_)
    void growSets();

    std::uint32_t findSet(std::uint32_t x);

    /// `child` (the top of its tree) now rides on `parent`.
    void joinSets(std::uint32_t child, std::uint32_t parent);

    /// SceneDesc::attachOrder: each attached object after the attached object
    /// it rides on; every object that may ride when the rides change.
    void orderAttachments();

    void warnReplaced(Target t, TrackProperty property, double frame, Pos now, Pos before);

    /// A target's `/interp` sets its property tracks' default mode too (SPEC 10.3).
    void applyInterpToPropertyTracks();

    /// Whole objects' colour tracks first, then parts', then shapes', so that
    /// the most specific track, applied last, wins.
    void orderColourTracks();

    void sortUnsortedTracks();

    SymbolIndex* index_ = nullptr;
    SceneDesc scene_;
    /// The command of the line being built (a model instance's line reads as /robot's).
    CommandId command_ = CommandId::Camera;

    /// Loop notes of objects defined in a loop ("in /repeat k = 0"); ObjectBook::loopNote - 1.
    std::vector<std::string> loopNotes_;
    std::size_t nameSuggestWork_ = 0;
    std::unordered_map<std::string, std::size_t, StringHash, std::equal_to<>> names_;
    std::vector<ObjectBook> books_;  ///< parallel to scene_.objects

    /// By target (slotOf): SceneBuilder::trackBooks_ index of its pose track, where
    /// its /interp was given, and its colour and visible tracks' indices in
    /// SceneDesc::colourTracks and visibilityTracks.
    std::unordered_map<std::uint64_t, int> poseTrackBooks_;
    std::unordered_map<std::uint64_t, std::optional<Pos>> interps_;
    std::unordered_map<std::uint64_t, std::size_t> colourTrackIndex_, visibilityTrackIndex_;

    /// Model types by name (SPEC 10.1): the robot, the human, then the file's.
    std::unordered_map<std::string, TypeBook, StringHash, std::equal_to<>> types_{
        {"robot", {robotModel(), std::nullopt, {}}}, {"human", {humanModel(), std::nullopt, {}}}};
    std::optional<ModelBuild> building_;
    SourceExpander::BlockStart start_;  ///< of the last `/model` block opened
    std::vector<TrackBook> trackBooks_;
    std::optional<Pos> cameraSeen_, backgroundSeen_, fpsSeen_, lookAtSeen_, cameraAttached_, cameraInterp_;
    std::size_t keyLines_ = 0;
    std::size_t lightLines_ = 0;
    std::vector<CameraKey> cameraKeys_;
    std::vector<CaptionBook> captionBooks_;  ///< parallel to scene_.captions
    int cameraTrackBook_ = -1, cameraZoomBook_ = -1;
    float writtenAmbient_ = 0;  ///< every /amb_light's intensity as written, named or not

    /// Named lights (SPEC 10.2): name -> SceneDesc::lightMotions index, and their books.
    std::unordered_map<std::string, std::size_t, StringHash, std::equal_to<>> lightNames_;
    std::vector<LightBook> lightBooks_;
    std::vector<int> colourTrackBooks_;      ///< parallel to scene_.colourTracks: trackBooks_ indices
    std::vector<int> visibilityTrackBooks_;  ///< parallel to scene_.visibilityTracks: trackBooks_ indices

    /// Attachment trees as disjoint sets (union by size, path halving), each
    /// set knowing the object at its top: an `/attach` closes a cycle exactly
    /// when the new parent's top is the object being attached. Near O(1) per
    /// `/attach`, so a chain of a million attachments parses fast.
    std::vector<std::uint32_t> setParent_, setSize_, setTop_;

    /// `/attach … at` (SPEC 10.7) until the end of the file (checkAttachChanges).
    std::vector<AttachChangeBook> attachChangeBooks_;

    /// Every `/drive` (SPEC 10.7) until the end of the file, when `/fps` is known.
    std::vector<std::shared_ptr<f2::Drive>> drives_;
};

}  // namespace f2::parsing

#include "core/parse/language.h"

#include <array>

#include "core/util/decimal_text.h"

namespace f2 {

namespace {

using enum ArgKind;

constexpr std::array kNumbers = {Number};
constexpr std::array kCreate = {NewName, Number};
constexpr std::array kTargetThenNumbers = {Target, Number};
constexpr std::array kTarget = {Target};
constexpr std::array kAnim = {Target, Part};
constexpr std::array kKey = {Number, Target, Number, Number, Number, Number, Number, Number, Mode};
constexpr std::array kInterp = {Target, Mode};
constexpr std::array kLet = {Variable, Number};
constexpr std::array kRepeat = {Variable, Number};
constexpr std::array kInclude = {Path};
constexpr std::array kLookAt = {PointOrTarget, Number};
constexpr std::array kAttach = {Object, Target};
constexpr std::array kModel = {NewName};
constexpr std::array kPart = {NewName, Part, Number};
constexpr std::array kCaption = {Number, Number, Number, Number, Number, Text, Number};
constexpr std::array kDrive = {Target, Channel, Number};
constexpr std::array<ArgKind, 0> kNone = {};
// Argument counts (CommandSpec::counts). /amb_light's 3 is with `name <lname>`,
// its one option; a primitive's are its name, sizes and centre, then a rotation.
constexpr std::array kCountsCamera = {3, 6, 9};
constexpr std::array kCountsAmbLight = {1, 3};
constexpr std::array kCountsDirLight = {4};
constexpr std::array kCountsPointLight = {4};
constexpr std::array kCountsSpotLight = {9};
constexpr std::array kCountsBackground = {3};
constexpr std::array kCountsMaterial = {5, 6};
constexpr std::array kCountsSphere = {5, 8};
constexpr std::array kCountsCylinder = {6, 9};
constexpr std::array kCountsBox = {7, 10};
constexpr std::array kCountsPaint = {4};
constexpr std::array kCountsChecker = {5};
constexpr std::array kCountsRobot = {4, 7};
constexpr std::array kCountsHuman = {4, 7};
constexpr std::array kCountsAnim = {1, 2};
constexpr std::array kCountsInterp = {2, 6};
constexpr std::array kCountsFps = {1};
constexpr std::array kCountsLookAt = {1, 3};
constexpr std::array kCountsAttach = {2, 4};
constexpr std::array kCountsNoShadow = {1};
constexpr std::array kCountsPart = {5, 8};
constexpr std::array kCountsDrive = {3};
constexpr std::array<int, 0> kCountedByBuilder = {};
#ifdef F2_SCRATCH_COMMAND
#include "scratch_command_counts.inc"
#endif

// Rows in CommandId order (checked below). The syntax and meaning are what
// hover shows; docs/scene-language.md has each command's full story.
constexpr auto kCommands = std::to_array<CommandSpec>({
    {CommandId::Camera, "/camera", Edition::First, CommandGroup::Setting, kNumbers, kCountsCamera,
     "/camera <w> <h> <d> [<px> <py> <pz> [<rx> <ry> <rz>]]",
     "/camera ${1:800} ${2:600} ${3:0.5} ${4:0} ${5:0} ${6:0} ${7:0} ${8:0} ${9:0}",
     "An image of `w × h` pixels seen from the eye at `p` (default the origin), looking along "
     "the rotated +z axis. `d` is the distance to the screen in screen widths (`0.5` gives "
     "90°). At most one per scene; without one, `/camera 800 600 0.5`.",
     false},
    {CommandId::AmbLight, "/amb_light", Edition::First, CommandGroup::Setting, kNumbers, kCountsAmbLight,
     "/amb_light <i> [name <lname>]", "/amb_light ${1:0.2}",
     "Ambient light of intensity `i ≥ 0`; several add up. `name lname`: its intensity can be keyed "
     "(`/key t lname intensity i`).",
     false},
    {CommandId::DirLight, "/dir_light", Edition::First, CommandGroup::Setting, kNumbers, kCountsDirLight,
     "/dir_light <i> <x> <y> <z> [angle <r> <n>] [name <lname>]", "/dir_light ${1:0.8} ${2:0} ${3:-1} ${4:1}",
     "A directional light of intensity `i ≥ 0` whose light travels along `(x, y, z)`; it casts "
     "shadows. `angle r n`: a sun of angular radius `r` degrees with soft shadows from `n × n` "
     "shadow rays. `name lname`: a light that keys and `/attach` move (its direction turns with it).",
     false},
    {CommandId::PointLight, "/point_light", Edition::Third, CommandGroup::Setting, kNumbers,
     kCountsPointLight, "/point_light <i> <x> <y> <z> [fade <d> <p>] [size <s> <n>] [name <lname>]",
     "/point_light ${1:0.8} ${2:0} ${3:300} ${4:0}",
     "A light of intensity `i ≥ 0` at `(x, y, z)`, casting shadows. `fade d p`: intensity "
     "`i · 2 / (1 + (D/d)^p)` at distance `D` (POV-Ray's fade_distance, fade_power). `size s n`: "
     "soft shadows from a disc of diameter `s`, `n × n` shadow rays. `name lname`: a light that keys "
     "and `/attach` move (a bulb on a lamp's head), whose `intensity` can be keyed.",
     false},
    {CommandId::SpotLight, "/spot_light", Edition::Third, CommandGroup::Setting, kNumbers, kCountsSpotLight,
     "/spot_light <i> <x> <y> <z> <dx> <dy> <dz> <radius> <falloff> [tightness <k>] [fade <d> <p>] "
     "[size <s> <n>] [name <lname>]",
     "/spot_light ${1:0.8} ${2:0} ${3:300} ${4:0} ${5:0} ${6:-1} ${7:0} ${8:20} ${9:30}",
     "A point light whose light travels along `(dx, dy, dz)` in a cone: full within `radius` "
     "degrees of the axis, none beyond `falloff`, a smooth edge between (POV-Ray's spotlight). "
     "Options as for `/point_light`, and `tightness k`: times `cos(θ)^k`.",
     false},
    {CommandId::Background, "/background", Edition::First, CommandGroup::Setting, kNumbers, kCountsBackground,
     "/background <r> <g> <b>", "/background ${1:0} ${2:0} ${3:0}",
     "Colour of rays that hit nothing, integers 0..255 (default black). At most one per scene.", false},
    {CommandId::Material, "/material", Edition::First, CommandGroup::Look, kTargetThenNumbers,
     kCountsMaterial, "/material <target> <ka> <kd> <ks> <n> [<reflection>] [emit <e>]",
     "/material ${1:target} ${2:1} ${3:1} ${4:0.3} ${5:32}",
     "Phong coefficients of an object or part (default `1 1 0.3 32`): `ka, kd, ks ≥ 0`, `n > 0`; "
     "an optional mirror `reflection ≥ 0` (default 0) adds that share of what the surface "
     "reflects, as POV-Ray's `reflection`; `emit e ≥ 0` adds `e` times the colour whatever the lights "
     "(a glow, as POV-Ray's `emission`). On a robot or human it applies to every part.",
     false},
    {CommandId::Sphere, "/sphere", Edition::First, CommandGroup::Creating, kCreate, kCountsSphere,
     "/sphere <name> <r> <px> <py> <pz> [<rx> <ry> <rz>]", "/sphere ${1:name} ${2:r} ${3:0} ${4:0} ${5:0}",
     "A sphere of radius `r > 0` centred at `p`.", false},
    {CommandId::Cylinder, "/cylinder", Edition::First, CommandGroup::Creating, kCreate, kCountsCylinder,
     "/cylinder <name> <r> <h> <px> <py> <pz> [<rx> <ry> <rz>]",
     "/cylinder ${1:name} ${2:r} ${3:h} ${4:0} ${5:0} ${6:0}",
     "A closed cylinder of radius `r > 0` and height `h > 0` along its local y, centred on `p`.", false},
    {CommandId::Box, "/box", Edition::First, CommandGroup::Creating, kCreate, kCountsBox,
     "/box <name> <sx> <sy> <sz> <px> <py> <pz> [<rx> <ry> <rz>]",
     "/box ${1:name} ${2:sx} ${3:sy} ${4:sz} ${5:0} ${6:0} ${7:0}",
     "A box with sides `sx, sy, sz > 0` along its local axes, centred on `p`.", false},
    {CommandId::Paint, "/paint", Edition::First, CommandGroup::Look, kTargetThenNumbers, kCountsPaint,
     "/paint <target> <r> <g> <b>", "/paint ${1:target} ${2:200} ${3:200} ${4:200}",
     "Colour of an object, a whole model or one part (`name.head`), integers 0..255. Applied in "
     "file order.",
     false},
    {CommandId::Checker, "/checker", Edition::Third, CommandGroup::Look, kTargetThenNumbers, kCountsChecker,
     "/checker <target> <r> <g> <b> <size>", "/checker ${1:target} ${2:40} ${3:40} ${4:40} ${5:100}",
     "A checker pattern: cells of side `size > 0` in the primitive's own frame alternate between "
     "the `/paint` colour and this second colour (0..255), as POV-Ray's `checker`. Same targets "
     "and file order as `/paint`.",
     false},
    {CommandId::Robot, "/robot", Edition::First, CommandGroup::Creating, kCreate, kCountsRobot,
     "/robot <name> <px> <py> <pz> [<rx> <ry> <rz>]",
     "/robot ${1:name} ${2:0} ${3:0} ${4:0} ${5:0} ${6:180} ${7:0}",
     "The robot F-2 (200 tall, stands on local y = −105) with its root at `p`, facing its local "
     "+z. Parts: body, head (with two eyes), lhand, rhand.",
     false},
    {CommandId::Human, "/human", Edition::First, CommandGroup::Creating, kCreate, kCountsHuman,
     "/human <name> <px> <py> <pz> [<rx> <ry> <rz>]",
     "/human ${1:name} ${2:0} ${3:0} ${4:0} ${5:0} ${6:180} ${7:0}",
     "A human (182 tall, stands on local y = −105) with its root at `p`, facing its local +z. "
     "Parts: body, head, lhand, rhand.",
     false},
    {CommandId::Anim, "/anim", Edition::First, CommandGroup::Motion, kAnim, kCountsAnim,
     "/anim <target>  or  /anim <name> <part>", "/anim ${1:target}",
     "Marks a target as animated (checked, no other effect: a `/key` needs no `/anim`).", true},
    {CommandId::Key, "/key", Edition::First, CommandGroup::Motion, kKey, kCountedByBuilder,
     "/key <t> <target> [<px> <py> <pz> <rx> <ry> <rz>] [<mode>]  or  /key <t> <target> <property> <values…> "
     "[<mode>]",
     "/key ${1:0} ${2:target} ${3:0} ${4:0} ${5:0} ${6:0} ${7:0} ${8:0}",
     "Time `t` is a key of `target`: an object's absolute position and rotation, or a part's "
     "offset from its pivot and rotation about it. Without the six numbers: the rest state. "
     "`t` is in frames (fractions allowed) or, as `2.5s` or `(expr)s`, in seconds at the scene's `/fps`. "
     "A property instead of the pose: `colour r g b` (an object or part), `intensity i` (a named "
     "light), `d` (the camera's zoom).",
     true},
    {CommandId::Interp, "/interp", Edition::First, CommandGroup::Motion, kInterp, kCountsInterp,
     "/interp <target> <mode>", "/interp ${1:target} ${2|linear,ease,spline|}",
     "How the target moves between its keys: `linear` (default), `ease` (smoothstep), `spline` "
     "(Catmull-Rom through the keys); in the second edition `ease_in`, `ease_out`, `step`; in the "
     "third `back` (overshoots), `elastic` (wobbles), `bounce`, `bezier x1 y1 x2 y2` (CSS's "
     "cubic-bezier).",
     true},
    {CommandId::Fps, "/fps", Edition::First, CommandGroup::Setting, kNumbers, kCountsFps, "/fps <n>",
     "/fps ${1:24}", "Playback frames per second, 1..1000 (default 24).", false},
    {CommandId::Let, "/let", Edition::Second, CommandGroup::Source, kLet, kCountedByBuilder,
     "/let <var> <number>", "/let ${1:var} ${2:0}",
     "Defines a variable from the next line on; use it in an expression as `(var)`.", false},
    {CommandId::Repeat, "/repeat", Edition::Second, CommandGroup::Source, kRepeat, kCountedByBuilder,
     "/repeat <var> <from> <to> [<step>]  …  /end", "/repeat ${1:i} ${2:1} ${3:3}\n$0\n/end",
     "Reads the lines up to `/end` once for each value of `var` from `from` to `to`.", false},
    {CommandId::End, "/end", Edition::Second, CommandGroup::Source, kNone, kCountedByBuilder, "/end", "/end",
     "Closes a `/repeat` block.", false},
    {CommandId::Include, "/include", Edition::Second, CommandGroup::Source, kInclude, kCountedByBuilder,
     "/include <path>", "/include ${1:file.f2}",
     "Reads another scene file here, as if its lines stood here (relative to this file's "
     "directory).",
     false},
    {CommandId::LookAt, "/look_at", Edition::Second, CommandGroup::Motion, kLookAt, kCountsLookAt,
     "/look_at <x> <y> <z>  or  /look_at <target>", "/look_at ${1:target}",
     "At every frame the camera turns to face a fixed point, an object or a part.", false},
    {CommandId::Attach, "/attach", Edition::Second, CommandGroup::Motion, kAttach, kCountsAttach,
     "/attach <name> <target> [at <t>]", "/attach ${1:name} ${2:target}",
     "The object `name` (or `camera`) rides on `target`: its pose is read in the target's frame. With "
     "`at <t>` an object changes its ride at key time `t` (`world`: the ride ends).",
     true},
    {CommandId::Caption, "/caption", Edition::Third, CommandGroup::Setting, kCaption, kCountedByBuilder,
     "/caption <from> <to> <x> <y> <size> \"<text>\" [colour <r> <g> <b>]",
     "/caption ${1:0} ${2:2s} ${3:0.05} ${4:0.9} ${5:0.06} \"${6:text}\"",
     "Text over the picture while `from ≤ t < to` (key times: frames, or seconds as `2s`): its "
     "baseline starts at `(x, y)` in fractions of the image (0 0 top left), its font is `size` "
     "of the image height; `colour r g b` (default white). `\\\"` and `\\\\` in the text stand for "
     "`\"` and `\\`, `{ … }` is expanded.",
     false},
    {CommandId::NoShadow, "/no_shadow", Edition::Third, CommandGroup::Look, kTarget, kCountsNoShadow,
     "/no_shadow <target>", "/no_shadow ${1:target}",
     "The target (an object, a part or a shape) casts no shadow; it is still seen and reflected, as "
     "POV-Ray's `no_shadow`.",
     false},
    {CommandId::Model, "/model", Edition::Third, CommandGroup::Creating, kModel, kCountedByBuilder,
     "/model <type>  …  /end",
     "/model ${1:type}\n/part ${2:base} root ${3:0} ${4:0} ${5:0}\n/box ${2:base}.${6:shape} ${7:40} ${8:10} "
     "${9:40} ${10:0} ${11:0} ${12:0}\n$0\n/end",
     "Defines a model type: `/part`s and shapes on them (`/sphere`, `/cylinder`, `/box` named "
     "`part.shape`, placed in the part's frame), and their `/paint`, `/material`, `/checker`, up to "
     "`/end`. `/type name px py pz [rx ry rz]` then makes an instance, as `/robot` does.",
     false},
    {CommandId::Part, "/part", Edition::Third, CommandGroup::Creating, kPart, kCountsPart,
     "/part <part> <parent> <px> <py> <pz> [<rx> <ry> <rz>]",
     "/part ${1:part} ${2:root} ${3:0} ${4:0} ${5:0}",
     "Inside `/model`: a part hanging on `root` or an earlier part, its pivot at `p` in the parent's "
     "frame, turned by its rest rotation `r`. Its keys (`/key t name.part …`) move it about the pivot.",
     false},
    {CommandId::Drive, "/drive", Edition::Third, CommandGroup::Motion, kDrive, kCountsDrive,
     "/drive <target> <channel> (<expression>)", "/drive ${1:target} ${2|px,py,pz,rx,ry,rz|} (${3:frame})",
     "Every frame, one channel of the target is the expression's value, in place of its keys: "
     "`px py pz rx ry rz` (the six numbers of a key), `intensity` (a named light), `d` (the camera), "
     "`r g b` (a colour channel 0..255). In it, `frame` is the frame drawn (fractional in motion "
     "blur) and `time` is `frame / fps`; other variables keep their value at this line.",
     true},
#ifdef F2_SCRATCH_COMMAND
#include "scratch_command_row.inc"
#endif
});

constexpr bool inIdOrder() {
    for (std::size_t i = 0; i < kCommands.size(); ++i) {
        if (static_cast<std::size_t>(kCommands[i].id) != i) return false;
    }
    return true;
}
static_assert(inIdOrder(), "kCommands must list the commands in CommandId order");

constexpr std::array<LightOptionSpec, 5> kLightOptions = {{
    {LightOption::Fade, "fade", 2, "a distance and a power"},
    {LightOption::Size, "size", 2, "a diameter and the samples per side"},
    {LightOption::Angle, "angle", 2, "an angular radius and the samples per side"},
    {LightOption::Tightness, "tightness", 1, "a number"},
    {LightOption::Name, "name", 1, "a new name"},
}};

constexpr std::array<KeyPropertySpec, 4> kKeyProperties = {{
    {KeyProperty::Colour, "colour", 3, "r g b", "a primitive, a robot or human, or a part"},
    {KeyProperty::Intensity, "intensity", 1, "i", "a named light"},
    {KeyProperty::Zoom, "d", 1, "d", "the camera"},
    {KeyProperty::Visible, "visible", 1, "0 or 1", "a primitive, a robot or human, or a part"},
}};

constexpr std::array<Interpolation, 10> kModes = {
    Interpolation::Linear, Interpolation::Ease,   Interpolation::EaseIn, Interpolation::EaseOut,
    Interpolation::Step,   Interpolation::Spline, Interpolation::Back,   Interpolation::Elastic,
    Interpolation::Bounce, Interpolation::Bezier};

}  // namespace

ArgKind CommandSpec::argumentKind(int index) const {
    if (args.empty()) return ArgKind::Number;
    const auto i = static_cast<std::size_t>(index);
    return i < args.size() ? args[i] : args.back();
}

int CommandSpec::cameraArgument() const {
    if (!takesCamera) return -1;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == ArgKind::Target || args[i] == ArgKind::Object) return static_cast<int>(i);
    }
    return -1;
}

std::span<const CommandSpec> commands() { return kCommands; }

const CommandSpec& command(CommandId id) { return kCommands[static_cast<std::size_t>(id)]; }

const CommandSpec* findCommand(std::string_view name) {
    for (const CommandSpec& c : kCommands) {
        if (c.name == name) return &c;
    }
    return nullptr;
}

std::span<const LightOptionSpec> lightOptions() { return kLightOptions; }

std::span<const KeyPropertySpec> keyProperties() { return kKeyProperties; }

const KeyPropertySpec* findKeyProperty(std::string_view word) {
    for (const KeyPropertySpec& p : kKeyProperties) {
        if (p.word == word) return &p;
    }
    return nullptr;
}

std::span<const Interpolation> interpolationModes() { return kModes; }

std::optional<Interpolation> modeFromWord(std::string_view word) {
    for (Interpolation m : kModes) {
        if (interpolationName(m) == word) return m;
    }
    return std::nullopt;
}

int modeNumberCount(Interpolation mode) { return mode == Interpolation::Bezier ? 4 : 0; }

std::string easingText(const Easing& easing) {
    std::string text(interpolationName(easing.mode));
    if (easing.mode == Interpolation::Bezier) {
        for (float v : {easing.curve.x1, easing.curve.y1, easing.curve.x2, easing.curve.y2}) {
            // The float's own shortest form: 0.1, not 0.10000000149011612.
            text += ' ';
            text += shortestText(v == 0 ? 0.0f : v);
        }
    }
    return text;
}

}  // namespace f2

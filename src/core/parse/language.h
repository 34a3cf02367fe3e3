#pragma once
/// The one definition of the scene language's vocabulary: every command with
/// its argument kinds, syntax, snippet, one-line doc and edition; the light
/// options; the interpolation modes; and the name rule (the expression
/// functions are expression.h's table, the part names scene_desc.h's).
/// The parser's dispatch, the source expander, the language server's
/// completion and hover, the viewer's highlighter, and the generated TextMate
/// grammar and fuzz dictionary (`f2 language`) all read it. Adding a command:
/// docs/design.md, "Adding a command".
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/scene/scene_desc.h"

namespace f2 {

/// The edition a word came in: SPEC 2-7 (first), SPEC 9 (second), SPEC 10 (third).
enum class Edition : std::uint8_t { First = 1, Second = 2, Third = 3 };

/// What an argument of a command holds (for completion, hover and the grammar).
enum class ArgKind : std::uint8_t {
    Number,         ///< any number (or an expression)
    NewName,        ///< a name the command creates
    Target,         ///< `name` or `name.part` (or `camera` where the command takes it)
    Object,         ///< an existing object's name (or `camera`, for /attach)
    Part,           ///< body, head, lhand or rhand
    Mode,           ///< an interpolation mode
    Variable,       ///< a variable's name
    Path,           ///< a file path
    PointOrTarget,  ///< /look_at: x y z, or a target
    Text,           ///< a text in double quotes (/caption)
    Channel,        ///< a drive's channel: px … rz, intensity, d, r g b (SPEC 10.7)
};

/// What a command does; the grammar and the highlighters colour by it.
enum class CommandGroup : std::uint8_t {
    Setting,   ///< camera, lights, background, fps
    Creating,  ///< creates a named object
    Look,      ///< /paint, /material, /checker
    Motion,    ///< /anim, /key, /interp, /look_at, /attach
    Source,    ///< read by the SourceExpander, never by the command parser: /let, /repeat, /end, /include
};

/// Every command, in table order (completion lists them so).
enum class CommandId : std::uint8_t {
    Camera,
    AmbLight,
    DirLight,
    PointLight,
    SpotLight,
    Background,
    Material,
    Sphere,
    Cylinder,
    Box,
    Paint,
    Checker,
    Robot,
    Human,
    Anim,
    Key,
    Interp,
    Fps,
    Let,
    Repeat,
    End,
    Include,
    LookAt,
    Attach,
    Caption,
    NoShadow,
    Model,
    Part,
    Drive,
#ifdef F2_SCRATCH_COMMAND
    Scratch,  // tests/scratch_command: a command added as docs/design.md says, in a build of its own
#endif
};

struct CommandSpec {
    CommandId id;
    std::string_view name;  ///< "/robot"
    Edition edition;
    CommandGroup group;
    std::span<const ArgKind> args;  ///< argument kinds; the last repeats for further arguments
    /// The argument counts it takes, a light's options not counted: what the
    /// parser checks and its message lists ("takes 3, 6 or 9 arguments").
    /// Empty where the count depends on the line: /key (its property),
    /// /caption (its colour), /model (its parameters) and the four the
    /// SourceExpander reads.
    std::span<const int> counts;
    std::string_view syntax;   ///< "/robot <name> <px> <py> <pz> [<rx> <ry> <rz>]"
    std::string_view snippet;  ///< LSP snippet of the whole command
    std::string_view meaning;  ///< a short explanation (Markdown)
    /// Whether its first target (or object) argument may be `camera` (SPEC 9.1)
    /// or a named light (SPEC 10.2): /anim, /key, /interp and /attach's rider.
    bool takesCamera = false;

    /// The kind of argument `index` (0-based).
    ArgKind argumentKind(int index) const;
    /// The index of the argument that may be `camera`, or -1.
    int cameraArgument() const;
};

/// Whether the command makes a shape in a `/model` block (SPEC 10.1): /sphere, /cylinder, /box.
constexpr bool createsModelShape(CommandId id) {
    return id == CommandId::Sphere || id == CommandId::Cylinder || id == CommandId::Box;
}

/// Every command of the language, in CommandId order.
std::span<const CommandSpec> commands();
const CommandSpec& command(CommandId id);
/// The command named `name` ("/robot"), or nullptr.
const CommandSpec* findCommand(std::string_view name);

/// The options of the light commands (docs/scene-language.md, "Point and spot lights").
/// `name` (SPEC 10.2) makes the light a named one, which keys and `/attach` reach.
enum class LightOption : std::uint8_t { Fade, Size, Angle, Tightness, Name };
struct LightOptionSpec {
    LightOption option;
    std::string_view word;  ///< "fade"
    int numbers;            ///< how many numbers (for `name`: words) follow it
    std::string_view what;  ///< "a distance and a power", for messages
};
/// Every light option, in LightOption order.
std::span<const LightOptionSpec> lightOptions();

/// `/material`'s option word of a glow (SPEC 10.8): `… [<reflection>] emit <e>`.
inline constexpr std::string_view kEmitWord = "emit";

/// What a `/key <t> <target> <property> <values…>` keys besides the pose (SPEC 10.3).
enum class KeyProperty : std::uint8_t { Colour, Intensity, Zoom, Visible };
struct KeyPropertySpec {
    KeyProperty property;
    std::string_view word;     ///< "colour"
    int numbers;               ///< how many values follow it
    std::string_view values;   ///< "r g b", for messages and hover
    std::string_view targets;  ///< what has it: "a primitive, a robot or human, or a part"
};
/// Every key property, in KeyProperty order.
std::span<const KeyPropertySpec> keyProperties();
/// The property named `word` ("colour"), or nullptr.
const KeyPropertySpec* findKeyProperty(std::string_view word);

/// The interpolation modes (SPEC 6, 9.3), in the order completion lists them.
std::span<const Interpolation> interpolationModes();
/// The mode named `word`, if any.
std::optional<Interpolation> modeFromWord(std::string_view word);
/// How many numbers follow the mode's word: 4 for `bezier x1 y1 x2 y2`, else 0.
int modeNumberCount(Interpolation mode);
/// The mode's words as written: "ease_in", or "bezier 0.25 0.1 0.25 1".
std::string easingText(const Easing& easing);

/// The name of the scene camera as a target (SPEC 9.1); no object may take it.
inline constexpr std::string_view kCameraName = "camera";
/// `/attach <name> world at <t>` (SPEC 10.7): no holder, the ride ends
/// (unless an object is named so).
inline constexpr std::string_view kWorldName = "world";
/// A `/part`'s parent when it hangs on the model's root frame (SPEC 10.1).
inline constexpr std::string_view kRootName = "root";
/// The word before a change of ride's time: `/attach <name> <target> at <t>` (SPEC 10.7).
inline constexpr std::string_view kAtWord = "at";

/// The name rule (SPEC 3, 9.4), in ASCII whatever the locale: a letter or
/// '_', then letters, digits or '_'. Object names and variables follow it.
constexpr bool isNameStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
constexpr bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }
constexpr bool isValidName(std::string_view s) {
    if (s.empty() || !isNameStart(s.front())) return false;
    for (char c : s.substr(1)) {
        if (!isNameChar(c)) return false;
    }
    return true;
}

}  // namespace f2

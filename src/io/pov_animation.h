#pragma once
/// The whole animation as one POV-Ray 3.7 scene driven by `clock` (seconds)
/// and an .ini beside it that renders frames 0..lastFrame as numbered PNGs:
/// `cd DIR && povray NAME.ini`. Every value that holds over the animation is
/// written as the single-frame export writes it (pov_scene_text.h); key
/// tracks (shapes, rides for good, a free camera, lights, colours,
/// visibility) are evaluated by POV-Ray (pov_track.h); any other value that
/// changes (drives, changing rides, a riding camera) is read from an array of its
/// per-frame numbers at the frame nearest `clock * fps` (docs/output.md,
/// "The whole animation in POV-Ray").
#include <string>
#include <string_view>

#include "core/scene/scene_desc.h"

namespace f2 {

struct PovAnimation {
    std::string scene;  ///< the .pov
    std::string ini;    ///< the .ini
    int lastFrame = 0;
    bool cameraEvaluated = false;    ///< POV-Ray evaluates the camera's keys
    std::size_t evaluated = 0;       ///< shapes POV-Ray moves by evaluating their keys (pov_track.h)
    std::size_t evaluatedLooks = 0;  ///< shapes' colours and visibilities POV-Ray evaluates from keys
    std::size_t arrays = 0;          ///< other values that change, each an array of every frame's value
};

/// `stem` is the files' name without directory and extension, a povIniName():
/// the .ini renders STEM.pov into STEM_000.png, STEM_001.png… (POV-Ray pads
/// the numbers to the digits of the last). `source` names the scene in comments.
PovAnimation povAnimation(const SceneDesc& scene, int width, int height, const std::string& source,
                          const std::string& stem);

/// Whether a file name can stand as an .ini value: letters, digits and
/// `._+-` only. An .ini line is not a comment: a newline or `;` in a name
/// would add options (a Post_Frame_Command runs a shell), so such names are
/// refused, never written.
bool povIniName(std::string_view name);

}  // namespace f2

#include "view_option.h"

#include <string>

namespace f2::cli {

namespace {
/// "shaded, normals, ..., cost": every mode's name, in menu order.
std::string modeList() {
    std::string names;
    for (ViewMode mode : kViewModes) names += (names.empty() ? "" : ", ") + std::string(viewModeName(mode));
    return names;
}
}  // namespace

void addViewOption(CLI::App& command, ViewMode& view) {
    const std::string names = modeList();
    command
        .add_option_function<std::string>(
            "--view", [&view](const std::string& name) { view = *viewModeNamed(name); },
            "What the pixels show: " + names +
                " (default shaded). The others trace one ray per pixel centre (--aa is ignored): normals "
                "(n+1)/2, depth (near white to far dark, legend), shadow-mask (per light: lit white, blocked "
                "red, facing away black), primitive-ids (a colour per primitive), cost (BVH boxes + "
                "primitives tested by the primary and shadow rays, heat map with legend); docs/rendering.md")
        ->type_name("MODE")
        ->check(CLI::Validator(
            [names](std::string& name) -> std::string {
                return viewModeNamed(name) ? "" : "unknown view mode '" + name + "' (expected " + names + ")";
            },
            ""));
}

}  // namespace f2::cli

// f2 check: parse a scene and report every problem.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "options.h"
#include "scene_source.h"

namespace f2::cli {

Command addCheckCommand(CLI::App& app) {
    auto path = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "check", "Parse a scene and report every problem as FILE:LINE:COL: error: ...; exit 1 on error");
    sub->add_option("scene", *path, "Scene file; '-' reads standard input; none = the default scene")
        ->check(nonEmptyPath("check the default scene"));
    return {sub, [path] {
                auto loaded = loadScene(*path);
                if (!loaded) return 1;
                // Drives are evaluated at every whole frame of the animation: the
                // first without a finite value is reported as a render would (SPEC 10.7).
                const SceneDesc& scene = loaded->scene;
                for (int frame = 0; !scene.drives.empty() && frame <= scene.lastFrame(); ++frame) {
                    if (std::optional<std::string> problem = firstDriveProblem(scene, double(frame))) {
                        std::cerr << *problem << '\n';
                        return 1;
                    }
                }
                std::cout << loaded->name << ": ok\n";
                return 0;
            }};
}

}  // namespace f2::cli

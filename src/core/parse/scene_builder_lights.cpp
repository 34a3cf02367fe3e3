#include <algorithm>
#include <cmath>

#include "core/parse/expression.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/scene_builder.h"
#include "core/parse/suggest.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

void SceneBuilder::parseCamera() {
    if (!firstOnly(cameraSeen_) || !expectCounts()) return;
    bool ok = true;
    CameraDesc camera;
    camera.width = whole(0, "image width", 1, limits_.maxImageSide, ok);
    camera.height = whole(1, "image height", 1, limits_.maxImageSide, ok);
    {
        bool good = true;
        camera.distance = number(2, good);
        if (good && !(camera.distance > 0)) {
            error(argPos(2), "screen distance must be > 0, got " + printable(arg(2)));
            good = false;
        }
        ok = ok && good;
    }
    if (argCount() >= 6) camera.pose = pose(3, argCount() == 9, ok);
    // Keys, /look_at and /attach of the camera may come before /camera.
    camera.track = std::move(scene_.camera.track);
    camera.zoom = std::move(scene_.camera.zoom);
    camera.attachedTo = scene_.camera.attachedTo;
    camera.lookAt = scene_.camera.lookAt;
    if (!ok) return;
    const long long pixels = static_cast<long long>(camera.width) * camera.height;
    if (pixels > limits_.maxImagePixels) {
        error(argPos(0), "image of " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                             " = " + std::to_string(pixels) + " pixels is larger than the limit of " +
                             std::to_string(limits_.maxImagePixels) + " pixels");
        return;
    }
    scene_.camera = camera;
}

bool SceneBuilder::lightAllowed() {
    if (++lightLines_ <= limits_.maxLights) return true;
    error(commandPos(), "too many lights: at most " + std::to_string(limits_.maxLights) +
                            " allowed (ambient, directional, point and spot together)");
    return false;
}

void SceneBuilder::parseAmbLight() {
    if (!expectCounts() || !lightAllowed()) return;
    bool ok = true;
    const float i = nonNegative(0, "ambient intensity", ok);
    LightOptions options;
    if (!lightOptions(1, {LightOption::Name}, options) || !ok) return;
    // Named or not, every ambient light as written adds to one sum.
    const float sum = writtenAmbient_ + i;
    if (!std::isfinite(sum)) {
        error(argPos(0), "total ambient intensity is out of range");
        return;
    }
    writtenAmbient_ = sum;
    if (options.nameArg >= 0) {
        scene_.namedAmbients.push_back({i, static_cast<std::uint32_t>(registerLight(options.nameArg, true))});
        return;
    }
    scene_.ambient += i;
}

Vec3 SceneBuilder::lightDirection(int first, bool& ok) {
    bool good = true;
    const Vec3 d = vec3(first, good);
    if (good && d.x == 0 && d.y == 0 && d.z == 0) {
        error(argPos(first), "light direction must not be 0 0 0");
        good = false;
    }
    // The renderer normalises in float: the squared length must neither vanish nor overflow.
    const float lengthSquared = dot(d, d);
    if (good && (!(lengthSquared > 0) || !std::isfinite(lengthSquared))) {
        error(argPos(first),
              "light direction cannot be normalised (its length is too close to 0 or too large)");
        good = false;
    }
    ok = ok && good;
    return d;
}

bool SceneBuilder::lightOptions(int first, std::initializer_list<LightOption> allowed, LightOptions& out) {
    const std::span<const LightOptionSpec> kSpecs = f2::lightOptions();
    bool ok = true;
    std::vector<LightOption> seen;
    for (int i = first; i < argCount();) {
        const LightOptionSpec* spec = nullptr;
        for (const LightOptionSpec& candidate : kSpecs)
            if (candidate.word == arg(i) &&
                std::find(allowed.begin(), allowed.end(), candidate.option) != allowed.end())
                spec = &candidate;
        if (!spec) {
            std::string expected;
            for (LightOption o : allowed) {
                if (!expected.empty()) expected += o == *(allowed.end() - 1) ? " or " : ", ";
                expected += "'" + std::string(kSpecs[static_cast<std::size_t>(o)].word) + "'";
            }
            error(argPos(i), "unknown option " + quoteToken(arg(i)) + " of " + quoteToken(commandText()) +
                                 " (expected " + expected + ")");
            return false;
        }
        if (std::find(seen.begin(), seen.end(), spec->option) != seen.end()) {
            error(argPos(i), "second " + quoteToken(arg(i)) + " option");
            return false;
        }
        seen.push_back(spec->option);
        if (i + spec->numbers >= argCount()) {
            error(argPos(i), quoteToken(arg(i)) + " takes " + std::string(spec->what));
            return false;
        }
        switch (spec->option) {
            case LightOption::Fade:
                out.fade.distance = positive(i + 1, "fade distance", ok);
                out.fade.power = positive(i + 2, "fade power", ok);
                break;
            case LightOption::Size:
            case LightOption::Angle: {
                const bool angle = spec->option == LightOption::Angle;
                bool good = true;
                out.shadow.size = positive(i + 1, angle ? "angular radius" : "light diameter", good);
                if (good && angle && out.shadow.size > kMaxSunRadius) {
                    error(argPos(i + 1),
                          "angular radius must be at most 45 degrees, got " + printable(arg(i + 1)));
                    good = false;
                }
                out.shadow.samplesPerSide =
                    whole(i + 2, "samples per side", 2, kMaxShadowSamplesPerSide, good);
                ok = ok && good;
                break;
            }
            case LightOption::Tightness:
                out.tightness = nonNegative(i + 1, "tightness", ok);
                break;
            case LightOption::Name:
                if (newName(i + 1))
                    out.nameArg = i + 1;
                else
                    ok = false;
                break;
        }
        i += 1 + spec->numbers;
    }
    return ok;
}

bool SceneBuilder::lightArgsAllowed() {
    const int fixed = command(command_).counts.front();
    if (argCount() < fixed) {
        expectCounts();
        return false;
    }
    if (argCount() > kMostLightArgs) {
        error(commandPos(), quoteToken(commandText()) + " takes at most " + std::to_string(kMostLightArgs) +
                                " arguments with its options, got " + std::to_string(argCount()));
        return false;
    }
    return lightAllowed();
}

void SceneBuilder::parseDirLight() {
    if (!lightArgsAllowed()) return;
    bool ok = true;
    DirectionalLight light;
    light.intensity = nonNegative(0, "light intensity", ok);
    light.direction = lightDirection(1, ok);
    LightOptions options;
    if (!lightOptions(4, {LightOption::Angle, LightOption::Name}, options) || !ok) return;
    light.sun = options.shadow;
    if (options.nameArg >= 0) light.motion = registerLight(options.nameArg, false);
    scene_.lights.push_back(light);
}

void SceneBuilder::parseLocalLight(LocalLightKind kind) {
    const bool spot = kind == LocalLightKind::Spot;
    const int fixed = command(command_).counts.front();
    if (!lightArgsAllowed()) return;
    bool ok = true;
    LocalLight light;
    light.kind = kind;
    light.intensity = nonNegative(0, "light intensity", ok);
    light.position = vec3(1, ok);
    if (spot) {
        light.direction = lightDirection(4, ok);
        bool good = true;
        light.radius = nonNegative(7, "spot radius", good);
        light.falloff = nonNegative(8, "spot falloff", good);
        if (good && light.falloff > 90) {
            error(argPos(8), "spot falloff must be at most 90 degrees, got " + printable(arg(8)));
            good = false;
        }
        if (good && light.radius > light.falloff) {
            error(argPos(7), "spot radius must be at most its falloff (" + printable(arg(8)) + "), got " +
                                 printable(arg(7)));
            good = false;
        }
        ok = ok && good;
    }
    LightOptions options;
    const bool optionsOk =
        spot ? lightOptions(fixed,
                            {LightOption::Tightness, LightOption::Fade, LightOption::Size, LightOption::Name},
                            options)
             : lightOptions(fixed, {LightOption::Fade, LightOption::Size, LightOption::Name}, options);
    if (!optionsOk || !ok) return;
    light.tightness = options.tightness;
    light.fade = options.fade;
    light.area = options.shadow;
    if (options.nameArg >= 0) light.motion = registerLight(options.nameArg, false);
    scene_.localLights.push_back(light);
}

std::int32_t SceneBuilder::registerLight(int nameArg, bool ambient) {
    const auto index = static_cast<std::int32_t>(scene_.lightMotions.size());
    LightMotion motion;
    motion.name = std::string(arg(nameArg));
    motion.ambient = ambient;
    lightNames_.emplace(motion.name, scene_.lightMotions.size());
    scene_.lightMotions.push_back(std::move(motion));
    lightBooks_.push_back({argPos(nameArg), definitionLoopNote(), -1, -1, std::nullopt, std::nullopt});
    if (index_) {
        index_->lights.push_back({std::string(arg(nameArg)), std::string(commandText()),
                                  span(argPos(nameArg), arg(nameArg)), sourceLoc(commandPos())});
    }
    return index;
}

void SceneBuilder::parseBackground() {
    if (!firstOnly(backgroundSeen_) || !expectCounts()) return;
    bool ok = true;
    const Color8 c = color(0, ok);
    if (ok) scene_.background = c;
}

void SceneBuilder::parseFps() {
    if (!firstOnly(fpsSeen_) || !expectCounts()) return;
    bool ok = true;
    const int fps = whole(0, "fps", 1, limits_.maxFps, ok);
    if (ok) scene_.fps = fps;
}

}  // namespace f2::parsing

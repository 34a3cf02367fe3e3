#include "io/pov_scene_text.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/anim/light_evaluation.h"
#include "core/render/reflection.h"
#include "io/comment_text.h"

namespace f2 {

namespace {
// Strings are built with append: GCC 12 warns falsely (-Wrestrict) on
// `"literal" + std::string` chains.
std::string join(std::initializer_list<std::string> parts) {
    std::string text;
    for (const std::string& p : parts) text.append(p);
    return text;
}

std::string vec(Vec3 v) { return povVector(v); }

std::string color(Color8 c) {
    return join({"<", std::to_string(c.r), ", ", std::to_string(c.g), ", ", std::to_string(c.b), "> / 255"});
}

/// POV-Ray's `matrix` maps a row vector: p' = p * M, rows 0..2 the images of
/// the local axes (our columns), row 3 the translation.
std::string matrix(const Transform& m) {
    std::string text = "matrix <";
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 c = m.linear.column(axis);
        text.append(join({formatNumber(c.x), ", ", formatNumber(c.y), ", ", formatNumber(c.z), ",  "}));
    }
    Vec3 t = m.translation;
    return text.append(join({formatNumber(t.x), ", ", formatNumber(t.y), ", ", formatNumber(t.z), ">"}));
}

std::string shape(const PlacedPrimitive& p) {
    switch (p.kind) {
        case ShapeKind::Sphere:
            return join({"sphere { <0, 0, 0>, ", formatNumber(p.size.x)});
        case ShapeKind::Cylinder: {
            std::string h = formatNumber(p.size.y * 0.5f);
            // Closed (no `open`): caps at local y = +-h/2, as SPEC 4.
            return join({"cylinder { <0, -", h, ", 0>, <0, ", h, ", 0>, ", formatNumber(p.size.x)});
        }
        case ShapeKind::Box:
            return join({"box { ", vec(p.size * -0.5f), ", ", vec(p.size * 0.5f)});
    }
    return "";
}

/// A disc of n x n samples, as f2 samples a soft light: a fixed grid (no
/// jitter), pushed out to a circle, every sample traced (adaptive deep enough
/// that POV-Ray never stops at the corners; the mean is then exact for n a
/// power of two), facing each lit point when `orient`.
std::string areaLight(const std::string& axisA, const std::string& axisB, int n, bool orient) {
    std::string count = std::to_string(n);
    return join({"area_light ", axisA, ", ", axisB, ", ", count, ", ", count, " circular",
                 orient ? " orient" : "", " adaptive 10"});
}

/// `color rgb <i, i, i>`: f2's lights are white.
std::string grey(const std::string& i) { return join({"color rgb <", i, ", ", i, ", ", i, ">"}); }

/// The colour, or the checker pattern in the primitive's own frame: written
/// before the transform, the pigment moves with the shape, as f2's does.
std::string pigment(const PlacedPrimitive& p, const std::string& colour) {
    if (!(p.checker.size > 0)) return join({"pigment { rgb ", colour, " }"});
    return join({"pigment { checker rgb ", colour, ", rgb ", color(p.checker.color), " scale ",
                 formatNumber(p.checker.size), " }"});
}

/// Radius of a sphere around the primitive's centre that holds it.
float boundingRadius(const PlacedPrimitive& p) {
    switch (p.kind) {
        case ShapeKind::Sphere:
            return p.size.x;
        case ShapeKind::Cylinder:
            return std::hypot(p.size.x, p.size.y * 0.5f);
        case ShapeKind::Box:
            return length(p.size) * 0.5f;
    }
    return 0;
}
}  // namespace

std::string povVector(Vec3 v) {
    return join({"<", formatNumber(v.x), ", ", formatNumber(v.y), ", ", formatNumber(v.z), ">"});
}

void PovBounds::grow(const Camera& camera, const std::vector<PlacedPrimitive>& prims) {
    auto add = [&](Vec3 c, float radius) {
        lo = vmin(lo, c - Vec3{radius, radius, radius});
        hi = vmax(hi, c + Vec3{radius, radius, radius});
    };
    add(camera.eye, 0);
    for (const PlacedPrimitive& p : prims) add(p.worldFromLocal.translation, boundingRadius(p));
}

PovValues povValuesAt(const SceneDesc& scene, double t, const Camera& camera,
                      const std::vector<PlacedPrimitive>& prims, const PovBounds& bounds) {
    PovValues v;
    // SPEC 2: the ray of image point (x, y) in [-1/2, 1/2] x [-h/2w, h/2w] is
    // R (x, y, d); POV-Ray's is direction + x' right + y' up with x', y' in
    // [-1/2, 1/2], so right = R x^, up = R y^ * h/w, direction = R z^ * d.
    const Mat3& r = camera.worldFromCamera;
    const float aspect = float(camera.height) / float(camera.width);
    v.eye = vec(camera.eye);
    v.right = vec(r.column(0));
    v.up = vec(r.column(1) * aspect);
    v.direction = vec(r.column(2) * camera.distance);

    // Directional lights: parallel lights placed beyond everything.
    const Vec3 centre = bounds.centre();
    const float far = bounds.far();
    for (const DirectionalLight& light : scene.lights) {
        const Vec3 direction = placeLight(scene, light.motion, Vec3{}, light.direction, t).direction;
        const Vec3 toLight = -normalize(direction);
        PovLightValues& l = v.suns.emplace_back();
        l.location = vec(centre + toLight * far);
        l.pointAt = vec(centre);
        l.intensity = formatNumber(lightIntensityAt(scene, light.motion, light.intensity, t));
        l.note = vec(direction);
        if (light.sun.soft()) {
            // The sun's disc (angular radius r) as a parallel area light: its
            // sample k shines along the light's place plus the sample's offset,
            // minus point_at, as f2's L + (u a + v b) 2 tan r (docs/rendering.md).
            const DiscAxes axes = discAxes(toLight);
            const float span = far * float(2.0 * std::tan(double(light.sun.size) * std::numbers::pi / 180.0));
            l.areaA = vec(axes.a * span);
            l.areaB = vec(axes.b * span);
        }
    }
    for (const LocalLight& light : scene.localLights) {
        const PlacedLight placed = placeLight(scene, light.motion, light.position, light.direction, t);
        PovLightValues& l = v.locals.emplace_back();
        l.location = vec(placed.position);
        l.intensity = formatNumber(lightIntensityAt(scene, light.motion, light.intensity, t));
        if (light.kind == LocalLightKind::Spot)
            l.pointAt = vec(placed.position + normalize(placed.direction));
        if (light.area.soft()) {
            l.areaA = vec({light.area.size, 0, 0});
            l.areaB = vec({0, 0, light.area.size});
        }
    }

    const float ambient = ambientAt(scene, t);
    v.ambient = formatNumber(ambient);
    for (const PlacedPrimitive& p : prims)
        v.shapes.push_back({matrix(p.worldFromLocal), color(p.color), formatNumber(p.material.ka * ambient),
                            p.hidden ? "0" : "1"});
    return v;
}

std::string povSceneBody(const SceneDesc& scene, const std::vector<PlacedPrimitive>& prims,
                         const PovValues& values) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    // srgb working gamma = POV-Ray's default sRGB output gamma: colours go out
    // as computed, like f2's (it shades in display values, no gamma step).
    // Ambient light 1: each finish carries ka * (the scene's ambient).
    // Mirrors: f2's trace levels (reflection.h), and no adaptive depth
    // control, which f2 does not have (it would cut faint reflections).
    out << "global_settings { assumed_gamma srgb ambient_light rgb <1, 1, 1> max_trace_level "
        << kMaxTraceLevel << " adc_bailout 0 }\n\n"
        << "background { rgb " << color(scene.background) << " }\n\n";
    out << "camera {\n  perspective\n  location " << values.eye << "\n  right " << values.right << "\n  up "
        << values.up << "\n  direction " << values.direction << "\n}\n\n";

    // Named lights (SPEC 10.2) where they are and as bright as they are.
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const DirectionalLight& light = scene.lights[i];
        const PovLightValues& l = values.suns[i];
        out << "light_source { " << l.location << " " << grey(l.intensity) << " parallel point_at "
            << l.pointAt;
        if (light.sun.soft())
            out << "\n  " << areaLight(l.areaA, l.areaB, light.sun.samplesPerSide, false) << "\n";
        out << " }  // travels along " << l.note << "\n";
    }
    for (std::size_t i = 0; i < scene.localLights.size(); ++i) {
        const LocalLight& light = scene.localLights[i];
        const PovLightValues& l = values.locals[i];
        out << "light_source { " << l.location << " " << grey(l.intensity);
        if (light.kind == LocalLightKind::Spot)
            out << "\n  spotlight point_at " << l.pointAt << " radius " << formatNumber(light.radius)
                << " falloff " << formatNumber(light.falloff) << " tightness "
                << formatNumber(light.tightness);
        if (light.fade.fades())
            out << "\n  fade_distance " << formatNumber(light.fade.distance) << " fade_power "
                << formatNumber(light.fade.power);
        if (light.area.soft()) out << "\n  " << areaLight(l.areaA, l.areaB, light.area.samplesPerSide, true);
        out << " }\n";
    }
    out << "\n";

    for (std::size_t i = 0; i < prims.size(); ++i) {
        const PlacedPrimitive& p = prims[i];
        const PovShapeValues& s = values.shapes[i];
        if (s.visible == "0") continue;  // hidden all along (SPEC 10.7)
        const Material& m = p.material;
        out << "// " << commentText(p.label) << "\n";
        const bool sometimes = s.visible != "1";
        if (sometimes) out << "#if (" << s.visible << ")\n";
        out << shape(p) << "\n  " << pigment(p, s.colour) << "\n  " << s.transform << "\n"
            << "  finish { ambient " << s.ambient << " diffuse " << formatNumber(m.kd) << " phong "
            << formatNumber(m.ks) << " phong_size " << formatNumber(m.n);
        if (m.reflection > 0) out << " reflection " << formatNumber(m.reflection);
        if (m.emission > 0) out << " emission " << formatNumber(m.emission);  // SPEC 10.8: e · C, as ours
        out << " }\n";
        if (!p.castsShadow) out << "  no_shadow\n";
        out << "}\n";
        if (sometimes) out << "#end\n";
    }
    return out.str();
}

}  // namespace f2

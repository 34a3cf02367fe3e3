#include "pixel_story.h"

#include <charconv>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/render/diagnostic_view.h"
#include "core/render/pixel_report.h"
#include "core/render/reflection.h"
#include "core/render/renderer.h"

namespace f2::cli {

namespace {
std::string str(float f) {
    std::ostringstream s;
    s << std::setprecision(6) << f;
    return s.str();
}

std::string str(Vec3 v) {
    std::ostringstream s;
    s << std::setprecision(6) << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return s.str();
}

const char* faceName(const Primitive& prim, Face face) {
    switch (face) {
        case Face::Curved:
            return prim.kind == ShapeKind::Sphere ? "surface" : "side";
        case Face::Cap:
            return "cap";
        case Face::SlabX:
            return "local x face";
        case Face::SlabY:
            return "local y face";
        case Face::SlabZ:
            return "local z face";
    }
    return "?";
}

bool parseInt(std::string_view text, int& value) {
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}
}  // namespace

bool parsePixel(const std::string& text, int width, int height, int& x, int& y, std::string& error) {
    auto comma = text.find(',');
    if (comma == std::string::npos || !parseInt(std::string_view(text).substr(0, comma), x) ||
        !parseInt(std::string_view(text).substr(comma + 1), y)) {
        error = "--pixel: expected X,Y (whole numbers), got '" + text + "'";
        return false;
    }
    if (x < 0 || x >= width || y < 0 || y >= height) {
        error = "--pixel: " + text + " is outside the " + std::to_string(width) + "x" +
                std::to_string(height) + " image (0,0 is the top-left pixel)";
        return false;
    }
    return true;
}

int printPixelStory(const LoadedScene& loaded, const Camera& camera, double t, int x, int y, int antialias,
                    int threads) {
    Renderer renderer(threads);
    Image image;
    renderer.render(loaded.scene, t, camera, image, {antialias});
    const PreparedFrame& frame = renderer.frame();
    const PixelReport r = tracePixel(frame, camera, x, y);
    auto name = [&](std::uint32_t primitive) { return primitiveName(loaded.scene, frame, primitive); };
    std::ostream& out = std::cout;
    out << std::setprecision(6);

    out << "pixel " << x << "," << y << " of " << camera.width << "x" << camera.height << ", " << loaded.name
        << " at frame " << t << " (single-ray reference path, the pixel centre " << r.px << ", " << r.py
        << ")\n";
    out << "ray      from " << str(r.ray.origin) << " along " << str(r.ray.direction)
        << ", counting hits from t = " << r.tMin << " on (nearer ones are at the eye itself)\n";
    if (r.crossings.empty())
        out << "along it nothing\n";
    else
        out << "along it, nearest first:\n";
    for (const PixelReport::Crossing& c : r.crossings) {
        bool chosen = r.hit && c.primitive == r.chosen.primitive && c.t == r.chosen.t;
        out << "  t = " << std::setw(10) << std::left << c.t << std::right << " #" << c.primitive << " "
            << name(c.primitive) << ", " << faceName(frame.primitives[c.primitive], c.face)
            << (chosen ? "   <- nearest" : "") << "\n";
    }
    if (!r.hit) {
        out << "hit      none: the background " << str(frame.background) << "\n";
    } else {
        out << "hit      #" << r.chosen.primitive << " " << name(r.chosen.primitive)
            << " at t = " << r.chosen.t << ", point " << str(r.surface.position) << "\n";
        out << "normal   " << str(r.surface.normal)
            << (r.surface.inside ? " (seen from inside: turned to face the eye)" : " (facing the eye)")
            << "\n";
        const float checker = frame.surfaces[r.chosen.primitive].checkerSize;
        out << "surface  colour " << str(r.surfaceColor)
            << (checker > 0 ? " (the /checker cell the point is in; cells of " + str(checker) + ")" : "")
            << ", ka " << r.material.ka << " kd " << r.material.kd << " ks " << r.material.ks << " n "
            << r.material.n << "\n";
        if (r.material.emission > 0)
            out << "ambient  ka * " << frame.ambient << " + emit " << r.material.emission << " = "
                << r.ambientTerm << "\n";
        else
            out << "ambient  ka * " << frame.ambient << " = " << r.ambientTerm << "\n";
        out << "shadow rays from " << str(r.surface.shadowOrigin)
            << (r.surface.skip == Bvh::kNoPrimitive ? "" : ", skipping the primitive itself") << "\n";
        for (const PixelReport::Light& l : r.lights) {
            const bool local = l.term.light >= frame.lights.size();
            out << "light " << l.term.light + 1 << (local ? " (point or spot)" : "") << "  toward "
                << str(l.toLight) << ", N.L = " << l.term.nDotL << ": ";
            if (l.term.nDotL <= 0)
                out << "faces away (no shadow ray)\n";
            else if (local && l.term.intensity <= 0)
                out << "outside the spot's cone (no shadow ray)\n";
            else if (l.term.shadowed && l.occluder != Bvh::kNoPrimitive)
                out << "in shadow of #" << l.occluder << " " << name(l.occluder) << " at t = " << l.occluderT
                    << "\n";
            else if (l.term.shadowed)
                out << "in shadow (every shadow sample is blocked)\n";
            else
                out << "lit, intensity " << l.term.intensity
                    << (l.term.visible < 1 ? " x " + std::to_string(l.term.visible) + " unshadowed" : "")
                    << ", diffuse " << l.term.diffuse << ", specular " << l.term.specular << "\n";
        }
    }
    if (r.hit && r.material.reflection > 0)
        out << "mirror   own colour " << str(r.ownColor) << ", plus reflection " << r.material.reflection
            << " x what the mirrored ray sees (traced to level " << kMaxTraceLevel
            << "): " << str(r.color - r.ownColor) << "\n";
    out << "colour   " << str(r.color) << " -> pixel " << int(r.pixel.r) << " " << int(r.pixel.g) << " "
        << int(r.pixel.b) << "\n";
    const Rgb8 rendered = image.at(x, y);
    out << "image    " << int(rendered.r) << " " << int(rendered.g) << " " << int(rendered.b)
        << " (the packet path" << (antialias > 1 ? ", --aa " + std::to_string(antialias) + " samples" : "")
        << ")\n";
    // What --view cost shows for this pixel, counted by the same traversals.
    const RayProbe probe = probeRay(frame, r.ray);
    out << "cost     " << probe.cost.total() << " = " << probe.cost.nodes << " BVH node boxes + "
        << probe.cost.primitives << " primitives tested, by the primary ray and " << probe.shadowRays
        << " shadow ray" << (probe.shadowRays == 1 ? "" : "s") << " (--view cost)\n";
    return 0;
}

}  // namespace f2::cli

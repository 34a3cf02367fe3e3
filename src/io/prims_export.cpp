#include "io/prims_export.h"

#include <sstream>

#include "core/anim/light_evaluation.h"
#include "io/comment_text.h"
#include "io/frame_primitives.h"

namespace f2 {

namespace {
/// m00 m01 m02 m03 m10 ... m23 of [A | t], row by row.
std::string matrix3x4(const Mat3& a, Vec3 t) {
    std::string text;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) text += formatNumber(a.row[row][col]) + " ";
        text += formatNumber(t[row]) + (row < 2 ? " " : "");
    }
    return text;
}

}  // namespace

std::string primsScene(const SceneDesc& scene, double t, const Camera& camera, const std::string& source) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << "# " << commentText(source) << " at frame " << t << ", exported by f2 (F2 Stage)\n"
        << "camera " << camera.width << " " << camera.height << " " << formatNumber(camera.distance) << " "
        << matrix3x4(camera.worldFromCamera, camera.eye) << "\n"
        << "background " << int(scene.background.r) << " " << int(scene.background.g) << " "
        << int(scene.background.b)
        << "\n"
        // The sum of the /amb_light lines at t: one line says the same.
        << "amb " << formatNumber(ambientAt(scene, t)) << "\n";
    for (const DirectionalLight& light : scene.lights) {
        const Vec3 d = placeLight(scene, light.motion, Vec3{}, light.direction, t).direction;
        out << "dir " << formatNumber(lightIntensityAt(scene, light.motion, light.intensity, t)) << " "
            << formatNumber(d.x) << " " << formatNumber(d.y) << " " << formatNumber(d.z) << "\n";
    }
    for (const PlacedPrimitive& p : framePrimitives(scene, t)) {
        float r = p.kind == ShapeKind::Box ? 0 : p.size.x;
        float h = p.kind == ShapeKind::Cylinder ? p.size.y : 0;
        Vec3 box = p.kind == ShapeKind::Box ? p.size : Vec3{};
        const Material& m = p.material;
        out << shapeKindName(p.kind) << " " << formatNumber(r) << " " << formatNumber(h) << " "
            << formatNumber(box.x) << " " << formatNumber(box.y) << " " << formatNumber(box.z) << " "
            << matrix3x4(p.worldFromLocal.linear, p.worldFromLocal.translation) << " " << int(p.color.r)
            << " " << int(p.color.g) << " " << int(p.color.b) << " " << formatNumber(m.ka) << " "
            << formatNumber(m.kd) << " " << formatNumber(m.ks) << " " << formatNumber(m.n) << "\n";
    }
    return out.str();
}

}  // namespace f2

#include "core/anim/light_evaluation.h"

#include <algorithm>
#include <limits>
#include <numbers>

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"

namespace f2 {

void appendDiscPattern(int n, std::vector<DiscPoint>& out) {
    // In double, as POV-Ray works it out, then stored in float.
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            double s = double(i) / double(n - 1) - 0.5 + 0.001;
            double t = double(j) / double(n - 1) - 0.5 + 0.001;
            double scale = std::max(std::fabs(s), std::fabs(t)) / std::sqrt(s * s + t * t);
            out.push_back({float(s * scale), float(t * scale)});
        }
    }
}

namespace {
float cosDegrees(float degrees) { return float(std::cos(double(degrees) * std::numbers::pi / 180.0)); }
}  // namespace

Transform lightFrameAt(const SceneDesc& scene, const LightMotion& motion, double t) {
    const Pose pose = evaluateTrack(motion.track, t, Pose{});
    const Transform local = Transform::fromPose(pose.position, pose.rotation);
    return motion.attachedTo ? worldFromRef(scene, *motion.attachedTo, t) * local : local;
}

float lightIntensityAt(const SceneDesc& scene, std::int32_t motion, float written, double t) {
    if (motion == kStillLight) return written;
    const Track& track = scene.lightMotions[std::size_t(motion)].intensity;
    if (track.keys.empty() && !track.drives) return written;
    return std::max(0.0f, evaluateTrack(track, t, Pose{{written, 0, 0}, {}}).position.x);
}

PlacedLight placeLight(const SceneDesc& scene, std::int32_t motion, Vec3 position, Vec3 direction, double t) {
    if (motion == kStillLight) return {position, direction};
    const LightMotion& m = scene.lightMotions[std::size_t(motion)];
    // A named light that neither moves nor rides keeps its numbers bit for bit.
    if (m.track.keys.empty() && !m.track.drives && !m.attachedTo) return {position, direction};
    const Transform world = lightFrameAt(scene, m, t);
    return {world.applyToPoint(position), world.applyToVector(direction)};
}

float ambientAt(const SceneDesc& scene, double t) {
    float ambient = scene.ambient;
    for (const AmbientLight& light : scene.namedAmbients)
        ambient += lightIntensityAt(scene, std::int32_t(light.motion), light.intensity, t);
    // Keyed intensities may add up past the float range: saturate (as shading's
    // kMaxLight does), so that ka 0 times it stays 0, never NaN.
    return std::min(ambient, std::numeric_limits<float>::max());
}

void evaluateLights(const SceneDesc& scene, double t, EvaluatedFrame& frame) {
    frame.ambient = ambientAt(scene, t);
    frame.lights.clear();
    frame.sunDirections.clear();
    frame.localLights.clear();
    frame.discPoints.clear();
    std::vector<DiscPoint>& disc = frame.discPoints;
    for (const DirectionalLight& light : scene.lights) {
        const Vec3 direction = placeLight(scene, light.motion, Vec3{}, light.direction, t).direction;
        LightSample sample{-normalize(direction), lightIntensityAt(scene, light.motion, light.intensity, t)};
        if (light.sun.soft()) {
            // The sun's disc of angular radius r, seen from the scene: directions
            // toward L + (u a + v b) * 2 tan r, (u, v) on the unit-diameter disc.
            const std::size_t first = disc.size();
            appendDiscPattern(light.sun.samplesPerSide, disc);
            const DiscAxes axes = discAxes(sample.toLight);
            const float spread = float(2.0 * std::tan(double(light.sun.size) * std::numbers::pi / 180.0));
            sample.firstSample = std::uint32_t(frame.sunDirections.size());
            sample.sampleCount = std::uint32_t(disc.size() - first);
            for (std::size_t k = first; k < disc.size(); ++k)
                frame.sunDirections.push_back(normalize(sample.toLight + axes.a * (disc[k].u * spread) +
                                                        axes.b * (disc[k].v * spread)));
            disc.resize(first);  // the directions are what shading needs
        }
        frame.lights.push_back(sample);
    }
    for (const LocalLight& light : scene.localLights) {
        const PlacedLight placed = placeLight(scene, light.motion, light.position, light.direction, t);
        LocalLightSample sample;
        sample.position = placed.position;
        sample.intensity = lightIntensityAt(scene, light.motion, light.intensity, t);
        sample.spot = light.kind == LocalLightKind::Spot;
        if (sample.spot) {
            sample.axis = normalize(placed.direction);
            sample.cosRadius = cosDegrees(light.radius);
            sample.cosFalloff = cosDegrees(light.falloff);
            sample.tightness = light.tightness;
        }
        sample.fade = light.fade;
        if (light.area.soft()) {
            sample.diameter = light.area.size;
            sample.firstSample = std::uint32_t(disc.size());
            appendDiscPattern(light.area.samplesPerSide, disc);
            sample.sampleCount = std::uint32_t(disc.size()) - sample.firstSample;
        }
        frame.localLights.push_back(sample);
    }
}

}  // namespace f2

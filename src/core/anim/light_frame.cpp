#include "core/anim/light_frame.h"

#include <algorithm>
#include <numbers>

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

void evaluateLights(const SceneDesc& scene, EvaluatedFrame& frame) {
    frame.lights.clear();
    frame.sunDirections.clear();
    frame.localLights.clear();
    frame.discPoints.clear();
    std::vector<DiscPoint>& disc = frame.discPoints;
    for (const DirectionalLight& light : scene.lights) {
        LightSample sample{-normalize(light.direction), light.intensity};
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
        LocalLightSample sample;
        sample.position = light.position;
        sample.intensity = light.intensity;
        sample.spot = light.kind == LocalLightKind::Spot;
        if (sample.spot) {
            sample.axis = normalize(light.direction);
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

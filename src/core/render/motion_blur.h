#pragma once
/// Motion blur as a film camera makes it: the shutter stays open for a part
/// of each frame and the image is the mean of what it saw meanwhile. f2 takes
/// `samples` sub-frames at fixed times in that interval (stratified, like
/// `--aa`: no randomness, so frames are deterministic) and averages them with
/// Renderer::renderAveraged.
#include <vector>

#include "core/render/camera.h"
#include "core/render/renderer.h"

namespace f2 {

struct MotionBlur {
    /// How long the shutter is open, as a fraction of a frame, in (0, 1]; 0 = off (sharp frames).
    double shutter = 0;
    /// Sub-frames averaged per frame.
    int samples = kDefaultSamples;

    static constexpr int kDefaultSamples = 8;
    static constexpr int kMaxSamples = 256;

    bool enabled() const { return shutter > 0; }

    /// Scene time of sub-frame `i` (0..samples-1) of the frame at time `t`:
    /// the shutter is centred on `t` (Blender's convention) and sub-frame i is
    /// the centre of the i-th of `samples` equal slices of the open time,
    ///     t + shutter · frameLength · ((i + 0.5) / samples − 0.5).
    /// `frameLength` is one output frame in scene frames (scene fps / output fps).
    double subFrameTime(double t, double frameLength, int i) const {
        return t + shutter * frameLength * ((double(i) + 0.5) / double(samples) - 0.5);
    }

    /// The sub-frames of the frame at `t` seen through `view` (a moving
    /// camera blurs too); without blur, the frame itself.
    std::vector<SubFrame> subFrames(const SceneDesc& scene, const FrameView& view, double t,
                                    double frameLength) const {
        std::vector<SubFrame> subs;
        const int n = enabled() ? samples : 1;
        for (int i = 0; i < n; ++i) {
            const double time = enabled() ? subFrameTime(t, frameLength, i) : t;
            subs.push_back({time, view.at(scene, time)});
        }
        return subs;
    }
};

}  // namespace f2

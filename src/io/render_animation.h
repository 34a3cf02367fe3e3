#pragma once
/// The one loop that renders a range of frames into an output: the command
/// line (`f2 render`) and the viewer's export both call renderAnimation.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/anim/frame_time.h"
#include "core/render/camera.h"
#include "core/render/motion_blur.h"
#include "core/render/renderer.h"
#include "core/scene/scene_desc.h"
#include "io/frame_sink.h"

namespace f2 {

/// Which output frames to render, and which scene time each one shows.
struct AnimationRange {
    std::int64_t first = 0, last = 0;   ///< output frame numbers, inclusive
    int sceneFps = 24, outputFps = 24;  ///< see sceneTimeOfOutputFrame
    double timeOffset = 0;              ///< added to every frame's time (a still at a fractional time)
    int shardIndex = 0,
        shardCount = 1;     ///< only frames ≡ shardIndex (mod shardCount): a render farm's worker
    std::int64_t step = 1;  ///< every step-th frame from first (a quick preview)

    /// One image at scene time `t` (frames, may be fractional).
    static AnimationRange still(double t, int sceneFps);
    /// Scene time of output frame `frame`.
    double timeOf(std::int64_t frame) const {
        return timeOffset + sceneTimeOfOutputFrame(frame, sceneFps, outputFps);
    }
    /// Length of one output frame in scene frames (a motion-blur shutter is a fraction of it).
    double frameLength() const { return double(sceneFps) / double(outputFps); }
    /// The frame belongs to this shard (whether or not it is in [first, last]).
    bool inShard(std::int64_t frame) const { return frame % shardCount == shardIndex; }
    /// Frames first, first + step, ... up to last that are in this shard.
    std::int64_t count() const;
    /// The last of first, first + step, ... that is <= last (whatever the shard).
    std::int64_t lastRendered() const { return last < first ? last : last - (last - first) % step; }
};

struct AnimationProgress {
    std::int64_t done = 0;     ///< complete in the output (rendered or skipped)
    std::int64_t skipped = 0;  ///< of them, already there (a resumed sequence)
    std::int64_t total = 0;
    /// Motion blur: sub-frames of the frame in flight already traced (0 at a frame's end), of
    /// subFramesPerFrame.
    int subFramesDone = 0, subFramesPerFrame = 1;
};

struct AnimationOptions {
    int threads = 0;  ///< render threads; 0 = every core
    RenderOptions render;
    MotionBlur motionBlur;  ///< off by default: every frame sharp
};

struct AnimationResult {
    enum class Outcome { Finished, Cancelled, Failed };
    Outcome outcome = Outcome::Finished;
    std::string error;                              ///< why it failed (empty when cancelled)
    std::int64_t done = 0, skipped = 0, total = 0;  ///< as in AnimationProgress, at the end
    int threads = 0;                                ///< render threads used
    double renderMs = 0;                            ///< time spent rendering, summed over frames
    std::int64_t rendered() const { return done - skipped; }
};

/// Renders the frames of `range` (in order) of `scene` seen through `view`
/// (the scene's moving camera, or a fixed one) into `sink`. Stops inside the current frame when `cancel` is
/// raised (that frame is dropped) and abandons the sink, as on any error; `progress` (optional) is called, on
/// this thread, after every frame, and with motion blur also after each sub-frame but a frame's last.
AnimationResult renderAnimation(const SceneDesc& scene, const AnimationRange& range, const FrameView& view,
                                FrameSink& sink, const std::atomic<bool>* cancel,
                                const std::function<void(const AnimationProgress&)>& progress = {},
                                const AnimationOptions& options = {});

}  // namespace f2

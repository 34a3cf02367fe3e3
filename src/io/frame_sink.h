#pragma once
/// Where the frames of an animation go: a numbered PNG sequence, one PNG, or a
/// video. renderAnimation drives any of them; the command line and the viewer
/// choose which. Errors are plain facts about files ("cannot write 'x': ..."),
/// never advice about a particular front end's options.
#include <atomic>
#include <cstdint>
#include <string>

#include "core/render/image.h"

namespace f2 {

/// What every frame of one output has in common.
struct FrameFormat {
    int width = 0, height = 0;
    int fps = 24;                 ///< output frames per second
    std::int64_t frameCount = 0;  ///< frames that will be written (or skipped)
};

class FrameSink {
   public:
    virtual ~FrameSink() = default;

    /// Once, before the first frame. False (and `error`) means nothing is written.
    virtual bool begin(const FrameFormat& format, std::string& error) = 0;
    /// True if output frame `frame` is already in the output (a resumed
    /// sequence): it is skipped instead of rendered.
    virtual bool alreadyDone(std::int64_t /*frame*/) { return false; }
    /// One rendered frame, in increasing `frame` order. A sink may finish the
    /// work in the background; then an error shows at a later call. A sink that
    /// has to wait (a full pipe to an encoder) gives up when `cancel` is raised.
    virtual bool write(const Image& image, std::int64_t frame, std::string& error,
                       const std::atomic<bool>* cancel) = 0;
    /// After the last frame: completes the output (pending writes, the encoder,
    /// the rename). Gives up, as abandon(), if `cancel` is raised meanwhile.
    virtual bool finish(std::string& error, const std::atomic<bool>* cancel) = 0;
    /// After a cancel or an error: stops and removes everything incomplete.
    /// Complete files of a sequence stay (they are each whole).
    virtual void abandon() = 0;
    /// Frames that are complete in the output so far (written, or handed to the encoder).
    virtual std::int64_t framesCompleted() const = 0;
};

}  // namespace f2

#pragma once
/// A numbered PNG sequence (`frames/f_%04d.png`): one file per frame, each
/// written atomically, so a file that exists is a finished frame.
#include <deque>
#include <future>
#include <string>
#include <vector>

#include "io/frame_pattern.h"
#include "io/frame_sink.h"

namespace f2 {

class PngSequenceSink : public FrameSink {
   public:
    /// `resume`: frames whose file already exists are skipped, and temporary
    /// files of this sink's frames left by a killed run (`kill -9`, a lost
    /// machine) are removed.
    explicit PngSequenceSink(FramePattern pattern, bool resume = false);
    /// Waits for the frames still being written.
    ~PngSequenceSink() override;

    bool begin(const FrameFormat& format, std::string& error) override;
    bool alreadyDone(std::int64_t frame) override;
    /// Compressing a PNG takes longer than tracing a frame on a few cores, so
    /// frames are written on their own threads while the next ones render; a
    /// couple in flight keep memory bounded. The frame's directory is created
    /// (also when the pattern numbers directories, `out_%d/f.png`).
    bool write(const Image& image, std::int64_t frame, std::string& error,
               const std::atomic<bool>* cancel) override;
    bool finish(std::string& error, const std::atomic<bool>* cancel) override;
    /// Frames being written are finished (each file is whole); nothing is removed.
    void abandon() override;
    std::int64_t framesCompleted() const override { return completed_; }

    /// The file of output frame `frame`.
    std::string fileName(std::int64_t frame) const;

   private:
    /// Waits for the oldest write; false (and error_) if it failed.
    bool collectOldest();
    bool makeDirectoryOf(const std::string& path, std::string& error);
    /// Removes the temporary files of `path` left by an earlier, killed run.
    void removeLeftoverTemporaries(const std::string& path);

    FramePattern pattern_;
    bool resume_;
    std::deque<std::future<std::string>> writes_;  // each write's error, empty on success
    std::string error_, lastDirectory_;
    std::string scannedDirectory_;            // the directory whose temporaries are listed below
    std::vector<std::string> leftoverNames_;  // file names there that look like temporaries
    std::int64_t completed_ = 0;
};

}  // namespace f2

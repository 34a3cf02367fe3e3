#pragma once
/// Progress of a multi-frame render on stderr: a live bar (frames done, frames
/// per second, time left; a motion-blurred frame fills it sub-frame by sub-frame) when stderr is a terminal;
/// otherwise nothing until the one-line summary, so logs of farm jobs stay short.
#include <chrono>
#include <string>

namespace f2::cli {

class Progress {
   public:
    /// `total` frames to render; `live` = draw the bar (see isInteractive()).
    Progress(int total, bool live);

    /// `done` frames are finished (rendered or skipped), and `partial` (0..1)
    /// of the next one (its motion-blur sub-frames): the bar and the time left
    /// move during a long frame.
    void update(int done, double partial = 0);
    /// Clears the bar's line so the next message starts on a clean line.
    void clear();

    /// Seconds since construction.
    double elapsedSeconds() const;
    /// Frames rendered per second so far (skipped frames excluded).
    double framesPerSecond() const;

    /// "12.3 s, 19.5 frames/s" (rendered frames over the wall-clock time).
    std::string summary() const;

    /// Skipped frames (already on disk with --resume) do not count toward speed.
    void skipped(int count) { skipped_ += count; }

    /// stderr is a terminal that can redraw a line.
    static bool isInteractive();

   private:
    using Clock = std::chrono::steady_clock;
    int total_;
    bool live_;
    int done_ = 0, skipped_ = 0;
    Clock::time_point start_ = Clock::now(), lastDraw_{};
    std::size_t drawnWidth_ = 0;
};

/// "1:05" / "1:02:05" for a number of seconds.
std::string formatDuration(double seconds);

/// A time with three significant digits: "0.250 ms", "9.28 ms", "45.1 ms", "312 ms", "1.25 s",
/// "4350 s" (whole seconds beyond 100 s).
std::string formatMilliseconds(double ms);

/// `value` with three significant digits ("0.0412", "9.28", "45.1", "312"), whole beyond 100.
std::string threeSignificantDigits(double value);

}  // namespace f2::cli

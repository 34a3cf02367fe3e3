#pragma once
/// The animation clock: current time, play/pause, speed and looping. Time is
/// in frames and may be fractional (SPEC 6), so slow motion stays smooth.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <optional>

namespace f2::viewer {

/// Frames `first`..`last`, both included.
struct FrameRange {
    int first = 0;
    int last = 0;
    bool contains(int frame) const { return frame >= first && frame <= last; }
    friend bool operator==(const FrameRange&, const FrameRange&) = default;
};

class Playback : public QObject {
    Q_OBJECT
   public:
    explicit Playback(QObject* parent = nullptr);

    /// The animation runs over frames 0..lastFrame at `fps`; the time and the
    /// loop points are clamped into it.
    void setRange(int lastFrame, int fps);
    int lastFrame() const { return lastFrame_; }
    int fps() const { return fps_; }

    double time() const { return time_; }
    /// The whole frame the current time falls in.
    int frame() const;
    bool isPlaying() const { return timer_.isActive(); }
    double speed() const { return speed_; }
    /// Milliseconds between the clock's ticks while playing: one scene frame, at most 60 a second.
    int tickIntervalMs() const { return timer_.interval(); }
    /// The loop in/out points, if set: playing loops over these frames (the
    /// out frame shown for one frame's duration, like every frame).
    std::optional<FrameRange> loopRange() const { return loop_; }
    /// The frames playing runs over and an export writes: the loop range, else 0..lastFrame.
    FrameRange playRange() const { return loop_.value_or(FrameRange{0, lastFrame_}); }

   public slots:
    void play();
    void pause();
    void togglePlaying();
    /// Pauses and moves `frames` whole frames from frame() (the frame shown), wrapping around.
    void step(int frames);
    /// Moves to `time` (clamped); keeps playing from there if playing.
    void seek(double time);
    void seekToStart() { seek(0); }
    void seekToEnd() { seek(lastFrame_); }
    void setSpeed(double speed);
    /// Sets the loop's in point (the out point is the last frame if unset, and
    /// moves along when `frame` passes it).
    void setLoopIn(int frame);
    /// Sets the loop's out point (the in point is 0 if unset, and moves along
    /// when `frame` is before it).
    void setLoopOut(int frame);
    void clearLoop();
    /// Scrubbing pauses the clock while the slider is held and resumes after.
    void beginScrub();
    void endScrub();

   signals:
    void timeChanged(double time);
    void playingChanged(bool playing);
    void loopRangeChanged();

   private:
    void tick();
    void restartClock();
    void setTime(double time);
    void setLoop(std::optional<FrameRange> loop);

    QTimer timer_;
    QElapsedTimer clock_;
    double clockBase_ = 0;  // time at the moment clock_ started
    double time_ = 0;
    double speed_ = 1;
    int lastFrame_ = 0;
    int fps_ = 24;
    bool resumeAfterScrub_ = false;
    std::optional<FrameRange> loop_;
};

}  // namespace f2::viewer

#pragma once
/// Transport bar under the picture: play/pause, step, a frame slider, speed
/// and the current frame, and under them the dope sheet of the selection's
/// keys (dope_sheet.h). It only reports what the user did; the Playback
/// clock owns the time and the window applies the dope sheet's edits.
#include <QWidget>

#include "dope_sheet.h"
#include "key_marker_slider.h"

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace f2::viewer {

class TimelineWidget : public QWidget {
    Q_OBJECT
   public:
    explicit TimelineWidget(QWidget* parent = nullptr);

    void setRange(int lastFrame, int fps);
    /// Shows `time` without emitting seekRequested.
    void setTime(double time);
    void setPlaying(bool playing);

    KeyMarkerSlider* slider() const { return slider_; }
    QSpinBox* frameBox() const { return frameBox_; }
    DopeSheet* dopeSheet() const { return dopeSheet_; }
    /// Key frames of the selection, drawn on the slider; a click on one seeks there.
    void setKeyMarkers(QList<int> frames);
    /// The loop in/out frames, drawn on the slider (nothing: no loop).
    void setLoop(std::optional<std::pair<int, int>> loop);
    QComboBox* speedBox() const { return speed_; }

    static constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};

   signals:
    void playToggled();
    void stepRequested(int frames);
    void seekRequested(double time);
    void scrubStarted();
    void scrubFinished();
    void speedChanged(double speed);
    /// The user set a loop point on the slider (dragged a flag or used its menu).
    void loopInRequested(int frame);
    void loopOutRequested(int frame);
    void loopClearRequested();

   private:
    QToolButton* addButton(int standardIcon, const QString& tip);

    QToolButton* playButton_ = nullptr;
    KeyMarkerSlider* slider_ = nullptr;
    DopeSheet* dopeSheet_ = nullptr;
    QSpinBox* frameBox_ = nullptr;
    QComboBox* speed_ = nullptr;
    QLabel* frameLabel_ = nullptr;
    int lastFrame_ = 0;
    int fps_ = 24;
};

}  // namespace f2::viewer

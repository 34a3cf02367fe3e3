#pragma once
/// The status bar's readouts of the frame on screen: the selection, the view
/// mode, refinement, the samples of playing frames, frame number, frame time,
/// frames per second and size. They yield to a message (status_bar_room.h)
/// and refresh twice a second, so the FPS readout falls to 0 when nothing renders.
#include <QObject>
#include <QString>
#include <QTimer>

class QLabel;
class QStatusBar;

namespace f2::viewer {

class StudioSession;

class StatusReadouts : public QObject {
    Q_OBJECT
   public:
    StatusReadouts(QStatusBar* bar, const StudioSession* session);

    /// Reads the session again.
    void update();
    /// The selection's label (StudioSession::SelectionView::label), empty for none.
    void setSelection(const QString& text);
    QString selection() const;
    /// About the samples of playing frames (empty while paused).
    QString playbackAntialias() const;

    static constexpr int kRefreshMs = 500;

   private:
    const StudioSession* session_;
    QLabel* frame_;
    QLabel* time_;
    QLabel* fps_;
    QLabel* size_;
    QLabel* selection_;
    QLabel* refine_;
    QLabel* view_;  ///< the view mode of the picture on screen
    QLabel* playbackAntialias_;
    QTimer refresh_;
};

}  // namespace f2::viewer

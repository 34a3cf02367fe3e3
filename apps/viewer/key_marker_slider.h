#pragma once
/// The timeline's frame slider with the selection's key frames drawn on it as
/// markers (a click on one jumps to that key) and the loop in/out points as
/// a band with a flag at each end (drag a flag to move it; the context menu
/// sets them at the frame under the mouse or clears them).
#include <QList>
#include <QSlider>
#include <memory>
#include <optional>

class QMenu;

namespace f2::viewer {

class KeyMarkerSlider : public QSlider {
    Q_OBJECT
   public:
    explicit KeyMarkerSlider(QWidget* parent = nullptr);

    void setMarkers(QList<int> frames);
    const QList<int>& markers() const { return markers_; }
    /// The loop's in and out frames to show (nothing: no loop).
    void setLoop(std::optional<std::pair<int, int>> loop);
    const std::optional<std::pair<int, int>>& loop() const { return loop_; }
    /// Centre x (widget pixels) of the handle at `frame`: where its marker is drawn.
    int positionOf(int frame) const;
    /// The frame whose position is nearest to widget x.
    int frameAtPosition(int x) const;
    /// The y (widget pixels) of the loop flags, above the groove.
    int loopFlagY() const { return kLoopFlagSize; }
    /// The context menu for the frame under the mouse: Set Loop In / Out Here, Clear Loop.
    std::unique_ptr<QMenu> loopMenu(int frame);

    /// A click this close to a marker (pixels) jumps to it; a press this
    /// close to a loop flag drags it.
    static constexpr int kMarkerReach = 4;
    static constexpr int kLoopFlagSize = 5;

   signals:
    void markerClicked(int frame);
    void loopInRequested(int frame);
    void loopOutRequested(int frame);
    void loopClearRequested();

   protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

   private:
    enum class LoopFlag { None, In, Out };
    /// Where the handle's centre travels: from x = start over span pixels.
    struct Track {
        int start = 0;
        int span = 1;
        bool upsideDown = false;
    };
    Track track() const;

    QList<int> markers_;
    std::optional<std::pair<int, int>> loop_;
    LoopFlag dragging_ = LoopFlag::None;
};

}  // namespace f2::viewer

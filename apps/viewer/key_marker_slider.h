#pragma once
/// The timeline's frame slider with the selection's key frames drawn on it as
/// markers; a click on a marker jumps to that key.
#include <QList>
#include <QSlider>

namespace f2::viewer {

class KeyMarkerSlider : public QSlider {
    Q_OBJECT
   public:
    explicit KeyMarkerSlider(QWidget* parent = nullptr);

    void setMarkers(QList<int> frames);
    const QList<int>& markers() const { return markers_; }
    /// Centre x (widget pixels) of the handle at `frame`: where its marker is drawn.
    int positionOf(int frame) const;

    /// A click this close to a marker (pixels) jumps to it.
    static constexpr int kMarkerReach = 4;

   signals:
    void markerClicked(int frame);

   protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

   private:
    QList<int> markers_;
};

}  // namespace f2::viewer

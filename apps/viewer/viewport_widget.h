#pragma once
/// The picture: paints the latest rendered frame scaled to fit (the previous
/// frame stretched while a new size renders, as in Qt's Mandelbrot example)
/// and turns mouse drags and the wheel into an orbit around the scene.
#include <QImage>
#include <QPoint>
#include <QRectF>
#include <QWidget>
#include <optional>

#include "core/render/camera.h"
#include "core/render/orbit_camera.h"

class QKeyEvent;
class QPainter;

namespace f2::viewer {

/// What draws over the picture and may take the mouse before the orbit and
/// the click (the selection's handles and motion path: gizmo_tool.h).
/// Positions are the widget's.
class ViewportOverlay {
   public:
    virtual ~ViewportOverlay() = default;
    virtual void paint(QPainter& painter) = 0;
    /// A left press: true if it takes this drag (then no orbit and no click).
    virtual bool press(QPointF pos, Qt::KeyboardModifiers modifiers) = 0;
    virtual void move(QPointF pos, Qt::KeyboardModifiers modifiers) = 0;
    /// The release of a press it took: true if, had nothing been dragged, it
    /// is a click of the picture all the same (a handle clicked without
    /// moving selects what is under it, as anywhere else).
    virtual bool release(QPointF pos, Qt::KeyboardModifiers modifiers) = 0;
    /// A key pressed while the picture has the focus: true if it used it.
    virtual bool key(QKeyEvent* event) = 0;
    /// The mouse moved over the picture with no button held.
    virtual void hover(QPointF pos) = 0;
};

/// How the render size follows the window.
enum class RenderScale { Quarter, Half, Full, SceneSize };

class ViewportWidget : public QWidget {
    Q_OBJECT
   public:
    explicit ViewportWidget(QWidget* parent = nullptr);

    /// The scene's own camera and the depth of the orbit target in front of it.
    /// `keepOrbit` keeps a look-around in progress (a reload of the same file).
    void setSceneCamera(const Camera& camera, float targetDistance, bool keepOrbit);
    /// The scene's camera at the time shown: a moving camera (SPEC 9.1) moves
    /// the view unless the user looks around. Does not ask for a render.
    void followSceneCamera(const Camera& camera) { sceneCamera_ = camera; }
    /// Back to the scene's camera.
    void resetView();
    bool isOrbiting() const { return orbit_.has_value(); }
    const std::optional<OrbitCamera>& orbit() const { return orbit_; }

    void setRenderScale(RenderScale scale);
    RenderScale renderScale() const { return scale_; }
    /// Pixel size to render at for the current widget size and scale.
    QSize renderSize() const;
    /// The camera to render with: the scene's (or the orbit's) at renderSize().
    Camera viewCamera() const { return viewCamera(renderSize()); }
    /// The same view at another image size (exports use the scene's size).
    Camera viewCamera(QSize size) const;

    void setImage(const QImage& image);
    const QImage& image() const { return image_; }

    /// Where the image is painted in the widget (fitted, centred).
    QRectF imageRect() const;
    /// The image point (pixels of image()) under widget position `pos`, if on the image.
    std::optional<QPointF> imagePointAt(QPointF pos) const;
    /// Draws a rectangle round `rect` (in image pixels) over the picture; nothing to clear it.
    void setSelectionOutline(std::optional<QRectF> rect);
    std::optional<QRectF> selectionOutline() const { return outline_; }
    /// Draws over the picture and gets the mouse first; null for none.
    void setOverlay(ViewportOverlay* overlay) { overlay_ = overlay; }
    /// The view at the size the picture is drawn on screen: its pixels are
    /// the widget's, from imageRect()'s top left corner, whatever size the
    /// frame on screen was rendered at (a drag's are a quarter).
    Camera displayCamera() const;

    QSize sizeHint() const override { return {800, 600}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

    static constexpr float kOrbitDegPerPixel = 0.3f;
    static constexpr float kZoomPerWheelStep = 0.9f;  ///< distance factor per wheel notch
    /// A press and release closer than this (pixels) is a click, not a drag.
    static constexpr int kClickSlop = 3;

   signals:
    /// The render size or the view camera changed: render again.
    void viewChanged();
    /// A click (not a drag) on the picture at `imagePoint` (pixels of image()),
    /// with the keyboard modifiers held at its release.
    void clicked(QPointF imagePoint, Qt::KeyboardModifiers modifiers);

   protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

   private:
    OrbitCamera& startOrbit();

    QImage image_;
    Camera sceneCamera_;
    float targetDistance_ = 500;
    std::optional<OrbitCamera> orbit_;
    RenderScale scale_ = RenderScale::Full;
    std::optional<QPoint> dragFrom_;
    QPoint pressAt_;
    bool dragged_ = false;
    std::optional<QRectF> outline_;
    ViewportOverlay* overlay_ = nullptr;
    bool overlayDrag_ = false;  // the overlay took the press: its moves and release go there
};

}  // namespace f2::viewer

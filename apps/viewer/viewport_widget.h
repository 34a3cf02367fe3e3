#pragma once
/// The picture: paints the latest rendered frame scaled to fit (the previous
/// frame stretched while a new size renders, as in Qt's Mandelbrot example)
/// and turns mouse drags and the wheel into an orbit around the scene.
#include <QImage>
#include <QPoint>
#include <QWidget>
#include <optional>

#include "core/render/camera.h"
#include "orbit_camera.h"

namespace f2::viewer {

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

    QSize sizeHint() const override { return {800, 600}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

    static constexpr float kOrbitDegPerPixel = 0.3f;
    static constexpr float kZoomPerWheelStep = 0.9f;  ///< distance factor per wheel notch

   signals:
    /// The render size or the view camera changed: render again.
    void viewChanged();

   protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

   private:
    OrbitCamera& startOrbit();

    QImage image_;
    Camera sceneCamera_;
    float targetDistance_ = 500;
    std::optional<OrbitCamera> orbit_;
    RenderScale scale_ = RenderScale::Full;
    std::optional<QPoint> dragFrom_;
};

}  // namespace f2::viewer

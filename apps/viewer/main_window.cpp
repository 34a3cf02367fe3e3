#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

#include "animation_exporter.h"
#include "core/anim/frame_time.h"
#include "image_convert.h"
#include "io/png_writer.h"
#include "io/sequence_sink.h"
#include "io/video_sink.h"
#include "orbit_camera.h"
#include "playback.h"
#include "scene_document.h"
#include "timeline_widget.h"
#include "viewport_widget.h"

namespace f2::viewer {

namespace {
constexpr int kStatusRefreshMs = 500;
constexpr int kProblemsDockHeight = 110;
const char* const kRecentKey = "recentFiles";
const char* const kScaleKey = "renderScale";
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), controller_(std::make_unique<RenderController>()) {
    document_ = new SceneDocument(this);
    playback_ = new Playback(this);

    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    viewport_ = new ViewportWidget(central);
    timeline_ = new TimelineWidget(central);
    layout->addWidget(viewport_, 1);
    layout->addWidget(timeline_);
    setCentralWidget(central);

    diagnosticsDock_ = new QDockWidget(tr("Problems"), this);
    diagnosticsDock_->setObjectName("problemsDock");
    diagnosticsView_ = new QPlainTextEdit(diagnosticsDock_);
    diagnosticsView_->setReadOnly(true);
    diagnosticsView_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    diagnosticsView_->setPlainText(tr("No problems."));
    diagnosticsDock_->setWidget(diagnosticsView_);
    addDockWidget(Qt::BottomDockWidgetArea, diagnosticsDock_);
    diagnosticsDock_->hide();

    frameStatus_ = new QLabel(this);
    timeStatus_ = new QLabel(this);
    fpsStatus_ = new QLabel(this);
    sizeStatus_ = new QLabel(this);
    for (QLabel* label : {frameStatus_, timeStatus_, fpsStatus_, sizeStatus_})
        statusBar()->addPermanentWidget(label);

    frameTimer_.setSingleShot(true);
    frameTimer_.setInterval(0);
    connect(&frameTimer_, &QTimer::timeout, this, &MainWindow::requestFrame);
    statusTimer_.setInterval(kStatusRefreshMs);
    connect(&statusTimer_, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer_.start();

    connect(document_, &SceneDocument::sceneChanged, this, &MainWindow::onSceneChanged);
    connect(document_, &SceneDocument::diagnosticsChanged, this, &MainWindow::onDiagnosticsChanged);
    connect(controller_.get(), &RenderController::frameReady, this, &MainWindow::onFrameReady);
    connect(viewport_, &ViewportWidget::viewChanged, this, &MainWindow::scheduleFrame);
    connect(playback_, &Playback::timeChanged, this, [this](double t) {
        timeline_->setTime(t);
        scheduleFrame();
    });
    connect(playback_, &Playback::playingChanged, timeline_, &TimelineWidget::setPlaying);
    connect(timeline_, &TimelineWidget::playToggled, playback_, &Playback::togglePlaying);
    connect(timeline_, &TimelineWidget::stepRequested, playback_, &Playback::step);
    connect(timeline_, &TimelineWidget::seekRequested, playback_, &Playback::seek);
    connect(timeline_, &TimelineWidget::scrubStarted, playback_, &Playback::beginScrub);
    connect(timeline_, &TimelineWidget::scrubFinished, playback_, &Playback::endScrub);
    connect(timeline_, &TimelineWidget::speedChanged, playback_, &Playback::setSpeed);

    createActions();
    setAcceptDrops(true);
    resizeForViewport(viewport_->sizeHint());
    viewport_->setFocus();
    document_->loadDefault();
    updateStatus();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openDialog);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("Open &Default Scene"), this, [this] { document_->loadDefault(); });
    file->addAction(tr("&Reload"), QKeySequence(Qt::Key_F5), this, [this] { document_->reload(); });
    file->addSeparator();
    file->addAction(tr("&Save Frame as PNG…"), QKeySequence::Save, this, &MainWindow::saveFrame);
    file->addAction(tr("&Export PNG Sequence…"), this, &MainWindow::exportPngSequence);
    file->addAction(tr("Export &Video…"), this, &MainWindow::exportVideo);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);
    rebuildRecentMenu();

    QMenu* play = menuBar()->addMenu(tr("&Playback"));
    play->addAction(tr("&Play / Pause"), QKeySequence(Qt::Key_Space), playback_, &Playback::togglePlaying);
    play->addAction(tr("Step &Back"), QKeySequence(Qt::Key_Left), this, [this] { playback_->step(-1); });
    play->addAction(tr("Step &Forward"), QKeySequence(Qt::Key_Right), this, [this] { playback_->step(1); });
    play->addAction(tr("F&irst Frame"), QKeySequence(Qt::Key_Home), playback_, &Playback::seekToStart);
    play->addAction(tr("&Last Frame"), QKeySequence(Qt::Key_End), playback_, &Playback::seekToEnd);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Scene Camera"), QKeySequence(Qt::Key_C), viewport_, &ViewportWidget::resetView);
    QMenu* scaleMenu = view->addMenu(tr("Render S&cale"));
    auto* scales = new QActionGroup(this);
    const std::pair<QString, RenderScale> choices[] = {{tr("25 %"), RenderScale::Quarter},
                                                       {tr("50 %"), RenderScale::Half},
                                                       {tr("100 %"), RenderScale::Full},
                                                       {tr("Scene Size (/camera)"), RenderScale::SceneSize}};
    const int saved = QSettings().value(kScaleKey, int(RenderScale::Full)).toInt();
    for (const auto& [label, scale] : choices) {
        QAction* a = scaleMenu->addAction(label, this, [this, s = scale] { setRenderScale(s); });
        a->setCheckable(true);
        a->setChecked(int(scale) == saved);
        scales->addAction(a);
        if (int(scale) == saved) viewport_->setRenderScale(scale);
    }
    view->addSeparator();
    view->addAction(diagnosticsDock_->toggleViewAction());
}

void MainWindow::resizeForViewport(QSize viewportSize) {
    // Qt would open a top-level at most 2/3 of the screen; ask for the picture
    // size itself (800x600 by default, the scenes' usual /camera) where it fits.
    const QSize chrome = sizeHint() - centralWidget()->sizeHint() + QSize(0, timeline_->sizeHint().height());
    QSize wanted = viewportSize + chrome;
    if (const QScreen* s = screen()) wanted = wanted.boundedTo(s->availableGeometry().size());
    resize(wanted);
}

void MainWindow::setRenderScale(RenderScale scale) {
    QSettings().setValue(kScaleKey, int(scale));
    viewport_->setRenderScale(scale);
}

void MainWindow::openFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    document_->load(absolute);
    addRecentFile(absolute);
}

void MainWindow::onSceneChanged(bool newDocument) {
    const auto scene = document_->scene();
    playback_->setRange(scene->lastFrame(), scene->fps);
    timeline_->setRange(scene->lastFrame(), scene->fps);
    if (newDocument) playback_->seek(0);
    timeline_->setTime(playback_->time());
    const Camera camera = Camera::fromDesc(scene->camera);
    // A reload of the same file keeps the user's look-around; a new file starts at its camera.
    viewport_->setSceneCamera(camera, orbitTargetDistance(*scene, camera), !newDocument);
    setWindowTitle(tr("%1 — f2-viewer").arg(document_->displayName()));
    scheduleFrame();
}

void MainWindow::onDiagnosticsChanged() {
    const QStringList lines = document_->diagnostics();
    diagnosticsView_->setPlainText(lines.isEmpty() ? tr("No problems.") : lines.join('\n'));
    if (document_->hasErrors()) {
        showDiagnostics();
        diagnosticsDock_->raise();
        statusBar()->showMessage(
            tr("%1 has errors; showing the last good scene").arg(document_->displayName()));
    } else {
        if (!lines.isEmpty()) showDiagnostics();  // warnings
        statusBar()->clearMessage();
    }
}

void MainWindow::showDiagnostics() {
    if (diagnosticsDock_->isVisible()) return;
    diagnosticsDock_->show();
    // A few lines of messages; the picture keeps most of the window.
    resizeDocks({diagnosticsDock_}, {kProblemsDockHeight}, Qt::Vertical);
}

void MainWindow::scheduleFrame() {
    if (!frameTimer_.isActive()) frameTimer_.start();
}

void MainWindow::requestFrame() {
    auto scene = document_->scene();
    if (!scene) return;
    controller_->request({std::move(scene), playback_->time(), viewport_->viewCamera()});
}

void MainWindow::onFrameReady(const QImage& image, const FrameInfo& info) {
    shownFrame_ = info;
    viewport_->setImage(image);
    updateStatus();
}

void MainWindow::updateStatus() {
    const int last = playback_->lastFrame();
    if (shownFrame_.serial == 0) {
        frameStatus_->setText(tr("frame –/%1").arg(last));
        timeStatus_->setText(tr("– ms/frame"));
        sizeStatus_->setText(tr("–"));
    } else {
        frameStatus_->setText(tr("frame %1/%2").arg(frameAt(shownFrame_.time)).arg(last));
        timeStatus_->setText(tr("%1 ms/frame").arg(shownFrame_.timings.totalMs(), 0, 'f', 1));
        sizeStatus_->setText(tr("%1×%2").arg(shownFrame_.size.width()).arg(shownFrame_.size.height()));
    }
    fpsStatus_->setText(tr("%1 fps").arg(controller_->achievedFps(), 0, 'f', 1));
}

void MainWindow::openDialog() {
    const QString dir = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Scene"), dir, tr("F2 scenes (*.f2);;All files (*)"));
    if (!path.isEmpty()) openFile(path);
}

QString MainWindow::exportStem() const {
    // "<default scene>" has no file name: its brackets do not belong in one.
    return QFileInfo(document_->displayName()).completeBaseName().remove('<').remove('>');
}

bool MainWindow::refuseSceneFile(const QString& path, const QString& title) {
    // The viewer never writes the scene file, whatever name the user picks.
    if (document_->path().isEmpty() || QFileInfo(path) != QFileInfo(document_->path())) return false;
    QMessageBox::warning(this, title, tr("Refusing to overwrite the scene file."));
    return true;
}

void MainWindow::saveFrame() {
    if (viewport_->image().isNull()) return;
    const QString stem = exportStem();
    const QString suggested =
        QStringLiteral("%1_frame_%2.png").arg(stem).arg(playback_->frame(), 4, 10, QChar('0'));
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save Frame"), suggested, tr("PNG images (*.png)"));
    if (path.isEmpty() || refuseSceneFile(path, tr("Save Frame"))) return;
    std::string error;
    if (!writePng(fromQImage(viewport_->image()), QFile::encodeName(path).toStdString(), error))
        QMessageBox::warning(this, tr("Save Frame"), QString::fromStdString(error));
    else
        statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
}

void MainWindow::exportPngSequence() {
    auto scene = document_->scene();
    if (!scene) return;
    playback_->pause();  // the export gets the CPU
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export PNG Sequence to Folder"));
    if (dir.isEmpty()) return;
    const QString stem = exportStem();
    const FramePattern pattern = exportSequencePattern(dir, stem, scene->lastFrame() + 1);
    runExport(std::move(scene), std::make_unique<PngSequenceSink>(pattern), QDir(dir).filePath(stem + "_*.png"));
}

void MainWindow::exportVideo() {
    auto scene = document_->scene();
    if (!scene) return;
    playback_->pause();
    QFileDialog dialog(this, tr("Export Video"), exportStem() + ".mp4",
                       tr("MP4 video (*.mp4);;WebM video (*.webm);;GIF animation (*.gif)"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix("mp4");
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return;
    const QString path = dialog.selectedFiles().first();
    const std::string file = QFile::encodeName(path).toStdString();
    const auto format = videoFormatForPath(file);
    if (!format) {
        QMessageBox::warning(this, tr("Export Video"), tr("Use a .mp4, .webm or .gif file name."));
        return;
    }
    if (refuseSceneFile(path, tr("Export Video"))) return;
    const Color8 bg = scene->background;
    runExport(std::move(scene), std::make_unique<VideoSink>(file, *format, Rgb8{bg.r, bg.g, bg.b}), path);
}

void MainWindow::runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                           const QString& destination) {
    ExportJob job;
    // Like `f2 render`: the scene's /camera size, seen from the current view.
    job.camera = viewport_->viewCamera(QSize(scene->camera.width, scene->camera.height));
    job.scene = std::move(scene);
    job.lastFrame = job.scene->lastFrame();
    job.sink = std::move(sink);
    job.destination = destination;
    exportWithProgress(this, std::move(job), [this](bool ok, bool cancelled, const QString& message) {
        if (ok || cancelled)
            statusBar()->showMessage(message, 10000);
        else
            QMessageBox::warning(this, tr("Export"), message);
    });
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value(kRecentKey).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue(kRecentKey, files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = QSettings().value(kRecentKey).toStringList();
    for (const QString& path : files)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openFile(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.first().isLocalFile()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.first().isLocalFile()) return;
    openFile(urls.first().toLocalFile());
    event->acceptProposedAction();
}

}  // namespace f2::viewer

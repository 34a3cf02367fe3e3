#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSaveFile>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTextBlock>
#include <QVBoxLayout>
#include <QWindow>
#include <cmath>

#include "animation_exporter.h"
#include "autosave.h"
#include "camera_key_writer.h"
#include "capture_pose.h"
#include "core/anim/frame_builder.h"
#include "core/anim/frame_time.h"
#include "core/render/pick.h"
#include "core/render/renderer.h"
#include "editor_dock.h"
#include "help_windows.h"
#include "image_convert.h"
#include "include_origin.h"
#include "io/png_writer.h"
#include "io/sequence_sink.h"
#include "io/video_sink.h"
#include "opening_indicator.h"
#include "orbit_camera.h"
#include "playback.h"
#include "problems_dock.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "status_bar_room.h"
#include "text_capture.h"
#include "timeline_widget.h"
#include "view_mode_menu.h"
#include "viewport_widget.h"

namespace f2::viewer {

namespace {
constexpr int kStatusRefreshMs = 500;
const char* const kRecentKey = "recentFiles";
const char* const kScaleKey = "renderScale";
const char* const kPlaybackAntialiasKey = "playbackAntialias";
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

    diagnosticsDock_ = new ProblemsDock(this);
    connect(diagnosticsDock_, &ProblemsDock::problemClicked, this, &MainWindow::onProblemClicked);

    editorDock_ = new EditorDock(this);
    addDockWidget(Qt::LeftDockWidgetArea, editorDock_);
    connect(editorDock_, &EditorDock::textSettled, this, &MainWindow::onTextSettled);
    connect(editorDock_, &EditorDock::modificationChanged, this, [this](bool modified) {
        document_->setHoldsUnsavedEdits(modified);
        updateTitle();
    });

    frameStatus_ = new QLabel(this);
    timeStatus_ = new QLabel(this);
    fpsStatus_ = new QLabel(this);
    sizeStatus_ = new QLabel(this);
    selectionStatus_ = new QLabel(this);
    refineStatus_ = new QLabel(this);
    viewStatus_ = new QLabel(this);
    playbackAntialiasStatus_ = new QLabel(this);
    for (QLabel* label : {selectionStatus_, viewStatus_, refineStatus_, playbackAntialiasStatus_,
                          frameStatus_, timeStatus_, fpsStatus_, sizeStatus_})
        statusBar()->addPermanentWidget(label);
    // A message (a pick, an error) shows whole: the readouts make room for it.
    opening_ = new OpeningIndicator(statusBar(), document_, editorDock_);
    new StatusBarRoom(statusBar(), {fpsStatus_, timeStatus_, refineStatus_, playbackAntialiasStatus_,
                                    sizeStatus_, viewStatus_, selectionStatus_});

    frameTimer_.setSingleShot(true);
    frameTimer_.setInterval(0);
    connect(&frameTimer_, &QTimer::timeout, this, &MainWindow::requestFrame);
    statusTimer_.setInterval(kStatusRefreshMs);
    connect(&statusTimer_, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer_.start();

    connect(document_, &SceneDocument::sceneChanged, this, &MainWindow::onSceneChanged);
    connect(document_, &SceneDocument::diagnosticsChanged, this, &MainWindow::onDiagnosticsChanged);
    connect(document_, &SceneDocument::textLoaded, this, &MainWindow::onTextLoaded);
    connect(document_, &SceneDocument::fileChangedOnDisk, this, &MainWindow::onFileChangedOnDisk);
    connect(controller_.get(), &RenderController::frameReady, this, &MainWindow::onFrameReady);
    connect(viewport_, &ViewportWidget::viewChanged, this, &MainWindow::scheduleFrame);
    connect(viewport_, &ViewportWidget::clicked, this, &MainWindow::selectAt);
    connect(playback_, &Playback::timeChanged, this, [this](double t) {
        timeline_->setTime(t);
        scheduleFrame();
    });
    connect(playback_, &Playback::playingChanged, timeline_, &TimelineWidget::setPlaying);
    // Pausing shows the frame again, then refines it.
    connect(playback_, &Playback::playingChanged, this, [this](bool playing) {
        if (!playing) scheduleFrame();
    });
    connect(timeline_, &TimelineWidget::playToggled, playback_, &Playback::togglePlaying);
    connect(timeline_, &TimelineWidget::stepRequested, playback_, &Playback::step);
    connect(timeline_, &TimelineWidget::seekRequested, playback_, &Playback::seek);
    connect(timeline_, &TimelineWidget::scrubStarted, playback_, &Playback::beginScrub);
    connect(timeline_, &TimelineWidget::scrubFinished, playback_, &Playback::endScrub);
    connect(timeline_, &TimelineWidget::speedChanged, playback_, &Playback::setSpeed);
    connect(timeline_, &TimelineWidget::loopInRequested, playback_, &Playback::setLoopIn);
    connect(timeline_, &TimelineWidget::loopOutRequested, playback_, &Playback::setLoopOut);
    connect(timeline_, &TimelineWidget::loopClearRequested, playback_, &Playback::clearLoop);
    connect(playback_, &Playback::loopRangeChanged, this, [this] {
        const auto loop = playback_->loopRange();
        timeline_->setLoop(loop ? std::optional(std::pair(loop->first, loop->last)) : std::nullopt);
    });

    createActions();
    setAcceptDrops(true);
    resizeForViewport(viewport_->sizeHint());
    viewport_->setFocus();
    document_->loadDefault();
    updateStatus();
}

MainWindow::~MainWindow() = default;

SceneEditor* MainWindow::editor() const { return editorDock_->editor(); }

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New Scene"), QKeySequence::New, this, &MainWindow::newFile);
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openDialog);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("Open &Default Scene"), this, &MainWindow::openDefaultScene);
    file->addAction(tr("&Reload from Disk"), QKeySequence(Qt::Key_F5), this, [this] {
        if (maybeSave()) document_->reload();
    });
    file->addSeparator();
    file->addAction(tr("&Save Scene"), QKeySequence::Save, this, &MainWindow::saveScene);
    file->addAction(tr("Save Scene &As…"), QKeySequence::SaveAs, this, &MainWindow::saveSceneAs);
    file->addSeparator();
    file->addAction(tr("Save &Frame as PNG…"), QKeySequence(Qt::Key_F12), this, &MainWindow::saveFrame);
    file->addAction(tr("&Export PNG Sequence…"), this, &MainWindow::exportPngSequence);
    file->addAction(tr("Export &Video…"), this, &MainWindow::exportVideo);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);
    rebuildRecentMenu();

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    SceneEditor* editor = editorDock_->editor();
    QAction* undo = edit->addAction(tr("&Undo"), QKeySequence::Undo, editor, &QPlainTextEdit::undo);
    QAction* redo = edit->addAction(tr("&Redo"), QKeySequence::Redo, editor, &QPlainTextEdit::redo);
    undo->setEnabled(false);
    redo->setEnabled(false);
    connect(editor, &QPlainTextEdit::undoAvailable, undo, &QAction::setEnabled);
    connect(editor, &QPlainTextEdit::redoAvailable, redo, &QAction::setEnabled);
    edit->addSeparator();
    edit->addAction(tr("&Find…"), QKeySequence::Find, editorDock_, &EditorDock::showFind);
    edit->addAction(tr("Find &Next"), QKeySequence::FindNext, this, [this] { editorDock_->findNext(false); });
    edit->addAction(tr("Find &Previous"), QKeySequence::FindPrevious, this,
                    [this] { editorDock_->findNext(true); });
    edit->addAction(tr("&Go to Line…"), QKeySequence(Qt::CTRL | Qt::Key_L), editorDock_,
                    &EditorDock::goToLineDialog);
    edit->addAction(tr("&Comment / Uncomment Lines"), QKeySequence(Qt::CTRL | Qt::Key_Slash), editor,
                    &SceneEditor::toggleComment);

    // One-key playback shortcuts act only while the picture or the timeline
    // has the focus, so that they type into the editor.
    QWidget* stage = centralWidget();
    auto stageShortcut = [stage](QAction* action) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        stage->addAction(action);
    };
    QMenu* play = menuBar()->addMenu(tr("&Playback"));
    stageShortcut(play->addAction(tr("&Play / Pause"), QKeySequence(Qt::Key_Space), playback_,
                                  &Playback::togglePlaying));
    stageShortcut(
        play->addAction(tr("Step &Back"), QKeySequence(Qt::Key_Left), this, [this] { playback_->step(-1); }));
    stageShortcut(play->addAction(tr("Step &Forward"), QKeySequence(Qt::Key_Right), this,
                                  [this] { playback_->step(1); }));
    stageShortcut(
        play->addAction(tr("F&irst Frame"), QKeySequence(Qt::Key_Home), playback_, &Playback::seekToStart));
    stageShortcut(
        play->addAction(tr("&Last Frame"), QKeySequence(Qt::Key_End), playback_, &Playback::seekToEnd));
    play->addSeparator();
    stageShortcut(play->addAction(tr("Set Loop &In Here"), QKeySequence(Qt::Key_I), this,
                                  [this] { playback_->setLoopIn(playback_->frame()); }));
    stageShortcut(play->addAction(tr("Set Loop &Out Here"), QKeySequence(Qt::Key_O), this,
                                  [this] { playback_->setLoopOut(playback_->frame()); }));
    play->addAction(tr("&Clear Loop"), QKeySequence(Qt::ALT | Qt::Key_X), playback_, &Playback::clearLoop);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    stageShortcut(
        view->addAction(tr("&Scene Camera"), QKeySequence(Qt::Key_C), viewport_, &ViewportWidget::resetView));
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
    viewModes_ = new ViewModeMenu(view);
    connect(viewModes_, &ViewModeMenu::modeChanged, this, &MainWindow::scheduleFrame);
    QAction* refineAction = view->addAction(tr("&Refine When Paused"), this, &MainWindow::setRefinement);
    refineAction->setCheckable(true);
    refineAction->setChecked(refinement_);
    QMenu* playbackAa = view->addMenu(tr("Playback &Anti-aliasing"));
    playbackAntialiasActions_ = new QActionGroup(this);
    const std::pair<QString, PlaybackAntialiasMode> modes[] = {
        {tr("&Off (1 sample)"), PlaybackAntialiasMode::Off},
        {tr("&Auto (as many samples as the frame budget allows)"), PlaybackAntialiasMode::Auto},
        {tr("O&n (2×2 samples)"), PlaybackAntialiasMode::On}};
    for (const auto& [label, mode] : modes) {
        QAction* a = playbackAa->addAction(label, this, [this, m = mode] { setPlaybackAntialias(m); });
        a->setCheckable(true);
        a->setData(int(mode));
        playbackAntialiasActions_->addAction(a);
    }
    const int savedMode = QSettings().value(kPlaybackAntialiasKey, int(PlaybackAntialiasMode::Auto)).toInt();
    setPlaybackAntialias(savedMode >= int(PlaybackAntialiasMode::Off) &&
                                 savedMode <= int(PlaybackAntialiasMode::On)
                             ? PlaybackAntialiasMode(savedMode)
                             : PlaybackAntialiasMode::Auto);
    view->addSeparator();
    view->addAction(editorDock_->toggleViewAction());
    view->addAction(diagnosticsDock_->toggleViewAction());

    QMenu* capture = menuBar()->addMenu(tr("&Capture"));
    capture->addAction(tr("Set &Camera from View"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C), this,
                       &MainWindow::setCameraFromView);
    capture->addAction(tr("Key C&amera Here"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K), this,
                       &MainWindow::keyCameraHere);
    capture->addAction(tr("&Key Selection Here"), QKeySequence(Qt::CTRL | Qt::Key_K), this,
                       &MainWindow::keySelectionHere);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Keyboard Shortcuts"), this, [this] { showShortcuts(this, menuBar()); });
    help->addAction(tr("Scene &Language Reference"), QKeySequence::HelpContents, this,
                    [this] { showLanguageReference(this); });
    help->addSeparator();
    help->addAction(tr("&About f2-viewer"), this, [this] { showAbout(this); });
}

void MainWindow::resizeForViewport(QSize viewportSize) {
    // Qt would open a top-level at most 2/3 of the screen; ask for the picture
    // size itself (800x600 by default, the scenes' usual /camera) where it fits.
    const QSize chrome = sizeHint() - centralWidget()->sizeHint() + QSize(0, timeline_->sizeHint().height());
    QSize wanted = viewportSize + chrome;
    if (const QScreen* s = screen()) wanted = wanted.boundedTo(s->availableGeometry().size());
    resize(wanted);
}

void MainWindow::setPlaybackAntialias(PlaybackAntialiasMode mode) {
    QSettings().setValue(kPlaybackAntialiasKey, int(mode));
    playbackAntialias_.setMode(mode);
    for (QAction* a : playbackAntialiasActions_->actions()) a->setChecked(a->data().toInt() == int(mode));
    updateStatus();
}

QString MainWindow::playbackAntialiasStatus() const { return playbackAntialiasStatus_->text(); }

void MainWindow::setRenderScale(RenderScale scale) {
    QSettings().setValue(kScaleKey, int(scale));
    viewport_->setRenderScale(scale);
}

bool MainWindow::openFile(const QString& path) {
    if (!maybeSave()) return false;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    document_->load(absolute);
    addRecentFile(absolute);
    editorDock_->show();
    offerAutosave();
    return true;
}

bool MainWindow::newFile() {
    if (!maybeSave()) return false;
    document_->loadEmpty();
    editorDock_->show();
    offerAutosave();
    editor()->setFocus();
    return true;
}

bool MainWindow::openDefaultScene() {
    if (!maybeSave()) return false;
    document_->loadDefault();
    offerAutosave();
    return true;
}

void MainWindow::offerAutosave() {
    disconnect(deferredAutosaveOffer_);
    if (editorDock_->isLoading()) {
        // Restored edits go into the file's text, so they wait for it.
        deferredAutosaveOffer_ = connect(editorDock_, &EditorDock::textShown, this,
                                         &MainWindow::offerAutosave, Qt::SingleShotConnection);
        return;
    }
    const std::optional<QString> copy = Autosave::read(document_->path());
    if (!copy) return;
    if (*copy == document_->text() ||
        ask(Question::RestoreAutosave,
            tr("There are unsaved edits of %1 from an earlier session (the viewer did not close "
               "normally). Restore them?")
                .arg(document_->displayName())) != QMessageBox::Yes) {
        Autosave::remove(document_->path());
        return;
    }
    // One edit on top of the file's text: Undo goes back to what is on disk.
    QTextCursor cursor(editor()->document());
    cursor.select(QTextCursor::Document);
    cursor.insertText(*copy);
    document_->setText(*copy);
}

bool MainWindow::saveScene() {
    if (document_->path().isEmpty()) return saveSceneAs();
    return writeScene(document_->path());
}

bool MainWindow::saveSceneAs() {
    const QString dir = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absolutePath();
    const QString suggested =
        QDir(dir).filePath(document_->path().isEmpty() ? QStringLiteral("untitled.f2")
                                                       : QFileInfo(document_->path()).fileName());
    QFileDialog dialog(this, tr("Save Scene"), suggested, tr("F2 scenes (*.f2);;All files (*)"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix("f2");
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return false;
    return writeScene(QFileInfo(dialog.selectedFiles().first()).absoluteFilePath());
}

bool MainWindow::writeScene(const QString& path) {
    if (!textIsReady()) return false;
    const QString text = editor()->toPlainText();
    QSaveFile file(path);  // a temporary file renamed over the old one
    if (!file.open(QIODevice::WriteOnly) || file.write(text.toUtf8()) < 0 || !file.commit()) {
        QMessageBox::warning(this, tr("Save Scene"),
                             tr("Could not save %1: %2").arg(path, file.errorString()));
        return false;
    }
    const QString oldPath = document_->path();
    document_->markSaved(path, text);
    editorDock_->setModified(false);
    Autosave::remove(oldPath);
    Autosave::remove(path);
    addRecentFile(path);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

bool MainWindow::isOpening() const { return opening_->isBusy(); }

bool MainWindow::textIsReady() {
    if (!editorDock_->isLoading()) return true;
    statusBar()->showMessage(
        tr("%1 is still opening: wait until its text is in the editor.").arg(document_->displayName()), 5000);
    return false;
}

bool MainWindow::maybeSave() {
    if (!editorDock_->isModified()) return true;
    switch (
        ask(Question::SaveChanges, tr("%1 has unsaved changes. Save them?").arg(document_->displayName()))) {
        case QMessageBox::Save:
            return saveScene();
        case QMessageBox::Discard:
            Autosave::remove(document_->path());
            editorDock_->setModified(false);
            return true;
        default:
            return false;
    }
}

QMessageBox::StandardButton MainWindow::ask(Question question, const QString& text) {
    if (asker_) return asker_(question, text);
    switch (question) {
        case Question::SaveChanges:
            return QMessageBox::question(this, tr("Unsaved Changes"), text,
                                         QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                         QMessageBox::Save);
        case Question::RestoreAutosave:
            return QMessageBox::question(this, tr("Restore Unsaved Edits"), text,
                                         QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        case Question::ReloadChangedFile:
            break;
    }
    QMessageBox box(QMessageBox::Question, tr("File Changed on Disk"), text, QMessageBox::NoButton, this);
    box.addButton(tr("Load the File"), QMessageBox::YesRole);
    QAbstractButton* keep = box.addButton(tr("Keep My Edits"), QMessageBox::NoRole);
    box.exec();
    return box.clickedButton() == keep ? QMessageBox::No : QMessageBox::Yes;
}

void MainWindow::onTextLoaded(const QString& text) {
    editorDock_->setSceneText(text);
    updateTitle();
}

void MainWindow::onTextSettled() {
    const QString text = editor()->toPlainText();
    document_->setText(text);
    if (editorDock_->isModified()) Autosave::write(document_->path(), text);
}

void MainWindow::onFileChangedOnDisk() {
    if (ask(Question::ReloadChangedFile,
            tr("%1 changed on disk, and the editor has unsaved changes. Load the file (your edits are "
               "lost) or keep your edits?")
                .arg(document_->displayName())) == QMessageBox::No)
        return;
    Autosave::remove(document_->path());
    document_->reload();
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — f2-viewer").arg(document_->displayName()));
    setWindowModified(editorDock_->isModified());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybeSave())
        event->accept();
    else
        event->ignore();
}

void MainWindow::onSceneChanged(bool newDocument) {
    const auto scene = document_->scene();
    playback_->setRange(scene->lastFrame(), scene->fps);
    timeline_->setRange(scene->lastFrame(), scene->fps);
    // A playing frame may take one tick of the clock; another scene's cost is not known yet.
    playbackAntialias_.setBudgetMs(playback_->tickIntervalMs());
    if (newDocument) playbackAntialias_.reset();
    if (newDocument) {
        playback_->clearLoop();
        playback_->seek(0);
    }
    timeline_->setTime(playback_->time());
    const Camera camera = cameraAt(*scene, playback_->time());
    // A reload of the same file keeps the user's look-around; a new file starts at its camera.
    viewport_->setSceneCamera(camera, orbitTargetDistance(*scene, camera), !newDocument);
    updateTitle();
    scheduleFrame();
}

void MainWindow::onDiagnosticsChanged() {
    const auto& list = document_->diagnosticList();
    std::vector<EditorProblem> inEditor;
    const std::string ownFile = document_->sourceName();
    for (const Diagnostic& d : list)
        // Problems in an included file are listed but not underlined here.
        if (d.loc.file == ownFile)
            inEditor.push_back({d.loc.line, d.loc.column, QString::fromStdString(d.message),
                                d.severity == Severity::Error, d.length});
    editor()->setProblems(std::move(inEditor));
    diagnosticsDock_->setProblems(list, document_->diagnostics());
    if (document_->hasErrors())
        statusBar()->showMessage(
            tr("%1 has errors; showing the last good scene").arg(document_->displayName()));
    else
        statusBar()->clearMessage();
}

void MainWindow::onProblemClicked(const QString& file, int line, int column) {
    if (file.toStdString() != document_->sourceName()) return;
    editorDock_->show();
    editor()->goTo(line, column);
}

QListWidget* MainWindow::problemsList() const { return diagnosticsDock_->list(); }

void MainWindow::scheduleFrame() {
    if (!frameTimer_.isActive()) frameTimer_.start();
}

void MainWindow::requestFrame() {
    auto scene = document_->scene();
    if (!scene) return;
    const double time = playback_->time();
    viewport_->followSceneCamera(cameraAt(*scene, time));
    RenderOptions options;
    options.view = viewModes_->mode();
    lastRequest_ = {std::move(scene), time, viewport_->viewCamera(), options};
    RenderRequest request = lastRequest_;
    if (playback_->isPlaying() && options.view == ViewMode::Shaded)
        request.options.antialias = playbackAntialias_.level();
    controller_->request(request);
}

void MainWindow::setRefinement(bool on) {
    refinement_ = on;
    if (on)
        refine();
    else
        scheduleFrame();  // back to one sample
}

bool MainWindow::isRefining() const {
    return refinement_ && !playback_->isPlaying() && shownFrame_.serial != 0 &&
           shownFrame_.view == ViewMode::Shaded && shownFrame_.antialias < kRefinedAntialias;
}

bool MainWindow::isPictureComplete() const {
    return isVisible() && windowHandle() && windowHandle()->isExposed() && shownFrame_.serial != 0 &&
           shownFrame_.size == viewport_->renderSize() && !controller_->hasPendingFrames() &&
           !frameTimer_.isActive() && !isRefining();
}

void MainWindow::refine() {
    // Only the latest view, only when nothing newer is on its way: any change
    // (time, camera, size, scene) makes a new one-sample request, which
    // restarts refinement from its frame.
    if (!isRefining() || controller_->hasPendingFrames() || frameTimer_.isActive() || !lastRequest_.scene)
        return;
    RenderRequest next = lastRequest_;
    next.options.antialias = shownFrame_.antialias * 2;
    controller_->request(next);
}

void MainWindow::onFrameReady(const QImage& image, const FrameInfo& info) {
    playbackAntialias_.observe(info.antialias, info.timings);
    shownFrame_ = info;
    viewport_->setImage(image);
    updateSelectionView();
    updateStatus();
    refine();
}

void MainWindow::selectAt(QPointF imagePoint) {
    const QImage& image = viewport_->image();
    const auto scene = document_->scene();
    if (image.isNull() || !scene) return;
    // The frame on screen: its time and the view at its size, so the pick
    // names what the user sees.
    const Camera camera = viewport_->viewCamera(image.size());
    const auto hit = pickPixel(*scene, shownFrame_.time, camera, int(imagePoint.x()), int(imagePoint.y()));
    setSelection(hit ? std::optional(selectionOf(*scene, *hit)) : std::nullopt);
    if (selection_) showCreatingLine();
}

int MainWindow::editorLineOf(const CreatedAt& created, ObjectKind kind) const {
    if (created.loc.file != document_->sourceName()) return 0;
    const QTextBlock block = editor()->document()->findBlockByNumber(created.loc.line - 1);
    if (!block.isValid()) return 0;
    // The text may have changed since the scene parsed: the line must still hold the command.
    const std::string_view name = objectKindName(kind);
    const QString command = u'/' + QString::fromLatin1(name.data(), qsizetype(name.size()));
    return block.text().mid(created.loc.column - 1).startsWith(command) ? created.loc.line : 0;
}

void MainWindow::showCreatingLine() {
    const auto scene = document_->scene();
    const auto object = findObject(*scene, *selection_);
    const CreatedAt* created = document_->locations()->object(selection_->object);
    if (!object || !created) return;
    const QString target = selection_->target();
    // Several objects from one line: a loop made them (or an include read more than once).
    const QString loop =
        created->sameLine > 1 ? tr(", one of %1 objects that line makes").arg(created->sameLine) : QString();
    if (const int line = editorLineOf(*created, scene->objects[*object].kind)) {
        QTextCursor cursor(editor()->document()->findBlockByNumber(line - 1));
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        editor()->setTextCursor(cursor);
        editor()->centerCursor();
        if (!loop.isEmpty())
            statusBar()->showMessage(tr("%1 is made by line %2%3").arg(target).arg(line).arg(loop));
        return;
    }
    const QString place = QStringLiteral("%1:%2")
                              .arg(includedFileName(created->loc.file, document_->path()))
                              .arg(created->loc.line);
    // Another file: the /include line of this file that made this one.
    if (const int line = created->loc.file == document_->sourceName()
                             ? 0
                             : includingLine(editor()->toPlainText(), document_->sourceName(), created->loc,
                                             created->instance)) {
        QTextCursor cursor(editor()->document()->findBlockByNumber(line - 1));
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        editor()->setTextCursor(cursor);
        editor()->centerCursor();
        statusBar()->showMessage(tr("%1 made in %2 (included at line %3)").arg(target, place).arg(line));
        return;
    }
    // Text that changed since (or an include no longer there): name the place, select nothing.
    statusBar()->showMessage(created->loc.file == document_->sourceName()
                                 ? tr("%1 was made by line %2 before the latest edits%3")
                                       .arg(target)
                                       .arg(created->loc.line)
                                       .arg(loop)
                                 : tr("%1 is made in an included file, %2%3").arg(target, place, loop));
}

void MainWindow::setSelection(std::optional<Selection> selection) {
    selection_ = std::move(selection);
    updateSelectionView();
}

void MainWindow::updateSelectionView() {
    const auto scene = document_->scene();
    const auto object = selection_ && scene ? findObject(*scene, *selection_) : std::nullopt;
    if (!object) {
        selection_.reset();  // deleted or renamed in the text
        viewport_->setSelectionOutline(std::nullopt);
        selectionStatus_->clear();
        timeline_->setKeyMarkers({});
        return;
    }
    const SceneObject& target = scene->objects[*object];
    // The timeline's steps are whole frames: a key at a fractional time
    // (SPEC 10.4) shows at the nearest one.
    QList<int> keys;
    for (const Key& key :
         (selection_->part ? target.partTracks[std::size_t(*selection_->part)] : target.track).keys)
        keys << int(std::lround(key.time));
    timeline_->setKeyMarkers(keys);
    EvaluatedFrame frame;
    evaluateFrame(*scene, shownFrame_.time, frame);
    const Bounds bounds = selectionBounds(*scene, frame, *object, selection_->part);
    const QImage& image = viewport_->image();
    viewport_->setSelectionOutline(image.isNull() ? std::nullopt
                                                  : outlineRect(viewport_->viewCamera(image.size()), bounds));
    const Vec3 centre = (bounds.lo + bounds.hi) * 0.5f;
    selectionStatus_->setText(tr("%1 at (%2, %3, %4)")
                                  .arg(selection_->target())
                                  .arg(double(centre.x), 0, 'f', 1)
                                  .arg(double(centre.y), 0, 'f', 1)
                                  .arg(double(centre.z), 0, 'f', 1));
}

void MainWindow::setCameraFromView() {
    if (!textIsReady()) return;
    const auto scene = document_->scene();
    const Pose pose = viewport_->orbit() ? viewport_->orbit()->pose() : scene->camera.pose;
    applyEdit(editor(), cameraEdit(editor()->toPlainText(), scene->camera, pose));
}

bool MainWindow::keySelectionHere() {
    if (!textIsReady()) return false;
    const auto scene = document_->scene();
    const auto object = selection_ ? findObject(*scene, *selection_) : std::nullopt;
    if (!object) {
        statusBar()->showMessage(tr("Select an object or part first (click it in the picture)."), 5000);
        return false;
    }
    const int frame = playback_->frame();
    const Pose pose = selectionKeyPose(*scene, *object, selection_->part, frame);
    // A new target's first key goes after its creating line, unless a loop
    // made it (inside the loop it would be read on every pass) or it is in
    // another file: then at the end.
    const CreatedAt* created = document_->locations()->object(selection_->object);
    const int createdAt =
        created && created->sameLine == 1 ? editorLineOf(*created, scene->objects[*object].kind) : 0;
    applyEdit(editor(), keyEdit(editor()->toPlainText(), selection_->target(), frame, pose, createdAt));
    return true;
}

void MainWindow::keyCameraHere() {
    if (!textIsReady()) return;
    const auto scene = document_->scene();
    const int frame = playback_->frame();
    // What the user sees: the look-around if there is one, else the scene camera.
    const auto& orbit = viewport_->orbit();
    const Pose pose = cameraKeyPose(*scene, frame, orbit ? std::optional(orbit->pose()) : std::nullopt);
    const CameraKeyWrite write = cameraKeyWrite(editor()->toPlainText(), *scene, frame, pose);
    applyEdits(editor(), write.edits);
    QStringList notes;
    if (!write.note.isEmpty()) notes << write.note;
    if (orbit && scene->camera.lookAt)
        notes << tr("The camera's /look_at turns it: the key moves the eye, not where it looks.");
    if (!notes.isEmpty()) statusBar()->showMessage(notes.join(u' '), 8000);
}

QString MainWindow::selectionStatus() const { return selectionStatus_->text(); }

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
    viewStatus_->setText(tr("view: %1").arg(ViewModeMenu::label(shownFrame_.view)));
    const int n = shownFrame_.antialias;
    refineStatus_->setText(shownFrame_.serial == 0 || playback_->isPlaying() || !refinement_ ||
                                   shownFrame_.view != ViewMode::Shaded
                               ? QString()
                           : isRefining() ? tr("refining: %1×%1 samples…").arg(n)
                                          : tr("refined: %1×%1 samples").arg(n));
    const char* const modeNames[] = {"off", "auto", "on"};
    playbackAntialiasStatus_->setText(
        shownFrame_.serial != 0 && playback_->isPlaying() && shownFrame_.view == ViewMode::Shaded
            ? tr("playing: %1×%1 samples (%2)").arg(n).arg(tr(modeNames[int(playbackAntialias_.mode())]))
            : QString());
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
    // The viewer never writes the scene file or a file it includes, whatever
    // name the user picks.
    for (const QString& source : document_->sources()) {
        if (QFileInfo(path) != QFileInfo(source)) continue;
        QMessageBox::warning(this, title,
                             source == document_->path()
                                 ? tr("Refusing to overwrite the scene file.")
                                 : tr("Refusing to overwrite a file the scene includes."));
        return true;
    }
    return false;
}

QString MainWindow::outputFolder() const {
    return document_->path().isEmpty() ? QDir::currentPath() : QFileInfo(document_->path()).absolutePath();
}

Image MainWindow::frameToSave() const {
    // Rendered again rather than taken from the screen: the picture on screen
    // may be a stretched older frame while the window resizes, and its size
    // follows the docks at 25-100 %. One frame is milliseconds, so the GUI
    // thread can afford it for a menu command.
    const QSize size = viewport_->renderSize();
    Renderer renderer;
    Image image;
    RenderOptions options;
    options.view = viewModes_->mode();  // what the picture shows
    renderer.render(*document_->scene(), playback_->time(), viewport_->viewCamera(size), image, options);
    return image;
}

void MainWindow::saveFrame() {
    const QString stem = exportStem();
    const QString suggested =
        QStringLiteral("%1_frame_%2.png").arg(stem).arg(playback_->frame(), 4, 10, QChar('0'));
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save Frame"), QDir(outputFolder()).filePath(suggested), tr("PNG images (*.png)"));
    if (path.isEmpty() || refuseSceneFile(path, tr("Save Frame"))) return;
    std::string error;
    if (!writePng(frameToSave(), QFile::encodeName(path).toStdString(), error))
        QMessageBox::warning(this, tr("Save Frame"), QString::fromStdString(error));
    else
        statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
}

void MainWindow::exportPngSequence() {
    auto scene = document_->scene();
    if (!scene) return;
    playback_->pause();  // the export gets the CPU
    const QString dir =
        QFileDialog::getExistingDirectory(this, tr("Export PNG Sequence to Folder"), outputFolder());
    if (dir.isEmpty()) return;
    const QString stem = exportStem();
    const FramePattern pattern = exportSequencePattern(dir, stem, playback_->playRange().last + 1);
    runExport(std::move(scene), std::make_unique<PngSequenceSink>(pattern),
              QDir(dir).filePath(stem + "_*.png"));
}

void MainWindow::exportVideo() {
    auto scene = document_->scene();
    if (!scene) return;
    playback_->pause();
    QFileDialog dialog(this, tr("Export Video"), QDir(outputFolder()).filePath(exportStem() + ".mp4"),
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

ExportJob MainWindow::exportJob(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                                const QString& destination) const {
    ExportJob job;
    // Like `f2 render`: the scene's /camera size, seen from the current view.
    // The scene's moving camera, unless the user is looking around.
    const QSize size(scene->camera.width, scene->camera.height);
    job.view = viewport_->isOrbiting() ? FrameView::fixedCamera(viewport_->viewCamera(size))
                                       : FrameView::sceneCamera(size.width(), size.height());
    job.scene = std::move(scene);
    // The loop's frames when it is set, else the whole scene.
    const FrameRange frames = playback_->playRange();
    job.firstFrame = frames.first;
    job.lastFrame = frames.last;
    job.sink = std::move(sink);
    job.destination = destination;
    return job;
}

void MainWindow::runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                           const QString& destination) {
    ExportJob job = exportJob(std::move(scene), std::move(sink), destination);
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

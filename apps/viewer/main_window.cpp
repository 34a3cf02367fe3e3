#include "main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QListWidget>
#include <QMenuBar>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTextBlock>
#include <QVBoxLayout>
#include <QWindow>

#include "core/render/orbit_camera.h"
#include "editor_dock.h"
#include "gizmo_tool.h"
#include "help_windows.h"
#include "opening_indicator.h"
#include "playback.h"
#include "problems_dock.h"
#include "scene_document.h"
#include "scene_editor.h"
#include "studio_session.h"
#include "text_capture.h"
#include "timeline_widget.h"
#include "view_mode_menu.h"
#include "viewport_widget.h"

namespace f2::viewer {

namespace {
const char* const kScaleKey = "renderScale";
const char* const kPlaybackAntialiasKey = "playbackAntialias";
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    // Made first, so it is destroyed first: the render worker joins while
    // every widget it could talk to still exists.
    session_ = new StudioSession(this);
    document_ = session_->document();
    playback_ = session_->playback();

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

    readouts_ = new StatusReadouts(statusBar(), session_);
    opening_ = new OpeningIndicator(statusBar(), document_, editorDock_);
    files_ = new SceneFiles(this, document_, editorDock_);

    session_->setViewCamera([this](const Camera& sceneCamera) {
        viewport_->followSceneCamera(sceneCamera);
        return viewport_->viewCamera();
    });

    connect(session_, &StudioSession::sceneChanged, this, &MainWindow::onSceneChanged);
    connect(document_, &SceneDocument::diagnosticsChanged, this, &MainWindow::onDiagnosticsChanged);
    connect(session_, &StudioSession::frameShown, this, &MainWindow::onFrameShown);
    connect(session_, &StudioSession::selectionChanged, this, &MainWindow::showSelection);
    connect(viewport_, &ViewportWidget::viewChanged, this, &MainWindow::scheduleFrame);
    connect(viewport_, &ViewportWidget::clicked, this,
            [this](QPointF point, Qt::KeyboardModifiers modifiers) {
                selectAt(point, modifiers.testFlag(Qt::ControlModifier));
            });
    connect(playback_, &Playback::timeChanged, timeline_, &TimelineWidget::setTime);
    connect(playback_, &Playback::playingChanged, timeline_, &TimelineWidget::setPlaying);
    connect(timeline_, &TimelineWidget::playToggled, playback_, &Playback::togglePlaying);
    connect(timeline_, &TimelineWidget::stepRequested, playback_, &Playback::step);
    connect(timeline_, &TimelineWidget::seekRequested, playback_, &Playback::seek);
    connect(timeline_, &TimelineWidget::scrubStarted, playback_, &Playback::beginScrub);
    connect(timeline_, &TimelineWidget::scrubFinished, playback_, &Playback::endScrub);
    connect(timeline_, &TimelineWidget::speedChanged, playback_, &Playback::setSpeed);
    connect(timeline_, &TimelineWidget::loopInRequested, playback_, &Playback::setLoopIn);
    connect(timeline_, &TimelineWidget::loopOutRequested, playback_, &Playback::setLoopOut);
    connect(timeline_, &TimelineWidget::loopClearRequested, playback_, &Playback::clearLoop);
    // A dope sheet gesture: one undo step, unless the text changed under it.
    connect(timeline_->dopeSheet(), &DopeSheet::editsRequested, this,
            [this](const std::vector<SpanEdit>& edits, const QString& base) {
                if (files_->textIsReady() && editor()->toPlainText() == base)
                    applySourceEdits(editor(), edits);
            });
    connect(playback_, &Playback::loopRangeChanged, this, [this] {
        const auto loop = playback_->loopRange();
        timeline_->setLoop(loop ? std::optional(std::pair(loop->first, loop->last)) : std::nullopt);
    });

    exports_ = new ExportActions(this, session_, viewport_);
    gizmo_ = new GizmoTool(session_, viewport_, editor(), this);
    gizmo_->setCanEdit([this] { return files_->textIsReady(); });
    connect(gizmo_, &GizmoTool::message, statusBar(), &QStatusBar::showMessage);
    createActions();
    setAcceptDrops(true);
    resizeForViewport(viewport_->sizeHint());
    viewport_->setFocus();
    document_->loadDefault();
    readouts_->update();
}

MainWindow::~MainWindow() = default;

SceneEditor* MainWindow::editor() const { return editorDock_->editor(); }

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New Scene"), QKeySequence::New, files_, &SceneFiles::newFile);
    file->addAction(tr("&Open…"), QKeySequence::Open, files_, &SceneFiles::openDialog);
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("Open &Default Scene"), files_, &SceneFiles::openDefaultScene);
    file->addAction(tr("&Reload from Disk"), QKeySequence(Qt::Key_F5), files_, &SceneFiles::reload);
    file->addSeparator();
    file->addAction(tr("&Save Scene"), QKeySequence::Save, files_, &SceneFiles::saveScene);
    file->addAction(tr("Save Scene &As…"), QKeySequence::SaveAs, files_, &SceneFiles::saveSceneAs);
    file->addSeparator();
    file->addAction(tr("Save &Frame as PNG…"), QKeySequence(Qt::Key_F12), exports_,
                    &ExportActions::saveFrame);
    file->addAction(tr("&Export PNG Sequence…"), exports_, &ExportActions::exportPngSequence);
    file->addAction(tr("Export &Video…"), exports_, &ExportActions::exportVideo);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);
    files_->setRecentMenu(recent);

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
    connect(viewModes_, &ViewModeMenu::modeChanged, session_, &StudioSession::setViewMode);
    QAction* refineAction = view->addAction(tr("&Refine When Paused"), this, &MainWindow::setRefinement);
    refineAction->setCheckable(true);
    refineAction->setChecked(session_->refinement());
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
    gizmo_->addActions(view, stage);
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
    session_->playbackAntialias().setMode(mode);
    for (QAction* a : playbackAntialiasActions_->actions()) a->setChecked(a->data().toInt() == int(mode));
    readouts_->update();
}

void MainWindow::setRenderScale(RenderScale scale) {
    QSettings().setValue(kScaleKey, int(scale));
    viewport_->setRenderScale(scale);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (files_->maybeSave())
        event->accept();
    else
        event->ignore();
}

void MainWindow::onSceneChanged(bool newDocument) {
    const auto scene = document_->scene();
    timeline_->setRange(scene->lastFrame(), scene->fps);
    timeline_->setTime(playback_->time());
    const Camera camera = cameraAt(*scene, playback_->time());
    // A reload of the same file keeps the user's look-around; a new file starts at its camera.
    viewport_->setSceneCamera(camera, orbitTargetDistance(*scene, camera), !newDocument);
    files_->updateTitle();
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

bool MainWindow::isOpening() const { return opening_->isBusy(); }

bool MainWindow::isPictureComplete() const {
    return isVisible() && windowHandle() && windowHandle()->isExposed() && session_->isFrameSettled() &&
           shownFrame().size == viewport_->renderSize();
}

void MainWindow::onFrameShown(const QImage& image, const FrameInfo& info) {
    viewport_->setImage(image);
    showSelection();
    readouts_->update();
    // A drive without a finite value (SPEC 10.7): the picture keeps the keyed
    // value of that channel, and the status bar says which drive and frame.
    if (!info.driveProblem.empty()) {
        statusBar()->showMessage(QString::fromStdString(info.driveProblem));
        showsDriveProblem_ = true;
    } else if (showsDriveProblem_) {
        statusBar()->clearMessage();
        showsDriveProblem_ = false;
    }
}

void MainWindow::selectAt(QPointF imagePoint, bool toShape) {
    const QImage& image = viewport_->image();
    if (image.isNull()) return;
    // The view at the size of the frame on screen, so the pick names what the user sees.
    if (!session_->pick(imagePoint, viewport_->viewCamera(image.size()))) return;
    const QString text = editor()->toPlainText();
    const StudioSession::CreatingLine found =
        toShape ? session_->shapeLine(text) : session_->creatingLine(text);
    if (found.line) {
        QTextCursor cursor(editor()->document()->findBlockByNumber(found.line - 1));
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        editor()->setTextCursor(cursor);
        editor()->centerCursor();
    }
    if (!found.message.isEmpty()) statusBar()->showMessage(found.message);
}

void MainWindow::showSelection() {
    const auto& view = session_->selectionView();
    const QImage& image = viewport_->image();
    viewport_->setSelectionOutline(view && !image.isNull()
                                       ? outlineRect(viewport_->viewCamera(image.size()), view->bounds)
                                       : std::nullopt);
    readouts_->setSelection(view ? view->label : QString());
    timeline_->setKeyMarkers(view ? view->keyFrames : QList<int>());
    timeline_->dopeSheet()->setRows(session_->dopeSheetRows(), session_->dopeSheetText(),
                                    document_->scene()->fps);
}

std::optional<Pose> MainWindow::lookAround() const {
    const auto& orbit = viewport_->orbit();
    return orbit ? std::optional(orbit->pose()) : std::nullopt;
}

bool MainWindow::applyCapture(const StudioSession::Capture& capture) {
    applyEdits(editor(), capture.edits);
    if (!capture.note.isEmpty()) statusBar()->showMessage(capture.note, capture.noteMs);
    return !capture.edits.empty();
}

void MainWindow::setCameraFromView() {
    if (files_->textIsReady()) applyCapture(session_->cameraFromView(editor()->toPlainText(), lookAround()));
}

bool MainWindow::keySelectionHere() {
    return files_->textIsReady() && applyCapture(session_->keySelectionHere(editor()->toPlainText()));
}

void MainWindow::keyCameraHere() {
    // What the user sees: the look-around if there is one, else the scene camera.
    if (files_->textIsReady()) applyCapture(session_->keyCameraHere(editor()->toPlainText(), lookAround()));
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

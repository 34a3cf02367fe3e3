#include "studio_session.h"

#include <algorithm>
#include <cmath>

#include "camera_key_writer.h"
#include "capture_pose.h"
#include "core/anim/frame_builder.h"
#include "core/anim/frame_time.h"
#include "core/render/pick.h"
#include "core/render/renderer.h"
#include "core/scene/models.h"
#include "include_origin.h"
#include "key_target.h"
#include "playback.h"
#include "scene_document.h"

namespace f2::viewer {

namespace {

/// Line `line` (1-based) of `text`, as the editor's block of that number holds it.
std::optional<QStringView> lineOfText(const QString& text, int line) {
    if (line < 1) return std::nullopt;
    qsizetype start = 0;
    for (int i = 1; i < line; ++i) {
        start = text.indexOf(u'\n', start);
        if (start < 0) return std::nullopt;
        ++start;
    }
    const qsizetype end = text.indexOf(u'\n', start);
    return QStringView(text).mid(start, end < 0 ? -1 : end - start);
}

}  // namespace

StudioSession::StudioSession(QObject* parent)
    : QObject(parent), controller_(std::make_unique<RenderController>()) {
    document_ = new SceneDocument(this);
    playback_ = new Playback(this);
    frameTimer_.setSingleShot(true);
    frameTimer_.setInterval(0);
    connect(&frameTimer_, &QTimer::timeout, this, &StudioSession::requestFrame);
    connect(document_, &SceneDocument::sceneChanged, this, &StudioSession::onSceneChanged);
    // A written key that does not parse (the text had errors): show the text's last good scene.
    connect(document_, &SceneDocument::diagnosticsChanged, this, [this] {
        if (document_->hasErrors() && previewScene_ && !dragging_) cancelPreview();
    });
    connect(controller_.get(), &RenderController::frameReady, this, &StudioSession::onFrameReady);
    connect(playback_, &Playback::timeChanged, this, &StudioSession::scheduleFrame);
    // Pausing shows the frame again, then refines it.
    connect(playback_, &Playback::playingChanged, this, [this](bool playing) {
        if (!playing) scheduleFrame();
    });
}

StudioSession::~StudioSession() = default;

void StudioSession::onSceneChanged(bool newDocument) {
    // The text now holds the released key (or changed under a drag: the drag goes on over its copy).
    if (!dragging_) previewScene_.reset();
    const auto scene = document_->scene();
    playback_->setRange(scene->lastFrame(), scene->fps);
    // A playing frame may take one tick of the clock; another scene's cost is not known yet.
    playbackAntialias_.setBudgetMs(playback_->tickIntervalMs());
    if (newDocument) playbackAntialias_.reset();
    if (newDocument) {
        playback_->clearLoop();
        playback_->seek(0);
    }
    emit sceneChanged(newDocument);
    scheduleFrame();
}

void StudioSession::setViewMode(ViewMode mode) {
    viewMode_ = mode;
    scheduleFrame();
}

void StudioSession::scheduleFrame() {
    if (!frameTimer_.isActive()) frameTimer_.start();
}

void StudioSession::requestFrame() {
    auto scene = sceneShown();
    if (!scene) return;
    const double time = playback_->time();
    const Camera sceneCamera = cameraAt(*scene, time);
    RenderOptions options;
    options.view = viewMode_;
    const std::optional<BoundsOf> outlined = selectionIn(*scene);
    Camera camera = viewCamera_ ? viewCamera_(sceneCamera) : sceneCamera;
    // A drag's frames come at a quarter of the size (the same view), to keep up with the mouse.
    if (dragging_) camera = camera.resized(std::max(1, camera.width / 4), std::max(1, camera.height / 4));
    lastRequest_ = {std::move(scene), time, camera, options, outlined};
    RenderRequest request = lastRequest_;
    if (playback_->isPlaying() && options.view == ViewMode::Shaded)
        request.options.antialias = playbackAntialias_.level();
    controller_->request(request);
}

void StudioSession::setRefinement(bool on) {
    refinement_ = on;
    if (on)
        refine();
    else
        scheduleFrame();  // back to one sample
}

bool StudioSession::isRefining() const {
    return refinement_ && !playback_->isPlaying() && !dragging_ && shownFrame_.serial != 0 &&
           shownFrame_.view == ViewMode::Shaded && shownFrame_.antialias < kRefinedAntialias;
}

bool StudioSession::isFrameSettled() const {
    return shownFrame_.serial != 0 && !controller_->hasPendingFrames() && !frameTimer_.isActive() &&
           !isRefining();
}

void StudioSession::refine() {
    // Only the latest view, only when nothing newer is on its way: any change
    // (time, camera, size, scene) makes a new one-sample request, which
    // restarts refinement from its frame.
    if (!isRefining() || controller_->hasPendingFrames() || frameTimer_.isActive() || !lastRequest_.scene)
        return;
    RenderRequest next = lastRequest_;
    next.options.antialias = shownFrame_.antialias * 2;
    next.boundsOf = selectionIn(*next.scene);  // it may have changed since
    controller_->request(next);
}

void StudioSession::onFrameReady(const QImage& image, const FrameInfo& info) {
    playbackAntialias_.observe(info.antialias, info.timings);
    shownFrame_ = info;
    updateSelectionView();
    emit frameShown(image, info);
    refine();
}

void StudioSession::renderStill(const Camera& camera, std::function<void(const Image&)> done) {
    // Rendered again rather than taken from the screen: the picture on screen
    // may be a stretched older frame while the window resizes, and its size
    // follows the docks at 25-100 %.
    RenderRequest request;
    request.scene = document_->scene();
    if (!request.scene) return;
    request.time = playback_->time();
    request.camera = camera;
    request.options.view = viewMode_;  // what the picture shows
    controller_->requestStill(std::move(request), std::move(done));
}

bool StudioSession::pick(QPointF imagePoint, const Camera& camera) {
    const auto scene = document_->scene();
    if (!scene) return false;
    // The frame shown: its time and the view at its size, so the pick names what the user sees.
    const auto hit = pickPixel(*scene, shownFrame_.time, camera, int(imagePoint.x()), int(imagePoint.y()));
    setSelection(hit ? std::optional(selectionOf(*scene, *hit)) : std::nullopt);
    return selection_.has_value();
}

void StudioSession::setSelection(std::optional<Selection> selection) {
    selection_ = std::move(selection);
    updateSelectionView();
    emit selectionChanged();
}

bool StudioSession::selectTarget(const QString& target) {
    const auto scene = document_->scene();
    if (!scene) return false;
    Selection selection{target.section(u'.', 0, 0).toStdString(), std::nullopt,
                        target.section(u'.', 1).toStdString()};
    // The camera and a named light, as their markers in the picture select them.
    const bool light = std::any_of(scene->lightMotions.begin(), scene->lightMotions.end(),
                                   [&](const LightMotion& l) { return l.name == selection.object; });
    if (selection.partName.empty() &&
        (target == QLatin1String(kCameraName.data(), kCameraName.size()) || light)) {
        selection.kind = light ? Selection::Kind::Light : Selection::Kind::Camera;
        setSelection(selection);
        return selection_.has_value();  // an ambient light has no pose to select
    }
    for (const SceneObject& object : scene->objects) {
        if (object.name != selection.object) continue;
        if (!selection.partName.empty()) {
            const int part = object.model ? object.model->partIndex(selection.partName) : -1;
            if (part < 0) break;
            selection.part = part;
        }
        setSelection(selection);
        return true;
    }
    return false;
}

void StudioSession::updateDopeSheet() {
    const auto scene = document_->scene();
    if (!scene) return;
    if (scene == dopeScene_ && selection_ == dopeSelection_ && document_->text() == dopeText_) return;
    dopeScene_ = scene;
    dopeSelection_ = selection_;
    dopeText_ = document_->text();
    dopeRows_ = f2::viewer::dopeSheetRows(dopeText_, *scene, selection_);
}

void StudioSession::updateSelectionView() {
    updateDopeSheet();
    const auto scene = document_->scene();
    const Track* track = selection_ && scene ? targetTrack(*scene, *selection_) : nullptr;
    if (!track) {
        selection_.reset();  // deleted or renamed in the text
        selectionView_.reset();
        motionPath_.reset();
        updateDopeSheet();
        return;
    }
    // A preview is a copy of the document's scene with one key changed: the same objects.
    const auto shown = sceneShown();
    updateMotionPath(shown);
    SelectionView view;
    // The timeline's steps are whole frames: a key at a fractional time
    // (SPEC 10.4) shows at the nearest one.
    for (const Key& key : track->keys) view.keyFrames << int(std::lround(key.time));
    const auto object = findObject(*scene, *selection_);
    Vec3 centre;
    if (!object) {
        // A light or the camera: no surface to outline; the label says where it is.
        centre = targetPosition(*shown, *selection_, shownFrame_.time).value_or(Vec3{});
    } else {
        // The frame shown brings the bounds when it was rendered from this scene
        // with this selection; otherwise (a click, an edit since) evaluate it here.
        if (shownFrame_.bounds && (shownFrame_.scene == scene || shownFrame_.scene == shown) &&
            shownFrame_.boundsOf == BoundsOf{*object, selection_->part}) {
            view.bounds = *shownFrame_.bounds;
        } else {
            EvaluatedFrame frame;
            evaluateFrame(*shown, shownFrame_.time, frame);
            view.bounds = selectionBounds(*shown, frame, *object, selection_->part);
        }
        centre = (view.bounds.lo + view.bounds.hi) * 0.5f;
    }
    view.label = tr("%1 at (%2, %3, %4)")
                     .arg(selection_->target())
                     .arg(double(centre.x), 0, 'f', 1)
                     .arg(double(centre.y), 0, 'f', 1)
                     .arg(double(centre.z), 0, 'f', 1);
    selectionView_ = std::move(view);
}

std::optional<BoundsOf> StudioSession::selectionIn(const SceneDesc& scene) const {
    const auto object = selection_ ? findObject(scene, *selection_) : std::nullopt;
    return object ? std::optional(BoundsOf{*object, selection_->part}) : std::nullopt;
}

int StudioSession::lineOf(const QString& text, const CreatedAt& created, std::string_view type) const {
    if (created.loc.file != document_->sourceName()) return 0;
    const auto line = lineOfText(text, created.loc.line);
    if (!line) return 0;
    // The text may have changed since the scene parsed: the line must still hold the command.
    const QString command = u'/' + QString::fromUtf8(type.data(), qsizetype(type.size()));
    return line->mid(created.loc.column - 1).startsWith(command) ? created.loc.line : 0;
}

StudioSession::CreatingLine StudioSession::creatingLine(const QString& text) const {
    const auto scene = document_->scene();
    const auto object = selection_ && scene ? findObject(*scene, *selection_) : std::nullopt;
    const CreatedAt* created = selection_ ? document_->locations()->object(selection_->object) : nullptr;
    if (!object || !created) return {};
    const QString target = selection_->target();
    // Several objects from one line: a loop made them (or an include read more than once).
    const QString loop =
        created->sameLine > 1 ? tr(", one of %1 objects that line makes").arg(created->sameLine) : QString();
    if (const int line = lineOf(text, *created, typeNameOf(scene->objects[*object])))
        return {line,
                loop.isEmpty() ? QString() : tr("%1 is made by line %2%3").arg(target).arg(line).arg(loop)};
    const QString place = QStringLiteral("%1:%2")
                              .arg(includedFileName(created->loc.file, document_->path()))
                              .arg(created->loc.line);
    // Another file: the /include line of this file that made this one.
    if (const int line = created->loc.file == document_->sourceName()
                             ? 0
                             : includingLine(text, document_->sourceName(), created->loc, created->instance))
        return {line, tr("%1 made in %2 (included at line %3)").arg(target, place).arg(line)};
    // Text that changed since (or an include no longer there): name the place, select nothing.
    return {0, created->loc.file == document_->sourceName()
                   ? tr("%1 was made by line %2 before the latest edits%3")
                         .arg(target)
                         .arg(created->loc.line)
                         .arg(loop)
                   : tr("%1 is made in an included file, %2%3").arg(target, place, loop)};
}

StudioSession::CreatingLine StudioSession::shapeLine(const QString& text) const {
    const auto scene = document_->scene();
    const auto object = selection_ && scene ? findObject(*scene, *selection_) : std::nullopt;
    if (!object || !selection_->part || !selection_->shape) return creatingLine(text);
    const ModelType& model = *scene->objects[*object].model;
    const auto index = std::size_t(*selection_->shape);
    if (index >= model.shapes.size() || model.shapes[index].part != *selection_->part)
        return creatingLine(text);
    const QString shapeName = QString::fromStdString(model.shapes[index].name);
    const QString target = selection_->target() + u'.' + shapeName;
    const SourceLoc* loc = document_->locations()->shape(model.name, *selection_->shape);
    const QString type = QString::fromStdString(model.name);
    if (!loc) {
        return {creatingLine(text).line,
                tr("%1 is built into the %2 model: no line of the scene defines it").arg(target, type)};
    }
    // The text may have changed since the scene parsed: the line must still name the shape.
    const QString written = QString::fromStdString(selection_->partName) + u'.' + shapeName;
    if (loc->file == document_->sourceName()) {
        if (const auto line = lineOfText(text, loc->line);
            line && line->mid(loc->column - 1).startsWith(written)) {
            return {loc->line,
                    tr("%1: line %2, in the /model %3 block").arg(target).arg(loc->line).arg(type)};
        }
        return {0, tr("%1 was made by line %2 before the latest edits").arg(target).arg(loc->line)};
    }
    return {0, tr("%1 is made in %2:%3, in the /model %4 block")
                   .arg(target, includedFileName(loc->file, document_->path()))
                   .arg(loc->line)
                   .arg(type)};
}

StudioSession::Capture StudioSession::cameraFromView(const QString& text,
                                                     const std::optional<Pose>& lookAround) const {
    const auto scene = document_->scene();
    return {{cameraEdit(text, scene->camera, lookAround.value_or(scene->camera.pose))}, {}, 0};
}

StudioSession::Capture StudioSession::keySelectionHere(const QString& text) const {
    const auto scene = document_->scene();
    const auto object = selection_ ? findObject(*scene, *selection_) : std::nullopt;
    if (selection_ && !object)
        return {{},
                tr("Key Selection Here keys objects and parts: move %1 with its handles.")
                    .arg(selection_->target()),
                5000};
    if (!object) return {{}, tr("Select an object or part first (click it in the picture)."), 5000};
    const int frame = playback_->frame();
    const Pose pose = selectionKeyPose(*scene, *object, selection_->part, frame);
    // A new target's first key goes after its creating line, unless a loop
    // made it (inside the loop it would be read on every pass) or it is in
    // another file: then at the end.
    const CreatedAt* created = document_->locations()->object(selection_->object);
    const int createdAt =
        created && created->sameLine == 1 ? lineOf(text, *created, typeNameOf(scene->objects[*object])) : 0;
    return {{keyEdit(text, selection_->target(), frame, pose, createdAt)}, {}, 0};
}

StudioSession::Capture StudioSession::keyCameraHere(const QString& text,
                                                    const std::optional<Pose>& lookAround) const {
    const auto scene = document_->scene();
    const int frame = playback_->frame();
    const Pose pose = cameraKeyPose(*scene, frame, lookAround);
    CameraKeyWrite write = cameraKeyWrite(text, *scene, frame, pose);
    QStringList notes;
    if (!write.note.isEmpty()) notes << write.note;
    if (lookAround && scene->camera.lookAt)
        notes << tr("The camera's /look_at turns it: the key moves the eye, not where it looks.");
    return {std::move(write.edits), notes.join(u' '), 8000};
}

std::shared_ptr<const SceneDesc> StudioSession::sceneShown() const {
    return previewScene_ ? previewScene_ : document_->scene();
}

std::optional<GizmoFrame> StudioSession::selectionKeyFrame() const {
    const auto scene = sceneShown();
    if (!selection_ || !scene) return std::nullopt;
    return targetKeyFrame(*scene, *selection_, playback_->frame());
}

std::vector<TargetMarker> StudioSession::targetMarkers() const {
    const auto scene = sceneShown();
    return scene ? f2::viewer::targetMarkers(*scene, shownFrame_.time) : std::vector<TargetMarker>{};
}

void StudioSession::previewKey(const Pose& key) {
    // Rendering a changed copy of the parsed scene rather than the edited text:
    // no parse per mouse move, no undo step per move, and the text is left
    // byte for byte as it was if the drag is cancelled.
    const auto scene = document_->scene();
    if (!selection_ || !scene || !targetTrack(*scene, *selection_)) return;
    if (!dragging_) {
        dragging_ = true;
        playback_->pause();
        // The key goes at the frame on the timeline: show that frame exactly.
        if (playback_->time() != playback_->frame()) playback_->seek(playback_->frame());
    }
    previewScene_ = sceneWithKey(*scene, *selection_, playback_->frame(), key);
    scheduleFrame();
}

void StudioSession::cancelPreview() {
    dragging_ = false;
    previewScene_.reset();
    scheduleFrame();
}

WriteBack StudioSession::releaseKey(const QString& text, const Pose& key) {
    const auto scene = document_->scene();
    if (!selection_ || !scene || !targetTrack(*scene, *selection_)) {
        cancelPreview();
        return {};
    }
    const Vec3 p = key.position, r = key.rotation;
    WriteBack write = writeBack(
        text, {selection_->target(), std::nullopt, playback_->frame(), {p.x, p.y, p.z, r.x, r.y, r.z}});
    const QString written = withEdits(text, write.edits);
    if (write.refused() || written == text) {
        cancelPreview();  // nothing to parse: back to the text's picture now
        return write;
    }
    dragging_ = false;
    // Parsed now rather than after the editor's typing pause: the preview goes
    // at that parse's scene, so an undo straight after still gets its own parse.
    document_->setText(written);
    scheduleFrame();  // the preview at full size, until the text's scene comes
    return write;
}

void StudioSession::updateMotionPath(const std::shared_ptr<const SceneDesc>& scene) {
    if (motionPath_ && pathScene_ == scene && pathSelection_ == selection_) return;
    pathScene_ = scene;
    pathSelection_ = selection_;
    const auto at = [&](double t) { return targetPosition(*scene, *selection_, t).value_or(Vec3{}); };
    MotionPath path;
    const int last = scene->lastFrame();
    const int step = std::max(1, (last + kMaxPathPoints - 1) / kMaxPathPoints);
    for (int frame = 0; frame <= last; frame += step) path.points.push_back(at(frame));
    if (last % step != 0) path.points.push_back(at(last));
    for (const Key& key : targetTrack(*scene, *selection_)->keys)
        path.keys.push_back({int(std::lround(key.time)), at(key.time)});
    motionPath_ = std::move(path);
}

WriteBack StudioSession::writeBack(const QString& text, const WriteRequest& request) const {
    const auto scene = document_->scene();
    const auto locations = document_->locations();
    if (!scene || !locations) return {{}, tr("There is no scene to write to yet."), {}, {}};
    return f2::viewer::writeBack({text, *scene, *locations, document_->sourceName()}, request);
}

}  // namespace f2::viewer

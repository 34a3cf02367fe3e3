#include "scene_files.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QStatusBar>
#include <QTextCursor>

#include "autosave.h"
#include "editor_dock.h"
#include "scene_document.h"
#include "scene_editor.h"

namespace f2::viewer {

namespace {
const char* const kRecentKey = "recentFiles";
}  // namespace

SceneFiles::SceneFiles(QMainWindow* window, SceneDocument* document, EditorDock* editorDock)
    : QObject(window), window_(window), document_(document), editorDock_(editorDock) {
    connect(editorDock_, &EditorDock::textSettled, this, &SceneFiles::onTextSettled);
    connect(editorDock_, &EditorDock::modificationChanged, this, [this](bool modified) {
        document_->setHoldsUnsavedEdits(modified);
        updateTitle();
    });
    connect(document_, &SceneDocument::textLoaded, this, &SceneFiles::onTextLoaded);
    connect(document_, &SceneDocument::fileChangedOnDisk, this, &SceneFiles::onFileChangedOnDisk);
}

void SceneFiles::reload() {
    if (maybeSave()) document_->reload();
}

void SceneFiles::setRecentMenu(QMenu* menu) {
    recentMenu_ = menu;
    rebuildRecentMenu();
}

bool SceneFiles::openFile(const QString& path) {
    if (!maybeSave()) return false;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    document_->load(absolute);
    addRecentFile(absolute);
    editorDock_->show();
    offerAutosave();
    return true;
}

bool SceneFiles::newFile() {
    if (!maybeSave()) return false;
    document_->loadEmpty();
    editorDock_->show();
    offerAutosave();
    editorDock_->editor()->setFocus();
    return true;
}

bool SceneFiles::openDefaultScene() {
    if (!maybeSave()) return false;
    document_->loadDefault();
    offerAutosave();
    return true;
}

void SceneFiles::offerAutosave() {
    disconnect(deferredAutosaveOffer_);
    if (editorDock_->isLoading()) {
        // Restored edits go into the file's text, so they wait for it.
        deferredAutosaveOffer_ = connect(editorDock_, &EditorDock::textShown, this,
                                         &SceneFiles::offerAutosave, Qt::SingleShotConnection);
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
    QTextCursor cursor(editorDock_->editor()->document());
    cursor.select(QTextCursor::Document);
    cursor.insertText(*copy);
    document_->setText(*copy);
}

bool SceneFiles::saveScene() {
    if (document_->path().isEmpty()) return saveSceneAs();
    return writeScene(document_->path());
}

bool SceneFiles::saveSceneAs() {
    const QString dir = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absolutePath();
    const QString suggested =
        QDir(dir).filePath(document_->path().isEmpty() ? QStringLiteral("untitled.f2")
                                                       : QFileInfo(document_->path()).fileName());
    QFileDialog dialog(window_, tr("Save Scene"), suggested, tr("F2 scenes (*.f2);;All files (*)"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix("f2");
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return false;
    return writeScene(QFileInfo(dialog.selectedFiles().first()).absoluteFilePath());
}

bool SceneFiles::writeScene(const QString& path) {
    if (!textIsReady()) return false;
    const QString text = editorDock_->editor()->toPlainText();
    QSaveFile file(path);  // a temporary file renamed over the old one
    if (!file.open(QIODevice::WriteOnly) || file.write(text.toUtf8()) < 0 || !file.commit()) {
        QMessageBox::warning(window_, tr("Save Scene"),
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
    window_->statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

bool SceneFiles::textIsReady() {
    if (!editorDock_->isLoading()) return true;
    window_->statusBar()->showMessage(
        tr("%1 is still opening: wait until its text is in the editor.").arg(document_->displayName()), 5000);
    return false;
}

bool SceneFiles::maybeSave() {
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

QMessageBox::StandardButton SceneFiles::ask(Question question, const QString& text) {
    if (asker_) return asker_(question, text);
    switch (question) {
        case Question::SaveChanges:
            return QMessageBox::question(window_, tr("Unsaved Changes"), text,
                                         QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                         QMessageBox::Save);
        case Question::RestoreAutosave:
            return QMessageBox::question(window_, tr("Restore Unsaved Edits"), text,
                                         QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        case Question::ReloadChangedFile:
            break;
    }
    QMessageBox box(QMessageBox::Question, tr("File Changed on Disk"), text, QMessageBox::NoButton, window_);
    box.addButton(tr("Load the File"), QMessageBox::YesRole);
    QAbstractButton* keep = box.addButton(tr("Keep My Edits"), QMessageBox::NoRole);
    box.exec();
    return box.clickedButton() == keep ? QMessageBox::No : QMessageBox::Yes;
}

void SceneFiles::onTextLoaded(const QString& text) {
    editorDock_->setSceneText(text);
    updateTitle();
}

void SceneFiles::onTextSettled() {
    const QString text = editorDock_->editor()->toPlainText();
    document_->setText(text);
    if (editorDock_->isModified()) Autosave::write(document_->path(), text);
}

void SceneFiles::onFileChangedOnDisk() {
    if (ask(Question::ReloadChangedFile,
            tr("%1 changed on disk, and the editor has unsaved changes. Load the file (your edits are "
               "lost) or keep your edits?")
                .arg(document_->displayName())) == QMessageBox::No)
        return;
    Autosave::remove(document_->path());
    document_->reload();
}

void SceneFiles::updateTitle() {
    window_->setWindowTitle(tr("%1[*] — f2-viewer").arg(document_->displayName()));
    window_->setWindowModified(editorDock_->isModified());
}

void SceneFiles::openDialog() {
    const QString dir = document_->path().isEmpty() ? QString() : QFileInfo(document_->path()).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(window_, tr("Open Scene"), dir, tr("F2 scenes (*.f2);;All files (*)"));
    if (!path.isEmpty()) openFile(path);
}

void SceneFiles::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value(kRecentKey).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue(kRecentKey, files);
    rebuildRecentMenu();
}

void SceneFiles::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = QSettings().value(kRecentKey).toStringList();
    for (const QString& path : files)
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openFile(path); })
            ->setToolTip(path);
    recentMenu_->setEnabled(!files.isEmpty());
}

}  // namespace f2::viewer

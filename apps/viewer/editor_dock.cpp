#include "editor_dock.h"

#include <QHBoxLayout>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QTextDocument>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "number_scrubber.h"
#include "scene_editor.h"

namespace f2::viewer {

EditorDock::EditorDock(QWidget* parent) : QDockWidget(tr("Scene"), parent) {
    setObjectName("editorDock");
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    editor_ = new SceneEditor(content);
    layout->addWidget(editor_, 1);

    findBar_ = new QWidget(content);
    auto* findLayout = new QHBoxLayout(findBar_);
    findLayout->setContentsMargins(4, 2, 4, 2);
    findField_ = new QLineEdit(findBar_);
    findField_->setPlaceholderText(tr("Find"));
    findField_->setClearButtonEnabled(true);
    findStatus_ = new QLabel(findBar_);
    auto* previous = new QToolButton(findBar_);
    previous->setArrowType(Qt::UpArrow);
    previous->setToolTip(tr("Previous match (Shift+F3)"));
    auto* next = new QToolButton(findBar_);
    next->setArrowType(Qt::DownArrow);
    next->setToolTip(tr("Next match (F3, Enter)"));
    auto* close = new QToolButton(findBar_);
    close->setText(QStringLiteral("×"));
    close->setToolTip(tr("Close (Esc)"));
    findLayout->addWidget(findField_, 1);
    findLayout->addWidget(findStatus_);
    findLayout->addWidget(previous);
    findLayout->addWidget(next);
    findLayout->addWidget(close);
    layout->addWidget(findBar_);
    findBar_->hide();
    setWidget(content);

    connect(findField_, &QLineEdit::returnPressed, this, [this] { findNext(false); });
    connect(previous, &QToolButton::clicked, this, [this] { findNext(true); });
    connect(next, &QToolButton::clicked, this, [this] { findNext(false); });
    connect(close, &QToolButton::clicked, this, [this] {
        findBar_->hide();
        editor_->setFocus();
    });
    auto* escape = new QAction(findBar_);
    escape->setShortcut(Qt::Key_Escape);
    escape->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(escape, &QAction::triggered, close, &QToolButton::click);
    findBar_->addAction(escape);

    settleTimer_.setSingleShot(true);
    settleTimer_.setInterval(kSettleMs);
    connect(&settleTimer_, &QTimer::timeout, this, &EditorDock::textSettled);
    connect(editor_, &QPlainTextEdit::textChanged, this, [this] {
        if (!loading_) settleTimer_.start();
    });
    // A scrubbed number is no typing to wait for: the picture follows each step
    // (the parse of the latest text wins, so steps faster than parsing are skipped).
    scrubber_ = new NumberScrubber(editor_);
    connect(scrubber_, &NumberScrubber::scrubbed, this, [this] {
        settleTimer_.stop();
        emit textSettled();
    });
    // The editor's own signal: it follows the document when a loaded one replaces it.
    connect(editor_, &QPlainTextEdit::modificationChanged, this, &EditorDock::modificationChanged);
}

EditorDock::~EditorDock() {
    for (QFutureWatcher<QTextDocument*>* layout : layouts_) {
        layout->waitForFinished();
        delete layout->result();
    }
}

void EditorDock::setSceneText(const QString& text) {
    settleTimer_.stop();
    const quint64 generation = ++generation_;
    const bool wasLoading = isLoading();
    waitingForLayout_ = false;
    if (text.size() < kBackgroundChars) {
        loading_ = true;
        if (editor_->toPlainText() != text) editor_->setPlainText(text);
        loading_ = false;
        editor_->setReadOnly(false);
        editor_->document()->clearUndoRedoStacks();
        editor_->document()->setModified(false);
        if (wasLoading) emit loadingChanged(false);
        emit textShown();
        return;
    }
    // Until the layout arrives: an empty editor that takes no typing.
    loading_ = true;
    editor_->adoptDocument(SceneEditor::makeDocument(QString(), editor_->font(), thread()));
    loading_ = false;
    editor_->setReadOnly(true);
    waitingForLayout_ = true;
    auto* layout = new QFutureWatcher<QTextDocument*>(this);
    layouts_ << layout;
    connect(layout, &QFutureWatcher<QTextDocument*>::finished, this, [this, layout, generation] {
        layouts_.removeOne(layout);
        layout->deleteLater();
        showDocument(layout->result(), generation);
    });
    layout->setFuture(QtConcurrent::run(&layoutPool_, [text, font = editor_->font(), gui = thread()] {
        return SceneEditor::makeDocument(text, font, gui);
    }));
    if (!wasLoading) emit loadingChanged(true);
}

void EditorDock::showDocument(QTextDocument* document, quint64 generation) {
    if (generation != generation_) {
        delete document;  // another text came meanwhile
        return;
    }
    loading_ = true;
    editor_->adoptDocument(document);
    loading_ = false;
    editor_->setReadOnly(false);
    waitingForLayout_ = false;
    emit modificationChanged(false);
    emit loadingChanged(false);
    emit textShown();
}

bool EditorDock::isModified() const { return editor_->document()->isModified(); }

void EditorDock::setModified(bool modified) { editor_->document()->setModified(modified); }

void EditorDock::showFind() {
    show();
    raise();
    findBar_->show();
    const QString selected = editor_->textCursor().selectedText();
    if (!selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator)) findField_->setText(selected);
    findField_->setFocus();
    findField_->selectAll();
}

bool EditorDock::findNext(bool backward) {
    const QString what = findField_->text();
    if (what.isEmpty()) return false;
    const QTextDocument::FindFlags flags =
        backward ? QTextDocument::FindBackward : QTextDocument::FindFlags();
    QTextCursor found = editor_->document()->find(what, editor_->textCursor(), flags);
    if (found.isNull()) {
        // Wrap round to the other end.
        QTextCursor from(editor_->document());
        if (backward) from.movePosition(QTextCursor::End);
        found = editor_->document()->find(what, from, flags);
    }
    findStatus_->setText(found.isNull() ? tr("not found") : QString());
    if (found.isNull()) return false;
    editor_->setTextCursor(found);
    editor_->centerCursor();
    return true;
}

void EditorDock::goToLineDialog() {
    bool ok = false;
    const int line =
        QInputDialog::getInt(this, tr("Go to Line"), tr("Line (1–%1):").arg(editor_->blockCount()),
                             editor_->textCursor().blockNumber() + 1, 1, editor_->blockCount(), 1, &ok);
    if (ok) editor_->goTo(line);
}

}  // namespace f2::viewer

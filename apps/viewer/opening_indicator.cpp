#include "opening_indicator.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QStatusBar>

#include "editor_dock.h"
#include "scene_document.h"

namespace f2::viewer {

OpeningIndicator::OpeningIndicator(QStatusBar* bar, SceneDocument* document, EditorDock* editor)
    : QWidget(bar), bar_(bar), document_(document), editor_(editor), label_(new QLabel(this)) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(label_);
    auto* busy = new QProgressBar(this);
    busy->setRange(0, 0);  // no steps to count: a busy bar
    busy->setMaximumWidth(120);
    busy->setMaximumHeight(label_->sizeHint().height());
    layout->addWidget(busy);
    bar->addWidget(this);
    hide();
    connect(document, &SceneDocument::openingChanged, this, &OpeningIndicator::update);
    connect(editor, &EditorDock::loadingChanged, this, &OpeningIndicator::update);
    // Another file read (this runs before the editor is given its text): a
    // file still opening is superseded, so its line and clock start again.
    connect(document, &SceneDocument::textLoaded, this, [this] {
        clock_.invalidate();
        update();
    });
}

bool OpeningIndicator::isBusy() const { return document_->isOpening() || editor_->isLoading(); }

QString OpeningIndicator::text() const { return clock_.isValid() ? label_->text() : QString(); }

void OpeningIndicator::update() {
    if (isBusy()) {
        if (clock_.isValid()) return;
        clock_.start();
        const qint64 bytes = QFileInfo(document_->path()).size();
        label_->setText(tr("Opening %1 (%2)…")
                            .arg(document_->displayName(),
                                 QLocale().formattedDataSize(bytes, 1, QLocale::DataSizeSIFormat)));
        show();
        return;
    }
    if (!clock_.isValid()) return;
    const double seconds = double(clock_.elapsed()) / 1000.0;
    clock_.invalidate();
    hide();
    bar_->showMessage(tr("Opened %1 in %2 s").arg(document_->displayName()).arg(seconds, 0, 'f', 1), 5000);
    emit opened();
}

}  // namespace f2::viewer

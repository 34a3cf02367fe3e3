#include "view_mode_menu.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace f2::viewer {

QString ViewModeMenu::label(ViewMode mode) {
    switch (mode) {
        case ViewMode::Shaded:
            return tr("Shaded");
        case ViewMode::Normals:
            return tr("Normals");
        case ViewMode::Depth:
            return tr("Depth");
        case ViewMode::ShadowMask:
            return tr("Shadow Mask");
        case ViewMode::PrimitiveIds:
            return tr("Primitive IDs");
        case ViewMode::Cost:
            return tr("BVH Cost");
    }
    return {};
}

ViewModeMenu::ViewModeMenu(QMenu* parent) : QObject(parent) {
    QMenu* menu = parent->addMenu(tr("&Mode"));
    auto* group = new QActionGroup(this);
    for (ViewMode mode : kViewModes) {
        QAction* a = menu->addAction(label(mode), this, [this, mode] { setMode(mode); });
        a->setCheckable(true);
        a->setChecked(mode == mode_);
        group->addAction(a);
        actions_[std::size_t(mode)] = a;
    }
}

void ViewModeMenu::setMode(ViewMode mode) {
    action(mode)->setChecked(true);
    if (mode == mode_) return;
    mode_ = mode;
    emit modeChanged(mode);
}

}  // namespace f2::viewer

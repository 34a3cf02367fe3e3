#pragma once
/// The Help menu's windows: every keyboard shortcut (read from the menus, so
/// the list cannot go stale), the scene-language reference compiled into the
/// binary (docs/scene-language.md) and About.
#include <QString>

class QMenuBar;
class QWidget;

namespace f2::viewer {

/// One line per menu command that has a shortcut: "Menu › Command<TAB>Keys".
QString shortcutList(const QMenuBar* menus);
/// The scene-language reference (Markdown), as built into the binary.
QString languageReference();

void showShortcuts(QWidget* parent, const QMenuBar* menus);
void showLanguageReference(QWidget* parent);
void showAbout(QWidget* parent);

}  // namespace f2::viewer

#include "help_windows.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace f2::viewer {

namespace {

void listMenu(const QMenu* menu, const QString& prefix, QStringList& lines) {
    for (const QAction* action : menu->actions()) {
        const QString name = prefix + QStringLiteral(" › ") + QString(action->text()).remove('&');
        if (action->menu())
            listMenu(action->menu(), name, lines);
        else if (!action->shortcut().isEmpty())
            lines << name + QLatin1Char('\t') + action->shortcut().toString(QKeySequence::NativeText);
    }
}

/// A resizable window showing `text` in a browser (Markdown when `markdown`).
void showText(QWidget* parent, const QString& title, const QString& text, bool markdown) {
    auto* dialog = new QDialog(parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(title);
    auto* layout = new QVBoxLayout(dialog);
    auto* browser = new QTextBrowser(dialog);
    browser->setOpenExternalLinks(true);
    if (markdown)
        browser->setMarkdown(text);
    else
        browser->setPlainText(text);
    layout->addWidget(browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(760, 640);
    dialog->show();
}

}  // namespace

QString shortcutList(const QMenuBar* menus) {
    QStringList lines;
    for (const QAction* action : menus->actions())
        if (action->menu()) listMenu(action->menu(), QString(action->text()).remove('&'), lines);
    return lines.join('\n');
}

QString languageReference() {
    QFile file(QStringLiteral(":/docs/scene-language.md"));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

void showShortcuts(QWidget* parent, const QMenuBar* menus) {
    const QString text =
        shortcutList(menus) +
        QObject::tr(
            "\n\nSpace, Left, Right, Home, End and C act while the picture or the timeline has the "
            "focus (click the picture); in the editor they type.\n"
            "In the picture: drag to orbit, wheel to zoom, click to select an object or part (its "
            "line in the editor), Ctrl+click to go to the clicked shape's line in its /model block.");
    showText(parent, QObject::tr("Keyboard Shortcuts"), text, false);
}

void showLanguageReference(QWidget* parent) {
    showText(parent, QObject::tr("Scene Language Reference"), languageReference(), true);
}

void showAbout(QWidget* parent) {
    QMessageBox::about(parent, QObject::tr("About f2-viewer"),
                       QObject::tr("<h3>F2 Stage %1</h3>"
                                   "<p>Write a scene of robots and people in a few lines of text and watch "
                                   "it as a ray-traced animation while you type.</p>"
                                   "<p>The viewer of F2 Stage, built with Qt %2.</p>")
                           .arg(QApplication::applicationVersion(), QString::fromLatin1(qVersion())));
}

}  // namespace f2::viewer

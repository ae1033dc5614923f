#include "shared/Help.h"

#include "marbler/gl/Backend.h"

#include <QAction>
#include <QCoreApplication>
#include <QKeySequence>
#include <QMenu>

#include <algorithm>

namespace marbler::ui {

namespace {

QString helpText(const char* text) {
    return QCoreApplication::translate("Help", text);
}

QString row(const QString& keys, const QString& what, const QString& where) {
    return QStringLiteral("<tr><td><b>%1</b></td><td>%2</td><td>%3</td></tr>")
        .arg(keys.toHtmlEscaped(), what.toHtmlEscaped(), where.toHtmlEscaped());
}

/// The words of the menu holding an action ("Edit"), empty for one in no menu.
QString menuOf(const QAction* action) {
    for (QObject* object : action->associatedObjects())
        if (auto* menu = qobject_cast<QMenu*>(object)) {
            QString title = menu->title();
            return title.remove(QLatin1Char('&'));
        }
    return {};
}

} // namespace

QString shortcutKeys(const QAction* action) {
    QStringList list;
    for (const QKeySequence& key : action->shortcuts())
        list << key.toString(QKeySequence::NativeText);
    return list.join(QStringLiteral(", "));
}

QString marblerVersion() {
    return QStringLiteral(MARBLER_VERSION);
}

QList<QAction*> shortcutActions(const QWidget* window) {
    QList<QAction*> result;
    for (QAction* action : window->findChildren<QAction*>())
        if (!action->shortcuts().isEmpty() && !result.contains(action)) result << action;
    return result;
}

QString plainActionText(const QAction* action) {
    QString text = action->text();
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    if (text.endsWith(QStringLiteral("…"))) text.chop(1);
    // A dock's toggle is named after the dock alone.
    if (action->isCheckable() && menuOf(action) == helpText("View") && !text.contains(QLatin1Char(':')))
        text = helpText("Show or hide %1").arg(text);
    return text;
}

QString shortcutTableHtml(const QList<QAction*>& actions) {
    QString html = QStringLiteral("<table cellspacing='0' cellpadding='3'>");
    html +=
        QStringLiteral("<tr><th align='left'>%1</th><th align='left'>%2</th><th align='left'>%3</th></tr>")
            .arg(helpText("Keys"), helpText("Does"), helpText("Menu"));
    for (const QAction* action : actions)
        html += row(shortcutKeys(action), plainActionText(action), menuOf(action));
    return html + QStringLiteral("</table>");
}

QString aboutHtml(const AboutFacts& facts) {
    QString html = helpText("<h2>Marbler %1</h2>"
                            "<p>A workbench for breeding marbled designs, after <i>mathematical marbling</i> "
                            "(Lu, Jaffer, Jin, Zhao, Mao, IEEE CG&amp;A 2012).</p>")
                       .arg(facts.version.toHtmlEscaped());
    html += QStringLiteral("<table cellpadding='2'>");
    const auto line = [&](const QString& what, const QString& value) {
        html += QStringLiteral("<tr><td valign='top'><b>%1</b></td><td>%2</td></tr>")
                    .arg(what, value.toHtmlEscaped());
    };
    line(helpText("Qt"), facts.qt);
    line(helpText("OpenImageIO"),
         facts.imageIo.isEmpty()
             ? helpText("not loaded: it loads on the first export to EXR, JPEG or another format "
                        "beyond PNG and TIFF")
             : facts.imageIo);
    line(helpText("Renderer"), facts.renderer.isEmpty() ? helpText("being chosen…") : facts.renderer);
    html += QStringLiteral("</table>");
    html += helpText("<p>Choose the renderer in View ▸ Renderer; the environment variable %1=auto|gpu|cpu "
                     "overrides it.</p>")
                .arg(QString::fromLatin1(gl::BackendEnvironmentVariable));
    return html;
}

} // namespace marbler::ui

#include "workbench/WorkbenchGuide.h"

#include "shared/Help.h"
#include "workbench/WorkbenchWindow.h"

namespace marbler::ui {

QString guideHtml(const WorkbenchWindow& window) {
    using Op = GeneticOperator;
    const auto actionText = [](const QAction* action) { return plainActionText(action).toHtmlEscaped(); };
    const auto keyOf = [](const QAction* action) { return shortcutKeys(action).toHtmlEscaped(); };
    QString html =
        WorkbenchWindow::tr("<h2>Marbler guide</h2>"
                            "<p>The grid shows nine designs: one <i>generation</i>. Breed the next one from "
                            "the designs you like.</p>"
                            "<h3>Pick parents</h3>"
                            "<p>Click a design to pick it as a parent (it gets a frame); click it again to "
                            "let it go. With the keyboard, "
                            "the arrows move between designs and Space picks. %1 (%2) lets every parent go. "
                            "Parents stay in their cells; every other cell gets offspring.</p>"
                            "<h3>Breed</h3><p>Apply an operator from the Breed menu or the toolbar:</p><ul>")
            .arg(actionText(window.findChild<QAction*>(QStringLiteral("clearSelectionAction"))),
                 keyOf(window.findChild<QAction*>(QStringLiteral("clearSelectionAction"))));
    for (Op op : {Op::Alter, Op::Recombine, Op::Swap, Op::Reinit}) {
        const QAction* action = window.operatorAction(op);
        html += QStringLiteral("<li><b>%1</b> (%2): %3.</li>")
                    .arg(actionText(action), keyOf(action), action->statusTip().toHtmlEscaped());
    }
    html += WorkbenchWindow::tr("</ul><p>The <b>Strength</b> slider beside them sets how far %1 moves the "
                                "strokes, from 0 % (barely) to "
                                "100 % (a lot). An operator that cannot run is greyed out; its tooltip says "
                                "what it needs. Flat (2D) and "
                                "solid (3D) designs do not breed together.</p>")
                .arg(operatorLabel(Op::Alter).toHtmlEscaped());
    html += WorkbenchWindow::tr("<h3>Back and forward</h3>"
                                "<p>Every change (breeding, a new random population, opening designs, "
                                "bringing back a favourite) is a new "
                                "generation, and nothing is lost: <b>%1</b> (%2) and <b>%3</b> (%4) step "
                                "through them. The Lineage panel "
                                "lists every generation; double-click one to go to it.</p>")
                .arg(actionText(window.backAction()), keyOf(window.backAction()),
                     actionText(window.forwardAction()), keyOf(window.forwardAction()));
    html += WorkbenchWindow::tr("<h3>Favourites</h3>"
                                "<p>Press F on a design (or right-click it, <i>Keep as favourite</i>) to "
                                "keep it on the Favourites shelf, "
                                "where it is saved as a genome file. Double-click a favourite, or drag it "
                                "onto a cell, to bring it back.</p>"
                                "<h3>The large view</h3>"
                                "<p>Double-click a design, or press Enter on it, to see it large. Drag a "
                                "solid design to turn its object. "
                                "<i>Save genome…</i> (%1) writes the design's genome file; <i>Export "
                                "image…</i> (%2) renders it to PNG, "
                                "TIFF, EXR or JPEG at any size; a PNG or TIFF carries the design's genome, "
                                "so it opens again as a design. "
                                "<i>Copy genome</i> (%3) puts the genome on the clipboard as text. The "
                                "status bar then says where the "
                                "file went, with <i>Show in folder</i>.</p>")
                .arg(QKeySequence(QKeySequence::Save).toString(QKeySequence::NativeText),
                     QKeySequence(Qt::CTRL | Qt::Key_E).toString(QKeySequence::NativeText),
                     QKeySequence(QKeySequence::Copy).toString(QKeySequence::NativeText));
    html +=
        WorkbenchWindow::tr("<h3>Opening designs</h3>"
                            "<p>File ▸ Open designs, or drop genome files on the window (or PNG and TIFF "
                            "images Marbler exported, "
                            "which carry their genomes; a plain image is refused): they go into the selected "
                            "cells, then free "
                            "ones. <b>%1</b> (%2) copies the focused or selected design as genome text, and "
                            "<b>%3</b> (%4) puts "
                            "a genome from the clipboard into the grid the same way. When they would replace "
                            "designs you are asked whether to replace the selected cells or add them as "
                            "a new generation that keeps the parents. Dropped on a cell, a file replaces "
                            "that cell (a parent only "
                            "after asking). A flat design opened among solid ones (or the reverse) starts a "
                            "generation of its own "
                            "kind, since the two kinds cannot breed together; the grid it replaces is one "
                            "generation back.</p>")
            .arg(actionText(window.copyDesignAction()), keyOf(window.copyDesignAction()),
                 actionText(window.pasteDesignAction()), keyOf(window.pasteDesignAction()));
    html += WorkbenchWindow::tr(
        "<h3>Keyboard</h3><p>On a design in the grid: the arrows move, Space picks or lets go, "
        "Enter opens it large, F keeps it as a favourite, the Menu key opens its menu.</p>");
    html += shortcutTableHtml(shortcutActions(&window));
    return html;
}

} // namespace marbler::ui

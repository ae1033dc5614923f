// New designs of a chosen bath shape (BathSizes.h).

#include "editor/BathSizes.h"

#include "editor/EditorWindow.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>

#include <algorithm>

namespace marbler::ui {

namespace {
QString bathTr(const char* text) {
    return QCoreApplication::translate("BathSizes", text);
}
} // namespace

std::vector<BathSize> bathSizes() {
    // A4 is 210 × 297 mm: 1000 units across its short side.
    return {
        {bathTr("&Square"), 1000, 1000},       {bathTr("A4 &portrait"), 1000, 1414},
        {bathTr("A4 &landscape"), 1414, 1000}, {bathTr("&16:9 (wide)"), 1600, 900},
        {bathTr("&9:16 (tall)"), 900, 1600},
    };
}

Genome blankDesignOfSize(int dimension, const BathSize& size) {
    Genome g = blankDesign(dimension);
    g.size.x = size.width;
    g.size.y = size.height;
    g.size.z = std::min(size.width, size.height);
    return g;
}

void addBathSizeMenus(QMenu* newMenu, const std::function<void(const Genome&)>& open) {
    newMenu->addSeparator();
    for (int dimension : {2, 3}) {
        QMenu* menu =
            newMenu->addMenu(dimension == 2 ? bathTr("Flat bath of si&ze") : bathTr("Solid bl&ock of size"));
        menu->setObjectName(dimension == 2 ? QStringLiteral("newFlatSizeMenu")
                                           : QStringLiteral("newSolidSizeMenu"));
        menu->setToolTipsVisible(true);
        for (const BathSize& size : bathSizes()) {
            QAction* a = menu->addAction(
                size.name, newMenu, [open, dimension, size] { open(blankDesignOfSize(dimension, size)); });
            a->setToolTip(dimension == 2
                              ? bathTr("A blank bath %1 × %2 design units").arg(size.width).arg(size.height)
                              : bathTr("A blank block %1 × %2 × %3 design units")
                                    .arg(size.width)
                                    .arg(size.height)
                                    .arg(std::min(size.width, size.height)));
        }
    }
}

} // namespace marbler::ui

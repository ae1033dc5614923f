#include "workbench/PopulationBar.h"

#include "marbler/Families.h"
#include "marbler/Mesh.h"
#include "shared/StartDialog.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolBar>

#include <algorithm>

namespace marbler::ui {

PopulationBar::PopulationBar(QToolBar* bar, QAction* newRandom)
    : QObject(bar) {
    auto* kindLabel = new QLabel(tr(" New population: "), bar);
    bar->addWidget(kindLabel);

    mDimension = new QComboBox(bar);
    mDimension->addItem(tr("2D designs"), 2);
    mDimension->addItem(tr("Solid designs"), 3);
    mDimension->setToolTip(
        tr("What a new random population holds: flat marbling or solid (volume) marbling"));
    bar->addWidget(mDimension);
    kindLabel->setBuddy(mDimension);
    kindLabel->setToolTip(tr("What File ▸ New random population (%1) makes")
                              .arg(newRandom->shortcut().toString(QKeySequence::NativeText)));
    mFamily = new QComboBox(bar);
    mFamily->setObjectName(QStringLiteral("familyCombo"));
    mFamily->setToolTip(
        tr("The pattern family of a new random population, or a mix of the craft's families"));
    bar->addWidget(mFamily);
    fillFamilies();
    connect(mDimension, &QComboBox::currentIndexChanged, this, &PopulationBar::fillFamilies);
    bar->addAction(newRandom);
    bar->addSeparator();

    auto* meshLabel = new QLabel(tr(" Solids on: "), bar);
    bar->addWidget(meshLabel);
    mMesh = new QComboBox(bar);
    mMesh->addItems(meshNames());
    mMesh->setToolTip(tr("The object solid designs are shown on (drag in a cell to turn it)"));
    meshLabel->setBuddy(mMesh);
    meshLabel->setToolTip(mMesh->toolTip());
    connect(mMesh, &QComboBox::currentTextChanged, this, &PopulationBar::meshChanged);
    bar->addWidget(mMesh);
}

int PopulationBar::dimension() const {
    return mDimension->currentData().toInt();
}

void PopulationBar::setDimension(int dimension) {
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
}

void PopulationBar::fillFamilies() {
    const int dimension = mDimension->currentData().toInt();
    const QString chosen = mFamily->currentData().toString();
    const QSignalBlocker quiet(mFamily);
    mFamily->clear();
    mFamily->addItem(tr("Mixed families"), QString());
    mFamily->setItemData(0, tr("Every cell a different family of the craft (and some free designs)"),
                         Qt::ToolTipRole);
    for (const Family& f : allFamilies()) {
        if (f.dimension != dimension) continue;
        QString label = QString::fromUtf8(f.name.data(), qsizetype(f.name.size()));
        label.replace(QLatin1Char('-'), QLatin1Char(' '));
        label[0] = label[0].toUpper();
        mFamily->addItem(label, QString::fromUtf8(f.name.data(), qsizetype(f.name.size())));
        mFamily->setItemData(mFamily->count() - 1,
                             QString::fromUtf8(f.summary.data(), qsizetype(f.summary.size())),
                             Qt::ToolTipRole);
    }
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(chosen)));
}

QString PopulationBar::family() const {
    return mFamily->currentData().toString();
}

void PopulationBar::setFamily(const QString& family) {
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(family)));
}

QString PopulationBar::mesh() const {
    return mMesh->currentText();
}

void PopulationBar::setMesh(const QString& mesh) {
    if (mMesh->findText(mesh) >= 0) mMesh->setCurrentText(mesh);
}

} // namespace marbler::ui

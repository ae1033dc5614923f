#include "workbench/PopulationBar.h"

#include "marbler/Families.h"
#include "marbler/Mesh.h"
#include "shared/ErrorReport.h"
#include "shared/Language.h"
#include "shared/MeshChooser.h"
#include "shared/StartDialog.h"

#include <QAction>
#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolBar>

#include <algorithm>

namespace marbler::ui {

namespace {

/// The object box's data for "Mesh file…": neither a built-in name nor an absolute path.
const QString ChooseFileEntry = QStringLiteral("<mesh file>");

/// A built-in object's name or a mesh file's path: what the object box can show.
bool isShowableObject(const QString& mesh) {
    return meshNames().contains(mesh) || QFileInfo(mesh).isAbsolute();
}

} // namespace

PopulationBar::PopulationBar(QToolBar* bar, QAction* newRandom)
    : QObject(bar) {
    auto* kindLabel = new QLabel(tr(" New population: "), bar);
    bar->addWidget(kindLabel);

    mDimension = new QComboBox(bar);
    mDimension->setObjectName(QStringLiteral("kindCombo"));
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

    auto* meshLabel = new QLabel(tr(" Show on: "), bar);
    bar->addWidget(meshLabel);
    mMesh = new QComboBox(bar);
    mMesh->setObjectName(QStringLiteral("objectCombo"));
    mMesh->setToolTip(tr("The object the designs are shown on (drag in a cell to turn it): a "
                         "built-in or a mesh file; flat designs also flat"));
    meshLabel->setBuddy(mMesh);
    meshLabel->setToolTip(mMesh->toolTip());
    mSolidMesh = QString::fromLatin1(DefaultMesh);
    fillObjects();
    connect(mMesh, &QComboBox::activated, this, &PopulationBar::objectActivated);
    bar->addWidget(mMesh);
}

void PopulationBar::fillObjects() {
    const QSignalBlocker quiet(mMesh);
    mMesh->clear();
    if (mShownKind == 2) {
        mMesh->addItem(tr("Flat"), QString());
        mMesh->setItemData(0, tr("Flat designs shown flat"), Qt::ToolTipRole);
    }
    for (const QString& name : meshNames())
        mMesh->addItem(name, name);
    const QString chosen = mShownKind == 3 ? mSolidMesh : mFlatMesh;
    if (!chosen.isEmpty() && mMesh->findData(chosen) < 0) {
        mMesh->addItem(QFileInfo(chosen).fileName(), chosen);
        mMesh->setItemData(mMesh->count() - 1, chosen, Qt::ToolTipRole);
    }
    mMesh->addItem(tr("Mesh file…"), ChooseFileEntry);
    mMesh->setItemData(mMesh->count() - 1, tr("Show the designs on an OBJ, STL, PLY or glTF file"),
                       Qt::ToolTipRole);
    mMesh->setCurrentIndex(std::max(0, mMesh->findData(chosen)));
}

void PopulationBar::objectActivated(int index) {
    const QString data = mMesh->itemData(index).toString();
    if (data != ChooseFileEntry) {
        setObject(mShownKind, data);
        return;
    }
    QWidget* parent = mMesh->window();
    const QString file = chooseMeshFile(parent);
    fillObjects(); // the box shows the object until another is set
    if (file.isEmpty()) return;
    if (const QString problem = meshFileProblem(file); !problem.isEmpty()) {
        reportError(parent, tr("Cannot show the mesh"),
                    tr("%1\n\nThe designs stay on what they were shown on.").arg(problem));
        return;
    }
    // Whether the file holds triangles (and, for flat designs, texture coordinates) the render
    // service finds out off the GUI thread; the window hears of it (meshUnreadable).
    setObject(mShownKind, QFileInfo(file).absoluteFilePath());
}

void PopulationBar::setObject(int dimension, const QString& mesh) {
    QString& object = dimension == 3 ? mSolidMesh : mFlatMesh;
    if (mesh == object) {
        fillObjects();
        return;
    }
    object = mesh;
    if (dimension == mShownKind) fillObjects();
    if (dimension == 3)
        emit meshChanged(mesh);
    else
        emit flatMeshChanged(mesh);
}

void PopulationBar::setShownKind(int dimension) {
    dimension = dimension == 3 ? 3 : 2;
    if (dimension == mShownKind) return;
    mShownKind = dimension;
    fillObjects();
    // The grid's kind changed (Back, the lineage, Ctrl+Z, a design of the other kind): the kind
    // box follows, so it never says "Solid designs" over a flat grid (issue 29). A kind chosen
    // while the grid stays of one kind is left as chosen.
    setDimension(dimension);
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
        mFamily->addItem(registryText(label.toStdString()),
                         QString::fromUtf8(f.name.data(), qsizetype(f.name.size())));
        mFamily->setItemData(mFamily->count() - 1, registryText(f.summary), Qt::ToolTipRole);
    }
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(chosen)));
}

QString PopulationBar::family() const {
    return mFamily->currentData().toString();
}

void PopulationBar::setFamily(const QString& family) {
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(family)));
}

void PopulationBar::setMesh(const QString& mesh) {
    if (isShowableObject(mesh)) setObject(3, mesh);
}

void PopulationBar::setFlatMesh(const QString& mesh) {
    if (mesh.isEmpty() || isShowableObject(mesh)) setObject(2, mesh);
}

} // namespace marbler::ui

// The tool panel's controls of a solid design (SectionControls.h).

#include "editor/SectionControls.h"

#include "shared/StartDialog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace marbler::ui {

SectionControls::SectionControls(std::function<glm::dvec3()> size, const Slice& slice, QWidget* parent)
    : QWidget(parent)
    , mSize(std::move(size))
    , mAxis(new QComboBox(this))
    , mPosition(new QSlider(Qt::Horizontal, this))
    , mValue(new QDoubleSpinBox(this))
    , mMesh(new QComboBox(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // The cross-section: its axis and where along it.
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Section"), this));
    mAxis->setObjectName(QStringLiteral("sliceAxis"));
    mAxis->addItems({tr("x"), tr("y"), tr("z")});
    mAxis->setCurrentIndex(slice.axis);
    mAxis->setToolTip(tr("The axis the cross-section is cut across; clicks on it place the 3D tools"));
    row->addWidget(mAxis);
    layout->addLayout(row);
    mPosition->setObjectName(QStringLiteral("slicePosition"));
    mPosition->setRange(0, 1000);
    mPosition->setValue(500);
    mPosition->setToolTip(tr("Where along its axis the cross-section is cut (PgUp / PgDn move it)"));
    // Where the section is, as a number too (design units along its axis).
    mValue->setObjectName(QStringLiteral("sliceValue"));
    mValue->setDecimals(1);
    mValue->setToolTip(tr("Where the cross-section is cut, in design units along its axis"));
    auto* positionRow = new QHBoxLayout;
    positionRow->addWidget(mPosition, 1);
    positionRow->addWidget(mValue);
    layout->addLayout(positionRow);
    const auto sliceChanged = [this] {
        if (mUpdating) return;
        const glm::dvec3 extent = mSize();
        const int axis = mAxis->currentIndex();
        emit sliceChosen(Slice{axis, extent[axis] * mPosition->value() / 1000.0});
    };
    connect(mAxis, &QComboBox::currentIndexChanged, this, sliceChanged);
    connect(mPosition, &QSlider::valueChanged, this, sliceChanged);
    connect(mValue, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (mUpdating) return;
        const glm::dvec3 extent = mSize();
        emit sliceChosen(Slice{mAxis->currentIndex(), std::clamp(value, 0.0, extent[mAxis->currentIndex()])});
    });

    auto* meshRow = new QHBoxLayout;
    meshRow->addWidget(new QLabel(tr("Object"), this));
    mMesh->setObjectName(QStringLiteral("objectMesh"));
    mMesh->addItems(meshNames());
    mMesh->addItem(tr("Mesh file…"));
    mMesh->setToolTip(tr("The object the design is shown on (drag the object to turn it)"));
    meshRow->addWidget(mMesh);
    layout->addLayout(meshRow);
    connect(mMesh, &QComboBox::activated, this, &SectionControls::chooseMesh);
}

void SectionControls::showSlice(const Slice& slice) {
    mUpdating = true;
    const double extent = mSize()[slice.axis];
    mAxis->setCurrentIndex(slice.axis);
    mValue->setRange(0.0, extent);
    mValue->setValue(slice.value);
    mValue->setPrefix(tr("%1 = ").arg(QLatin1String(axisName(slice.axis))));
    if (extent > 0.0) mPosition->setValue(int(std::lround(slice.value / extent * 1000.0)));
    mUpdating = false;
}

void SectionControls::chooseMesh(int index) {
    if (index < int(meshNames().size())) {
        emit meshChosen(mMesh->itemText(index));
        return;
    }
    const QString file =
        QFileDialog::getOpenFileName(window(), tr("Show the design on a mesh"), QString(),
                                     tr("Meshes (*.obj *.ply *.stl *.off *.gltf *.glb);;All files (*)"));
    if (file.isEmpty()) return;
    emit meshChosen(file);
}

} // namespace marbler::ui

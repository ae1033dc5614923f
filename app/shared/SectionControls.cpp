// The controls of a solid design's cross-section (SectionControls.h).

#include "shared/SectionControls.h"

#include "shared/StartDialog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marbler::ui {

namespace {

/// Degrees to radians.
double sectionRadians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

/// A number as the normal's box shows it: few digits, no trailing zeros.
QString normalNumber(double value) {
    return QString::number(std::abs(value) < 5e-7 ? 0.0 : value, 'g', 4);
}

} // namespace

SectionControls::SectionControls(std::function<glm::dvec3()> size, const Slice& slice, QWidget* parent,
                                 bool withObject)
    : QWidget(parent)
    , mSize(std::move(size))
    , mAxis(new QComboBox(this))
    , mPosition(new QSlider(Qt::Horizontal, this))
    , mValue(new QDoubleSpinBox(this))
    , mMesh(new QComboBox(this))
    , mNormal(new QLineEdit(this))
    , mTilt(new QSlider(Qt::Horizontal, this))
    , mTurn(new QSlider(Qt::Horizontal, this))
    , mNormalError(new QLabel(this)) {
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
    // A turned section: tilted away from the axis, and turned about it (handles to drag), or its
    // normal typed.
    auto* tiltRow = new QHBoxLayout;
    tiltRow->addWidget(new QLabel(tr("Tilt"), this));
    mTilt->setObjectName(QStringLiteral("sliceTilt"));
    mTilt->setRange(0, 89);
    mTilt->setToolTip(tr("Tilts the section away from its axis (degrees): strokes drawn on it are placed "
                         "on the tilted plane"));
    tiltRow->addWidget(mTilt, 1);
    mTurn->setObjectName(QStringLiteral("sliceTurn"));
    mTurn->setRange(0, 359);
    mTurn->setToolTip(tr("Turns the tilt about the section's axis (degrees)"));
    tiltRow->addWidget(new QLabel(tr("Turn"), this));
    tiltRow->addWidget(mTurn, 1);
    layout->addLayout(tiltRow);
    auto* normalRow = new QHBoxLayout;
    normalRow->addWidget(new QLabel(tr("Normal"), this));
    mNormal->setObjectName(QStringLiteral("sliceNormal"));
    mNormal->setPlaceholderText(tr("across the axis"));
    mNormal->setToolTip(tr("The section's normal as x, y, z (e.g. 1, 1, 0), Enter to turn the section to "
                           "it; empty: across the axis"));
    normalRow->addWidget(mNormal, 1);
    layout->addLayout(normalRow);
    mNormalError->setObjectName(QStringLiteral("sliceNormalError"));
    mNormalError->setStyleSheet(QStringLiteral("color: #b00020"));
    mNormalError->setWordWrap(true);
    mNormalError->hide();
    layout->addWidget(mNormalError);
    mPosition->setObjectName(QStringLiteral("slicePosition"));
    mPosition->setRange(0, 1000);
    mPosition->setValue(500);
    mPosition->setToolTip(tr("Where along its axis the cross-section is cut (PgUp / PgDn move it)"));
    // Where the section is, as a number too (design units along its axis).
    mValue->setObjectName(QStringLiteral("sliceValue"));
    mValue->setDecimals(1);
    mValue->setToolTip(tr("Where the cross-section is cut, in design units along its axis (or normal)"));
    auto* positionRow = new QHBoxLayout;
    positionRow->addWidget(mPosition, 1);
    positionRow->addWidget(mValue);
    layout->addLayout(positionRow);
    connect(mAxis, &QComboBox::currentIndexChanged, this, [this] {
        if (mUpdating) return;
        // A new axis: the section across it, untilted.
        mTurned.reset();
        emit sliceChosen(current());
    });
    connect(mPosition, &QSlider::valueChanged, this, [this] {
        if (mUpdating) return;
        emit sliceChosen(current());
    });
    connect(mValue, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (mUpdating) return;
        Slice slice = current();
        slice.value = std::clamp(value, mValue->minimum(), mValue->maximum());
        emit sliceChosen(slice);
    });
    connect(mTilt, &QSlider::valueChanged, this, &SectionControls::handlesMoved);
    connect(mTurn, &QSlider::valueChanged, this, &SectionControls::handlesMoved);
    connect(mNormal, &QLineEdit::editingFinished, this, &SectionControls::normalTyped);

    auto* meshRow = new QHBoxLayout;
    meshRow->addWidget(new QLabel(tr("Object"), this));
    mMesh->setObjectName(QStringLiteral("objectMesh"));
    mMesh->addItems(meshNames());
    mMesh->addItem(tr("Mesh file…"));
    mMesh->setToolTip(tr("The object the design is shown on (drag the object to turn it)"));
    meshRow->addWidget(mMesh);
    layout->addLayout(meshRow);
    if (!withObject) {
        meshRow->itemAt(0)->widget()->hide();
        mMesh->hide();
    }
    connect(mMesh, &QComboBox::activated, this, &SectionControls::chooseMesh);
}

Slice SectionControls::current() const {
    const glm::dvec3 extent = mSize();
    const int axis = mAxis->currentIndex();
    if (!mTurned) return Slice{axis, extent[axis] * mPosition->value() / 1000.0};
    const glm::dvec2 range = sliceOffsetRange(*mTurned, extent);
    return Slice{axis, range.x + (range.y - range.x) * mPosition->value() / 1000.0, mTurned};
}

glm::dvec3 SectionControls::handledNormal() const {
    const SlicePlane across = slicePlane(3, mAxis->currentIndex());
    const double tilt = sectionRadians(mTilt->value()), turn = sectionRadians(mTurn->value());
    return std::cos(tilt) * across.normal() +
           std::sin(tilt) * (std::cos(turn) * across.u() + std::sin(turn) * across.v());
}

void SectionControls::handlesMoved() {
    if (mUpdating) return;
    mNormalError->hide();
    if (mTilt->value() == 0)
        mTurned.reset();
    else
        mTurned = handledNormal();
    emit sliceChosen(current());
}

void SectionControls::normalTyped() {
    if (mUpdating) return;
    const QString text = mNormal->text().trimmed();
    if (text.isEmpty()) {
        mNormalError->hide();
        if (!mTurned) return;
        mTurned.reset();
        emit sliceChosen(current());
        return;
    }
    std::string error;
    const std::optional<glm::dvec3> n = parseDirection(text.toStdString(), "Normal", &error);
    if (!n) {
        mNormalError->setText(QString::fromStdString(error));
        mNormalError->show();
        return;
    }
    mNormalError->hide();
    if (mTurned && *mTurned == *n) return;
    // Typed: tilted from the nearest axis.
    int nearest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs((*n)[i]) > std::abs((*n)[nearest])) nearest = i;
    Slice slice{nearest, 0.0, *n};
    const glm::dvec2 range = sliceOffsetRange(*n, mSize());
    slice.value = range.x + (range.y - range.x) * mPosition->value() / 1000.0;
    // Along an axis: the plain section across it.
    const SlicePlane plane = slicePlane(3, slice, mSize());
    if (!plane.turned) slice = Slice{plane.normalAxis, plane.value};
    emit sliceChosen(slice);
}

void SectionControls::showSlice(const Slice& slice) {
    mUpdating = true;
    const glm::dvec3 size = mSize();
    const SlicePlane plane = slicePlane(3, slice, size);
    // Moved by the handles or the position: the handles stay as the user left them.
    const bool handled = plane.turned && mTurned && slice.normal && *slice.normal == *mTurned &&
                         plane.normalAxis == mAxis->currentIndex();
    mAxis->setCurrentIndex(plane.normalAxis);
    glm::dvec2 range(0.0, size[plane.normalAxis]);
    if (handled) {
        range = sliceOffsetRange(*mTurned, size);
        const glm::dvec3 n = *mTurned;
        mNormal->setText(
            QStringLiteral("%1, %2, %3").arg(normalNumber(n.x), normalNumber(n.y), normalNumber(n.z)));
        mValue->setPrefix(tr("n·p = "));
    } else if (plane.turned) {
        mTurned = plane.normal();
        range = sliceOffsetRange(*mTurned, size);
        // The handles: the normal's tilt from its axis and its turn about it.
        const SlicePlane across = slicePlane(3, plane.normalAxis);
        const glm::dvec3 n = *mTurned;
        const double along = n.x * across.normal().x + n.y * across.normal().y + n.z * across.normal().z;
        const double inU = n.x * across.u().x + n.y * across.u().y + n.z * across.u().z;
        const double inV = n.x * across.v().x + n.y * across.v().y + n.z * across.v().z;
        mTilt->setValue(
            int(std::lround(std::acos(std::clamp(std::abs(along), 0.0, 1.0)) * 180.0 / std::numbers::pi)));
        int turn = int(std::lround(std::atan2(inV, inU) * 180.0 / std::numbers::pi));
        if (along < 0.0) turn += 180;
        mTurn->setValue(((turn % 360) + 360) % 360);
        mNormal->setText(
            QStringLiteral("%1, %2, %3").arg(normalNumber(n.x), normalNumber(n.y), normalNumber(n.z)));
        mValue->setPrefix(tr("n·p = "));
    } else {
        mTurned.reset();
        mTilt->setValue(0);
        mTurn->setValue(0);
        mNormal->clear();
        mValue->setPrefix(tr("%1 = ").arg(QLatin1String(axisName(plane.normalAxis))));
    }
    mValue->setRange(range.x, range.y);
    mValue->setValue(plane.value);
    if (range.y > range.x)
        mPosition->setValue(int(std::lround((plane.value - range.x) / (range.y - range.x) * 1000.0)));
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

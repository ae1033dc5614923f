// The editor's palette (PaletteEditor.h).

#include "editor/PaletteEditor.h"

#include <QAction>
#include <QButtonGroup>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPixmap>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace marbler::ui {
namespace {

QColor toQColor(const Color& c) { return QColor(c.r, c.g, c.b); }
Color fromQColor(const QColor& c) {
    return Color{std::uint8_t(c.red()), std::uint8_t(c.green()), std::uint8_t(c.blue())};
}

/// Double-clicks on a swatch open its colour dialog.
class DoubleClickFilter : public QObject {
public:
    DoubleClickFilter(QObject* button, PaletteEditor* editor, int index) : QObject(button), mEditor(editor), mIndex(index) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::MouseButtonDblClick) {
            mEditor->editColor(mIndex);
            return true;
        }
        return QObject::eventFilter(watched, event);
    }

private:
    PaletteEditor* mEditor;
    int mIndex;
};

} // namespace

PaletteEditor::PaletteEditor(QWidget* parent)
    : QWidget(parent), mSwatches(new QHBoxLayout), mGroup(new QButtonGroup(this)), mBleed(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("paletteEditor"));
    mGroup->setExclusive(true);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(mSwatches);
    auto* bleedRow = new QHBoxLayout;
    auto* bleedLabel = new QLabel(tr("&Bleed"), this);
    bleedLabel->setBuddy(mBleed);
    mBleed->setObjectName(QStringLiteral("bleedSpin"));
    mBleed->setRange(0.0, 1000.0);
    mBleed->setDecimals(1);
    mBleed->setKeyboardTracking(false);
    mBleed->setToolTip(tr("Soft ink edges: the width of the blend between inks, in design units (0: sharp)"));
    bleedLabel->setToolTip(mBleed->toolTip());
    bleedRow->addWidget(bleedLabel);
    bleedRow->addWidget(mBleed, 1);
    layout->addLayout(bleedRow);
    connect(mBleed, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!mUpdating) emit bleedChanged(v, false);
    });
    connect(mGroup, &QButtonGroup::idClicked, this, [this](int id) {
        if (id == mCurrent) return;
        mCurrent = id;
        emit currentInkChanged(id);
    });
}

QToolButton* PaletteEditor::swatch(const Color& color, const QString& tip) {
    auto* button = new QToolButton(this);
    QPixmap pixmap(22, 22);
    pixmap.fill(toQColor(color));
    button->setIcon(QIcon(pixmap));
    button->setToolTip(tip);
    return button;
}

void PaletteEditor::setDesign(const Genome& design) {
    mDesign = design;
    mUpdating = true;
    for (QToolButton* b : mButtons) delete b;
    mButtons.clear();
    delete mBackground;
    while (QLayoutItem* item = mSwatches->takeAt(0)) delete item;
    for (std::size_t i = 0; i < design.palette.size(); ++i) {
        QToolButton* b = swatch(design.palette[i], tr("Ink %1: click to lay it with the tools, double-click to change "
                                                      "its colour").arg(i + 1));
        b->setObjectName(QStringLiteral("inkSwatch%1").arg(i));
        b->setCheckable(true);
        b->setContextMenuPolicy(Qt::ActionsContextMenu);
        auto* change = new QAction(tr("Change colour…"), b);
        connect(change, &QAction::triggered, this, [this, i] { editColor(int(i)); });
        b->addAction(change);
        b->installEventFilter(new DoubleClickFilter(b, this, int(i)));
        mGroup->addButton(b, int(i));
        mSwatches->addWidget(b);
        mButtons.push_back(b);
    }
    auto* add = new QToolButton(this);
    add->setObjectName(QStringLiteral("addInkButton"));
    add->setText(QStringLiteral("+"));
    add->setToolTip(tr("Add an ink to the palette"));
    connect(add, &QToolButton::clicked, this, [this] {
        // A mid grey the user then changes: the palette must hold it before the dialog edits it.
        emit inkAdded(Color{0x80, 0x80, 0x80});
    });
    mButtons.push_back(add);
    mSwatches->addWidget(add);
    mSwatches->addStretch(1);
    mBackground = swatch(design.background, tr("The background (the bare bath): click to change its colour"));
    mBackground->setObjectName(QStringLiteral("backgroundSwatch"));
    connect(mBackground, &QToolButton::clicked, this, [this] { editColor(-1); });
    mSwatches->addWidget(mBackground);
    mBleed->setMaximum(std::max({1000.0, design.bleed, std::max(design.size.x, design.size.y)}));
    mBleed->setValue(design.bleed);
    mCurrent = std::clamp(mCurrent, 0, std::max(0, int(design.palette.size()) - 1));
    if (!design.palette.empty()) mButtons[std::size_t(mCurrent)]->setChecked(true);
    mUpdating = false;
}

void PaletteEditor::setCurrentInk(int index) {
    if (index < 0 || index >= int(mDesign.palette.size())) return;
    mCurrent = index;
    mButtons[std::size_t(index)]->setChecked(true);
}

void PaletteEditor::editColor(int index) {
    if (index >= int(mDesign.palette.size())) return;
    const Color original = index < 0 ? mDesign.background : mDesign.palette[std::size_t(index)];
    delete mDialog;
    mDialog = new QColorDialog(toQColor(original), this);
    mDialog->setObjectName(QStringLiteral("paletteColorDialog"));
    mDialog->setWindowTitle(index < 0 ? tr("Background colour") : tr("Colour of ink %1").arg(index + 1));
    auto emitColor = [this, index](const Color& c, bool dragging) {
        if (index < 0) emit backgroundChanged(c, dragging);
        else emit colorChanged(index, c, dragging);
    };
    connect(mDialog, &QColorDialog::currentColorChanged, this,
            [emitColor](const QColor& c) { emitColor(fromQColor(c), true); });
    connect(mDialog, &QColorDialog::colorSelected, this,
            [emitColor](const QColor& c) { emitColor(fromQColor(c), false); });
    connect(mDialog, &QDialog::rejected, this, [emitColor, original] { emitColor(original, false); });
    mDialog->open();
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_PaletteEditor.cpp"

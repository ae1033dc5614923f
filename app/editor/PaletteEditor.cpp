// The editor's palette (PaletteEditor.h).

#include "editor/PaletteEditor.h"

#include "marbler/Params.h"

#include <QAction>
#include <QButtonGroup>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPixmap>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace marbler::ui {
namespace {

QColor toQColor(const Color& c) {
    return QColor(c.r, c.g, c.b);
}
Color fromQColor(const QColor& c) {
    return Color{std::uint8_t(c.red()), std::uint8_t(c.green()), std::uint8_t(c.blue())};
}

std::size_t inkUses(const Genome& design, int index) {
    std::size_t n = 0;
    for (const auto* part : {&design.initial, &design.operations})
        for (const Operation& op : *part)
            if (toolSpec(op.tool).laysInk && op.color == index) ++n;
    return n;
}

/// Double-clicks on a swatch open its colour dialog.
class DoubleClickFilter : public QObject {
public:
    DoubleClickFilter(QObject* button, PaletteEditor* editor, int index)
        : QObject(button)
        , mEditor(editor)
        , mIndex(index) {}
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

const std::vector<PalettePreset>& palettePresets() {
    static std::vector<PalettePreset> presets;
    // Refilled on each call, in the window's language (issue 25).
    presets = {
        {PaletteEditor::tr("Turkish ebru"),
         {{0x1f, 0x4e, 0x79}, {0xc8, 0x55, 0x3d}, {0xe9, 0xc4, 0x6a}, {0x2a, 0x9d, 0x8f}},
         {0xf4, 0xec, 0xdc}},
        {PaletteEditor::tr("Florentine"),
         {{0x8c, 0x1c, 0x13}, {0xd4, 0xa0, 0x17}, {0x1b, 0x3a, 0x5c}, {0x2e, 0x5e, 0x3a}},
         {0xf2, 0xe6, 0xc9}},
        {PaletteEditor::tr("Suminagashi"),
         {{0x1a, 0x1a, 0x1a}, {0x3a, 0x4a, 0x6b}, {0x9a, 0x2b, 0x2b}},
         {0xf7, 0xf4, 0xec}},
        {PaletteEditor::tr("Ocean"),
         {{0x03, 0x30, 0x4f}, {0x1b, 0x76, 0xa8}, {0x68, 0xc3, 0xd4}, {0xe8, 0xf4, 0xf2}},
         {0x0b, 0x1d, 0x33}},
        {PaletteEditor::tr("Autumn"),
         {{0x7f, 0x27, 0x04}, {0xd9, 0x73, 0x06}, {0xf2, 0xb7, 0x05}, {0x59, 0x37, 0x1b}},
         {0xfb, 0xf1, 0xe1}},
    };
    return presets;
}

Genome withPalettePreset(Genome design, const PalettePreset& preset) {
    for (std::size_t i = 0; i < preset.inks.size(); ++i) {
        if (i < design.palette.size())
            design.palette[i] = preset.inks[i];
        else
            design.palette.push_back(preset.inks[i]);
    }
    design.background = preset.background;
    return design;
}

int nearestOtherInk(const std::vector<Color>& palette, int index) {
    int best = -1;
    long bestDistance = 0;
    for (int i = 0; i < int(palette.size()); ++i) {
        if (i == index) continue;
        const Color& a = palette[std::size_t(i)];
        const Color& b = palette[std::size_t(index)];
        const long d =
            long(a.r - b.r) * (a.r - b.r) + long(a.g - b.g) * (a.g - b.g) + long(a.b - b.b) * (a.b - b.b);
        if (best < 0 || d < bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    return best;
}

PaletteEditor::PaletteEditor(QWidget* parent)
    : QWidget(parent)
    , mSwatches(new QHBoxLayout)
    , mGroup(new QButtonGroup(this))
    , mBleed(new QDoubleSpinBox(this)) {
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
    for (QToolButton* b : mButtons)
        delete b;
    mButtons.clear();
    delete mBackground;
    while (QLayoutItem* item = mSwatches->takeAt(0))
        delete item;
    for (std::size_t i = 0; i < design.palette.size(); ++i) {
        QToolButton* b =
            swatch(design.palette[i], tr("Ink %1: click to lay it with the tools, double-click to change "
                                         "its colour")
                                          .arg(i + 1));
        b->setObjectName(QStringLiteral("inkSwatch%1").arg(i));
        b->setCheckable(true);
        b->setContextMenuPolicy(Qt::ActionsContextMenu);
        auto* change = new QAction(tr("Change colour…"), b);
        connect(change, &QAction::triggered, this, [this, i] { editColor(int(i)); });
        b->addAction(change);
        auto* remove = new QAction(tr("Delete ink"), b);
        remove->setObjectName(QStringLiteral("deleteInk%1").arg(i));
        connect(remove, &QAction::triggered, this, [this, i] { removeInk(int(i)); });
        b->addAction(remove);
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
    auto* remove = new QToolButton(this);
    remove->setObjectName(QStringLiteral("removeInkButton"));
    remove->setText(QStringLiteral("−"));
    remove->setToolTip(tr("Delete the current ink from the palette (asks first when steps lay it)"));
    remove->setEnabled(!design.palette.empty());
    connect(remove, &QToolButton::clicked, this, [this] { removeInk(mCurrent); });
    mButtons.push_back(remove);
    mSwatches->addWidget(remove);
    auto* presets = new QToolButton(this);
    presets->setObjectName(QStringLiteral("palettePresetsButton"));
    presets->setText(tr("Presets"));
    presets->setToolTip(tr("Replace the inks and the bath with a named palette (one undo step)"));
    presets->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(presets);
    menu->setObjectName(QStringLiteral("palettePresetsMenu"));
    for (std::size_t p = 0; p < palettePresets().size(); ++p)
        menu->addAction(palettePresets()[p].name, this, [this, p] { emit presetChosen(int(p)); });
    presets->setMenu(menu);
    mButtons.push_back(presets);
    mSwatches->addWidget(presets);
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

void PaletteEditor::removeInk(int index) {
    if (index < 0 || index >= int(mDesign.palette.size())) return;
    const std::size_t uses = inkUses(mDesign, index);
    if (uses == 0) {
        emit inkRemoved(index, -1);
        return;
    }
    delete mQuestion;
    const int other = nearestOtherInk(mDesign.palette, index);
    if (other < 0) {
        mQuestion = new QMessageBox(
            QMessageBox::Information, tr("Delete ink"),
            tr("Ink %1 is the only ink, and steps lay it: add another ink first.").arg(index + 1),
            QMessageBox::Ok, this);
        mQuestion->setObjectName(QStringLiteral("removeInkQuestion"));
        mQuestion->open();
        return;
    }
    mQuestion = new QMessageBox(
        QMessageBox::Question, tr("Delete ink"),
        (uses == 1 ? tr("1 step lays ink %1.").arg(index + 1)
                   : tr("%1 steps lay ink %2.").arg(uses).arg(index + 1)) +
            QLatin1Char(' ') +
            tr("Delete it and lay them with ink %1, the nearest colour, instead?").arg(other + 1),
        QMessageBox::Cancel, this);
    mQuestion->setObjectName(QStringLiteral("removeInkQuestion"));
    QPushButton* remap = mQuestion->addButton(tr("&Delete and re-map"), QMessageBox::AcceptRole);
    remap->setObjectName(QStringLiteral("remapInkButton"));
    mQuestion->setDefaultButton(QMessageBox::Cancel);
    connect(mQuestion, &QMessageBox::buttonClicked, this, [this, remap, index, other](QAbstractButton* b) {
        if (b == remap) emit inkRemoved(index, other);
    });
    mQuestion->open();
}

void PaletteEditor::editColor(int index) {
    if (index >= int(mDesign.palette.size())) return;
    const Color original = index < 0 ? mDesign.background : mDesign.palette[std::size_t(index)];
    delete mDialog;
    mDialog = new QColorDialog(toQColor(original), this);
    mDialog->setObjectName(QStringLiteral("paletteColorDialog"));
    mDialog->setWindowTitle(index < 0 ? tr("Background colour") : tr("Colour of ink %1").arg(index + 1));
    auto emitColor = [this, index](const Color& c, bool dragging) {
        if (index < 0)
            emit backgroundChanged(c, dragging);
        else
            emit colorChanged(index, c, dragging);
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

#include "editor/ToolOptions.h"

#include "marbler/Params.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPixmap>
#include <QSpinBox>

#include <algorithm>
#include <functional>

namespace marbler::ui {

using T = EditorTool;

namespace {

/// A parameter's word and unit as the registry gives them, so the panel and the step's form
/// (ParamForm) say the same ("Shift", not alpha here and Shift there).
const ParamSpec& param(Tool tool, ParamField field) {
    const ParamSpec* spec = findParam(tool, field);
    Q_ASSERT(spec);
    return *spec;
}
QString labelOf(Tool tool, ParamField field) {
    const std::string_view label = param(tool, field).label;
    return QString::fromUtf8(label.data(), qsizetype(label.size()));
}
QString unitOf(Tool tool, ParamField field) {
    const std::string_view unit = param(tool, field).unit;
    return unit.empty() ? QString()
                        : QStringLiteral(" ") + QString::fromUtf8(unit.data(), qsizetype(unit.size()));
}

} // namespace

QString toolName(EditorTool tool) {
    switch (tool) {
    case T::Pick: return ToolOptions::tr("Pick");
    case T::Drop: return ToolOptions::tr("Drop");
    case T::Spray: return ToolOptions::tr("Spray");
    case T::DropLine: return ToolOptions::tr("Line of drops");
    case T::DropRings: return ToolOptions::tr("Rings");
    case T::DropScatter: return ToolOptions::tr("Scatter");
    case T::Line: return ToolOptions::tr("Line");
    case T::Comb: return ToolOptions::tr("Comb");
    case T::Wave: return ToolOptions::tr("Wave");
    case T::Circle: return ToolOptions::tr("Circle");
    case T::Vortex: return ToolOptions::tr("Vortex");
    case T::Stretch: return ToolOptions::tr("Stretch");
    case T::Flow: return ToolOptions::tr("Flow");
    }
    return {};
}

QString toolTip(EditorTool tool) {
    switch (tool) {
    case T::Pick: return ToolOptions::tr("Click to pick the ink there and select the step that laid it");
    case T::Drop:
        return ToolOptions::tr("Click to drop ink of the current colour; drag to set its radius. A drop in a drop "
                               "pushes the older ink into a ring");
    case T::Spray: return ToolOptions::tr("Drag a brush that sprinkles small droplets along its path");
    case T::DropLine: return ToolOptions::tr("Drag to lay a line of drops from the press to the release");
    case T::DropRings: return ToolOptions::tr("Drag from the centre: concentric rings out to the release");
    case T::DropScatter: return ToolOptions::tr("Drag from the centre: drops scattered evenly in the circle");
    case T::Line: return ToolOptions::tr("Drag a stylus through the ink: the drag's direction and length");
    case T::Comb: return ToolOptions::tr("Drag a comb through the ink: the drag's direction and length");
    case T::Wave: return ToolOptions::tr("Drag a wavy comb: the drag gives its direction and amplitude");
    case T::Circle: return ToolOptions::tr("Drag from the centre: a circular stroke of that radius");
    case T::Vortex: return ToolOptions::tr("Drag from the centre: a swirl, the drag's length its strength");
    case T::Stretch: return ToolOptions::tr("Drag to stretch the ink between teeth across the design");
    case T::Flow: return ToolOptions::tr("Drag out a cell of a steady flow (cells or one cavity)");
    }
    return {};
}

QKeySequence toolShortcut(EditorTool tool) {
    switch (tool) {
    case T::Pick: return QKeySequence(Qt::Key_I);
    case T::Drop: return QKeySequence(Qt::Key_D);
    case T::Spray: return QKeySequence(Qt::Key_S);
    case T::DropLine: return QKeySequence(Qt::Key_L);
    case T::DropRings: return QKeySequence(Qt::Key_R);
    case T::DropScatter: return QKeySequence(Qt::Key_A);
    case T::Line: return QKeySequence(Qt::Key_N);
    case T::Comb: return QKeySequence(Qt::Key_C);
    case T::Wave: return QKeySequence(Qt::Key_W);
    case T::Circle: return QKeySequence(Qt::Key_O);
    case T::Vortex: return QKeySequence(Qt::Key_V);
    case T::Stretch: return QKeySequence(Qt::Key_T);
    case T::Flow: return QKeySequence(Qt::Key_F);
    }
    return {};
}

ToolOptions::ToolOptions(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("toolOptions"));
    mForm = new QFormLayout(this);
    const QString units = unitOf(Tool::Drop, ParamField::Radius);
    const std::vector<T> inks{T::Drop, T::Spray, T::DropLine, T::DropRings, T::DropScatter};

    mInk = new QComboBox(this);
    mInk->setObjectName(QStringLiteral("toolInk"));
    mInk->setToolTip(tr("The palette ink the tool lays"));
    connect(mInk, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (mLoading || index < 0) return;
        mSettings.color = index;
        changed();
    });
    addRow(tr("Ink"), mInk, inks);
    mLoaders.push_back([this] { mInk->setCurrentIndex(std::min(mSettings.color, mInk->count() - 1)); });

    addNumber("toolRadius", labelOf(Tool::Drop, ParamField::Radius),
              tr("A clicked drop's radius (a drag sets it)"), &ToolSettings::radius, 0.1, 100000, units,
              {T::Drop, T::DropLine, T::DropRings, T::DropScatter});
    addNumber("toolSprayRadius", tr("Droplet"), tr("The radius of each sprayed droplet"), &ToolSettings::sprayRadius,
              0.1, 1000, units, {T::Spray});
    addCount("toolSprayCount", tr("Droplets"), tr("How many droplets one stroke sprinkles"), &ToolSettings::sprayCount,
             1, 2000, {T::Spray});
    addNumber("toolBrush", tr("Brush"), tr("How far from the stroke droplets land"), &ToolSettings::brush, 0, 10000,
              units, {T::Spray});
    addCount("toolPatternCount", tr("Drops"), tr("How many drops the pattern lays"), &ToolSettings::patternCount, 1,
             200, {T::DropLine, T::DropRings, T::DropScatter});
    addNumber("toolSpacing", labelOf(Tool::Comb, ParamField::Spacing),
              tr("The distance between the comb's tines"), &ToolSettings::spacing, 1, 100000, units,
              {T::Comb});
    addNumber("toolWavelength", labelOf(Tool::Wave, ParamField::Wavelength),
              tr("The length of one period of the wave"), &ToolSettings::wavelength, 1, 100000, units,
              {T::Wave});
    addNumber("toolAlpha", labelOf(Tool::Circle, ParamField::Alpha),
              tr("How far the circle moves the ink along its rim (a vortex's click too)"),
              &ToolSettings::alpha, -100000, 100000, units, {T::Circle, T::Vortex});
    addNumber("toolLambda", labelOf(Tool::Line, ParamField::Lambda),
              tr("Smaller concentrates the shift near the stroke"), &ToolSettings::lambda, 0.1, 100000, units,
              {T::Line, T::Comb, T::Circle, T::Vortex});
    addNumber("toolCore", labelOf(Tool::Circle, ParamField::Core),
              tr("A finite centre: 0 winds without end, larger keeps the eye clean"), &ToolSettings::core, 0,
              100000, units, {T::Circle, T::Vortex});
    addCount("toolTeeth", tr("Teeth"), tr("How many teeth span the design"), &ToolSettings::teeth, 2, 1000, {T::Stretch});
    addNumber("toolPower", labelOf(Tool::Stretch, ParamField::Power),
              tr("The tooth profile |sin|^p: small is blunt, large is pointed"), &ToolSettings::power, 0.05,
              50, unitOf(Tool::Stretch, ParamField::Power), {T::Stretch});

    mField = new QComboBox(this);
    mField->setObjectName(QStringLiteral("toolField"));
    mField->addItems({tr("Cells"), tr("Cavity")});
    mField->setToolTip(tr("The velocity field: a lattice of cells or one cavity"));
    connect(mField, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (mLoading || index < 0) return;
        mSettings.field = index;
        changed();
    });
    addRow(labelOf(Tool::Flow, ParamField::Field), mField, {T::Flow});
    mLoaders.push_back([this] { mField->setCurrentIndex(std::clamp(mSettings.field, 0, 1)); });
    addNumber("toolSpeed", labelOf(Tool::Flow, ParamField::Speed),
              tr("The flow's speed; its sign is the sense of turning"), &ToolSettings::speed, -100000, 100000,
              unitOf(Tool::Flow, ParamField::Speed), {T::Flow});
    addNumber("toolTime", labelOf(Tool::Flow, ParamField::Time), tr("How long the flow runs"),
              &ToolSettings::time, 0.01, 1000, unitOf(Tool::Flow, ParamField::Time), {T::Flow});
    addCount("toolSeed", tr("Seed"), tr("Where sprayed and scattered drops land: the same seed, the same drops"),
             nullptr, 1, 1000000, {T::Spray, T::DropScatter});
    refresh();
    setTool(mTool);
}

void ToolOptions::addRow(const QString& label, QWidget* field, std::vector<EditorTool> tools) {
    mForm->addRow(label, field);
    mRows.push_back(Row{field, std::move(tools)});
}

void ToolOptions::addNumber(const char* name, const QString& label, const QString& tip, double ToolSettings::*member,
                            double min, double max, const QString& suffix, std::vector<EditorTool> tools) {
    auto* box = new QDoubleSpinBox(this);
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(min, max);
    box->setDecimals(2);
    box->setSuffix(suffix);
    box->setToolTip(tip);
    box->setKeyboardTracking(false);
    connect(box, &QDoubleSpinBox::valueChanged, this, [this, member](double value) {
        if (mLoading) return;
        mSettings.*member = value;
        changed();
    });
    mLoaders.push_back([this, box, member] { box->setValue(mSettings.*member); });
    addRow(label, box, std::move(tools));
}

void ToolOptions::addCount(const char* name, const QString& label, const QString& tip, int ToolSettings::*member,
                           int min, int max, std::vector<EditorTool> tools) {
    auto* box = new QSpinBox(this);
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(min, max);
    box->setToolTip(tip);
    box->setKeyboardTracking(false);
    // A null member is the seed, which is 64 bits wide.
    connect(box, &QSpinBox::valueChanged, this, [this, member](int value) {
        if (mLoading) return;
        if (member)
            mSettings.*member = value;
        else
            mSettings.seed = std::uint64_t(value);
        changed();
    });
    mLoaders.push_back([this, box, member] {
        box->setValue(member ? mSettings.*member : int(std::min<std::uint64_t>(mSettings.seed, 1000000)));
    });
    addRow(label, box, std::move(tools));
}

void ToolOptions::setTool(EditorTool tool) {
    mTool = tool;
    for (const Row& row : mRows)
        mForm->setRowVisible(row.field, std::find(row.tools.begin(), row.tools.end(), tool) != row.tools.end());
}

void ToolOptions::setPalette(const std::vector<Color>& palette) {
    mLoading = true;
    mInk->clear();
    for (std::size_t i = 0; i < palette.size(); ++i) {
        QPixmap swatch(16, 16);
        swatch.fill(QColor(palette[i].r, palette[i].g, palette[i].b));
        mInk->addItem(QIcon(swatch), tr("Ink %1").arg(i + 1));
    }
    mLoading = false;
    refresh();
}

void ToolOptions::setSettings(const ToolSettings& settings) {
    mSettings = settings;
    refresh();
}

void ToolOptions::refresh() {
    mLoading = true;
    for (const auto& load : mLoaders) load();
    mLoading = false;
}

void ToolOptions::changed() { emit settingsChanged(mSettings); }

} // namespace marbler::ui

#include "editor/ToolOptions.h"
#include "shared/Language.h"

#include "marbler/Params.h"
#include "marbler/Sampling.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
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
    return registryText(label);
}
QString unitOf(Tool tool, ParamField field) {
    const std::string_view unit = param(tool, field).unit;
    return unit.empty() ? QString() : QStringLiteral(" ") + registryText(unit);
}

} // namespace

QString toolName(EditorTool tool) {
    if (tool.inRegistry()) return ToolOptions::tr(toolSpec(tool.tool()).editor.name.data());
    switch (tool.own()) {
    case EditorOnly::Pick:
        return ToolOptions::tr("Pick");
    case EditorOnly::DropLine:
        return ToolOptions::tr("Line of drops");
    case EditorOnly::DropRings:
        return ToolOptions::tr("Rings");
    case EditorOnly::DropScatter:
        return ToolOptions::tr("Scatter");
    }
    return {};
}

QString toolTip(EditorTool tool) {
    if (tool.inRegistry()) return ToolOptions::tr(toolSpec(tool.tool()).editor.tooltip.data());
    switch (tool.own()) {
    case EditorOnly::Pick:
        return ToolOptions::tr("Click to pick the ink there and select the step that laid it");
    case EditorOnly::DropLine:
        return ToolOptions::tr("Drag to lay a line of drops from the press to the release");
    case EditorOnly::DropRings:
        return ToolOptions::tr("Drag from the centre: concentric rings out to the release");
    case EditorOnly::DropScatter:
        return ToolOptions::tr("Drag from the centre: drops scattered evenly in the circle");
    }
    return {};
}

QKeySequence toolShortcut(EditorTool tool) {
    if (tool.inRegistry()) {
        const char key = toolSpec(tool.tool()).editor.shortcut;
        return key ? QKeySequence(QKeyCombination(Qt::Key(key))) : QKeySequence();
    }
    switch (tool.own()) {
    case EditorOnly::Pick:
        return QKeySequence(Qt::Key_I);
    case EditorOnly::DropLine:
        return QKeySequence(Qt::Key_L);
    case EditorOnly::DropRings:
        return QKeySequence(Qt::Key_R);
    case EditorOnly::DropScatter:
        return QKeySequence(Qt::Key_A);
    }
    return {};
}

ToolOptions::ToolOptions(QWidget* parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("toolOptions"));
    mForm = new QFormLayout(this);
    const QString units = unitOf(Tool::Drop, ParamField::Radius);
    // Rows of a parameter show for the tools whose gesture takes it from the panel (panelSets);
    // the editor's own rows for the gestures they serve.
    // A stylus has rows of its own (its pull and sharpness start elsewhere than a circle's).
    auto sets = [](ParamField field) {
        return [field](EditorTool t) { return gestureOf(t) != EditorGesture::Path && panelSets(t, field); };
    };
    auto drawn = [](ParamField field) {
        return [field](EditorTool t) { return gestureOf(t) == EditorGesture::Path && panelSets(t, field); };
    };
    auto gesture = [](EditorGesture g) { return [g](EditorTool t) { return gestureOf(t) == g; }; };
    auto pattern = [](EditorTool t) { return t == T::DropLine || t == T::DropRings || t == T::DropScatter; };

    mInk = new QComboBox(this);
    mInk->setObjectName(QStringLiteral("toolInk"));
    mInk->setToolTip(tr("The palette ink the tool lays"));
    connect(mInk, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (mLoading || index < 0) return;
        mSettings.color = index;
        changed();
    });
    addRow(tr("Ink"), mInk, [](EditorTool t) { return t != T::Pick && laysInk(t); });
    mLoaders.push_back([this] { mInk->setCurrentIndex(std::min(mSettings.color, mInk->count() - 1)); });

    addNumber("toolRadius", labelOf(Tool::Drop, ParamField::Radius),
              tr("A clicked drop's radius (a drag sets it)"), &ToolSettings::radius, 0.1, 100000, units,
              [=](EditorTool t) { return sets(ParamField::Radius)(t) || pattern(t); });
    addNumber("toolSprayRadius", tr("Droplet"), tr("The radius of each sprayed droplet"),
              &ToolSettings::sprayRadius, 0.1, 1000, units, gesture(EditorGesture::Spray));
    addCount("toolSprayCount", tr("Droplets"), tr("How many droplets one stroke sprinkles"),
             &ToolSettings::sprayCount, 1, 2000, gesture(EditorGesture::Spray));
    addNumber("toolBrush", tr("Brush"), tr("How far from the stroke droplets land"), &ToolSettings::brush, 0,
              10000, units, gesture(EditorGesture::Spray));
    addCount("toolPatternCount", tr("Drops"), tr("How many drops the pattern lays"),
             &ToolSettings::patternCount, 1, 200, pattern);
    addNumber("toolSpacing", labelOf(Tool::Comb, ParamField::Spacing),
              tr("The distance between the comb's tines"), &ToolSettings::spacing, 1, 100000, units,
              sets(ParamField::Spacing));
    addNumber("toolWavelength", labelOf(Tool::Wave, ParamField::Wavelength),
              tr("The length of one period of the wave"), &ToolSettings::wavelength, 1, 100000, units,
              sets(ParamField::Wavelength));
    addNumber("toolAlpha", labelOf(Tool::Circle, ParamField::Alpha),
              tr("How far the circle moves the ink along its rim (a vortex's click too)"),
              &ToolSettings::alpha, -100000, 100000, units, sets(ParamField::Alpha));
    addNumber("toolLambda", labelOf(Tool::Line, ParamField::Lambda),
              tr("Smaller concentrates the shift near the stroke"), &ToolSettings::lambda, 0.1, 100000, units,
              sets(ParamField::Lambda));
    addNumber("toolCore", labelOf(Tool::Circle, ParamField::Core),
              tr("A finite centre: 0 winds without end, larger keeps the eye clean"), &ToolSettings::core, 0,
              100000, units, sets(ParamField::Core));
    // A solid's circle and sphere turn about an axis: typed, else across the section drawn on.
    mAxis = new QLineEdit(this);
    mAxis->setObjectName(QStringLiteral("toolAxis"));
    mAxis->setPlaceholderText(tr("across the section"));
    mAxis->setToolTip(tr("The axis a solid's circle or sphere turns about, as x, y, z (e.g. 0, 1, 1); "
                         "empty: across the section it is drawn on"));
    connect(mAxis, &QLineEdit::editingFinished, this, [this] {
        if (mLoading) return;
        const QString text = mAxis->text().trimmed();
        std::optional<glm::dvec3> axis;
        if (!text.isEmpty()) {
            std::string error;
            axis = parseDirection(text.toStdString(), "Axis", &error);
            if (!axis) {
                mAxisError->setText(QString::fromStdString(error));
                mAxisError->show();
                return;
            }
        }
        mAxisError->hide();
        if (axis == mSettings.axis) return;
        mSettings.axis = axis;
        changed();
    });
    const auto turnsAbout = [this](EditorTool t) {
        return mDimension == 3 && gestureOf(t) == EditorGesture::Ring;
    };
    addRow(tr("Axis"), mAxis, turnsAbout);
    mAxisError = new QLabel(this);
    mAxisError->setObjectName(QStringLiteral("toolAxisError"));
    mAxisError->setStyleSheet(QStringLiteral("color: #b00020"));
    mAxisError->setWordWrap(true);
    mAxisError->hide();
    mForm->addRow(mAxisError);
    mLoaders.push_back([this] {
        if (!mSettings.axis) {
            mAxis->clear();
            return;
        }
        const glm::dvec3 a = *mSettings.axis;
        mAxis->setText(QStringLiteral("%1, %2, %3")
                           .arg(QString::number(a.x, 'g', 4), QString::number(a.y, 'g', 4),
                                QString::number(a.z, 'g', 4)));
    });
    addCount("toolTeeth", tr("Teeth"), tr("How many teeth span the design"), &ToolSettings::teeth, 2, 1000,
             gesture(EditorGesture::Teeth));
    addNumber("toolPower", labelOf(Tool::Stretch, ParamField::Power),
              tr("The tooth profile |sin|^p: small is blunt, large is pointed"), &ToolSettings::power, 0.05,
              50, unitOf(Tool::Stretch, ParamField::Power), sets(ParamField::Power));

    mField = new QComboBox(this);
    mField->setObjectName(QStringLiteral("toolField"));
    mField->addItems({tr("Cells"), tr("Cavity")});
    mField->setToolTip(tr("The velocity field: a lattice of cells or one cavity"));
    connect(mField, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (mLoading || index < 0) return;
        mSettings.field = index;
        changed();
    });
    addRow(labelOf(Tool::Flow, ParamField::Field), mField, sets(ParamField::Field));
    mLoaders.push_back([this] { mField->setCurrentIndex(std::clamp(mSettings.field, 0, 1)); });
    addNumber("toolSpeed", labelOf(Tool::Flow, ParamField::Speed),
              tr("The flow's speed; its sign is the sense of turning"), &ToolSettings::speed, -100000, 100000,
              unitOf(Tool::Flow, ParamField::Speed), sets(ParamField::Speed));
    addNumber("toolTime", labelOf(Tool::Flow, ParamField::Time), tr("How long the flow runs"),
              &ToolSettings::time, 0.01, 1000, unitOf(Tool::Flow, ParamField::Time), sets(ParamField::Time));
    // The stylus (and the rake) drawn along a path: the next stroke's values.
    addNumber("toolPull", labelOf(Tool::Stylus, ParamField::Alpha),
              tr("How hard the stylus pulls the ink along its path: about the shift on the track; "
                 "negative pushes it back"),
              &ToolSettings::pull, -100000, 100000, unitOf(Tool::Stylus, ParamField::Alpha),
              drawn(ParamField::Alpha));
    addNumber("toolStylusLambda", labelOf(Tool::Stylus, ParamField::Lambda),
              tr("How far to the side of the track the pull reaches: smaller is a finer line"),
              &ToolSettings::stylusLambda, 0.1, 100000, unitOf(Tool::Stylus, ParamField::Lambda),
              drawn(ParamField::Lambda));
    addNumber("toolReach", labelOf(Tool::Stylus, ParamField::Reach),
              tr("How far ahead of and behind the stylus the bath moves"), &ToolSettings::reach, 0.1, 100000,
              unitOf(Tool::Stylus, ParamField::Reach), drawn(ParamField::Reach));
    addCount("toolTines", labelOf(Tool::Stylus, ParamField::Tines),
             tr("1 draws with a single stylus; more draws a rake of that many tines"), &ToolSettings::tines,
             1, int(MaxTines), drawn(ParamField::Tines));
    addNumber("toolRakeSpacing", labelOf(Tool::Stylus, ParamField::Spacing),
              tr("The distance between the rake's tines (with more than one)"), &ToolSettings::rakeSpacing,
              0.1, 100000, unitOf(Tool::Stylus, ParamField::Spacing), drawn(ParamField::Spacing));
    addCount("toolSeed", tr("Seed"),
             tr("Where sprayed and scattered drops land: the same seed, the same drops"), nullptr, 1, 1000000,
             [=](EditorTool t) { return gestureOf(t) == EditorGesture::Spray || t == T::DropScatter; });
    refresh();
    setTool(mTool);
}

void ToolOptions::addRow(const QString& label, QWidget* field, Shows shows) {
    mForm->addRow(label, field);
    mRows.push_back(Row{field, std::move(shows)});
}

void ToolOptions::addNumber(const char* name, const QString& label, const QString& tip,
                            double ToolSettings::*member, double min, double max, const QString& suffix,
                            Shows shows) {
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
    addRow(label, box, std::move(shows));
}

void ToolOptions::addCount(const char* name, const QString& label, const QString& tip,
                           int ToolSettings::*member, int min, int max, Shows shows) {
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
    addRow(label, box, std::move(shows));
}

void ToolOptions::setTool(EditorTool tool) {
    mTool = tool;
    mAxisError->hide();
    for (const Row& row : mRows)
        mForm->setRowVisible(row.field, row.shows(tool));
}

void ToolOptions::setDimension(int dimension) {
    mDimension = dimension;
    setTool(mTool);
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
    for (const auto& load : mLoaders)
        load();
    mLoading = false;
}

void ToolOptions::changed() {
    emit settingsChanged(mSettings);
}

} // namespace marbler::ui

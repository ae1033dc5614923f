// The parameters of one step as widgets (ParamForm.h).

#include "editor/ParamForm.h"
#include "shared/Language.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QRegularExpression>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace marbler::ui {
namespace {

/// Slider positions: fine enough for a smooth drag, coarse enough to step with the keys.
constexpr int SliderSteps = 1000;

QString componentName(const ParamSpec& spec, int i, int count) {
    if (spec.kind == ParamKind::Position || spec.kind == ParamKind::Direction) {
        static const char* axes[] = {"X", "Y", "Z"};
        return QString::fromLatin1(axes[std::clamp(i, 0, 2)]);
    }
    if (spec.kind == ParamKind::Extent) return i == 0 ? QStringLiteral("X") : QStringLiteral("Y");
    if (count == 2) return i == 0 ? QStringLiteral("1") : QStringLiteral("2");
    return {};
}

bool hasSlider(ParamKind kind) {
    return kind == ParamKind::Position || kind == ParamKind::Angle || kind == ParamKind::Length ||
           kind == ParamKind::Shift || kind == ParamKind::Phase;
}

bool isInteger(ParamKind kind) {
    return kind == ParamKind::Count;
}

/// Parameters of any length, edited as text: a stretch's teeth, a stylus's path and pressure.
bool isList(ParamKind kind) {
    return kind == ParamKind::Teeth || kind == ParamKind::Path || kind == ParamKind::Pressure;
}

/// A stylus's steps after another of its fields changed: the fewest valid still where they were
/// the fewest, else at least that (a stroke that would need more than a stylus may take keeps
/// too few, and the validator refuses it).
void keepStylusSteps(const Operation& before, Operation& op) {
    if (!findParam(op.tool, ParamField::Path) || op.path.size() < 2) return;
    const int fewest = minimumStylusSteps(op);
    if (fewest > MaxStylusSteps) return;
    op.steps = before.path.size() >= 2 && before.steps == minimumStylusSteps(before)
                   ? fewest
                   : std::max(op.steps, fewest);
}

/// `values` (one a point of a path of `from` points) spread over `to` points, linearly.
std::vector<double> resampled(const std::vector<double>& values, std::size_t to) {
    if (values.empty() || values.size() == to) return values;
    std::vector<double> out(to);
    for (std::size_t i = 0; i < to; ++i) {
        const double at = to == 1 ? 0.0 : double(i) * double(values.size() - 1) / double(to - 1);
        const auto k = std::min(std::size_t(at), values.size() - 1);
        const double f = at - double(k);
        out[i] = k + 1 < values.size() ? values[k] + f * (values[k + 1] - values[k]) : values[k];
    }
    return out;
}

glm::dvec3 unitOrZero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 1e-12 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}

/// Sets a component; a 3D axis, direction or normal is kept unit, and the normal orthogonal to
/// the direction (what loading a file makes of them, so the design edited is the design saved).
void applyComponent(const ParamSpec& spec, Operation& op, int dimension, int component, double value) {
    setComponent(spec, op, component, value);
    if (spec.kind != ParamKind::Direction || dimension != 3) return;
    const auto params = toolSpec(op.tool).params(dimension);
    const bool hasNormal = std::any_of(params.begin(), params.end(),
                                       [](const ParamSpec& p) { return p.field == ParamField::Normal; });
    if (spec.field == ParamField::Axis) op.axis = unitOrZero(op.axis);
    if (spec.field == ParamField::Direction) op.direction = unitOrZero(op.direction);
    if (hasNormal && (spec.field == ParamField::Direction || spec.field == ParamField::Normal)) {
        // Gram-Schmidt twice, as the loader does.
        glm::dvec3 n = unitOrZero(op.normal);
        for (int pass = 0; pass < 2; ++pass)
            n = unitOrZero(n - glm::dot(n, op.direction) * op.direction);
        op.normal = n;
    }
}

QString text(std::string_view s) {
    return registryText(s); // issue 25: the registry's words in the window's language
}

} // namespace

bool isUndoKey(const QKeyEvent* key) {
    const QKeySequence pressed(key->keyCombination());
    return key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
           pressed == QKeySequence(Qt::CTRL | Qt::Key_Z) ||
           pressed == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z) ||
           pressed == QKeySequence(Qt::CTRL | Qt::Key_Y);
}

CompactSpinBox::CompactSpinBox(QWidget* parent)
    : QDoubleSpinBox(parent) {
    // What QDoubleSpinBox rounds every value to: fine enough that a value is kept as it is.
    setDecimals(15);
}

QSize CompactSpinBox::sizeHint() const {
    QSize size = QDoubleSpinBox::sizeHint();
    // Room for "-1234.56" and the suffix, the frame and the arrows.
    const int text = fontMetrics().horizontalAdvance(QStringLiteral("-1234.56") + suffix());
    size.setWidth(text + 2 * style()->pixelMetric(QStyle::PM_SpinBoxFrameWidth, nullptr, this) + 28);
    return size;
}

QSize CompactSpinBox::minimumSizeHint() const {
    QSize size = sizeHint();
    size.setWidth(fontMetrics().horizontalAdvance(QStringLiteral("-1234.5")) + 28);
    return size;
}

QString CompactSpinBox::compact(double value) {
    return QString::number(value, 'g', 6);
}

QString CompactSpinBox::textFromValue(double value) const {
    return compact(value);
}

namespace {

/// The number in a spin box's text, without its prefix and suffix.
QString numberPart(const QDoubleSpinBox& box, QString text) {
    if (!box.prefix().isEmpty() && text.startsWith(box.prefix())) text.remove(0, box.prefix().size());
    if (!box.suffix().isEmpty() && text.endsWith(box.suffix())) text.chop(box.suffix().size());
    return text.trimmed();
}

std::optional<double> parseNumber(const QLocale& locale, const QString& text) {
    bool ok = false;
    double value = text.toDouble(&ok);
    if (!ok) value = locale.toDouble(text, &ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

} // namespace

double CompactSpinBox::valueFromText(const QString& text) const {
    const QString number = numberPart(*this, text);
    // The text shown, unchanged, is the value itself (not its six digits).
    if (number == compact(value())) return value();
    return parseNumber(locale(), number).value_or(value());
}

QValidator::State CompactSpinBox::validate(QString& input, int&) const {
    const QString number = numberPart(*this, input);
    if (number.isEmpty()) return QValidator::Intermediate;
    if (const auto value = parseNumber(locale(), number))
        return *value >= minimum() && *value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    // A number being typed ("-", "1.", "2e", "2e-").
    static const QRegularExpression partial(QStringLiteral("^[+-]?[0-9]*[.,]?[0-9]*([eE][+-]?[0-9]*)?$"));
    return partial.match(number).hasMatch() ? QValidator::Intermediate : QValidator::Invalid;
}

void CompactSpinBox::fixup(QString& input) const {
    // A number out of range becomes the nearest in range; anything else keeps the old value.
    if (const auto value = parseNumber(locale(), numberPart(*this, input)))
        input = prefix() + compact(std::clamp(*value, minimum(), maximum())) + suffix();
}

/// The widgets of one parameter.
struct ParamForm::Row {
    const ParamSpec* spec = nullptr;
    QWidget* box = nullptr;
    std::vector<QDoubleSpinBox*> spins;
    std::vector<QSpinBox*> counts;
    std::vector<QSlider*> sliders;
    QComboBox* combo = nullptr;
    QLineEdit* text = nullptr;
    QLabel* error = nullptr;                ///< what is wrong with the text typed (a path, pressure)
    QSpinBox* teethCount = nullptr;         ///< a stretch's teeth: how many
    CompactSpinBox* teethSpacing = nullptr; ///< and how far apart (even)
};

ParamForm::ParamForm(QWidget* parent)
    : QWidget(parent)
    , mLayout(new QFormLayout(this)) {
    setObjectName(QStringLiteral("paramForm"));
    setToolTip(tr("The parameters of the selected step"));
    // Where the panel is narrow, a field goes below its label rather than off the edge.
    mLayout->setRowWrapPolicy(QFormLayout::WrapLongRows);
}

void ParamForm::clear() {
    mHasStep = false;
    for (Row* row : mRows) {
        delete row->box;
        delete row;
    }
    mRows.clear();
    mShape.clear();
    while (mLayout->rowCount() > 0)
        mLayout->removeRow(0);
}

void ParamForm::setStep(const Operation& op, int dimension, const Genome& design) {
    const bool sameTool = mHasStep && op.tool == mOp.tool && dimension == mDimension;
    mOp = op;
    mDimension = dimension;
    mSize = design.size;
    const bool paletteChanged = design.palette != mPalette;
    mPalette = design.palette;
    std::vector<int> shape;
    for (const ParamSpec& spec : toolSpec(op.tool).params(dimension))
        shape.push_back(isList(spec.kind) ? 0 : componentCount(spec, op, dimension));
    if (sameTool && shape == mShape && !paletteChanged) {
        refresh();
        return;
    }
    clear();
    mHasStep = true;
    mShape = shape;
    build();
    refresh();
}

double ParamForm::sliderSpan(const ParamSpec& spec, int component, double& low) const {
    const double side = std::max({mSize.x, mSize.y, mDimension == 3 ? mSize.z : 0.0});
    switch (spec.kind) {
    case ParamKind::Position:
        low = 0.0;
        return mSize[std::clamp(component, 0, 2)];
    case ParamKind::Angle:
        low = -180.0;
        return 360.0;
    case ParamKind::Phase:
        low = 0.0;
        return 360.0;
    case ParamKind::Shift:
        low = -side;
        return 2.0 * side;
    default: {
        low = std::isfinite(spec.range.min) ? spec.range.min : 0.0;
        const double high = std::isfinite(spec.range.max) ? std::min(spec.range.max, side) : side;
        return std::max(high - low, 1e-9);
    }
    }
}

void ParamForm::build() {
    const double side = std::max({mSize.x, mSize.y, mDimension == 3 ? mSize.z : 0.0});
    for (const ParamSpec& spec : toolSpec(mOp.tool).params(mDimension)) {
        auto* row = new Row;
        row->spec = &spec;
        row->box = new QWidget(this);
        const QString key = text(spec.key);
        const QString label = text(spec.label);
        row->box->setObjectName(QStringLiteral("param-") + key);
        QString tip = text(spec.help);
        if (spec.kind == ParamKind::Choice)
            tip +=
                QStringLiteral(" (") + QString::fromStdString(spec.describeChoices()) + QStringLiteral(")");
        else if (spec.kind != ParamKind::Color &&
                 (std::isfinite(spec.range.min) || std::isfinite(spec.range.max)))
            tip += QStringLiteral(" (") + QString::fromStdString(spec.range.describe()) + QStringLiteral(")");
        if (spec.version > 1) tip += tr(" [format version %1]").arg(spec.version);
        tip += tr("\nIn the file: \"%1\"").arg(key);
        row->box->setToolTip(tip);
        auto* layout = new QHBoxLayout(row->box);
        layout->setContentsMargins(0, 0, 0, 0);
        const QString unit = text(spec.unit);

        if (spec.kind == ParamKind::Color) {
            row->combo = new QComboBox(row->box);
            for (std::size_t i = 0; i < mPalette.size(); ++i) {
                QPixmap swatch(16, 16);
                swatch.fill(QColor(mPalette[i].r, mPalette[i].g, mPalette[i].b));
                row->combo->addItem(QIcon(swatch), tr("Ink %1").arg(i + 1));
            }
            connect(row->combo, &QComboBox::currentIndexChanged, this, [this, row](int index) {
                if (mUpdating || index < 0) return;
                commitComponent(*row->spec, 0, index, false);
            });
        } else if (spec.kind == ParamKind::Choice) {
            row->combo = new QComboBox(row->box);
            for (std::string_view choice : spec.choices)
                row->combo->addItem(QString::fromUtf8(choice.data(), qsizetype(choice.size())));
            connect(row->combo, &QComboBox::currentIndexChanged, this, [this, row](int index) {
                if (mUpdating || index < 0) return;
                commitComponent(*row->spec, 0, index, false);
            });
        } else if (spec.kind == ParamKind::Path || spec.kind == ParamKind::Pressure) {
            // A stylus's path ("x y; x y; ...") or pressure ("p p p ...", empty: all 1) as text,
            // checked when Enter is pressed or the field is left; what is wrong is said below it.
            auto* lines = new QVBoxLayout;
            layout->addLayout(lines, 1);
            row->text = new QLineEdit(row->box);
            row->text->setPlaceholderText(spec.kind == ParamKind::Path
                                              ? tr("x y; x y; ... (2 to %1 points)").arg(int(MaxPathPoints))
                                              : tr("all 1 (a mouse's stroke)"));
            lines->addWidget(row->text);
            row->error = new QLabel(row->box);
            row->error->setObjectName(QStringLiteral("error-") + key);
            row->error->setWordWrap(true);
            row->error->setStyleSheet(QStringLiteral("color: #c62828"));
            row->error->hide();
            lines->addWidget(row->error);
            connect(row->text, &QLineEdit::editingFinished, this, [this, row] {
                if (!mUpdating) commitListText(*row);
            });
        } else if (spec.kind == ParamKind::Teeth) {
            // Count and spacing for the usual even comb; the positions as text for any other.
            auto* lines = new QVBoxLayout;
            auto* even = new QHBoxLayout;
            layout->addLayout(lines, 1);
            lines->addLayout(even);
            row->teethCount = new QSpinBox(row->box);
            row->teethCount->setObjectName(QStringLiteral("edit-teeth-count"));
            row->teethCount->setRange(2, int(MaxTeeth));
            row->teethCount->setKeyboardTracking(false);
            row->teethCount->setToolTip(tr("How many teeth: more or fewer over the same span"));
            row->teethSpacing = new CompactSpinBox(row->box);
            row->teethSpacing->setObjectName(QStringLiteral("edit-teeth-spacing"));
            row->teethSpacing->setRange(1e-3, 1e9);
            row->teethSpacing->setSuffix(QStringLiteral(" ") + unit);
            row->teethSpacing->setKeyboardTracking(false);
            row->teethSpacing->setToolTip(tr("The distance between two teeth, about the same middle"));
            even->addWidget(new QLabel(tr("Count"), row->box));
            even->addWidget(row->teethCount, 1);
            even->addWidget(new QLabel(tr("Spacing"), row->box));
            even->addWidget(row->teethSpacing, 2);
            connect(row->teethCount, &QSpinBox::valueChanged, this, [this, row](int count) {
                if (mUpdating || mOp.teeth.size() < 2) return;
                // The same span, teeth spread evenly over it.
                setTeeth(*row, count, (mOp.teeth.back() - mOp.teeth.front()) / (count - 1));
            });
            connect(row->teethSpacing, &QDoubleSpinBox::valueChanged, this, [this, row](double spacing) {
                if (!mUpdating) setTeeth(*row, int(mOp.teeth.size()), spacing);
            });
            watch(row->teethCount);
            watch(row->teethSpacing);
            row->text = new QLineEdit(row->box);
            row->text->setPlaceholderText(tr("positions, increasing"));
            lines->addWidget(row->text);
            connect(row->text, &QLineEdit::editingFinished, this, [this, row] {
                if (mUpdating) return;
                Operation op = mOp;
                op.teeth.clear();
                bool ok = true;
                const QStringList words = row->text->text().split(
                    QRegularExpression(QStringLiteral("[\\s,;]+")), Qt::SkipEmptyParts);
                for (const QString& word : words) {
                    op.teeth.push_back(word.toDouble(&ok));
                    if (!ok) break;
                }
                if (ok && op.teeth != mOp.teeth && valid(op))
                    commitOperation(*row->spec, op, false);
                else
                    refreshRow(*row); // no valid list: show the teeth as they are
            });
        } else {
            const int count = componentCount(spec, mOp, mDimension);
            // A vector's components one above the other: the form stays as narrow as its panel.
            QVBoxLayout* stack = nullptr;
            if (count > 1) {
                stack = new QVBoxLayout;
                stack->setSpacing(2);
                layout->addLayout(stack, 1);
            }
            for (int i = 0; i < count; ++i) {
                QHBoxLayout* line = layout;
                if (stack) {
                    line = new QHBoxLayout;
                    stack->addLayout(line);
                    line->addWidget(new QLabel(componentName(spec, i, count), row->box));
                }
                if (isInteger(spec.kind)) {
                    auto* spin = new QSpinBox(row->box);
                    spin->setObjectName(QStringLiteral("edit-%1-%2").arg(key).arg(i));
                    spin->setRange(std::isfinite(spec.range.min) ? int(std::ceil(spec.range.min)) : -1000000,
                                   std::isfinite(spec.range.max) ? int(std::floor(spec.range.max)) : 1000000);
                    spin->setKeyboardTracking(false);
                    spin->setToolTip(tip);
                    watch(spin);
                    line->addWidget(spin, 1);
                    row->counts.push_back(spin);
                    connect(spin, &QSpinBox::valueChanged, this, [this, row, i](int value) {
                        if (!mUpdating) commitComponent(*row->spec, i, value, false);
                    });
                    continue;
                }
                auto* spin = new CompactSpinBox(row->box);
                spin->setObjectName(QStringLiteral("edit-%1-%2").arg(key).arg(i));
                const bool direction = spec.kind == ParamKind::Direction;
                watch(spin);
                const double wide = direction ? 1.0 : std::max(10.0 * side, 3600.0);
                double low = std::isfinite(spec.range.min) ? spec.range.min : -wide;
                if (spec.range.minOpen) low += direction ? 1e-4 : 0.01;
                const double high = std::isfinite(spec.range.max) ? spec.range.max : wide;
                spin->setRange(low, high);
                spin->setSingleStep(direction ? 0.05 : spec.kind == ParamKind::Number ? 0.1 : 1.0);
                if (!unit.isEmpty() && !direction) spin->setSuffix(QStringLiteral(" ") + unit);
                spin->setKeyboardTracking(false);
                spin->setToolTip(tip);
                row->spins.push_back(spin);
                connect(spin, &QDoubleSpinBox::valueChanged, this, [this, row, i](double value) {
                    if (!mUpdating) commitComponent(*row->spec, i, value, false);
                });
                if (hasSlider(spec.kind)) {
                    auto* slider = new QSlider(Qt::Horizontal, row->box);
                    slider->setObjectName(QStringLiteral("slider-%1-%2").arg(key).arg(i));
                    slider->setRange(0, SliderSteps);
                    slider->setToolTip(tip + tr("\nDrag to see the change as you go"));
                    line->addWidget(slider, 2);
                    row->sliders.push_back(slider);
                    auto valueOf = [this, row, i](int position) {
                        double lowValue = 0.0;
                        const double span = sliderSpan(*row->spec, i, lowValue);
                        return lowValue + span * position / SliderSteps;
                    };
                    connect(slider, &QSlider::valueChanged, this,
                            [this, row, i, slider, valueOf](int position) {
                                if (mUpdating) return;
                                commitComponent(*row->spec, i, valueOf(position), slider->isSliderDown());
                            });
                    connect(slider, &QSlider::sliderReleased, this, [this, row, i, slider, valueOf] {
                        if (!mUpdating) commitComponent(*row->spec, i, valueOf(slider->value()), false, true);
                    });
                }
                line->addWidget(spin, 1);
            }
        }
        if (row->combo) {
            row->combo->setObjectName(QStringLiteral("edit-%1-0").arg(key));
            row->combo->setToolTip(tip);
            layout->addWidget(row->combo, 1);
        }
        if (row->text) {
            row->text->setObjectName(QStringLiteral("edit-%1-0").arg(key));
            row->text->setToolTip(tip);
            watch(row->text);
        }
        // The registry's word, as the tool panel shows it; the unit is in the boxes' suffix.
        auto* caption = new QLabel(label, this);
        caption->setToolTip(tip);
        caption->setBuddy(row->box);
        mLayout->addRow(caption, row->box);
        mRows.push_back(row);
    }
}

void ParamForm::refresh() {
    for (const Row* row : mRows)
        refreshRow(*row);
}

void ParamForm::refreshRow(const Row& row) {
    const bool was = mUpdating;
    mUpdating = true;
    const ParamSpec& spec = *row.spec;
    if (row.combo) row.combo->setCurrentIndex(int(getComponent(spec, mOp, 0)));
    if (row.text) {
        QStringList words;
        if (spec.kind == ParamKind::Path) {
            for (const glm::dvec2& p : mOp.path)
                words << CompactSpinBox::compact(p.x) + QStringLiteral(" ") + CompactSpinBox::compact(p.y);
            row.text->setText(words.join(QStringLiteral("; ")));
        } else {
            for (double t : spec.kind == ParamKind::Pressure ? mOp.pressure : mOp.teeth)
                words << CompactSpinBox::compact(t);
            row.text->setText(words.join(QStringLiteral(" ")));
        }
        row.text->setCursorPosition(0);
    }
    if (row.teethCount && mOp.teeth.size() >= 2) {
        const double spacing = (mOp.teeth.back() - mOp.teeth.front()) / double(mOp.teeth.size() - 1);
        row.teethCount->setValue(int(mOp.teeth.size()));
        row.teethSpacing->setValue(spacing);
        bool evenly = true;
        for (std::size_t i = 1; i < mOp.teeth.size(); ++i)
            evenly = evenly &&
                     std::abs(mOp.teeth[i] - mOp.teeth[i - 1] - spacing) <= 1e-6 * (1.0 + std::abs(spacing));
        row.teethSpacing->setToolTip(
            evenly ? tr("The distance between two teeth, about the same middle")
                   : tr("The mean distance between the teeth, which are unevenly spaced: "
                        "a new spacing spaces them evenly"));
    }
    for (std::size_t i = 0; i < row.counts.size(); ++i)
        row.counts[i]->setValue(int(getComponent(spec, mOp, int(i))));
    for (std::size_t i = 0; i < row.spins.size(); ++i) {
        const double value = getComponent(spec, mOp, int(i));
        QDoubleSpinBox* spin = row.spins[i];
        // A value beyond the box's span (a file may hold one) widens the box rather than being cut.
        if (value > spin->maximum()) spin->setMaximum(value);
        if (value < spin->minimum()) spin->setMinimum(value);
        spin->setValue(value);
        if (i < row.sliders.size() && !row.sliders[i]->isSliderDown()) {
            double low = 0.0;
            const double span = sliderSpan(spec, int(i), low);
            row.sliders[i]->setValue(
                int(std::lround(std::clamp((value - low) / span, 0.0, 1.0) * SliderSteps)));
        }
    }
    mUpdating = was;
}

void ParamForm::watch(QWidget* field) {
    field->installEventFilter(this);
}

bool ParamForm::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride && isUndoKey(static_cast<QKeyEvent*>(event))) {
        // Not the field's own text undo: the key goes on to the window's Undo or Redo.
        event->ignore();
        return true;
    }
    if (event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            // The field takes its Enter first (it commits its text), then the form says so.
            watched->event(event);
            emit committed();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ParamForm::setTeeth(const Row& row, int count, double spacing) {
    if (!mHasStep || mOp.teeth.size() < 2 || !std::isfinite(spacing) || spacing <= 0.0) {
        refreshRow(row);
        return;
    }
    count = std::clamp(count, 2, int(MaxTeeth));
    const double middle = 0.5 * (mOp.teeth.front() + mOp.teeth.back());
    Operation op = mOp;
    op.teeth.clear();
    for (int i = 0; i < count; ++i)
        op.teeth.push_back(middle + (i - 0.5 * (count - 1)) * spacing);
    if (op.teeth != mOp.teeth && valid(op))
        commitOperation(*row.spec, op, false);
    else
        refreshRow(row);
}

bool ParamForm::valid(const Operation& op, QString* why) const {
    Genome g;
    g.dimension = mDimension;
    g.size = mSize;
    g.palette = mPalette;
    if (g.palette.empty()) g.palette.push_back(Color{});
    g.operations.push_back(op);
    try {
        validateGenome(g, "step");
        return true;
    } catch (const Error& e) {
        if (why) *why = QString::fromUtf8(e.what());
        return false;
    }
}

void ParamForm::showError(const Row& row, const QString& message) {
    row.error->setText(message);
    row.error->setToolTip(message);
    row.error->show();
    refreshRow(row); // the field shows the value kept
}

void ParamForm::commitListText(const Row& row) {
    if (!mHasStep) return;
    const ParamSpec& spec = *row.spec;
    const QString label = text(spec.label);
    const QString typed = row.text->text().trimmed();
    Operation op = mOp;
    auto number = [](const QString& word, double& value) {
        bool ok = false;
        value = word.toDouble(&ok);
        return ok && std::isfinite(value);
    };
    if (spec.kind == ParamKind::Path) {
        op.path.clear();
        const QStringList points =
            typed.split(QRegularExpression(QStringLiteral("\\s*[;\\n]\\s*")), Qt::SkipEmptyParts);
        for (int i = 0; i < points.size(); ++i) {
            const QStringList xy =
                points[i].split(QRegularExpression(QStringLiteral("[\\s,]+")), Qt::SkipEmptyParts);
            glm::dvec2 p;
            if (xy.size() != 2 || !number(xy[0], p.x) || !number(xy[1], p.y))
                return showError(row, tr("%1: point %2 (\"%3\") is not two numbers \"x y\"")
                                          .arg(label)
                                          .arg(i + 1)
                                          .arg(points[i]));
            if (!op.path.empty() && p == op.path.back())
                return showError(row,
                                 tr("%1: point %2 is the same as point %3; consecutive points must differ")
                                     .arg(label)
                                     .arg(i + 1)
                                     .arg(i));
            op.path.push_back(p);
        }
        if (op.path.size() < 2 || op.path.size() > MaxPathPoints)
            return showError(row, tr("%1: %2 points; a path has 2 to %3")
                                      .arg(label)
                                      .arg(op.path.size())
                                      .arg(int(MaxPathPoints)));
        // A pen's pressure follows the points (spread over as many as there are now).
        op.pressure = resampled(mOp.pressure, op.path.size());
    } else {
        op.pressure.clear();
        const QStringList words =
            typed.split(QRegularExpression(QStringLiteral("[\\s,;]+")), Qt::SkipEmptyParts);
        for (int i = 0; i < words.size(); ++i) {
            double p = 0.0;
            if (!number(words[i], p))
                return showError(
                    row, tr("%1: value %2 (\"%3\") is not a number").arg(label).arg(i + 1).arg(words[i]));
            if (!spec.range.contains(p))
                return showError(row, tr("%1: value %2 (%3) %4")
                                          .arg(label)
                                          .arg(i + 1)
                                          .arg(words[i])
                                          .arg(QString::fromStdString(spec.range.describe())));
            op.pressure.push_back(p);
        }
        if (!op.pressure.empty() && op.pressure.size() != op.path.size())
            return showError(row, tr("%1: %2 values for %3 path points; give one a point, or none for all 1")
                                      .arg(label)
                                      .arg(op.pressure.size())
                                      .arg(op.path.size()));
        // All 1 is what no pressure says (the file leaves it out).
        if (std::all_of(op.pressure.begin(), op.pressure.end(),
                        [&](double p) { return p == spec.defaultValue; }))
            op.pressure.clear();
    }
    keepStylusSteps(mOp, op);
    if (minimumStylusSteps(op) > MaxStylusSteps)
        return showError(row, tr("%1: this stroke would need more than %2 integration steps; split it into "
                                 "shorter strokes")
                                  .arg(label)
                                  .arg(MaxStylusSteps));
    if (!valid(op, &mLastError)) return showError(row, tr("%1: %2").arg(label, mLastError));
    if (op == mOp) {
        row.error->hide();
        refreshRow(row);
        return;
    }
    commitOperation(spec, op, false);
}

void ParamForm::commitComponent(const ParamSpec& spec, int component, double value, bool dragging,
                                bool endsDrag) {
    if (!mHasStep || !std::isfinite(value)) return;
    const double old = getComponent(spec, mOp, component);
    // Into the parameter's own range first.
    if (value > spec.range.max) value = spec.range.max;
    if (spec.range.minOpen ? value <= spec.range.min : value < spec.range.min)
        value = spec.range.minOpen ? std::max(spec.range.min + 1e-6, std::nextafter(spec.range.min, INFINITY))
                                   : spec.range.min;
    if (spec.kind == ParamKind::Color || spec.kind == ParamKind::Choice || spec.kind == ParamKind::Count)
        value = std::round(value);
    Operation op = mOp;
    applyComponent(spec, op, mDimension, component, value);
    if (spec.field != ParamField::Steps) keepStylusSteps(mOp, op);
    if (!valid(op)) {
        // A rule between parameters (a flow's steps, a direction's length): the valid value
        // nearest the one asked for, between it and the old value, which is valid.
        double good = old, bad = value;
        for (int i = 0; i < 60; ++i) {
            double mid = 0.5 * (good + bad);
            if (spec.kind == ParamKind::Count) mid = good < bad ? std::floor(mid) : std::ceil(mid);
            Operation probe = mOp;
            applyComponent(spec, probe, mDimension, component, mid);
            if (spec.field != ParamField::Steps) keepStylusSteps(mOp, probe);
            if (valid(probe))
                good = mid;
            else
                bad = mid;
            if (mid == good &&
                std::abs(good - bad) <= (spec.kind == ParamKind::Count ? 1.0 : 1e-9 * (1.0 + std::abs(bad))))
                break;
        }
        op = mOp;
        applyComponent(spec, op, mDimension, component, good);
        if (spec.field != ParamField::Steps) keepStylusSteps(mOp, op);
        if (!valid(op)) {
            refresh();
            return;
        }
    }
    commitOperation(spec, op, dragging, endsDrag);
}

void ParamForm::commitOperation(const ParamSpec& spec, const Operation& op, bool dragging, bool endsDrag) {
    const bool shapeChanged = spec.kind == ParamKind::Choice && op.shape != mOp.shape;
    if (op == mOp && !endsDrag) {
        // Nothing changed (a value brought back to where it was): show it, say nothing.
        refresh();
        return;
    }
    mOp = op;
    for (const Row* row : mRows)
        if (row->error) row->error->hide();
    // Show the values kept (brought into range, a direction made unit, its normal turned with it).
    refresh();
    emit edited(mOp, QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size())), dragging);
    if (shapeChanged) {
        // A 3D wave's pairs have one or two numbers by its shape: rebuild once this signal is done.
        QMetaObject::invokeMethod(
            this,
            [this] {
                Genome g;
                g.dimension = mDimension;
                g.size = mSize;
                g.palette = mPalette;
                const Operation keep = mOp;
                mHasStep = false;
                setStep(keep, mDimension, g);
            },
            Qt::QueuedConnection);
    }
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_ParamForm.cpp"

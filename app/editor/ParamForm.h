#pragma once
/// The parameters of one step, as widgets built from the tool registry (Params.h): spin boxes
/// with units and ranges, sliders for positions, lengths, angles, phases and shifts, the palette
/// for an ink's colour, a list for a choice, two boxes for an extent, a stretch's teeth as a
/// count and a spacing (and their positions as text), a stylus's path and pressure as text (what
/// is wrong with the text typed said under it, starting with the field's label). Each row is named by the
/// registry's label, the word the tool panel uses too; numbers show compactly (six significant digits, an
/// exponent for the huge and the tiny), the value kept exact until it is edited. Enter commits a field and
/// says so (`committed`), and the fields leave the undo keys to the window. Every value it emits is valid: a
/// value outside the parameter's range, or one that breaks a rule between parameters (a flow's steps, a
/// normal parallel to the direction), is brought back to the nearest valid value first. A 3D axis, direction
/// or normal is kept unit, and the normal orthogonal to the direction, as loading a file makes them (so
/// editing a direction may turn the normal with it).

#include "marbler/Genome.h"
#include "marbler/Params.h"

#include <QDoubleSpinBox>
#include <QString>
#include <QWidget>

#include <vector>

class QFormLayout;
class QKeyEvent;

namespace marbler::ui {

/// Whether a key is one of the editor's undo or redo keys (Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y and the
/// platform's): a field lets them go on to the window's Undo and Redo instead of its own.
bool isUndoKey(const QKeyEvent* key);

/// A number box that shows its value compactly ("1e+308", not 309 digits; six significant
/// digits) and reads any number back, exponents included. Text the user did not change reads
/// back as the exact value shown, so focusing and leaving a field never rounds the value.
class CompactSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit CompactSpinBox(QWidget* parent = nullptr);
    /// `value` in the compact form (no prefix or suffix).
    static QString compact(double value);
    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& input, int& pos) const override;
    void fixup(QString& input) const override;
    /// As wide as a compact number and the suffix: not the 15-decimal width of its range, which
    /// would widen the form.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
};

/// The form of one step's parameters (see the file comment).
class ParamForm : public QWidget {
    Q_OBJECT
public:
    explicit ParamForm(QWidget* parent = nullptr);

    /// Shows the parameters of `op`, a step of a design of `dimension`; `design` gives the
    /// palette (the colour list) and the size (the sliders' spans). Keeps the widgets (and a
    /// slider being dragged) when the tool and the shape of the form stay the same.
    void setStep(const Operation& op, int dimension, const Genome& design);
    /// Shows no step.
    void clear();
    /// The step as last set or edited.
    const Operation& step() const { return mOp; }

signals:
    /// The user changed parameter `key`: `op` is the step with it changed. `dragging` while a
    /// slider is held (render coarsely, merge into one undo step); the edit that ends a drag,
    /// and every other edit, has it false. An edit that changes nothing is not emitted, except
    /// the one that ends a drag.
    void edited(const marbler::Operation& op, const QString& key, bool dragging);
    /// Enter was pressed in a field: its value is committed (the window hands the focus back to
    /// the canvas, where the single-key shortcuts work).
    void committed();

protected:
    /// Leaves the undo and redo keys of the fields to the window's Undo and Redo (a spin box
    /// or line edit would otherwise take Ctrl+Z for its own text), and reports Enter.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Row;
    void build();
    void refresh();
    void refreshRow(const Row& row);
    void watch(QWidget* field);
    void setTeeth(const Row& row, int count, double spacing);
    /// Whether `op` is a valid step; `why` gets the validator's words when it is not.
    bool valid(const Operation& op, QString* why = nullptr) const;
    /// A path's or pressure's text, typed: committed, or what is wrong said under it.
    void commitListText(const Row& row);
    void showError(const Row& row, const QString& message);
    void commitComponent(const ParamSpec& spec, int component, double value, bool dragging,
                         bool endsDrag = false);
    void commitOperation(const ParamSpec& spec, const Operation& op, bool dragging, bool endsDrag = false);
    double sliderSpan(const ParamSpec& spec, int component, double& low) const;

    Operation mOp;
    int mDimension = 2;
    glm::dvec3 mSize{1000.0};
    std::vector<Color> mPalette;
    bool mHasStep = false;
    bool mUpdating = false;
    std::vector<int> mShape; ///< the component count of each parameter the widgets were built for
    std::vector<Row*> mRows;
    QString mLastError;
    QFormLayout* mLayout;
};

} // namespace marbler::ui

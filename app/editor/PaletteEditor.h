#pragma once
/// The editor's palette: a swatch per ink, the background and the bleed. Click a swatch to make
/// it the current ink (what the tools lay); double-click it (or use its menu) to change its
/// colour in a colour dialog, which shows each colour live while choosing. Knows no document:
/// it emits the changes the user asks for.

#include "marbler/Genome.h"

#include <QWidget>

#include <vector>

class QButtonGroup;
class QColorDialog;
class QDoubleSpinBox;
class QHBoxLayout;
class QToolButton;

namespace marbler::ui {

/// The palette panel (see the file comment).
class PaletteEditor : public QWidget {
    Q_OBJECT
public:
    explicit PaletteEditor(QWidget* parent = nullptr);

    /// Shows the palette, background and bleed of `design`.
    void setDesign(const Genome& design);
    /// The ink the tools lay (a palette index).
    int currentInk() const { return mCurrent; }
    /// Makes `index` the current ink (no signal).
    void setCurrentInk(int index);
    /// Opens the colour dialog on ink `index` (-1: the background).
    void editColor(int index);
    /// The open colour dialog, if any (for tests).
    QColorDialog* colorDialog() const { return mDialog; }

signals:
    /// Ink `index` has a new colour; `dragging` while the dialog is still open.
    void colorChanged(int index, marbler::Color color, bool dragging);
    /// The background has a new colour; `dragging` while the dialog is still open.
    void backgroundChanged(marbler::Color color, bool dragging);
    /// The user added an ink of this colour to the end of the palette.
    void inkAdded(marbler::Color color);
    /// The bleed (soft ink edges, design units) changed.
    void bleedChanged(double bleed, bool dragging);
    /// The user chose another current ink.
    void currentInkChanged(int index);

private:
    QToolButton* swatch(const Color& color, const QString& tip);
    Genome mDesign;
    int mCurrent = 0;
    QHBoxLayout* mSwatches;
    QButtonGroup* mGroup;
    std::vector<QToolButton*> mButtons;
    QToolButton* mBackground = nullptr;
    QDoubleSpinBox* mBleed;
    QColorDialog* mDialog = nullptr;
    bool mUpdating = false;
};

} // namespace marbler::ui

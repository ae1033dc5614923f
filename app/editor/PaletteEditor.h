#pragma once
/// The editor's palette: a swatch per ink, the background and the bleed. Click a swatch to make
/// it the current ink (what the tools lay); double-click it (or use its menu) to change its
/// colour in a colour dialog, which shows each colour live while choosing; its menu (or the −
/// button, for the current ink) deletes it, asking first when steps lay it. Presets replace the
/// inks and the bath with a named palette. Knows no document: it emits the changes the user asks
/// for.

#include "marbler/Genome.h"

#include <QString>
#include <QWidget>

#include <vector>

class QButtonGroup;
class QColorDialog;
class QDoubleSpinBox;
class QHBoxLayout;
class QMessageBox;
class QToolButton;

namespace marbler::ui {

/// A named palette: its inks and its bath colour.
struct PalettePreset {
    QString name;
    std::vector<Color> inks;
    Color background;
};
/// The presets of the palette's Presets menu.
const std::vector<PalettePreset>& palettePresets();
/// `design` with the preset's inks in place of its first ones and its bath colour; inks beyond
/// the preset's are kept, so every step still lays an ink of the palette.
Genome withPalettePreset(Genome design, const PalettePreset& preset);
/// The ink of `palette` nearest in colour to ink `index` (another one; -1 when there is none).
int nearestOtherInk(const std::vector<Color>& palette, int index);

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
    /// Deletes ink `index`: at once when no step lays it; otherwise asks (removeQuestion()) to
    /// lay those steps with the nearest other ink instead, or says why it cannot (the only ink).
    void removeInk(int index);
    /// The open question or message of removeInk, if any (for tests).
    QMessageBox* removeQuestion() const { return mQuestion; }

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
    /// The user deleted ink `index`; steps that lay it lay `replacement` instead (-1: none did).
    void inkRemoved(int index, int replacement);
    /// The user chose the preset palettePresets()[index].
    void presetChosen(int index);

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
    QMessageBox* mQuestion = nullptr;
    bool mUpdating = false;
};

} // namespace marbler::ui

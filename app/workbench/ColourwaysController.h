#pragma once
/// The workbench's Colourways mode (Breed ▸ Colourways) and Breed ▸ Export colourway sheet…: while
/// the mode is on, the grid breeds only palettes of one structure (marbler/Colourways.h), and the
/// sheet writes the grid's designs as one image (marbler/Sheet.h) on a BackgroundJob. Owns its two
/// actions and the sheet's state; the window asks it before breeding and when its actions change.

#include "marbler/Operators.h"
#include "marbler/Sheet.h"

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;

namespace marbler::ui {

class PopulationModel;

/// Draws a sheet's label texts (sheetTexts, Sheet.h) into its pixels with the window's font.
void drawSheetTexts(Image& sheet, const std::vector<SheetText>& texts);

class ColourwaysController : public QObject {
    Q_OBJECT
public:
    /// `window` shows the messages and the progress box; `operatorAction` gives the window's
    /// operator actions, whose states and tooltips the mode sets; `noteSavedFile` tells where a
    /// sheet went.
    ColourwaysController(QMainWindow* window, PopulationModel* model,
                         std::function<QAction*(GeneticOperator)> operatorAction,
                         std::function<void(const QString&)> noteSavedFile);

    /// Adds Colourways and Export colourway sheet… to the Breed menu, Colourways to the tool bar.
    void buildActions(QMenu* breedMenu, QToolBar* bar);
    QAction* modeAction() const { return mMode; }
    QAction* exportSheetAction() const { return mExportSheet; }
    /// Breed ▸ Colourway sheet with ink chips: each design's inks and their hex values under its
    /// name on the sheet (remembered).
    QAction* sheetChipsAction() const { return mSheetChips; }

    bool isOn() const;
    void setOn(bool on);
    /// In Colourways mode: the operators' states and tooltips for palette-only breeding; the
    /// sheet's action in any mode.
    void updateActions();
    /// Breeds palettes with an operator (Alter at `strength`); errors are reported.
    bool applyOperator(GeneticOperator op, double strength);

    /// See WorkbenchWindow::exportColourwaySheet.
    bool exportSheet(const QString& file = {});
    bool sheetRunning() const { return mSheetRunning; }
    void setSheetCellWidth(int width) { mSheetCellWidth = width; }

signals:
    /// The mode was switched or a sheet started or ended: the window's actions need updating.
    void actionsChanged();

private:
    void onToggled(bool on);

    QMainWindow* mWindow;
    PopulationModel* mModel;
    std::function<QAction*(GeneticOperator)> mOperatorAction;
    std::function<void(const QString&)> mNoteSavedFile;
    QAction* mMode = nullptr;
    QAction* mExportSheet = nullptr;
    QAction* mSheetChips = nullptr;
    int mSheetCellWidth = 600;
    bool mSheetRunning = false;
};

} // namespace marbler::ui

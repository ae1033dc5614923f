#pragma once
/// The workbench's four genetic operators as actions (Breed menu, tool bar, Ctrl+1..4) and the
/// Strength slider beside them. Owns the actions, the slider and the click that waits for the
/// renders: while the generation bred last is still rendering, a click waits for its renders (a
/// later click replacing it, going to another generation dropping it), so fast clicks make one
/// generation each time the grid has caught up, not one per click.

#include "marbler/Operators.h"

#include <QObject>

#include <functional>
#include <optional>

class QAction;
class QLabel;
class QMainWindow;
class QMenu;
class QSlider;
class QToolBar;

namespace marbler::ui {

class PopulationModel;

class OperatorActions : public QObject {
    Q_OBJECT
public:
    /// Adds the operators to `breedMenu`. `apply` breeds at once (false when it did not), and
    /// `renderingDone` says whether every cell shows its final image.
    OperatorActions(QMainWindow* window, QMenu* breedMenu, std::function<bool(GeneticOperator)> apply,
                    std::function<bool()> renderingDone);

    QAction* action(GeneticOperator op) const;
    /// Puts the operators on `bar`.
    void addToToolBar(QToolBar* bar);
    /// Puts the Strength slider and its label on `bar`.
    void addStrength(QToolBar* bar);
    QSlider* strengthSlider() const { return mStrength; }
    /// The alteration strength the slider gives, 0..1.
    double strength() const;
    void setStrength(double strength);

    /// What a click on an operator does (WorkbenchWindow::requestOperator).
    void request(GeneticOperator op);
    /// The click waiting for the renders, now that they are done.
    void onRenderingFinished();
    /// Another generation is shown: a click still waiting was meant for the one before, unless
    /// it is the one breeding now.
    void onPopulationChanged();
    /// Each operator enabled when the model can breed with it, its tooltip saying why not.
    void update(const PopulationModel& model);

    /// Adds the steering actions to `breedMenu` (issue 26, Steer.h): "Steer by my picks"
    /// (checkable, remembered in the settings as breed/steer, off by default: it does not yet beat
    /// plain breeding, docs/breeding.md; sets the model's steering) and "Less like this" (Ctrl+Shift+X: the
    /// selected designs are marked, or unmarked when all of them already are, and let go as parents).
    void addSteering(QMenu* breedMenu, PopulationModel* model);
    QAction* steerAction() const { return mSteer; }
    QAction* lessLikeAction() const { return mLessLike; }

private:
    QMainWindow* mWindow;
    std::function<bool(GeneticOperator)> mApply;
    std::function<bool()> mRenderingDone;
    QAction* mAlter = nullptr;
    QAction* mRecombine = nullptr;
    QAction* mSwap = nullptr;
    QAction* mReinit = nullptr;
    QSlider* mStrength = nullptr;
    QAction* mSteer = nullptr;
    QAction* mLessLike = nullptr;
    QLabel* mStrengthLabel = nullptr;
    /// A generation bred here is still rendering; the click waiting for it.
    bool mBredRendering = false;
    bool mBreedingNow = false;
    std::optional<GeneticOperator> mPendingOperator;
};

} // namespace marbler::ui

#include "workbench/OperatorActions.h"

#include "workbench/PopulationModel.h"

#include <QAction>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <algorithm>
#include <cmath>
#include <utility>

namespace marbler::ui {

OperatorActions::OperatorActions(QMainWindow* window, QMenu* breedMenu,
                                 std::function<bool(GeneticOperator)> apply,
                                 std::function<bool()> renderingDone)
    : QObject(window)
    , mWindow(window)
    , mApply(std::move(apply))
    , mRenderingDone(std::move(renderingDone)) {
    const auto makeOperator = [&](GeneticOperator op, const QString& text, const QString& tip,
                                  QKeySequence key) {
        QAction* action = breedMenu->addAction(text, this, [this, op] { request(op); });
        action->setShortcut(key);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
        // The tooltip when the operator can run; update() says why when it cannot.
        action->setProperty("readyTip", action->toolTip());
        action->setStatusTip(tip);
        return action;
    };
    mAlter = makeOperator(GeneticOperator::Alter, tr("Alter (1 parent)"),
                          tr("Offspring with the parent's strokes perturbed; the slider sets how much"),
                          QKeySequence(Qt::CTRL | Qt::Key_1));
    mRecombine = makeOperator(GeneticOperator::Recombine, tr("Recombine (2+ parents)"),
                              tr("Offspring that take strokes from each of the parents"),
                              QKeySequence(Qt::CTRL | Qt::Key_2));
    mSwap = makeOperator(GeneticOperator::Swap, tr("Swap (2 parents)"),
                         tr("One parent's initial drops with the other's strokes, both ways"),
                         QKeySequence(Qt::CTRL | Qt::Key_3));
    mReinit = makeOperator(GeneticOperator::Reinit, tr("Change initial state (1 parent)"),
                           tr("Offspring with new initial drops under the same strokes"),
                           QKeySequence(Qt::CTRL | Qt::Key_4));
}

QAction* OperatorActions::action(GeneticOperator op) const {
    switch (op) {
    case GeneticOperator::Alter:
        return mAlter;
    case GeneticOperator::Recombine:
        return mRecombine;
    case GeneticOperator::Swap:
        return mSwap;
    case GeneticOperator::Reinit:
        return mReinit;
    }
    return nullptr;
}

void OperatorActions::addToToolBar(QToolBar* bar) {
    for (QAction* a : {mAlter, mRecombine, mSwap, mReinit})
        bar->addAction(a);
}

void OperatorActions::addStrength(QToolBar* bar) {
    mStrength = new QSlider(Qt::Horizontal, bar);
    mStrength->setObjectName(QStringLiteral("strengthSlider"));
    mStrength->setRange(0, 100);
    mStrength->setMaximumWidth(120);
    mStrength->setToolTip(tr("How far %1 moves the strokes: 0 % barely, 100 % a lot")
                              .arg(operatorLabel(GeneticOperator::Alter)));
    // The value is always in sight, not only while the slider is dragged.
    mStrengthLabel = new QLabel(bar);
    mStrengthLabel->setObjectName(QStringLiteral("strengthLabel"));
    mStrengthLabel->setToolTip(mStrength->toolTip());
    // Wide enough for "Strength 100 %", so the toolbar does not shift as the value changes.
    mStrengthLabel->setMinimumWidth(
        mStrengthLabel->fontMetrics().horizontalAdvance(tr(" Strength %1 % ").arg(100)));
    mStrengthLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    mStrengthLabel->setBuddy(mStrength);
    connect(mStrength, &QSlider::valueChanged, this,
            [this](int value) { mStrengthLabel->setText(tr(" Strength %1 % ").arg(value)); });
    mStrength->setValue(50);
    mStrengthLabel->setText(tr(" Strength %1 % ").arg(mStrength->value()));
    bar->addWidget(mStrengthLabel);
    bar->addWidget(mStrength);
}

double OperatorActions::strength() const {
    return mStrength->value() / 100.0;
}

void OperatorActions::setStrength(double strength) {
    mStrength->setValue(int(std::lround(strength * 100.0)));
}

void OperatorActions::request(GeneticOperator op) {
    if (mBreedingNow) {
        // A generation is being bred (off the GUI thread, the window waiting): this one follows.
        mPendingOperator = op;
        return;
    }
    if (mBredRendering) {
        // Breeding is quick, its nine renders are not: clicks made meanwhile would queue
        // generations that keep arriving for seconds. The last click waits for the renders.
        mPendingOperator = op;
        mWindow->statusBar()->showMessage(
            tr("%1 follows when this generation has rendered").arg(operatorLabel(op)), 5000);
        return;
    }
    mBreedingNow = true;
    const bool bred = mApply(op);
    mBreedingNow = false;
    mBredRendering = bred && !mRenderingDone();
    if (mPendingOperator && !mBredRendering)
        QTimer::singleShot(0, this,
                           [this, op = *std::exchange(mPendingOperator, std::nullopt)] { request(op); });
}

void OperatorActions::onRenderingFinished() {
    mBredRendering = false;
    if (!mPendingOperator) return;
    const GeneticOperator op = *mPendingOperator;
    mPendingOperator.reset();
    // Not inside the render result's handler, which is still updating the cells.
    QTimer::singleShot(0, this, [this, op] { request(op); });
}

void OperatorActions::onPopulationChanged() {
    if (!mBreedingNow) mPendingOperator.reset();
}

void OperatorActions::addSteering(QMenu* breedMenu, PopulationModel* model) {
    mSteer = breedMenu->addAction(tr("&Steer by my picks"));
    mSteer->setObjectName(QStringLiteral("steerAction"));
    mSteer->setCheckable(true);
    mSteer->setChecked(QSettings().value(QStringLiteral("breed/steer"), true).toBool());
    mSteer->setStatusTip(tr("Offspring are drawn from many candidates and ranked by what your picks so far "
                            "say; the status line tells why"));
    mSteer->setToolTip(mSteer->statusTip());
    model->setSteering(mSteer->isChecked());
    connect(mSteer, &QAction::toggled, this, [model](bool on) {
        model->setSteering(on);
        QSettings().setValue(QStringLiteral("breed/steer"), on);
    });

    mLessLike = breedMenu->addAction(tr("&Less like this"));
    mLessLike->setObjectName(QStringLiteral("lessLikeAction"));
    mLessLike->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_X));
    mLessLike->setStatusTip(tr("Marks the selected designs as unlike what you have in mind: steering moves "
                               "away from them"));
    mLessLike->setToolTip(QStringLiteral("%1 (%2)").arg(
        mLessLike->statusTip(), mLessLike->shortcut().toString(QKeySequence::NativeText)));
    connect(mLessLike, &QAction::triggered, this, [this, model] {
        const std::vector<int> cells = model->selectedCells();
        if (cells.empty()) {
            mWindow->statusBar()->showMessage(tr("Less like this: click the designs you do not want first"),
                                              5000);
            return;
        }
        const bool all = std::all_of(cells.begin(), cells.end(), [&](int i) { return model->isDisliked(i); });
        for (int i : cells)
            model->setDisliked(i, !all);
        mWindow->statusBar()->showMessage(
            all ? tr("%n design(s) no longer marked less like this", nullptr, int(cells.size()))
                : tr("%n design(s) marked less like this: the next generation moves away from them", nullptr,
                     int(cells.size())),
            5000);
    });
}

void OperatorActions::update(const PopulationModel& model) {
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit}) {
        // A greyed-out operator says what it needs, so it is never disabled without a reason.
        QAction* a = action(op);
        const QString why = model.whyNot(op);
        a->setEnabled(why.isEmpty());
        a->setToolTip(why.isEmpty() ? a->property("readyTip").toString() : why);
    }
}

} // namespace marbler::ui

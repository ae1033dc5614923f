// The editor's timeline (Timeline.h).

#include "editor/Timeline.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace marbler::ui {
namespace {

/// Slider positions a step: smooth scrubbing through a step's growth.
constexpr int PerStep = 100;
constexpr double SecondsPerStep = 0.6;
constexpr double LongestPlay = 12.0;
/// The Speed box's factors of the normal pace.
constexpr double Speeds[] = {0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0};

/// A step count, whole or to a tenth, as the window's locale writes it (issue 25), without group
/// separators ("2000", "2,5" in German).
QString timelineNumber(double value) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'f', std::floor(value) == value ? 0 : 1);
}

} // namespace

Timeline::Timeline(QWidget* parent)
    : QWidget(parent)
    , mSlider(new QSlider(Qt::Horizontal, this))
    , mCompareSlider(new QSlider(Qt::Horizontal, this))
    , mPlay(new QToolButton(this))
    , mCompareBox(new QCheckBox(tr("&Compare"), this))
    , mSpeed(new QComboBox(this))
    , mLabel(new QLabel(this))
    , mTimer(new QTimer(this))
    , mClock(new QElapsedTimer) {
    setObjectName(QStringLiteral("timeline"));
    mSlider->setObjectName(QStringLiteral("timelineSlider"));
    mSlider->setToolTip(tr("The making of the design: drag to see it after any step, part way through a step "
                           "(0: the bare bath; the right end: the whole design)"));
    mCompareSlider->setObjectName(QStringLiteral("compareSlider"));
    mCompareSlider->setToolTip(tr("The second state compared side by side with the first"));
    mCompareSlider->setVisible(false);
    mPlay->setObjectName(QStringLiteral("playButton"));
    mPlay->setText(tr("Play"));
    mPlay->setCheckable(true);
    mPlay->setToolTip(tr("Play the making of the design, each step growing in; again to stop"));
    mCompareBox->setObjectName(QStringLiteral("compareBox"));
    mCompareBox->setToolTip(
        tr("Compare two states of the making side by side: the second slider picks the other"));
    mSpeed->setObjectName(QStringLiteral("playSpeed"));
    for (double f : Speeds)
        mSpeed->addItem(tr("%1×").arg(QLocale().toString(f)), f);
    mSpeed->setCurrentIndex(mSpeed->findData(1.0));
    mSpeed->setToolTip(
        tr("Play speed: 1× plays the whole making in at most 12 s (0.6 s a step); faster for a "
           "quick look, slower to watch each step ([ and ])"));
    auto* exportButton = new QToolButton(this);
    exportButton->setObjectName(QStringLiteral("exportAnimationButton"));
    exportButton->setText(tr("Export animation…"));
    exportButton->setToolTip(
        tr("Write the making of the design as a video, an animated image or PNG frames"));
    mLabel->setObjectName(QStringLiteral("timelineLabel"));
    mLabel->setToolTip(tr("The step shown, of all the design's steps"));

    auto* layout = new QHBoxLayout(this);
    layout->addWidget(mPlay);
    layout->addWidget(mSpeed);
    auto* sliders = new QVBoxLayout;
    sliders->addWidget(mSlider);
    sliders->addWidget(mCompareSlider);
    layout->addLayout(sliders, 1);
    layout->addWidget(mLabel);
    layout->addWidget(mCompareBox);
    layout->addWidget(exportButton);

    mTimer->setInterval(30);
    connect(mTimer, &QTimer::timeout, this, &Timeline::tick);
    connect(mPlay, &QToolButton::clicked, this, [this](bool on) { on ? play() : stop(); });
    connect(exportButton, &QToolButton::clicked, this, &Timeline::exportAnimationRequested);
    connect(mSlider, &QSlider::valueChanged, this, [this](int v) {
        if (mUpdating) return;
        stop();
        setGrowth(double(v) / PerStep);
    });
    connect(mCompareBox, &QCheckBox::toggled, this, [this](bool on) {
        if (!mUpdating) setComparing(on);
    });
    connect(mCompareSlider, &QSlider::valueChanged, this, [this](int v) {
        if (!mUpdating) setCompareGrowth(double(v) / PerStep);
    });
    // [ and ] step the speed anywhere in the window (the widget's actions, window-wide keys).
    auto* slower = new QAction(tr("Play slower"), this);
    slower->setObjectName(QStringLiteral("playSlower"));
    slower->setShortcut(QKeySequence(Qt::Key_BracketLeft));
    slower->setShortcutContext(Qt::WindowShortcut);
    connect(slower, &QAction::triggered, this,
            [this] { mSpeed->setCurrentIndex(std::max(0, mSpeed->currentIndex() - 1)); });
    auto* faster = new QAction(tr("Play faster"), this);
    faster->setObjectName(QStringLiteral("playFaster"));
    faster->setShortcut(QKeySequence(Qt::Key_BracketRight));
    faster->setShortcutContext(Qt::WindowShortcut);
    connect(faster, &QAction::triggered, this,
            [this] { mSpeed->setCurrentIndex(std::min(mSpeed->count() - 1, mSpeed->currentIndex() + 1)); });
    addAction(slower);
    addAction(faster);
    connect(mSpeed, &QComboBox::currentIndexChanged, this, [this] {
        // Keep the growth shown and go on from it at the new pace.
        if (!playing()) return;
        mPlayFrom = mGrowth;
        mRate = double(mSteps) / playSeconds();
        mClock->start();
    });
    setStepCount(0);
}

Timeline::~Timeline() {
    delete mClock;
}

void Timeline::setStepCount(std::size_t n) {
    const bool wasAtEnd = atEnd();
    mSteps = n;
    mUpdating = true;
    mSlider->setRange(0, int(n) * PerStep);
    mCompareSlider->setRange(0, int(n) * PerStep);
    mUpdating = false;
    const double before = mGrowth;
    mGrowth = wasAtEnd ? double(n) : std::clamp(mGrowth, 0.0, double(n));
    mCompare = std::clamp(mCompare, 0.0, double(n));
    showGrowth();
    if (mGrowth != before) emit growthChanged(mGrowth);
}

void Timeline::setGrowth(double g) {
    if (!std::isfinite(g)) return;
    g = std::clamp(g, 0.0, double(mSteps));
    if (g == mGrowth) return;
    mGrowth = g;
    showGrowth();
    emit growthChanged(mGrowth);
}

void Timeline::showGrowth() {
    mUpdating = true;
    mSlider->setValue(int(std::lround(mGrowth * PerStep)));
    mCompareSlider->setValue(int(std::lround(mCompare * PerStep)));
    mUpdating = false;
    mLabel->setText(tr("%1 / %2").arg(timelineNumber(mGrowth)).arg(mSteps));
    const bool on = comparing();
    emit captionsChanged(on ? caption(mGrowth) : QString(), on ? caption(mCompare) : QString());
}

void Timeline::play() {
    if (mSteps == 0) return;
    if (atEnd()) setGrowth(0.0);
    mPlayFrom = mGrowth;
    mRate = double(mSteps) / playSeconds();
    mClock->start();
    mPlay->setChecked(true);
    mPlay->setText(tr("Stop"));
    mTimer->start();
}

void Timeline::stop() {
    mTimer->stop();
    mPlay->setChecked(false);
    mPlay->setText(tr("Play"));
}

bool Timeline::playing() const {
    return mTimer->isActive();
}

void Timeline::setPlaySpeed(double factor) {
    if (!std::isfinite(factor) || factor <= 0.0) return;
    int best = 0;
    for (int i = 0; i < mSpeed->count(); ++i)
        if (std::abs(std::log(mSpeed->itemData(i).toDouble() / factor)) <
            std::abs(std::log(mSpeed->itemData(best).toDouble() / factor)))
            best = i;
    mSpeed->setCurrentIndex(best);
}

double Timeline::playSpeed() const {
    return mSpeed->currentData().toDouble();
}

double Timeline::playSeconds() const {
    return std::min(SecondsPerStep * double(std::max<std::size_t>(mSteps, 1)), LongestPlay) / playSpeed();
}

QString Timeline::caption(double g) const {
    if (g >= double(mSteps)) return tr("Now");
    if (g <= 0.0) return tr("Bare bath");
    return tr("Step %1 of %2").arg(timelineNumber(g)).arg(mSteps);
}

void Timeline::tick() {
    const double g = mPlayFrom + mRate * double(mClock->elapsed()) / 1000.0;
    if (g >= double(mSteps)) {
        stop();
        setGrowth(double(mSteps));
        return;
    }
    setGrowth(g);
}

bool Timeline::comparing() const {
    return mCompareBox->isChecked();
}

void Timeline::setComparing(bool on) {
    mUpdating = true;
    mCompareBox->setChecked(on);
    mUpdating = false;
    mCompareSlider->setVisible(on);
    showGrowth();
    emit compareChanged(on, mCompare);
}

void Timeline::setCompareGrowth(double g) {
    if (!std::isfinite(g)) return;
    mCompare = std::clamp(g, 0.0, double(mSteps));
    showGrowth();
    if (comparing()) emit compareChanged(true, mCompare);
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_Timeline.cpp"

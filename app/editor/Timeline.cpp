// The editor's timeline (Timeline.h).

#include "editor/Timeline.h"

#include <QCheckBox>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
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

} // namespace

Timeline::Timeline(QWidget* parent)
    : QWidget(parent), mSlider(new QSlider(Qt::Horizontal, this)), mCompareSlider(new QSlider(Qt::Horizontal, this)),
      mPlay(new QToolButton(this)), mCompareBox(new QCheckBox(tr("&Compare"), this)), mLabel(new QLabel(this)),
      mTimer(new QTimer(this)), mClock(new QElapsedTimer) {
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
    mCompareBox->setToolTip(tr("Compare two states of the making side by side: the second slider picks the other"));
    auto* exportButton = new QToolButton(this);
    exportButton->setObjectName(QStringLiteral("exportAnimationButton"));
    exportButton->setText(tr("Export animation…"));
    exportButton->setToolTip(tr("Write the making of the design as a video, an animated image or PNG frames"));
    mLabel->setObjectName(QStringLiteral("timelineLabel"));
    mLabel->setToolTip(tr("The step shown, of all the design's steps"));

    auto* layout = new QHBoxLayout(this);
    layout->addWidget(mPlay);
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
    setStepCount(0);
}

Timeline::~Timeline() { delete mClock; }

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
    mLabel->setText(tr("%1 / %2").arg(QString::number(mGrowth, 'f', std::floor(mGrowth) == mGrowth ? 0 : 1)).arg(mSteps));
}

void Timeline::play() {
    if (mSteps == 0) return;
    if (atEnd()) setGrowth(0.0);
    mPlayFrom = mGrowth;
    mRate = double(mSteps) / std::min(SecondsPerStep * double(mSteps), LongestPlay);
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

bool Timeline::playing() const { return mTimer->isActive(); }

void Timeline::tick() {
    const double g = mPlayFrom + mRate * double(mClock->elapsed()) / 1000.0;
    if (g >= double(mSteps)) {
        stop();
        setGrowth(double(mSteps));
        return;
    }
    setGrowth(g);
}

bool Timeline::comparing() const { return mCompareBox->isChecked(); }

void Timeline::setComparing(bool on) {
    mUpdating = true;
    mCompareBox->setChecked(on);
    mUpdating = false;
    mCompareSlider->setVisible(on);
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

#pragma once
/// The editor's timeline: the making of the design (Growth.h) on a slider from 0 (the bare bath)
/// to n (every step), Play that grows the steps one after another, a compare mode with a second
/// marker (two states side by side), and Export animation.

#include <QString>
#include <QWidget>

#include <cstddef>

class QCheckBox;
class QComboBox;
class QElapsedTimer;
class QLabel;
class QSlider;
class QTimer;
class QToolButton;

namespace marbler::ui {

/// The timeline (see the file comment).
class Timeline : public QWidget {
    Q_OBJECT
public:
    explicit Timeline(QWidget* parent = nullptr);
    ~Timeline() override;

    /// The design has `n` steps: the slider spans 0..n. At the end before, at the end after.
    void setStepCount(std::size_t n);
    /// The design's steps (the slider's right end).
    std::size_t stepCount() const { return mSteps; }
    /// What is shown: 0..n, fractional while playing or scrubbing.
    double growth() const { return mGrowth; }
    /// Whether the whole design is shown.
    bool atEnd() const { return mGrowth >= double(mSteps); }
    /// Grows the steps smoothly from the current point (from 0 when at the end) to n, about 0.6 s a
    /// step and at most about 12 s in all at 1×, divided by the play speed, then stops.
    void play();
    /// The play speed, a factor of the normal pace (the Speed box: 0.25× to 16×). Takes effect at
    /// once, also while playing. Values outside the box's choices take its nearest.
    void setPlaySpeed(double factor);
    double playSpeed() const;
    /// Seconds a play of the whole making takes at the current speed.
    double playSeconds() const;
    /// What a compare pane showing growth `g` says: "Now" for the whole design, "Bare bath" for
    /// none of it, else "Step 12 of 40" (with a tenth while part way through a step).
    QString caption(double g) const;
    /// Stops playing where it is.
    void stop();
    /// Whether Play is running.
    bool playing() const;
    /// Shows growth `g` (clamped to 0..n); emits growthChanged when it changes.
    void setGrowth(double g);
    /// Whether two states are compared side by side (the second marker is shown).
    bool comparing() const;
    /// The growth the second marker shows.
    double compareGrowth() const { return mCompare; }
    /// Turns compare mode on or off.
    void setComparing(bool on);
    /// Moves the second marker.
    void setCompareGrowth(double g);

signals:
    /// The growth shown changed (scrubbing, playing).
    void growthChanged(double g);
    /// Compare mode changed, or its second marker moved.
    void compareChanged(bool on, double otherGrowth);
    /// The user asked to export the making of the design as an animation.
    void exportAnimationRequested();
    /// The captions of the two compare panes (the main one, the second marker's); both empty
    /// when not comparing. Emitted whenever either may have changed.
    void captionsChanged(const QString& shown, const QString& other);

private:
    void tick();
    void showGrowth();
    std::size_t mSteps = 0;
    double mGrowth = 0.0, mCompare = 0.0;
    double mPlayFrom = 0.0, mRate = 1.0; // growth at the start of play, steps a second
    QSlider* mSlider;
    QSlider* mCompareSlider;
    QToolButton* mPlay;
    QCheckBox* mCompareBox;
    QComboBox* mSpeed;
    QLabel* mLabel;
    QTimer* mTimer;
    QElapsedTimer* mClock;
    bool mUpdating = false;
};

} // namespace marbler::ui

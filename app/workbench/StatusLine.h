#pragma once
/// The workbench's status bar widgets: on the left, under passing messages, the generation and
/// its parents; on the right the last file saved ("Show in folder") and what the window is doing
/// ("Rendering 5 of 9…", "Ready"). Owns the three widgets and the count of the renders under way.

#include <QObject>
#include <QString>

class QLabel;
class QMainWindow;

namespace marbler::ui {

class SavedFileNotice;

class StatusLine : public QObject {
    Q_OBJECT
public:
    /// Adds the widgets to `window`'s status bar.
    explicit StatusLine(QMainWindow* window);

    /// The generation's summary (object name "generationLabel").
    void setGeneration(const QString& text);
    /// `pending` cells still rendering: "Ready" at none, else how far the batch under way is (a
    /// batch counts every cell asked for since the window was last idle).
    void setPending(int pending);
    SavedFileNotice* savedNotice() const { return mSavedNotice; }

private:
    QLabel* mGeneration = nullptr;
    SavedFileNotice* mSavedNotice = nullptr;
    QLabel* mTask = nullptr;
    int mRenderBatch = 0; ///< cells in the renders under way, for "Rendering 5 of 9…"
};

} // namespace marbler::ui

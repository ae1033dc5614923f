#pragma once
/// The editor's exports: File ▸ Export image… (the large view, DesignDialog, opened on the
/// design) and Export animation… (the making of the design, an AnimationExportJob on a
/// BackgroundJob). The editor window (EditorWindow.h) owns one.

#include "marbler/Sampling.h"

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace marbler::ui {

class AnimationExportJob;
class EditorDocument;
class EditorFiles;
class RenderService;
class SolidObjectView;

class EditorExports : public QObject {
    Q_OBJECT
public:
    /// Exports `document` from `window`; `files` asks before a file is replaced, `slice` is the
    /// cross-section of a solid and `object` (null for a flat design) the object it is shown on.
    EditorExports(EditorDocument* document, RenderService* renderer, EditorFiles* files, QWidget* window,
                  std::function<Slice()> slice, SolidObjectView* object);

    /// File ▸ Export image…: the large view on the design, exporting at print size, in vector
    /// form and on objects.
    void exportImage();
    /// File ▸ Export animation…: asks what to write (and before replacing a file), then writes
    /// it in the background with progress ("animationProgress") and cancel.
    void exportAnimation();

signals:
    /// A line for the window's status bar, shown for `ms` milliseconds.
    void message(const QString& text, int ms);
    /// A file was written.
    void fileSaved(const QString& file);

private:
    EditorDocument* mDocument;
    RenderService* mRenderer;
    EditorFiles* mFiles;
    QWidget* mWindow;
    std::function<Slice()> mSlice;
    SolidObjectView* mObject;
    AnimationExportJob* mAnimationJob = nullptr; ///< Export animation's writer, made on first use
    QString mWrittenPath;                        ///< what the animation being written is saved as
};

} // namespace marbler::ui

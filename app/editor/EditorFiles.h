#pragma once
/// The editor's files: Open, Open recent and the new designs that open in another editor, Save,
/// Save as, the questions a save asks (unsaved changes, a design opened from an image, a file
/// changed on disk, a file to replace), Reload and the design written into an image (a
/// BackgroundJob). The editor window (EditorWindow.h) owns one and wires its menus to it.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

class QMenu;
class QWidget;

namespace marbler::ui {

class BackgroundJob;
class EditorDocument;

/// A file named by its real path, so that two names of one file compare equal.
QString canonicalFile(const QString& file);

class EditorFiles : public QObject {
    Q_OBJECT
public:
    /// Saves `document`, asking its questions over `window`; `slice` is the cross-section a
    /// solid is written into an image at.
    EditorFiles(EditorDocument* document, QWidget* window, std::function<Slice()> slice);

    /// Saves to the document's file, asking for one when it has none; errors are reported.
    bool save();
    /// Asks for a file (the design's name in the folder used last; askSaveFile, which tests
    /// replace) and saves there.
    bool saveAs();
    /// Saves to `file` atomically; errors are reported. Returns success.
    bool saveTo(const QString& file);
    /// Reads the document's file again (an undoable replacement of the design, clean after it).
    bool reloadFromDisk();
    /// Renders the design into `image` (PNG or TIFF) at that image's pixel size, with the design
    /// inside, in the background with progress ("imageProgress") and cancel; the image becomes
    /// the document's file. Returns whether the render started.
    bool writeDesignImage(const QString& image);
    /// Whether `file` may be written: it does not exist, or the user lets it be replaced.
    bool mayOverwrite(const QString& file);
    /// Whether the window may close or its design be left: asks about unsaved changes.
    bool maybeKeepChanges();
    /// The design's name as the title shows it: its file's name, else its own name.
    QString displayName() const;

    /// File ▸ Open…, Open recent (filled as it is shown), New design ▸ Random design and From a
    /// picture…: each asks the workbench for another editor.
    void openFileDialog();
    void fillRecentMenu(QMenu* menu);
    void startFromRandom();
    void startFromSourceImage();

    /// What closing with unsaved changes does when the question cannot be asked (tests):
    /// unset asks the user.
    enum class UnsavedAnswer { Save, Discard, Cancel };
    void setUnsavedAnswer(std::optional<UnsavedAnswer> answer) { mUnsavedAnswer = answer; }
    /// Save on a design opened from an image: a new design file (the default), the image written
    /// again with the design inside, or nothing. Unset asks the user.
    enum class ImageSaveAnswer { DesignFile, UpdateImage, Cancel };
    void setImageSaveAnswer(std::optional<ImageSaveAnswer> answer) { mImageSaveAnswer = answer; }
    /// Save on a file that someone else changed since it was opened or saved here. Unset asks.
    enum class DiskChangeAnswer { Overwrite, Reload, SaveAs, Cancel };
    void setDiskChangeAnswer(std::optional<DiskChangeAnswer> answer) { mDiskChangeAnswer = answer; }
    /// Whether an existing file may be replaced (unset asks the user).
    void setOverwriteAnswer(std::optional<bool> answer) { mOverwriteAnswer = answer; }

    /// The files opened or saved in the editor, newest first (QSettings editor/recentFiles).
    static QStringList recentFiles();
    static void addRecentFile(const QString& file);

signals:
    /// A line for the window's status bar, shown for `ms` milliseconds.
    void message(const QString& text, int ms);
    /// A file was written.
    void fileSaved(const QString& file);
    /// Another design to open in an editor of its own (`file` empty: not saved yet).
    void openEditorRequested(const marbler::Genome& design, const QString& file);
    /// The design was read again from its file (the selection no longer applies).
    void reloaded();

private:
    EditorDocument* mDocument;
    QWidget* mWindow;
    std::function<Slice()> mSlice;
    std::optional<UnsavedAnswer> mUnsavedAnswer;
    std::optional<ImageSaveAnswer> mImageSaveAnswer;
    std::optional<DiskChangeAnswer> mDiskChangeAnswer;
    std::optional<bool> mOverwriteAnswer;
    QPointer<BackgroundJob> mImageJob; ///< the design being written into an image, if any
};

} // namespace marbler::ui

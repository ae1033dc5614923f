#pragma once
/// Files the user saves from the window: the names offered (the design's name made safe for any
/// file system, in the folder used last), the question that asks for a name, and the status
/// bar's note of where a file went, with "Show in folder". The question and the opening of the
/// folder can be replaced, so tests run without a file dialog or a file manager.

#include "marbler/Genome.h"

#include <QString>
#include <QTimer>
#include <QUrl>
#include <QWidget>

#include <functional>

class QLabel;
class QToolButton;

namespace marbler::ui {

/// A design name as a file name: characters that some file system refuses (/ \ : * ? " < > |
/// and control characters) dropped, spaces collapsed, no leading or trailing dots or spaces.
/// Empty when nothing is left.
QString safeFileName(const QString& name);
/// The file offered for a design: its name (its short id when it has none) made safe, with the
/// extension (".marble.json", ".png", ...), in `folder` (the current folder when empty).
QString suggestedFile(const Genome& genome, const QString& folder, const QString& extension);

/// Asks for a file to save to (QFileDialog::getSaveFileName by default); empty: cancelled.
using SaveFileAsker = std::function<QString(QWidget* parent, const QString& caption, const QString& suggested,
                                            const QString& filter)>;
/// Installs an asker; an empty one restores the file dialog.
void setSaveFileAsker(SaveFileAsker asker);
QString askSaveFile(QWidget* parent, const QString& caption, const QString& suggested, const QString& filter);

/// Opens a URL with the desktop (QDesktopServices::openUrl by default): "Show in folder".
using UrlOpener = std::function<bool(const QUrl& url)>;
/// Installs an opener; an empty one restores the desktop's.
void setUrlOpener(UrlOpener opener);
bool openUrl(const QUrl& url);

/// The status bar's note of the last file written: its full path and a "Show in folder" button
/// that opens the folder holding it. Hidden until a file is shown; hides itself after a while.
class SavedFileNotice : public QWidget {
    Q_OBJECT
public:
    explicit SavedFileNotice(QWidget* parent = nullptr);

    /// Shows a file just written (an absolute path; a relative one is made absolute).
    void showFile(const QString& file);
    /// The file shown, empty before the first.
    QString file() const { return mFile; }
    /// The folder "Show in folder" opens.
    QString folder() const;
    QToolButton* showInFolderButton() const { return mShowInFolder; }
    QLabel* pathLabel() const { return mPath; }

private:
    QString mFile;
    QLabel* mPath;
    QToolButton* mShowInFolder;
    QTimer mHide;
};

} // namespace marbler::ui

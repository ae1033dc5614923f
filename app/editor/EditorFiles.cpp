// The editor's files (EditorFiles.h).

#include "editor/EditorFiles.h"

#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/RenderToFile.h"
#include "shared/BackgroundJob.h"
#include "shared/ErrorReport.h"
#include "shared/Help.h"
#include "shared/Lineage.h"
#include "shared/RenameDialog.h"
#include "shared/SavedFiles.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QImageReader>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSettings>

#include <cmath>
#include <filesystem>
#include <span>

namespace marbler::ui {

namespace {

const QString RecentKey = QStringLiteral("editor/recentFiles");

constexpr int MaxRecent = 10;

QString designFilter() {
    return EditorFiles::tr("Designs (*.marble.json *.json *.png *.tif *.tiff);;All files (*)");
}

QString nameOf(const Genome& design) {
    const LineageInfo info = lineageOf(design);
    return info.name.isEmpty() ? EditorFiles::tr("Untitled design") : info.name;
}

/// Whether `file` is an image (by its first bytes; by its name when it cannot be read): a design
/// opened from one is saved as a design file, never as JSON under the image's name.
bool isImageFile(const QString& file) {
    QFile f(file);
    if (f.open(QIODevice::ReadOnly)) {
        const QByteArray head = f.read(16);
        return imageKindOf(std::span(reinterpret_cast<const unsigned char*>(head.constData()),
                                     static_cast<std::size_t>(head.size()))) != ImageKind::NotAnImage;
    }
    static const QStringList imageSuffixes{"png", "tif", "tiff", "jpg", "jpeg", "webp", "exr", "gif", "bmp"};
    return imageSuffixes.contains(QFileInfo(file).suffix().toLower());
}

/// `file` with the design file's extension, unless it has a JSON one already.
QString withDesignExtension(const QString& file) {
    return file.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)
               ? file
               : file + QStringLiteral(".marble.json");
}

} // namespace

/// A file named by its real path, so that two names of one file compare equal.
QString canonicalFile(const QString& file) {
    const QFileInfo info(file);
    const QString real = info.canonicalFilePath();
    return real.isEmpty() ? info.absoluteFilePath() : real;
}

EditorFiles::EditorFiles(EditorDocument* document, QWidget* window, std::function<Slice()> slice)
    : QObject(window)
    , mDocument(document)
    , mWindow(window)
    , mSlice(std::move(slice)) {}

QString EditorFiles::displayName() const {
    const QString file = mDocument->fileName();
    if (file.isEmpty()) return nameOf(mDocument->design());
    // A design named other than its file says both: renamed, the title follows.
    const QString name = lineageOf(mDocument->design()).name;
    const QString fileName = QFileInfo(file).fileName();
    if (name.isEmpty() || name == tr("Untitled design") || fileName == name + QStringLiteral(".marble.json"))
        return fileName;
    return tr("%1 (%2)").arg(name, fileName);
}

bool EditorFiles::save() {
    const QString file = mDocument->fileName();
    if (file.isEmpty()) return saveAs();
    if (isImageFile(file)) {
        // A design opened from an image: its genome file is a new file, or the image is written
        // again with the design inside; JSON never goes under the image's name.
        ImageSaveAnswer answer = ImageSaveAnswer::DesignFile;
        if (mImageSaveAnswer) {
            answer = *mImageSaveAnswer;
        } else {
            QMessageBox box(QMessageBox::Question, tr("Save a design opened from an image"),
                            tr("“%1” is an image. Save the design as a design file, or write the image again "
                               "with the design inside?")
                                .arg(QFileInfo(file).fileName()),
                            QMessageBox::Cancel, mWindow);
            QPushButton* asFile = box.addButton(tr("Save as design file…"), QMessageBox::AcceptRole);
            QPushButton* asImage = box.addButton(tr("Update the image"), QMessageBox::DestructiveRole);
            asImage->setToolTip(tr("Render the design into %1 at its size; the picture there is replaced")
                                    .arg(QFileInfo(file).fileName()));
            box.setDefaultButton(asFile);
            box.exec();
            answer = box.clickedButton() == asFile    ? ImageSaveAnswer::DesignFile
                     : box.clickedButton() == asImage ? ImageSaveAnswer::UpdateImage
                                                      : ImageSaveAnswer::Cancel;
        }
        switch (answer) {
        case ImageSaveAnswer::DesignFile:
            return saveAs();
        case ImageSaveAnswer::UpdateImage:
            return writeDesignImage(file);
        case ImageSaveAnswer::Cancel:
            return false;
        }
        return false;
    }
    return saveTo(file);
}

bool EditorFiles::saveAs() {
    const QString folder = QSettings().value(QStringLiteral("files/saveDir")).toString();
    const QString current = mDocument->fileName();
    QString suggested;
    if (current.isEmpty())
        suggested = suggestedFile(mDocument->renderedDesign(), folder, QStringLiteral(".marble.json"));
    else if (isImageFile(current))
        suggested = QFileInfo(current).dir().filePath(QFileInfo(current).completeBaseName() +
                                                      QStringLiteral(".marble.json"));
    else
        suggested = current;
    const QString chosen =
        askSaveFile(mWindow, tr("Save design"), suggested, tr("Marbler designs (*.marble.json)"));
    if (chosen.isEmpty()) return false;
    // A name without the extension gets it (the Open dialog lists designs by it); the file
    // dialog asked about the name typed, so a file of the full name is asked about here.
    const QString file = withDesignExtension(chosen);
    if (file != chosen && !mayOverwrite(file)) return false;
    QSettings().setValue(QStringLiteral("files/saveDir"), QFileInfo(file).absolutePath());
    // A file name the user typed (not the one offered) names the design, one undo step: reopened,
    // it is called what its file is.
    Genome named = mDocument->fileGenome();
    if (QFileInfo(file).fileName() != QFileInfo(suggested).fileName() && adoptFileName(named, file))
        mDocument->replaceDesign(named, tr("Name “%1”").arg(QString::fromStdString(*named.meta.name)));
    return saveTo(file);
}

bool EditorFiles::saveTo(const QString& file) {
    if (!mDocument->fileName().isEmpty() && canonicalFile(file) == canonicalFile(mDocument->fileName()) &&
        mDocument->fileChangedOnDisk()) {
        // Someone else wrote the file since this editor read or wrote it: never overwritten
        // without a word.
        DiskChangeAnswer answer = DiskChangeAnswer::Cancel;
        if (mDiskChangeAnswer) {
            answer = *mDiskChangeAnswer;
        } else {
            QMessageBox box(
                QMessageBox::Warning, tr("The file was changed"),
                tr("“%1” was changed by another program or window since it was opened here. "
                   "Overwrite those changes, reload the file (your changes stay in Undo), or save "
                   "under another name?")
                    .arg(QFileInfo(file).fileName()),
                QMessageBox::Cancel, mWindow);
            QPushButton* overwrite = box.addButton(tr("Overwrite"), QMessageBox::DestructiveRole);
            QPushButton* reload = box.addButton(tr("Reload"), QMessageBox::ResetRole);
            QPushButton* other = box.addButton(tr("Save as…"), QMessageBox::AcceptRole);
            box.setDefaultButton(other);
            box.exec();
            answer = box.clickedButton() == overwrite ? DiskChangeAnswer::Overwrite
                     : box.clickedButton() == reload  ? DiskChangeAnswer::Reload
                     : box.clickedButton() == other   ? DiskChangeAnswer::SaveAs
                                                      : DiskChangeAnswer::Cancel;
        }
        switch (answer) {
        case DiskChangeAnswer::Overwrite:
            break;
        case DiskChangeAnswer::Reload:
            reloadFromDisk();
            return false;
        case DiskChangeAnswer::SaveAs:
            return saveAs();
        case DiskChangeAnswer::Cancel:
            return false;
        }
    }
    QString error;
    if (!mDocument->saveAs(file, &error)) {
        reportError(mWindow, tr("Cannot save the design"), error);
        return false;
    }
    addRecentFile(file);
    emit message(tr("Saved %1").arg(QDir::toNativeSeparators(file)), 5000);
    emit fileSaved(file);
    return true;
}

bool EditorFiles::reloadFromDisk() {
    const QString file = mDocument->fileName();
    if (file.isEmpty()) return false;
    try {
        Genome design = loadDesign(QFile::encodeName(file).toStdString());
        mDocument->replaceDesign(design, tr("Reload %1").arg(QFileInfo(file).fileName()));
        mDocument->markSaved(file);
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot reload the design"), QString::fromStdString(e.what()));
        return false;
    }
    emit reloaded();
    emit message(tr("Reloaded %1; Undo brings your changes back").arg(QFileInfo(file).fileName()), 6000);
    return true;
}

bool EditorFiles::writeDesignImage(const QString& image) {
    if (mImageJob) {
        emit message(tr("The image is being written already"), 4000);
        return false;
    }
    const Genome design = mDocument->renderedDesign();
    RenderSettings settings;
    // The image's own size; where its format has no reader here, the design's.
    const QSize pixels = QImageReader(image).size();
    settings.width = pixels.isValid() ? pixels.width() : int(std::lround(design.size.x));
    settings.height = pixels.isValid() ? pixels.height() : int(std::lround(design.size.y));
    settings.aa = "rgss";
    if (design.dimension == 3) settings.slice = mSlice();
    ExportOptions options;
    // The file's genome, muted steps and all, so that the image opens as it is edited.
    options.genome = serializeGenome(mDocument->fileGenome());
    // The design is saved in the image when it is still the state the render started from.
    const QString stateText = QString::fromStdString(options.genome);
    const std::filesystem::path file(QFile::encodeName(image).toStdString());
    mImageJob = BackgroundJob::start(
        this,
        JobBox(mWindow, tr("Writing %1…").arg(QFileInfo(image).fileName()), QStringLiteral("imageProgress")),
        [design, settings, file, options](const RenderControl& control) {
            renderToFile(design, settings, file, options, &control);
        },
        [this, image, stateText](const JobOutcome& outcome) {
            mImageJob = nullptr;
            if (outcome.done()) {
                if (QString::fromStdString(serializeGenome(mDocument->fileGenome())) == stateText)
                    mDocument->markSaved(image);
                addRecentFile(image);
                emit message(tr("Wrote %1 with the design inside").arg(QDir::toNativeSeparators(image)),
                             5000);
                emit fileSaved(image);
            } else if (outcome.failed()) {
                reportError(mWindow, tr("Cannot write the image"), outcome.error);
            } else {
                emit message(tr("Cancelled; the image is as it was"), 4000);
            }
        });
    return true;
}

bool EditorFiles::mayOverwrite(const QString& file) {
    if (!QFileInfo::exists(file)) return true;
    if (mOverwriteAnswer) return *mOverwriteAnswer;
    return QMessageBox::question(mWindow, tr("Replace the file?"),
                                 tr("“%1” exists already. Replace it?").arg(QFileInfo(file).fileName()),
                                 QMessageBox::Yes | QMessageBox::Cancel,
                                 QMessageBox::Cancel) == QMessageBox::Yes;
}

QStringList EditorFiles::recentFiles() {
    return QSettings().value(RecentKey).toStringList();
}

void EditorFiles::addRecentFile(const QString& file) {
    QStringList files = recentFiles();
    const QString path = QFileInfo(file).absoluteFilePath();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > MaxRecent)
        files.removeLast();
    QSettings().setValue(RecentKey, files);
}

void EditorFiles::fillRecentMenu(QMenu* menu) {
    menu->clear();
    const QStringList files = recentFiles();
    for (const QString& f : files) {
        QAction* a = menu->addAction(labelSafe(QFileInfo(f).fileName()), this, [this, f] {
            try {
                emit openEditorRequested(loadDesign(f.toStdString()), f);
            } catch (const Error& e) {
                reportError(mWindow, tr("Cannot open the design"), QString::fromStdString(e.what()));
            }
        });
        a->setToolTip(QDir::toNativeSeparators(f));
        a->setEnabled(QFileInfo::exists(f));
    }
    if (files.isEmpty()) menu->addAction(tr("No recent designs"))->setEnabled(false);
}

void EditorFiles::openFileDialog() {
    const QString file =
        QFileDialog::getOpenFileName(mWindow, tr("Open a design"), QString(), designFilter());
    if (file.isEmpty()) return;
    try {
        emit openEditorRequested(loadDesign(file.toStdString()), file);
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot open the design"), QString::fromStdString(e.what()));
    }
}

void EditorFiles::startFromRandom() {
    Genome g = randomGenome(QRandomGenerator::global()->generate64(), mDocument->design().dimension);
    emit openEditorRequested(g, {});
}

void EditorFiles::startFromSourceImage() {
    const QString image =
        QFileDialog::getOpenFileName(mWindow, tr("A picture for the bath"), QString(),
                                     tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)"));
    if (image.isEmpty()) return;
    // A new flat design whose bath is the picture. It is named by its full path and may be read
    // from there (the user chose it just now); saved beside the picture, the design renders
    // anywhere the two travel together.
    const QFileInfo info(image);
    Genome g = blankDesign(2);
    g.source = SourceImage{info.absoluteFilePath().toStdString()};
    g.baseDirectory = info.absolutePath().toStdString();
    g.allowExternalSource = true;
    g.meta.name = info.completeBaseName().toStdString();
    emit openEditorRequested(g, {});
}

bool EditorFiles::maybeKeepChanges() {
    if (!mDocument->isModified()) return true;
    UnsavedAnswer answer;
    if (mUnsavedAnswer) {
        answer = *mUnsavedAnswer;
    } else {
        const auto button = QMessageBox::warning(
            mWindow, tr("Unsaved changes"),
            tr("“%1” has changes that are not saved. Save them?").arg(displayName()),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        answer = button == QMessageBox::Save      ? UnsavedAnswer::Save
                 : button == QMessageBox::Discard ? UnsavedAnswer::Discard
                                                  : UnsavedAnswer::Cancel;
    }
    switch (answer) {
    case UnsavedAnswer::Save:
        return save();
    case UnsavedAnswer::Discard:
        return true;
    case UnsavedAnswer::Cancel:
        return false;
    }
    return false;
}

} // namespace marbler::ui

// The workbench's File ▸ Marble a picture…: nine designs whose bath is a picture the user picks
// (marbler/ImageDesign.h), placed in the grid as opened designs are.

#include "shared/ErrorReport.h"
#include "workbench/WorkbenchWindow.h"

#include "marbler/Error.h"
#include "marbler/ImageDesign.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QImageReader>
#include <QSettings>
#include <QStatusBar>

namespace marbler::ui {

namespace {

/// The pictures Qt reads (what the dialog offers; the renderer decodes more).
QString pictureFilter() {
    QStringList patterns;
    for (const QByteArray& format : QImageReader::supportedImageFormats())
        patterns << QStringLiteral("*.") + QString::fromLatin1(format);
    return QObject::tr("Pictures (%1);;All files (*)").arg(patterns.join(QLatin1Char(' ')));
}

} // namespace

std::vector<int> WorkbenchWindow::marblePicture(const QString& file) {
    const QFileInfo info(file);
    QImageReader reader(file);
    QSize size = reader.size();
    if (!size.isValid()) {
        // Some formats tell their size only once read.
        const QImage image = reader.read();
        size = image.size();
    }
    if (!info.isFile() || !size.isValid() || size.isEmpty()) {
        reportError(this, tr("Cannot marble the picture"),
                    tr("%1: %2").arg(QDir::toNativeSeparators(file),
                                     info.isFile() ? reader.errorString() : tr("no such file")));
        return {};
    }
    // The picture stays where it is and is named from its own folder, so the designs read it
    // without asking (SourcePath.h) and a session resumed later still finds it.
    const std::string folder = info.absolutePath().toStdString();
    const double aspect = double(size.width()) / double(size.height());
    const std::uint64_t seed = mModel->nextBreedSeed();
    std::vector<Genome> designs;
    try {
        for (int k = 0; k < CellCount; ++k) {
            // Nine designs, nine names: the captions, the lineage and saved files tell them apart.
            const std::string name =
                tr("%1 marbled %2").arg(info.completeBaseName()).arg(k + 1).toStdString();
            Genome design = imageDesign(seed + std::uint64_t(k), info.fileName().toStdString(), aspect, name);
            design.baseDirectory = folder;
            designs.push_back(std::move(design));
        }
    } catch (const Error& e) {
        reportError(this, tr("Cannot marble the picture"), QString::fromStdString(e.what()));
        return {};
    }
    // Nine designs fill the grid: like a new random population they are a generation of their
    // own, all nine, without a question (placed as opened designs, a selected parent kept one
    // of them out, and the question offered to replace "the selected cells" while all nine
    // went). The grid before is one generation back.
    return startGenerationOfKind(designs, tr("Marbled %1").arg(info.fileName()));
}

void WorkbenchWindow::marblePictureDialog() {
    const QString dir = QSettings().value(QStringLiteral("files/lastPictureDir")).toString();
    const QString file = QFileDialog::getOpenFileName(this, tr("Marble a picture"), dir, pictureFilter());
    if (file.isEmpty()) return;
    QSettings().setValue(QStringLiteral("files/lastPictureDir"), QFileInfo(file).absolutePath());
    marblePicture(file);
}

} // namespace marbler::ui

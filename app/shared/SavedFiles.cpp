#include "shared/SavedFiles.h"

#include "shared/Lineage.h"

#include <QClipboard>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QRegularExpression>
#include <QToolButton>

namespace marbler::ui {

namespace {

SaveFileAsker& askerHook() {
    static SaveFileAsker hook;
    return hook;
}

UrlOpener& openerHook() {
    static UrlOpener hook;
    return hook;
}

/// Long enough to read the path and reach for the button; short enough not to linger over
/// later work.
constexpr int NoticeMilliseconds = 60000;

} // namespace

QString safeFileName(const QString& name) {
    QString result;
    for (const QChar c : name) {
        if (c.category() == QChar::Other_Control || QStringLiteral("/\\:*?\"<>|").contains(c)) continue;
        result += c;
    }
    result = result.simplified();
    // A leading dot hides the file; Windows drops trailing dots and spaces.
    while (result.startsWith(QLatin1Char('.')) || result.startsWith(QLatin1Char(' ')))
        result.remove(0, 1);
    while (result.endsWith(QLatin1Char('.')) || result.endsWith(QLatin1Char(' ')))
        result.chop(1);
    return result;
}

QString suggestedFile(const Genome& genome, const QString& folder, const QString& extension) {
    const LineageInfo info = lineageOf(genome);
    QString name = safeFileName(info.name);
    if (name.isEmpty()) name = info.id.left(8);
    return QDir(folder.isEmpty() ? QDir::currentPath() : folder).filePath(name + extension);
}

void setSaveFileAsker(SaveFileAsker asker) {
    askerHook() = std::move(asker);
}

QString askSaveFile(QWidget* parent, const QString& caption, const QString& suggested,
                    const QString& filter) {
    if (askerHook()) return askerHook()(parent, caption, suggested, filter);
    return QFileDialog::getSaveFileName(parent, caption, suggested, filter);
}

void setUrlOpener(UrlOpener opener) {
    openerHook() = std::move(opener);
}

bool openUrl(const QUrl& url) {
    if (openerHook()) return openerHook()(url);
    return QDesktopServices::openUrl(url);
}

SavedFileNotice::SavedFileNotice(QWidget* parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("savedFileNotice"));
    mPath = new QLabel(this);
    mPath->setObjectName(QStringLiteral("savedPath"));
    mPath->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mShowInFolder = new QToolButton(this);
    mShowInFolder->setObjectName(QStringLiteral("showInFolder"));
    mShowInFolder->setText(tr("Show in folder"));
    mShowInFolder->setAutoRaise(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(mPath);
    layout->addWidget(mShowInFolder);
    connect(mShowInFolder, &QToolButton::clicked, this, [this] {
        if (mFile.isEmpty() || openUrl(QUrl::fromLocalFile(folder()))) return;
        // No file manager answered (issue 29: the button did nothing): the path goes to the
        // clipboard, to paste into whatever the user opens files with, and the note says so.
        QGuiApplication::clipboard()->setText(QDir::toNativeSeparators(mFile));
        mPath->setText(tr("No file manager opened %1; the file's path is copied to the clipboard: %2")
                           .arg(QDir::toNativeSeparators(folder()), QDir::toNativeSeparators(mFile)));
        mHide.start();
    });
    mHide.setSingleShot(true);
    mHide.setInterval(NoticeMilliseconds);
    connect(&mHide, &QTimer::timeout, this, &QWidget::hide);
    hide();
}

void SavedFileNotice::showFile(const QString& file) {
    mFile = QFileInfo(file).absoluteFilePath();
    mPath->setText(tr("Saved %1").arg(QDir::toNativeSeparators(mFile)));
    mPath->setToolTip(QDir::toNativeSeparators(mFile));
    mShowInFolder->setToolTip(tr("Open %1 in the file manager").arg(QDir::toNativeSeparators(folder())));
    show();
    mHide.start();
}

QString SavedFileNotice::folder() const {
    return mFile.isEmpty() ? QString() : QFileInfo(mFile).absolutePath();
}

} // namespace marbler::ui

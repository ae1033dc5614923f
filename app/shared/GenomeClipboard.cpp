#include "shared/GenomeClipboard.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QUrl>

namespace marbler::ui {

void copyGenomeToClipboard(const Genome& genome) {
    const QByteArray text = QByteArray::fromStdString(serializeGenome(genome));
    auto* mime = new QMimeData; // the clipboard takes ownership
    mime->setText(QString::fromUtf8(text));
    mime->setData(QString::fromLatin1(GenomeMimeType), text);
    QGuiApplication::clipboard()->setMimeData(mime);
}

ClipboardDesign clipboardDesign(const QMimeData* mime) {
    ClipboardDesign design;
    if (!mime) return design;
    if (mime->hasFormat(QString::fromLatin1(GenomeMimeType))) {
        design.genomeText = mime->data(QString::fromLatin1(GenomeMimeType));
        return design;
    }
    // A file manager's copy offers the files as URLs (and their paths as text): open the files.
    if (mime->hasUrls()) {
        for (const QUrl& url : mime->urls())
            if (url.isLocalFile()) design.files << url.toLocalFile();
        if (!design.files.isEmpty()) return design;
    }
    if (mime->hasText()) design.genomeText = mime->text().toUtf8();
    return design;
}

Genome parseClipboardGenome(const QByteArray& text) {
    if (text.trimmed().isEmpty()) throw InputError("the clipboard holds no text");
    return parseGenome(std::string_view(text.constData(), std::size_t(text.size())), "clipboard");
}

} // namespace marbler::ui

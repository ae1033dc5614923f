#pragma once
/// Designs on the clipboard: a genome copied as its canonical JSON text (the text a genome file
/// holds, so it pastes into an editor or a chat as it is), and read back from such text.

#include "marbler/Genome.h"

#include <QStringList>

class QMimeData;

namespace marbler::ui {

/// The MIME type of a design dragged or copied between Marbler's windows: the genome's JSON text.
inline constexpr const char* GenomeMimeType = "application/x-marbler-genome";

/// Puts a genome on the clipboard: as plain text and as application/x-marbler-genome.
void copyGenomeToClipboard(const Genome& genome);

/// What the clipboard offers to paste: a genome's text, or local files (copied in a file
/// manager) to open like File ▸ Open.
struct ClipboardDesign {
    QByteArray genomeText; ///< empty when the clipboard holds files, or nothing
    QStringList files;
};
ClipboardDesign clipboardDesign(const QMimeData* mime);

/// Parses genome text from the clipboard; errors name it "clipboard" and the JSON location.
/// Throws GenomeError, or InputError when there is no text at all.
Genome parseClipboardGenome(const QByteArray& text);

} // namespace marbler::ui

#pragma once
/// The window's answer to a design whose `source` image lies outside its folder (SourcePath.h):
/// the command line refuses such a design unless --allow-external-source is given; the window
/// asks instead ("This design reads an image outside its folder: /x/y.png. Read it?"), once per
/// image file for as long as the program runs (never saved: a later run asks again). The render
/// service consults it before rendering, the large view before exporting. The question goes
/// through a hook a test can replace, so no test blocks on a dialog.

#include "marbler/Genome.h"

#include <QString>

#include <functional>
#include <map>
#include <optional>

class QWidget;

namespace marbler::ui {

/// Asks whether a design may read `image` (the file's canonical path); true: read it. `design`
/// names the design's file (empty when it has none). A QMessageBox by default.
using ExternalSourceAsker = std::function<bool(QWidget* parent, const QString& design, const QString& image)>;
/// Installs an asker; an empty one restores the message box.
void setExternalSourceAsker(ExternalSourceAsker asker);
/// Asks through the installed asker.
bool askExternalSource(QWidget* parent, const QString& design, const QString& image);

/// The answers of this run, by canonical image path (GUI thread only).
class SourcePermissions {
public:
    /// The one set of answers of the running program.
    static SourcePermissions& session();

    /// The outside image `genome` reads, when it reads one (canonical path); empty otherwise.
    static QString externalImage(const Genome& genome);
    /// The answer given for an image, if any.
    std::optional<bool> answer(const QString& image) const;
    void setAnswer(const QString& image, bool allowed);
    /// Forgets every answer (tests).
    void clear();

    /// Sets genome.allowExternalSource from the answer given for its image (false when none
    /// was given; asks nothing). Returns whether the genome may be rendered as it is: it reads
    /// no outside image, or the one it reads was allowed.
    bool apply(Genome& genome) const;

private:
    std::map<QString, bool> mAnswers;
};

/// The message a design shows in place of its render when its outside image was not allowed.
QString refusedSourceMessage(const QString& image);

} // namespace marbler::ui

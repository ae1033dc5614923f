#pragma once
/// Naming a design: the small dialog that F2 and "Rename…" open in the grid, the favourites, the
/// large view and the editor (a name and a note, meta.name and meta.note), and the rule that a
/// design saved under a file name the user typed takes that name.

#include "marbler/Genome.h"

#include <QDialog>
#include <QString>

#include <functional>

class QDialogButtonBox;
class QLineEdit;

namespace marbler::ui {

/// A design's name and note, edited. OK is offered only while the name holds more than spaces.
class RenameDialog : public QDialog {
    Q_OBJECT
public:
    RenameDialog(const QString& name, const QString& note, QWidget* parent = nullptr);

    /// The name typed, its spaces trimmed and collapsed.
    QString name() const;
    /// The note typed, trimmed (empty: no note).
    QString note() const;
    QLineEdit* nameEdit() const { return mName; }
    QLineEdit* noteEdit() const { return mNote; }

private:
    QLineEdit* mName;
    QLineEdit* mNote;
    QDialogButtonBox* mButtons;
};

/// Opens the dialog for `design` window-modally and returns at once (the GUI thread never waits
/// on it); `done` gets the name and note when the user presses OK. The dialog deletes itself.
RenameDialog* askRename(QWidget* parent, const Genome& design,
                        std::function<void(const QString& name, const QString& note)> done);

/// The design named: meta.name set, meta.note set or (empty) removed.
void setNameAndNote(Genome& design, const QString& name, const QString& note);

/// The design's note, empty when it has none.
QString noteOf(const Genome& design);

/// What a design saved as `file` is called: the file's name without ".marble.json" (or
/// ".json"). When the user typed a name other than the design's own (the name offered), the
/// design takes it: meta.name set and true returned; false when the file carries the design's
/// own name (as offered) or nothing usable.
bool adoptFileName(Genome& design, const QString& file);

} // namespace marbler::ui

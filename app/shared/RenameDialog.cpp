#include "shared/RenameDialog.h"

#include "shared/Lineage.h"
#include "shared/SavedFiles.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLineEdit>
#include <QPushButton>

namespace marbler::ui {

RenameDialog::RenameDialog(const QString& name, const QString& note, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("renameDialog"));
    setWindowTitle(tr("Rename design"));
    mName = new QLineEdit(name, this);
    mName->setObjectName(QStringLiteral("renameName"));
    mName->setToolTip(tr("The design's name: shown under it, offered as its file name, kept in the file"));
    mName->selectAll();
    mNote = new QLineEdit(note, this);
    mNote->setObjectName(QStringLiteral("renameNote"));
    mNote->setPlaceholderText(tr("A note for yourself (optional)"));
    mNote->setToolTip(tr("Shown in the design's tooltip and kept in its file (meta.note)"));
    mButtons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* form = new QFormLayout(this);
    form->addRow(tr("&Name:"), mName);
    form->addRow(tr("N&ote:"), mNote);
    form->addRow(mButtons);
    connect(mButtons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(mButtons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // A design always has a name: an empty one cannot be given.
    const auto check = [this] {
        mButtons->button(QDialogButtonBox::Ok)->setEnabled(!this->name().isEmpty());
    };
    connect(mName, &QLineEdit::textChanged, this, check);
    check();
    mName->setFocus();
}

QString RenameDialog::name() const {
    return mName->text().simplified();
}

QString RenameDialog::note() const {
    return mNote->text().trimmed();
}

RenameDialog* askRename(QWidget* parent, const Genome& design,
                        std::function<void(const QString& name, const QString& note)> done) {
    auto* dialog = new RenameDialog(lineageOf(design).displayName(), noteOf(design), parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QDialog::accepted, dialog,
                     [dialog, done = std::move(done)] { done(dialog->name(), dialog->note()); });
    dialog->open();
    return dialog;
}

void setNameAndNote(Genome& design, const QString& name, const QString& note) {
    design.meta.name = name.toStdString();
    if (note.isEmpty())
        design.meta.erase(MetaKey::Note);
    else
        design.meta.note = note.toStdString();
}

QString noteOf(const Genome& design) {
    return design.meta.note ? QString::fromStdString(*design.meta.note) : QString();
}

bool adoptFileName(Genome& design, const QString& file) {
    QString base = QFileInfo(file).fileName();
    for (const QString& extension : {QStringLiteral(".marble.json"), QStringLiteral(".json")})
        if (base.endsWith(extension, Qt::CaseInsensitive)) {
            base.chop(extension.size());
            break;
        }
    base = base.simplified();
    if (base.isEmpty()) return false;
    const LineageInfo info = lineageOf(design);
    // The name offered (the design's own, made safe) is no new name.
    if (base == info.name || base == safeFileName(info.displayName())) return false;
    design.meta.name = base.toStdString();
    return true;
}

} // namespace marbler::ui

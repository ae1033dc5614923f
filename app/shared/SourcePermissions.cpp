#include "shared/SourcePermissions.h"

#include "marbler/SourcePath.h"

#include <QMessageBox>
#include <QPushButton>

namespace marbler::ui {

namespace {
ExternalSourceAsker& asker() {
    static ExternalSourceAsker instance;
    return instance;
}
} // namespace

void setExternalSourceAsker(ExternalSourceAsker a) {
    asker() = std::move(a);
}

bool askExternalSource(QWidget* parent, const QString& design, const QString& image) {
    if (asker()) return asker()(parent, design, image);
    QMessageBox box(QMessageBox::Question, QObject::tr("Read an image outside the design's folder?"),
                    QObject::tr("This design reads an image outside its folder: %1. Read it?").arg(image),
                    QMessageBox::NoButton, parent);
    if (!design.isEmpty())
        box.setInformativeText(
            QObject::tr("The design %1 names it. A design may read images only from its own "
                        "folder unless you allow it; the answer holds until Marbler closes.")
                .arg(design));
    QPushButton* allow = box.addButton(QObject::tr("Allow"), QMessageBox::AcceptRole);
    QPushButton* refuse = box.addButton(QObject::tr("Don't allow"), QMessageBox::RejectRole);
    // Refusing is the safe answer, so it is what Enter and Escape give.
    box.setDefaultButton(refuse);
    box.setEscapeButton(refuse);
    box.exec();
    return box.clickedButton() == allow;
}

SourcePermissions& SourcePermissions::session() {
    static SourcePermissions instance;
    return instance;
}

QString SourcePermissions::externalImage(const Genome& genome) {
    const SourceLocation where = locateSource(genome);
    if (where.kind != SourceLocation::Kind::Outside) return {};
    return QString::fromStdString(where.file.string());
}

std::optional<bool> SourcePermissions::answer(const QString& image) const {
    auto it = mAnswers.find(image);
    if (it == mAnswers.end()) return std::nullopt;
    return it->second;
}

void SourcePermissions::setAnswer(const QString& image, bool allowed) {
    mAnswers[image] = allowed;
}

void SourcePermissions::clear() {
    mAnswers.clear();
}

bool SourcePermissions::apply(Genome& genome) const {
    const QString image = externalImage(genome);
    if (image.isEmpty()) return true;
    genome.allowExternalSource = answer(image).value_or(false);
    return genome.allowExternalSource;
}

QString refusedSourceMessage(const QString& image) {
    return QObject::tr("this design reads an image outside its folder (%1), which you chose not to read")
        .arg(image);
}

} // namespace marbler::ui

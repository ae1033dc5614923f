#include "workbench/OpenPlacement.h"

#include <QCheckBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace marbler::ui {

namespace {

const QString ChoiceKey = QStringLiteral("open/placement");
const QString OpenAskKey = QStringLiteral("open/ask");

OpenChooser& openChooserHook() {
    static OpenChooser hook;
    return hook;
}

/// "design 5", "designs 1, 2 and 3": cells as the window numbers them (from 1).
QString designList(const std::vector<int>& cells) {
    QStringList numbers;
    for (int c : cells)
        numbers << QString::number(c + 1);
    if (numbers.size() == 1) return OpenPlacementDialog::tr("design %1").arg(numbers.front());
    const QString last = numbers.takeLast();
    return OpenPlacementDialog::tr("designs %1 and %2").arg(numbers.join(QStringLiteral(", ")), last);
}

} // namespace

OpenChoice lastOpenChoice() {
    return QSettings().value(ChoiceKey).toString() == QStringLiteral("replace") ? OpenChoice::Replace
                                                                                : OpenChoice::NewGeneration;
}

bool askOpenChoice() {
    return QSettings().value(OpenAskKey, true).toBool();
}

void rememberOpenChoice(OpenChoice choice, bool askAgain) {
    QSettings settings;
    settings.setValue(ChoiceKey, choice == OpenChoice::Replace ? QStringLiteral("replace")
                                                               : QStringLiteral("generation"));
    settings.setValue(OpenAskKey, askAgain);
}

OpenPlacementDialog::OpenPlacementDialog(const OpenQuestion& question, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Where do the opened designs go?"));
    const QString what = question.names.size() == 1 ? question.names.front()
                                                    : tr("%n designs", nullptr, int(question.names.size()));
    QString text =
        tr("<b>Opening %1 would replace %2.</b>").arg(what.toHtmlEscaped(), designList(question.replaced));
    if (!question.parents.empty())
        text += QStringLiteral("<br>") +
                (question.parents.size() == 1
                     ? tr("Design %1 is a selected parent.").arg(question.parents.front() + 1)
                     : tr("%1 are selected parents.").arg(designList(question.parents)));
    text +=
        QStringLiteral("<br>") + tr("Either way the grid as it is now stays one generation back (Ctrl+Z).");
    auto* intro = new QLabel(text, this);
    intro->setWordWrap(true);

    // "The selected cells" only where they are all that would be replaced: nine designs over
    // a grid with one parent replace all nine, and the button must say so.
    const bool onlyParents = !question.parents.empty() && question.parents.size() == question.replaced.size();
    mReplace = new QPushButton(
        onlyParents                     ? (question.replaced.size() == 1 ? tr("&Replace the selected cell")
                                                                         : tr("&Replace the selected cells"))
        : question.replaced.size() == 9 ? tr("&Replace all nine designs")
                                        : tr("&Replace %1").arg(designList(question.replaced)),
        this);
    mReplace->setObjectName(QStringLiteral("replaceButton"));
    mReplace->setToolTip(tr("Put the opened designs over %1").arg(designList(question.replaced)));
    mNewGeneration = new QPushButton(tr("Add as a &new generation"), this);
    mNewGeneration->setObjectName(QStringLiteral("newGenerationButton"));
    mNewGeneration->setToolTip(tr("A new generation that keeps the parents: the opened designs go into free "
                                  "cells, then over designs that are not parents"));
    mCancel = new QPushButton(tr("Cancel"), this);
    mDontAsk = new QCheckBox(tr("&Don't ask again (do the same next time)"), this);
    mDontAsk->setToolTip(tr("Remember this choice; opened designs then go where it says without a question"));
    // Keeping the parents loses nothing the user picked, so it is the safe default.
    mNewGeneration->setDefault(true);
    mNewGeneration->setFocus();

    connect(mReplace, &QPushButton::clicked, this, [this] {
        mChoice = OpenChoice::Replace;
        accept();
    });
    connect(mNewGeneration, &QPushButton::clicked, this, [this] {
        mChoice = OpenChoice::NewGeneration;
        accept();
    });
    connect(mCancel, &QPushButton::clicked, this, &QDialog::reject);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(mReplace);
    buttons->addWidget(mNewGeneration);
    buttons->addStretch();
    buttons->addWidget(mCancel);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addSpacing(8);
    layout->addLayout(buttons);
    layout->addWidget(mDontAsk);
}

bool OpenPlacementDialog::dontAskAgain() const {
    return mDontAsk->isChecked();
}

void setOpenChooser(OpenChooser chooser) {
    openChooserHook() = std::move(chooser);
}

std::optional<OpenChoice> chooseOpenPlacement(QWidget* parent, const OpenQuestion& question) {
    if (openChooserHook()) return openChooserHook()(parent, question);
    OpenPlacementDialog dialog(question, parent);
    dialog.exec();
    if (dialog.choice() && dialog.dontAskAgain()) rememberOpenChoice(*dialog.choice(), false);
    return dialog.choice();
}

namespace {

PictureOffer& pictureOfferHook() {
    static PictureOffer hook;
    return hook;
}

} // namespace

void setPictureOffer(PictureOffer offer) {
    pictureOfferHook() = std::move(offer);
}

bool offerMarblePicture(QWidget* parent, const QString& file) {
    if (pictureOfferHook()) return pictureOfferHook()(parent, file);
    QMessageBox box(QMessageBox::Question, QObject::tr("Marble a picture?"),
                    QObject::tr("%1 is a picture without a Marbler design in it.\n\nMarble it: nine designs "
                                "whose bath is the picture, as File ▸ Marble a picture makes?")
                        .arg(QFileInfo(file).fileName()),
                    QMessageBox::Cancel, parent);
    QPushButton* marble = box.addButton(QObject::tr("&Marble the picture"), QMessageBox::AcceptRole);
    box.setDefaultButton(marble);
    box.exec();
    return box.clickedButton() == marble;
}

} // namespace marbler::ui

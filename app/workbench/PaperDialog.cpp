#include "workbench/PaperDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QRandomGenerator>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace marbler::ui {

namespace {

PaperChooser& paperChooserHook() {
    static PaperChooser hook;
    return hook;
}

/// The sheets offered by name, in millimetres (portrait); "Custom" takes the fields' size.
struct PaperSheet {
    const char* name;
    double width, height;
};
constexpr PaperSheet PaperSheets[] = {
    {QT_TRANSLATE_NOOP("marbler::ui::PaperDialog", "A5 (148 × 210 mm)"), 148.0, 210.0},
    {QT_TRANSLATE_NOOP("marbler::ui::PaperDialog", "A4 (210 × 297 mm)"), 210.0, 297.0},
    {QT_TRANSLATE_NOOP("marbler::ui::PaperDialog", "A3 (297 × 420 mm)"), 297.0, 420.0},
    {QT_TRANSLATE_NOOP("marbler::ui::PaperDialog", "Letter (8.5 × 11 in)"), 215.9, 279.4},
    {QT_TRANSLATE_NOOP("marbler::ui::PaperDialog", "Square (300 × 300 mm)"), 300.0, 300.0}};

const QString PaperWidthKey = QStringLiteral("paper/width");
const QString PaperHeightKey = QStringLiteral("paper/height");
const QString PaperColorsKey = QStringLiteral("paper/colors");
const QString PaperPassesKey = QStringLiteral("paper/passes");
const QString PaperPastelKey = QStringLiteral("paper/pastel");
const QString PaperRecipeKey = QStringLiteral("paper/recipe");

} // namespace

PaperDialog::PaperDialog(const PaperChoice& start, QWidget* parent)
    : QDialog(parent)
    , mStartSeed(start.seed) {
    setWindowTitle(tr("New marbled paper"));
    auto* form = new QFormLayout;
    mSheet = new QComboBox(this);
    mSheet->setObjectName(QStringLiteral("paperSheet"));
    for (const PaperSheet& sheet : PaperSheets)
        mSheet->addItem(tr(sheet.name));
    mSheet->addItem(tr("Custom size"));
    mSheet->setToolTip(tr("The sheet the paper is made for; the design is measured in its millimetres "
                          "(marbler paper --size)"));
    mWidth = new QDoubleSpinBox(this);
    mWidth->setObjectName(QStringLiteral("paperWidth"));
    mHeight = new QDoubleSpinBox(this);
    mHeight->setObjectName(QStringLiteral("paperHeight"));
    for (QDoubleSpinBox* box : {mWidth, mHeight}) {
        box->setRange(10.0, 5000.0);
        box->setDecimals(1);
        box->setSuffix(tr(" mm"));
    }
    mWidth->setToolTip(tr("The sheet's width in millimetres"));
    mHeight->setToolTip(tr("The sheet's height in millimetres"));
    mColors = new QSpinBox(this);
    mColors->setObjectName(QStringLiteral("paperColors"));
    mColors->setRange(1, MaxPaperColors);
    mColors->setToolTip(tr("Inks, one layer of drops each, each later one smaller (marbler paper --colors)"));
    mPasses = new QSpinBox(this);
    mPasses->setObjectName(QStringLiteral("paperPasses"));
    mPasses->setRange(0, MaxPaperPasses);
    mPasses->setToolTip(tr("Combing passes along the sheet, each weaker than the one before "
                           "(marbler paper --passes)"));
    mPastel = new QCheckBox(tr("&Pastel inks on a white bath"), this);
    mPastel->setObjectName(QStringLiteral("paperPastel"));
    mPastel->setToolTip(tr("Pale, soft inks instead of random ones on cream (marbler paper --pastel)"));
    mRecipe = new QComboBox(this);
    mRecipe->setObjectName(QStringLiteral("paperRecipe"));
    mRecipe->addItem(tr("Golden-ratio drops, wrapping (the post's)"), int(PaperRecipe::Post));
    mRecipe->addItem(tr("Classic drops on cream"), int(PaperRecipe::Classic));
    mRecipe->setToolTip(tr("marbler paper --recipe post or classic"));
    mSeed = new QLineEdit(QString::number(start.seed), this);
    mSeed->setObjectName(QStringLiteral("paperSeed"));
    mSeed->setToolTip(tr("The same seed and options make the same paper (marbler paper --seed)"));
    form->addRow(tr("&Sheet"), mSheet);
    form->addRow(tr("&Width"), mWidth);
    form->addRow(tr("&Height"), mHeight);
    form->addRow(tr("&Colours"), mColors);
    form->addRow(tr("Combing &passes"), mPasses);
    form->addRow(QString(), mPastel);
    form->addRow(tr("&Recipe"), mRecipe);
    form->addRow(tr("S&eed"), mSeed);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);

    mWidth->setValue(start.options.width);
    mHeight->setValue(start.options.height);
    int sheet = int(std::size(PaperSheets));
    for (int i = 0; i < int(std::size(PaperSheets)); ++i)
        if (std::abs(PaperSheets[i].width - start.options.width) < 0.05 &&
            std::abs(PaperSheets[i].height - start.options.height) < 0.05)
            sheet = i;
    mSheet->setCurrentIndex(sheet);
    const auto showSheet = [this] {
        const int i = mSheet->currentIndex();
        const bool custom = i >= int(std::size(PaperSheets));
        mWidth->setEnabled(custom);
        mHeight->setEnabled(custom);
        if (!custom) {
            mWidth->setValue(PaperSheets[i].width);
            mHeight->setValue(PaperSheets[i].height);
        }
    };
    showSheet();
    connect(mSheet, &QComboBox::currentIndexChanged, this, showSheet);
    mColors->setValue(start.options.colors);
    mPasses->setValue(start.options.passes);
    mPastel->setChecked(start.options.pastel);
    mRecipe->setCurrentIndex(std::max(0, mRecipe->findData(int(start.options.recipe))));
}

PaperChoice PaperDialog::choice() const {
    PaperChoice choice;
    choice.options.width = mWidth->value();
    choice.options.height = mHeight->value();
    choice.options.colors = mColors->value();
    choice.options.passes = mPasses->value();
    choice.options.pastel = mPastel->isChecked();
    choice.options.recipe = PaperRecipe(mRecipe->currentData().toInt());
    bool ok = false;
    const qulonglong seed = mSeed->text().trimmed().toULongLong(&ok);
    choice.seed = ok ? seed : mStartSeed;
    return choice;
}

PaperChoice rememberedPaperChoice() {
    const QSettings settings;
    PaperChoice choice;
    const PaperOptions defaults;
    choice.options.width = settings.value(PaperWidthKey, defaults.width).toDouble();
    choice.options.height = settings.value(PaperHeightKey, defaults.height).toDouble();
    choice.options.colors =
        std::clamp(settings.value(PaperColorsKey, defaults.colors).toInt(), 1, MaxPaperColors);
    choice.options.passes =
        std::clamp(settings.value(PaperPassesKey, defaults.passes).toInt(), 0, MaxPaperPasses);
    choice.options.pastel = settings.value(PaperPastelKey, defaults.pastel).toBool();
    choice.options.recipe =
        settings.value(PaperRecipeKey, int(defaults.recipe)).toInt() == int(PaperRecipe::Classic)
            ? PaperRecipe::Classic
            : PaperRecipe::Post;
    choice.seed = QRandomGenerator::global()->generate64();
    return choice;
}

std::optional<PaperChoice> askPaper(QWidget* parent) {
    const PaperChoice start = rememberedPaperChoice();
    std::optional<PaperChoice> answer;
    if (paperChooserHook()) {
        answer = paperChooserHook()(parent, start);
    } else {
        PaperDialog dialog(start, parent);
        if (dialog.exec() == QDialog::Accepted) answer = dialog.choice();
    }
    if (!answer) return std::nullopt;
    QSettings settings;
    settings.setValue(PaperWidthKey, answer->options.width);
    settings.setValue(PaperHeightKey, answer->options.height);
    settings.setValue(PaperColorsKey, answer->options.colors);
    settings.setValue(PaperPassesKey, answer->options.passes);
    settings.setValue(PaperPastelKey, answer->options.pastel);
    settings.setValue(PaperRecipeKey, int(answer->options.recipe));
    return answer;
}

void setPaperChooser(PaperChooser chooser) {
    paperChooserHook() = std::move(chooser);
}

} // namespace marbler::ui

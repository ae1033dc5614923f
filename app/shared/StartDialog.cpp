#include "shared/StartDialog.h"

#include "marbler/Mesh.h"
#include "shared/Help.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace marbler::ui {

namespace {

const QString DimensionKey = QStringLiteral("population/dimension");
const QString MeshKey = QStringLiteral("view/mesh");
const QString StartAskKey = QStringLiteral("start/ask");

StartChooser& startChooserHook() {
    static StartChooser hook;
    return hook;
}

} // namespace

QStringList meshNames() {
    QStringList names;
    for (const std::string& name : builtinMeshNames())
        names << QString::fromStdString(name);
    return names;
}

StartChoice lastStartChoice() {
    QSettings settings;
    StartChoice choice;
    choice.dimension = settings.value(DimensionKey, 2).toInt() == 3 ? 3 : 2;
    const QString mesh = settings.value(MeshKey, choice.mesh).toString();
    if (meshNames().contains(mesh)) choice.mesh = mesh;
    return choice;
}

bool askStartChoice() {
    return QSettings().value(StartAskKey, true).toBool();
}

void rememberStartChoice(const StartChoice& choice, bool askAgain) {
    QSettings settings;
    settings.setValue(DimensionKey, choice.dimension);
    settings.setValue(MeshKey, choice.mesh);
    settings.setValue(StartAskKey, askAgain);
}

StartDialog::StartDialog(const StartChoice& defaults, QWidget* parent)
    : QDialog(parent)
    , mChoice(defaults) {
    setWindowTitle(tr("Marbler — what to breed"));
    auto* intro = new QLabel(tr("<b>What would you like to breed?</b><br>"
                                "Nine random designs start the first generation; pick the ones you like "
                                "as parents and breed the next."),
                             this);
    intro->setWordWrap(true);

    mFlat = new QPushButton(tr("Breed &flat (2D) designs"), this);
    mFlat->setToolTip(tr("Marbled paper: patterns in the plane"));
    mSolid = new QPushButton(tr("Breed &solid (3D) designs on an object"), this);
    mSolid->setToolTip(tr("Marbling through a volume, shown on the object chosen beside"));
    mMesh = new QComboBox(this);
    mMesh->addItems(meshNames());
    mMesh->setCurrentText(defaults.mesh);
    mMesh->setToolTip(tr("The object solid designs are shown on"));
    mDontAsk = new QCheckBox(tr("&Don't ask again (the toolbar still changes it)"), this);

    if (defaults.resumeGeneration > 0) {
        const QString named =
            defaults.resumeName.isEmpty() ? QString() : tr(" “%1”").arg(labelSafe(defaults.resumeName));
        mResume = new QPushButton(tr("&Resume the last session%1 (generation %2, %3)")
                                      .arg(named)
                                      .arg(defaults.resumeGeneration)
                                      .arg(defaults.resumeDimension == 3 ? tr("solid") : tr("2D")),
                                  this);
        mResume->setToolTip(tr("Every generation of the last session, back where you left it"));
        connect(mResume, &QPushButton::clicked, this, [this] {
            mChoice.resume = true;
            mChoice.resumeId.clear();
            accept();
        });
    }
    if (!defaults.otherSessions.isEmpty()) {
        mOthers = new QComboBox(this);
        for (const auto& [id, text] : defaults.otherSessions)
            mOthers->addItem(text, id);
        mOthers->setToolTip(tr("Every session is kept; File ▸ Sessions renames and deletes them"));
        mResumeOther = new QPushButton(tr("Resume &another session:"), this);
        connect(mResumeOther, &QPushButton::clicked, this, [this] {
            mChoice.resume = true;
            mChoice.resumeId = mOthers->currentData().toString();
            accept();
        });
    }
    QPushButton* preferred = mResume ? mResume : (defaults.dimension == 3 ? mSolid : mFlat);
    preferred->setDefault(true);
    preferred->setFocus();

    connect(mFlat, &QPushButton::clicked, this, [this] {
        mChoice.resume = false;
        mChoice.dimension = 2;
        accept();
    });
    connect(mSolid, &QPushButton::clicked, this, [this] {
        mChoice.resume = false;
        mChoice.dimension = 3;
        mChoice.mesh = mMesh->currentText();
        accept();
    });

    auto* solidRow = new QHBoxLayout;
    solidRow->addWidget(mSolid, 1);
    solidRow->addWidget(mMesh);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addSpacing(8);
    if (mResume) layout->addWidget(mResume);
    if (mOthers) {
        auto* othersRow = new QHBoxLayout;
        othersRow->addWidget(mResumeOther);
        othersRow->addWidget(mOthers, 1);
        layout->addLayout(othersRow);
    }
    layout->addWidget(mFlat);
    layout->addLayout(solidRow);
    layout->addSpacing(8);
    layout->addWidget(mDontAsk);
}

bool StartDialog::dontAskAgain() const {
    return mDontAsk->isChecked();
}

void setStartChooser(StartChooser chooser) {
    startChooserHook() = std::move(chooser);
}

std::optional<StartChoice> chooseStart(QWidget* parent, const StartChoice& defaults) {
    if (startChooserHook()) return startChooserHook()(parent, defaults);
    StartDialog dialog(defaults, parent);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    rememberStartChoice(dialog.choice(), !dialog.dontAskAgain());
    return dialog.choice();
}

} // namespace marbler::ui

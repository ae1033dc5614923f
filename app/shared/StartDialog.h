#pragma once
/// The start choice: resume the last session (when one was saved) or another kept one, breed
/// flat (2D) designs, or solid (3D) designs shown on an object (a new session either way; the
/// others stay kept). Asked when the workbench opens with no genome files,
/// unless the user ticked "don't ask again"; the toolbar's kind box changes it later.

#include "marbler/Mesh.h"

#include <QDialog>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <utility>

class QCheckBox;
class QComboBox;
class QPushButton;

namespace marbler::ui {

/// The objects solid designs can be shown on.
QStringList meshNames();

struct StartChoice {
    int dimension = 2;                               ///< 2: flat, 3: solid
    QString mesh = QString::fromLatin1(DefaultMesh); ///< the object a solid design is shown on
    /// The answer: resume the saved session instead of a new population (the default when one
    /// is offered).
    bool resume = false;
    /// The offer: the saved session's current generation (as shown, from 1) and kind; 0 when
    /// there is no session to resume.
    int resumeGeneration = 0;
    int resumeDimension = 2;
    /// The offered session's name (empty: unnamed).
    QString resumeName{};
    /// The other kept sessions offered, the most recent first: id and what a list shows.
    QList<std::pair<QString, QString>> otherSessions{};
    /// The answer: which kept session to resume (empty: the last one, offered above).
    QString resumeId{};
    bool operator==(const StartChoice&) const = default;
};

/// The last choice (QSettings population/dimension and view/mesh).
StartChoice lastStartChoice();
/// Whether the start choice is asked (false once "don't ask again" was ticked).
bool askStartChoice();
/// Remembers a choice as the next default, and whether to ask again.
void rememberStartChoice(const StartChoice& choice, bool askAgain);

class StartDialog : public QDialog {
    Q_OBJECT
public:
    explicit StartDialog(const StartChoice& defaults, QWidget* parent = nullptr);

    /// The choice made (the defaults until a button is pressed).
    StartChoice choice() const { return mChoice; }
    bool dontAskAgain() const;

    /// "Resume the last session (...)": nullptr when no session is offered.
    QPushButton* resumeButton() const { return mResume; }
    /// The other kept sessions and the button resuming the one chosen: nullptr when none.
    QComboBox* otherSessionsBox() const { return mOthers; }
    QPushButton* resumeOtherButton() const { return mResumeOther; }
    QPushButton* flatButton() const { return mFlat; }
    QPushButton* solidButton() const { return mSolid; }
    QComboBox* meshBox() const { return mMesh; }
    QCheckBox* dontAskBox() const { return mDontAsk; }

private:
    StartChoice mChoice;
    QPushButton* mResume = nullptr;
    QComboBox* mOthers = nullptr;
    QPushButton* mResumeOther = nullptr;
    QPushButton* mFlat;
    QPushButton* mSolid;
    QComboBox* mMesh;
    QCheckBox* mDontAsk;
};

/// Asks the start choice; nullopt when the user closed the question (the defaults apply then).
/// The default shows a StartDialog modally; tests replace it so nothing blocks.
using StartChooser = std::function<std::optional<StartChoice>(QWidget* parent, const StartChoice& defaults)>;
void setStartChooser(StartChooser chooser);
std::optional<StartChoice> chooseStart(QWidget* parent, const StartChoice& defaults);

} // namespace marbler::ui

#pragma once
/// Where opened designs go when they would replace designs of the grid: over the selected (or
/// first) cells, or into a new generation that keeps the parents. Asked by a small dialog unless
/// the user ticked "don't ask again"; tests install a chooser instead, so nothing blocks.

#include <QDialog>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

class QCheckBox;
class QPushButton;

namespace marbler::ui {

enum class OpenChoice {
    Replace,       ///< over the cells named in the question (the selected ones first)
    NewGeneration, ///< a new generation that keeps the parents: free cells, then non-parents
};

/// What is about to happen, for the question's words.
struct OpenQuestion {
    QStringList names;         ///< the opened designs' file (or design) names
    std::vector<int> replaced; ///< cells whose designs "Replace" would overwrite (0-based)
    std::vector<int> parents;  ///< those of them that are selected parents
};

/// The remembered answer (QSettings open/placement), and whether to ask at all (open/ask).
OpenChoice lastOpenChoice();
bool askOpenChoice();
void rememberOpenChoice(OpenChoice choice, bool askAgain);

class OpenPlacementDialog : public QDialog {
    Q_OBJECT
public:
    explicit OpenPlacementDialog(const OpenQuestion& question, QWidget* parent = nullptr);

    /// The answer; nullopt until a choice button is pressed (Cancel, Escape, closing).
    std::optional<OpenChoice> choice() const { return mChoice; }
    bool dontAskAgain() const;

    QPushButton* replaceButton() const { return mReplace; }
    QPushButton* newGenerationButton() const { return mNewGeneration; }
    QPushButton* cancelButton() const { return mCancel; }
    QCheckBox* dontAskBox() const { return mDontAsk; }

private:
    std::optional<OpenChoice> mChoice;
    QPushButton* mReplace;
    QPushButton* mNewGeneration;
    QPushButton* mCancel;
    QCheckBox* mDontAsk;
};

/// Asks where opened designs go; nullopt: cancelled (nothing is opened). The default shows an
/// OpenPlacementDialog modally and remembers the answer when "don't ask again" is ticked;
/// a chooser installed for tests replaces it.
using OpenChooser = std::function<std::optional<OpenChoice>(QWidget* parent, const OpenQuestion& question)>;
void setOpenChooser(OpenChooser chooser);
std::optional<OpenChoice> chooseOpenPlacement(QWidget* parent, const OpenQuestion& question);

/// A dropped or opened picture without a design in it (issue 29: "has no genome"): asks whether
/// to marble it (File ▸ Marble a picture); a function installed for tests answers instead.
using PictureOffer = std::function<bool(QWidget* parent, const QString& file)>;
void setPictureOffer(PictureOffer offer);
bool offerMarblePicture(QWidget* parent, const QString& file);

} // namespace marbler::ui

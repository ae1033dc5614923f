#pragma once
/// File ▸ New marbled paper's question (issue 29: the window made only the default A4 paper):
/// the sheet's size, the number of inks, the stretch passes, pastel inks, the recipe and the
/// seed, the options of `marbler paper`. Remembers the last answer; tests answer it through
/// setPaperChooser instead of a modal dialog.

#include "marbler/Paper.h"

#include <QDialog>

#include <cstdint>
#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace marbler::ui {

/// A paper to make: the generator's options and its seed.
struct PaperChoice {
    PaperOptions options;
    std::uint64_t seed = 0;
};

class PaperDialog : public QDialog {
    Q_OBJECT
public:
    /// Shows `start` (its seed too).
    PaperDialog(const PaperChoice& start, QWidget* parent = nullptr);
    /// What the fields say; the seed is the one typed, or `start`'s when the field does not parse.
    PaperChoice choice() const;

private:
    std::uint64_t mStartSeed = 0;
    QComboBox* mSheet = nullptr; ///< paper sizes; "Custom" enables the two size fields
    QDoubleSpinBox* mWidth = nullptr;
    QDoubleSpinBox* mHeight = nullptr;
    QSpinBox* mColors = nullptr;
    QSpinBox* mPasses = nullptr;
    QCheckBox* mPastel = nullptr;
    QComboBox* mRecipe = nullptr;
    QLineEdit* mSeed = nullptr;
};

/// The last paper asked for (QSettings paper/*; the defaults of `marbler paper` at first) with a
/// fresh random seed.
PaperChoice rememberedPaperChoice();
/// Asks for a paper (the dialog, or the installed chooser); nullopt: cancelled. An answer is
/// remembered for the next question.
std::optional<PaperChoice> askPaper(QWidget* parent);
using PaperChooser = std::function<std::optional<PaperChoice>(QWidget* parent, const PaperChoice& start)>;
/// Installs a chooser in place of the dialog (tests); an empty one restores the dialog.
void setPaperChooser(PaperChooser chooser);

} // namespace marbler::ui

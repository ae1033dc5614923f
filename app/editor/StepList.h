#pragma once
/// The editor's list of steps: one row a step of the design (the entries of `initial`, then those
/// of `operations`, numbered as Growth.h), each with a mute checkbox; drag a row to reorder,
/// Ctrl+D duplicates, Del deletes, M mutes (also in the context menu). A run of steps of one tool
/// (the droplets of one spray, a pattern's drops) folds into one group row, "40 drops (steps
/// 5–44)", that opens to show them (double-click, → or +; ← or - folds it again); a filter above
/// the list shows the steps of one tool only. Rows are numbered as the document's steps whatever
/// is folded or filtered: every index in and out is a step index. The list knows no document:
/// it shows rows and asks for changes by signals; the editor window applies them and sets the
/// rows again.

#include <QString>
#include <QWidget>

#include <cstddef>
#include <optional>
#include <vector>

class QComboBox;
class QListWidget;
class QListWidgetItem;

namespace marbler::ui {

/// What one row shows.
struct StepRow {
    QString name;         ///< e.g. "Drop (ink 2)"
    bool muted = false;   ///< left out of the rendered design
    bool initial = false; ///< an entry of `initial` (an ink laid before the strokes)
    QString detail;       ///< a short line of its main values, shown as the row's tooltip
    /// The step's tool as the registry names it ("drop"): consecutive steps of one tool fold
    /// into a group, and the filter chooses by it. Empty: the row never folds.
    QString tool;
};

/// Runs of at least this many consecutive steps of one tool fold into a group.
inline constexpr std::size_t MinGroupSize = 3;

class StepListView;

/// The list of steps (see the file comment).
class StepList : public QWidget {
    Q_OBJECT
public:
    explicit StepList(QWidget* parent = nullptr);

    /// Shows these rows, keeping the current row where it still exists.
    void setRows(const std::vector<StepRow>& rows);
    /// The rows shown.
    std::size_t rowCount() const;
    /// Selects a row (nullopt: none) without emitting currentChanged.
    void setCurrent(std::optional<std::size_t> row);
    /// The selected row.
    std::optional<std::size_t> current() const;
    /// The list widget inside (for tests and the window's focus handling).
    QListWidget* list() const;
    /// The tool filter above the list (its first entry shows every step).
    QComboBox* filter() const { return mFilter; }
    /// Shows the steps of this tool only (a registry name; empty: every step).
    void setFilter(const QString& tool);
    /// Whether step `row` is the first of a group of steps (it stands for the whole group).
    bool isGroupHead(std::size_t row) const;
    /// Opens (true) or folds the group step `row` belongs to; nothing when it is in none.
    void setGroupExpanded(std::size_t row, bool expanded);
    /// Whether the group step `row` belongs to is open.
    bool isGroupExpanded(std::size_t row) const;
    /// Whether step `row` has a visible row (not folded into its group nor filtered out).
    bool isRowShown(std::size_t row) const;

    /// Asks to move row `from` to `to` (what a drag does).
    void requestMove(std::size_t from, std::size_t to);

signals:
    /// The user selected another row (nullopt: none).
    void currentChanged(std::optional<std::size_t> row);
    /// A drag asks to move step `from` so that it becomes step `to`.
    void moveRequested(std::size_t from, std::size_t to);
    /// The user muted (true) or unmuted a step.
    void mutedToggled(std::size_t row, bool muted);
    /// The user muted (true) or unmuted a folded group: steps `first` to `last`, as one edit.
    void rangeMutedToggled(std::size_t first, std::size_t last, bool muted);
    /// Ctrl+D or the context menu asks for a copy of the step after it.
    void duplicateRequested(std::size_t row);
    /// Del or the context menu asks to delete the step.
    void deleteRequested(std::size_t row);

protected:
    /// Keeps the current row in view as the list is resized (its dock laid out or dragged): a
    /// row chosen while the list had another size would otherwise sit out of view.
    void resizeEvent(QResizeEvent* event) override;

private:
    /// A run of steps folded into one row.
    struct Group {
        std::size_t first = 0, last = 0;
    };
    const Group* groupOf(std::size_t row) const;
    void updateTexts();
    void updateVisibility();
    void fillFilter();
    void scrollToCurrent();
    void showMenu(const QPoint& pos);
    void toggleMuteOfCurrent();
    StepListView* mList;
    QComboBox* mFilter;
    std::vector<StepRow> mRows;
    std::vector<Group> mGroups;
    std::vector<std::size_t> mExpanded; ///< the first steps of the open groups
    bool mUpdating = false;
    friend class StepListView;
};

} // namespace marbler::ui

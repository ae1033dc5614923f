#pragma once
/// The tool panel: what a gesture does not set (the ink, a comb's spacing, a spray's brush...),
/// showing only the rows the current tool uses. Also the tools' names, tooltips and shortcuts
/// for the window's tool bar: a registry tool's from its row (Params.h), the editor's own here.

#include "editor/Gestures.h"

#include <QKeySequence>
#include <QString>
#include <QWidget>

#include <functional>
#include <vector>

class QFormLayout;
class QComboBox;
class QLabel;
class QLineEdit;

namespace marbler::ui {

/// The tool's name on its button and in menus ("Comb").
QString toolName(EditorTool tool);
/// What the tool does with a click or a drag, for its button's tooltip.
QString toolTip(EditorTool tool);
/// Its key in the tool bar (a single letter).
QKeySequence toolShortcut(EditorTool tool);

class ToolOptions : public QWidget {
    Q_OBJECT
public:
    explicit ToolOptions(QWidget* parent = nullptr);

    /// Shows the rows of this tool only.
    void setTool(EditorTool tool);
    EditorTool tool() const { return mTool; }
    /// The palette the ink row chooses from (the swatches and their count).
    void setPalette(const std::vector<Color>& palette);
    void setSettings(const ToolSettings& settings);
    /// The design's dimension: a solid's circle and sphere have an axis row.
    void setDimension(int dimension);
    const ToolSettings& settings() const { return mSettings; }

signals:
    /// A value was changed by the user.
    void settingsChanged(const marbler::ui::ToolSettings& settings);

private:
    /// Whether a row shows for a tool (read from the registry through Gestures.h).
    using Shows = std::function<bool(EditorTool)>;
    /// One row: a spin box bound to a field of the settings, shown for some tools.
    struct Row {
        QWidget* field = nullptr;
        Shows shows;
    };
    void addRow(const QString& label, QWidget* field, Shows shows);
    void addNumber(const char* name, const QString& label, const QString& tip, double ToolSettings::*member,
                   double min, double max, const QString& suffix, Shows shows);
    void addCount(const char* name, const QString& label, const QString& tip, int ToolSettings::*member,
                  int min, int max, Shows shows);
    void refresh();
    void changed();

    QFormLayout* mForm;
    QComboBox* mInk;
    QComboBox* mField;
    QLineEdit* mAxis;   ///< a solid's circle or sphere: the axis typed (empty: across the section)
    QLabel* mAxisError; ///< why the typed axis was refused
    int mDimension = 2;
    std::vector<Row> mRows;
    std::vector<std::function<void()>> mLoaders; ///< each row reads its value from mSettings
    ToolSettings mSettings;
    EditorTool mTool = Tool::Drop;
    bool mLoading = false;
};

} // namespace marbler::ui

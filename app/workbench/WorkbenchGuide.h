#pragma once
/// The workbench's guide (Help ▸ Marbler guide): what the operators do, how to pick parents,
/// step through generations, keep favourites and see a design large, and every keyboard
/// shortcut, in the words of the window's own actions (shared/Help.h builds the table).

#include <QString>

namespace marbler::ui {

class WorkbenchWindow;

/// The whole guide, in the words of the window's own actions.
QString guideHtml(const WorkbenchWindow& window);

} // namespace marbler::ui

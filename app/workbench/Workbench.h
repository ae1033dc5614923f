#pragma once
/// The workbench window (the breeding grid). Entry point used by main() when no verb is given.

#include "workbench/WorkbenchArgs.h"

namespace marbler::ui {

class WorkbenchWindow;

/// How a session starts when no genome file is given.
struct StartOptions {
    std::vector<std::string> files;
    std::optional<int> dimension; ///< forced (command line or MARBLER_SOLID); no question then
    bool ask = true;              ///< whether the start choice may be asked at all
    /// The folder whose kept sessions are resumed and autosaved to (defaultSessionFolder() for
    /// the window); empty: neither.
    std::string sessionFolder;
};

/// Opens the files, or else resumes a kept session or makes the first random population: flat
/// or solid as forced, as the start chooser answers (unless "don't ask again" was ticked), or as
/// last time. With no files and no forced kind, the last session (SessionStore.h) is offered as
/// the default choice (and resumed when the question is not asked), the other kept sessions
/// beside it. Anything else starts a new session in a file of its own and keeps every other one
/// (the status bar says where). The single-session layout (`session.json`,
/// `session.previous.json`) is moved into the store first. A session file that does not load is
/// reported once and moved aside as `.bad`. From then on the session autosaves to its file.
void startSession(WorkbenchWindow& window, const StartOptions& options);

/// Creates the QApplication, opens the window (with the genome files named in argv) and runs
/// the event loop; returns the exit status (2 for a bad option, reported on one line).
int runWorkbench(int argc, char** argv);

} // namespace marbler::ui

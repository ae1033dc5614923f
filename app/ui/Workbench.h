#pragma once
/// The workbench window (the breeding grid). Entry point used by main() when no verb is given.

namespace marbler::ui {

/// Creates the QApplication, opens the window (with the genome files named in argv) and runs
/// the event loop; returns the exit status.
int runWorkbench(int argc, char** argv);

} // namespace marbler::ui

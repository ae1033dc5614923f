// placeholder: replaced by the window's owner
#include "ui/Workbench.h"
#include <iostream>
namespace marbler::ui {
int runWorkbench(int, char**) {
    std::cerr << "marbler: the workbench window is not built yet\n";
    return 1;
}
} // namespace marbler::ui

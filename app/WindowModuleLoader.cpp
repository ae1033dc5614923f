#include "WindowModule.h"

#include "marbler/Modules.h"

namespace marbler::app {

WindowModule& windowModule() {
    static WindowModule* module = [] {
        auto entry = reinterpret_cast<WindowModule* (*)()>(moduleEntry(WindowModuleFile, WindowModuleEntry));
        return entry();
    }();
    return *module;
}

} // namespace marbler::app

// placeholder: replaced by its owner
#include "cli/Cli.h"
#include <iostream>
namespace marbler::cli {
int runRender(std::span<const std::string>) {
    std::cerr << "marbler render: not built yet\n";
    return ExitFailure;
}
} // namespace marbler::cli

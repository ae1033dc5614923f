// placeholder: replaced by its owner
#include "cli/Cli.h"
#include <iostream>
namespace marbler::cli {
int runInfo(std::span<const std::string>) {
    std::cerr << "marbler info: not built yet\n";
    return ExitFailure;
}
} // namespace marbler::cli

// placeholder: replaced by its owner
#include "cli/Cli.h"
#include <iostream>
namespace marbler::cli {
int runRandom(std::span<const std::string>) {
    std::cerr << "marbler random: not built yet\n";
    return ExitFailure;
}
} // namespace marbler::cli

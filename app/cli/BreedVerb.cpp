// placeholder: replaced by its owner
#include "cli/Cli.h"
#include <iostream>
namespace marbler::cli {
int runBreed(std::span<const std::string>) {
    std::cerr << "marbler breed: not built yet\n";
    return ExitFailure;
}
} // namespace marbler::cli

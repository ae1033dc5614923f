// `marbler doctor`: what this machine gives Marbler (spec/cli.md). Every line is "what: value";
// a missing piece is reported, not fatal, so the command always runs to the end (exit 0).

#include "WindowModule.h"
#include "cli/Cli.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/ImageFormats.h"
#include "marbler/Modules.h"

#include <fstream>
#include <iostream>
#include <string>
#include <thread>

namespace marbler::cli {
namespace {

constexpr const char* DoctorHelp = R"(usage: marbler doctor

Reports what this machine gives Marbler: versions, the image formats and where they come from,
the OpenGL renderer found (or why none), the back end the window will render with and why, and
the CPU kernel in use. Loading OpenGL and OpenImageIO to ask them takes a moment.

environment:
  MARBLER_RENDERER=auto|gpu|cpu   the window's renderer, over its remembered setting
  MARBLER_KERNEL=auto|avx512|avx2|baseline
                                  the CPU kernel variant
  MARBLER_MODULE_DIR=DIR          where Marbler's modules are looked for first
)";

std::string cpuModel() {
    std::ifstream info("/proc/cpuinfo");
    std::string line;
    while (std::getline(info, line))
        if (line.rfind("model name", 0) == 0) {
            std::size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
        }
    return "unknown CPU";
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "" : ", ") + name;
    return out;
}

int doctor(std::span<const std::string> words) {
    Args args = parseArgs(words, {}, {"help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << DoctorHelp;
        return ExitOk;
    }
    if (!args.positional.empty())
        throw InputError("doctor takes no arguments (got '" + args.positional[0] + "')");

    std::cout << "marbler: 0.1.0\n";
    std::cout << "machine: " << cpuModel() << ", " << std::thread::hardware_concurrency() << " threads\n";
    const CpuKernelInfo kernel = cpuKernel();
    std::cout << "CPU kernel: " << kernel.name << " (" << kernel.reason << "); this CPU runs "
              << joined(cpuKernelsSupported()) << "\n";
    std::cout << "image files built in: " << builtinImageFormats() << "\n" << std::flush;
    try {
        std::cout << "other image formats: OpenImageIO " << openImageIoVersion() << " ("
                  << moduleLocation("marbler-imageio.so") << ")\n";
    } catch (const Error& e) {
        std::cout << "other image formats: unavailable: " << e.what() << "\n";
    }
#ifdef MARBLER_HAVE_GUI
    try {
        app::WindowModule& window = app::windowModule();
        std::cout << "window and GL back end: Qt " << window.qtVersion() << " ("
                  << moduleLocation(app::WindowModuleFile) << ")\n"
                  << std::flush;
        const app::GlReport report = window.probeGl();
        const gl::GlProbe& gl = report.probe;
        if (gl.available)
            std::cout << "OpenGL: " << gl.version << ", " << gl.renderer << " (" << gl.vendor << ")"
                      << (gl.software ? ", a software rasteriser" : ", hardware") << "\n";
        else
            std::cout << "OpenGL: none: " << gl.reason << "\n";
        std::cout << "window renders with: " << report.backend << ": " << report.backendWhy << "\n";
    } catch (const Error& e) {
        std::cout << "window and GL back end: unavailable: " << e.what() << "\n";
        std::cout << "window renders with: nothing (no window module)\n";
    }
#else
    std::cout << "window and GL back end: not built (MARBLER_BUILD_GUI=OFF)\n";
#endif
    return ExitOk;
}

} // namespace

int runDoctor(std::span<const std::string> words) {
    return guarded("doctor", [&] { return doctor(words); });
}

} // namespace marbler::cli

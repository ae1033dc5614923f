// The marbler executable: a verb runs headless (spec/cli.md); no verb opens the workbench.
// The window lives in a module loaded only then (WindowModule.h), so verbs start fast.

#include "WindowModule.h"
#include "cli/Cli.h"
#include "marbler/Error.h"
#include "workbench/Workbench.h"

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char* Usage = R"(usage: marbler [GENOME...]            open the workbench (with these designs)
       marbler --solid | --flat         open it breeding solid (3D) or flat (2D) designs
       marbler VERB [OPTIONS]           work headless (no display, no GPU needed)

verbs:
  render GENOME -o OUT    render a raster (PNG, TIFF, EXR, JPEG), a slice or a solid on an object
  svg GENOME -o OUT.svg   vector output of a flat design: every ink as filled paths
  info GENOME             check a genome and summarise it
  random --dimension 2|3 --seed N -o OUT.marble.json
                          a random genome; the same seed gives the same file
  breed OPERATOR PARENT... --seed N -o DIR
                          offspring by alter, recombine, swap or reinit
  bake GENOME --mesh NAME|FILE -o OUT.{glb,gltf,obj}
                          a design baked into an object's texture, for other 3D tools
  bake GENOME --slices AXIS --count N -o DIR
                          a solid design as a stack of cross-section images
  animate GENOME -o OUT   the making of a design: PNG frames, or .gif, .webp, .mp4, .webm
  video GENOME IN -o OUT  every frame of the video IN marbled, as PNG frames or a video
  paper --seed N -o OUT   a marbled paper in one command, its genome beside it
  doctor                  what this machine gives Marbler: versions, OpenGL, the window's
                          renderer and why, the CPU kernel in use

GENOME is a genome file (.marble.json) or a PNG or TIFF image Marbler wrote: every PNG and TIFF
it writes carries its genome. 'marbler VERB --help' describes each verb's options.
exit status: 0 success, 2 bad usage or bad input, 1 any other failure.
)";

bool hasDisplay() {
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) {
        const char* value = std::getenv(name);
        if (value && *value) return true;
    }
    return false;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (!words.empty()) {
        const std::string& verb = words[0];
        std::span<const std::string> rest(words.data() + 1, words.size() - 1);
        if (verb == "render") return marbler::cli::runRender(rest);
        if (verb == "info") return marbler::cli::runInfo(rest);
        if (verb == "random") return marbler::cli::runRandom(rest);
        if (verb == "breed") return marbler::cli::runBreed(rest);
        if (verb == "doctor") return marbler::cli::runDoctor(rest);
        if (verb == "svg") return marbler::cli::runSvg(rest);
        if (verb == "bake") return marbler::cli::runBake(rest);
        if (verb == "animate") return marbler::cli::runAnimate(rest);
        if (verb == "video") return marbler::cli::runVideo(rest);
        if (verb == "paper") return marbler::cli::runPaper(rest);
        if (verb == "--help" || verb == "-h" || verb == "help") {
            std::cout << Usage;
            return marbler::cli::ExitOk;
        }
        if (verb == "--version") {
            std::cout << "marbler 0.1.0\n";
            return marbler::cli::ExitOk;
        }
    }
#ifdef MARBLER_HAVE_GUI
    // No verb: the words are for the window (genome files and its options). A bad option is
    // reported here, on one line, before anything needs a display.
    const marbler::ui::WorkbenchArgs windowArgs = marbler::ui::parseWorkbenchArgs(words);
    if (!windowArgs.error.empty()) {
        std::cerr << windowArgs.error << "\n";
        return marbler::cli::ExitBadInput;
    }
    if (windowArgs.help) {
        std::cout << Usage;
        return marbler::cli::ExitOk;
    }
#else
    for (const std::string& word : words)
        if (word.starts_with("-")) {
            std::cerr << "marbler: unknown option " << word << " (see marbler --help)\n";
            return marbler::cli::ExitBadInput;
        }
#endif
    // No verb: genome files (or nothing) open the workbench.
    if (!hasDisplay()) {
        std::cout << "marbler: no display here, so the workbench window cannot open.\n"
                     "Run it on a desktop session, or under a virtual display:\n"
                     "    xvfb-run -a marbler\n"
                     "or use the headless verbs, which need no display and no GPU:\n\n"
                  << Usage;
        return marbler::cli::ExitOk;
    }
#ifdef MARBLER_HAVE_GUI
    try {
        return marbler::app::windowModule().runWorkbench(argc, argv);
    } catch (const marbler::Error& e) {
        std::cerr << "marbler: cannot open the workbench: " << e.what() << "\n";
        return marbler::cli::ExitFailure;
    }
#else
    std::cerr << "marbler: this build has no workbench window (built without MARBLER_BUILD_GUI)\n";
    return marbler::cli::ExitFailure;
#endif
}

// libFuzzer target: bytes from the fuzzer as a breeding session file (workbench/Session.h), as a
// session folder copied from another machine or damaged by a crash can hold. parseSession must
// read it or refuse it with an InputError (a GenomeError naming the generation and cell); what
// it accepts must hold the promises the window relies on (a current generation that exists,
// parents earlier than their children, nine cells each, designs that save and read back). Any
// other exception, a crash, a sanitizer report or a hang is a finding. Qt is Debian's, not
// instrumented: coverage comes from Marbler's own code (Session.cpp, PopulationModel.cpp and the
// genome reader), which is. The same bytes are also read as one generation's file of a version 3
// session (parseGenerationText), which the session's folder holds beside its head.

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "workbench/Session.h"

#include <QCoreApplication>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

namespace {

[[noreturn]] void sessionFinding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_session: %s\n%s\n", what, detail.c_str());
    std::abort();
}

/// A design the session held is a genome file's design: it saves and reads back.
void checkDesign(const marbler::Genome& design) {
    try {
        const std::string saved = marbler::serializeGenome(design);
        if (!(marbler::parseGenome(saved, "saved") == design))
            sessionFinding("a session's design that does not read back as saved", saved);
    } catch (const marbler::Error& e) {
        sessionFinding("a session's design that does not save and read back", e.what());
    }
}

/// The same bytes as one generation's file of a version 3 session (g000001.json: its parent
/// must come before it).
void fuzzGenerationFile(std::string_view text) {
    marbler::ui::Generation generation;
    try {
        generation = marbler::ui::parseGenerationText(text, 1, "g000001.json");
    } catch (const marbler::InputError&) {
        return;
    } catch (const std::exception& e) {
        sessionFinding("an exception other than InputError from a generation file", e.what());
    }
    if (generation.parent < -1 || generation.parent >= 1)
        sessionFinding("an accepted generation file whose parent does not come before it");
    for (const auto& cell : generation.cells)
        if (cell) checkDesign(*cell);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    // QString, QDateTime and QFileInfo need no application, but the window always has one: read
    // sessions as it does.
    static std::unique_ptr<QCoreApplication> app = std::make_unique<QCoreApplication>(*argc, *argv);
    // A line a skipped file or step logs is the expected outcome, not worth printing a million times.
    qInstallMessageHandler([](QtMsgType, const QMessageLogContext&, const QString&) {});
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzzGenerationFile(text);
    marbler::ui::SavedSession session;
    try {
        session = marbler::ui::parseSession(text, "fuzz.json");
    } catch (const marbler::InputError&) {
        return 0; // refused, with its message: the expected outcome for most inputs
    } catch (const std::exception& e) {
        sessionFinding("an exception other than InputError", e.what());
    }
    if (session.history.empty()) sessionFinding("an accepted session without generations");
    if (session.current < 0 || std::size_t(session.current) >= session.history.size())
        sessionFinding("an accepted session whose current generation does not exist");
    if (session.dimension != 2 && session.dimension != 3)
        sessionFinding("an accepted session of dimension not 2 or 3");
    for (std::size_t k = 0; k < session.history.size(); ++k) {
        const auto& g = session.history[k];
        if (g.parent >= int(k) || (k == 0 && g.parent != -1) || (k > 0 && g.parent < 0))
            sessionFinding("an accepted generation whose parent is not an earlier one", std::to_string(k));
        for (const auto& cell : g.cells)
            if (cell) checkDesign(*cell);
    }
    return 0;
}

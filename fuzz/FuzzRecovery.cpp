// libFuzzer target: bytes from the fuzzer as an editor's recovery file (editor/Recovery.h), left
// behind by a crash and read at the next start. pendingRecoveries must take it or skip it with a
// warning, never stop; a design it takes must open in the editor (EditorDocument) and be the
// same design when written and opened again, muted steps included, as a recovered design is
// expected to be. Any other outcome (an exception, a crash, a sanitizer report, a hang) is a
// finding. Qt is Debian's, not instrumented: coverage comes from Marbler's own code
// (Recovery.cpp, EditorDocument.cpp and the genome reader), which is.

#include "editor/EditorDocument.h"
#include "editor/Recovery.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QStringList>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

[[noreturn]] void recoveryFinding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_recovery: %s\n%s\n", what, detail.c_str());
    std::abort();
}

/// A folder of this process's own, so parallel fuzzing jobs do not share files.
const QString& recoveryFolder() {
    static const QString dir = [] {
        const QString d = QDir::temp().filePath(QStringLiteral("marbler-fuzz-recovery-%1").arg(getpid()));
        QDir().mkpath(d);
        return d;
    }();
    return dir;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    // QLockFile and QStandardPaths read the application's name: one application, made once.
    static std::unique_ptr<QCoreApplication> app = std::make_unique<QCoreApplication>(*argc, *argv);
    // A line a skipped file or step logs is the expected outcome, not worth printing a million times.
    qInstallMessageHandler([](QtMsgType, const QMessageLogContext&, const QString&) {});
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QString file =
        QDir(recoveryFolder()).filePath(QStringLiteral("20261203-120000-fuzz.recovery.json"));
    {
        QFile out(file);
        if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) recoveryFinding("cannot write the input");
        out.write(reinterpret_cast<const char*>(data), qint64(size));
    }
    using namespace marbler::ui;
    std::vector<RecoveredDesign> found;
    QStringList warnings;
    try {
        found = pendingRecoveries(recoveryFolder(), &warnings);
    } catch (const std::exception& e) {
        recoveryFinding("pendingRecoveries threw", e.what());
    }
    if (found.size() + std::size_t(warnings.size()) != 1)
        recoveryFinding("the file was neither taken nor skipped with a warning");
    for (const RecoveredDesign& r : found) {
        try {
            EditorDocument doc(r.design);
            const marbler::Genome written = doc.fileGenome();
            (void)doc.renderedDesign();
            EditorDocument again(written);
            if (!(again.fileGenome() == written))
                recoveryFinding("a recovered design that is not the same when written and opened again",
                                marbler::serializeGenome(written));
        } catch (const std::exception& e) {
            recoveryFinding("a recovered design that the editor cannot hold", e.what());
        }
    }
    QFile::remove(file);
    return 0;
}

// soak_memory: the resident memory of a long session, driving the real classes without a
// window. Prints a table: after 100, 1,000 and 10,000 random edits of one design in the editor's
// document (EditorDocument: the kinds of edit the editor makes, drags merged) and after 100 and
// 1,000 generations bred in the workbench's model (PopulationModel, its session autosaved to a
// temporary folder as the window does), VmRSS and VmHWM from /proc/self/status and, for the
// editor, the history's own bytes (EditorDocument::historyBytes). docs/performance.md, "Long
// sessions", has the figures.
//
//   soak_memory [--edits N] [--generations N] [--breed-every N] [--seeds DIR]
//
// --breed-every N breeds every Nth generation only (default: every one) and makes the others by
// placing designs, as large as bred ones: breeding the generator's designs takes seconds each.
//
// --seeds DIR also writes, into DIR/session and DIR/recovery, session and recovery files made by
// the app's own code (the seed corpora of fuzz_session and fuzz_recovery).

#include "PlacedVariants.h"
#include "editor/EditorDocument.h"
#include "editor/Recovery.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QUndoStack>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>
#include <string>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// VmRSS and VmHWM in MiB.
std::pair<double, double> residentMiB() {
    std::ifstream in("/proc/self/status");
    std::string line;
    double rss = 0, hwm = 0;
    while (std::getline(in, line)) {
        if (line.rfind("VmRSS:", 0) == 0) rss = std::stod(line.substr(6)) / 1024.0;
        if (line.rfind("VmHWM:", 0) == 0) hwm = std::stod(line.substr(6)) / 1024.0;
    }
    return {rss, hwm};
}

void row(const char* what, long steps, double historyMiB) {
    const auto [rss, hwm] = residentMiB();
    if (historyMiB >= 0)
        std::printf("| %-22s | %8ld | %9.1f | %9.1f | %12.2f |\n", what, steps, rss, hwm, historyMiB);
    else
        std::printf("| %-22s | %8ld | %9.1f | %9.1f | %12s |\n", what, steps, rss, hwm, "");
    std::fflush(stdout);
}

void writeText(const QString& file, const std::string& text) {
    std::ofstream(QFile::encodeName(file).toStdString(), std::ios::binary) << text;
}

/// A random flat design, as a new population's are.
Genome startDesign(std::uint64_t seed) {
    return randomGenome(seed, 2);
}

/// One random edit of the kinds the editor makes (the mix of EditorHistoryBoundTest).
void randomEdit(EditorDocument& doc, std::mt19937_64& rng) {
    const std::size_t n = doc.stepCount();
    const auto pick = [&] { return static_cast<std::size_t>(rng() % n); };
    switch (rng() % 10) {
    case 0:
        if (n < 400) {
            Operation op = defaultOperation(Tool::Drop, 2, {double(rng() % 1000), double(rng() % 1000), 0.0});
            op.radius = 10.0 + double(rng() % 50);
            doc.addStep(op, pick());
        }
        break;
    case 1:
        if (n > 20) doc.removeStep(pick());
        break;
    case 2:
        doc.moveStep(pick(), pick());
        break;
    case 3:
        doc.setMuted(pick(), rng() % 2 == 0);
        break;
    case 4:
        doc.setPaletteColor(0, {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())});
        break;
    default: {
        const std::size_t i = pick();
        Operation op = doc.step(i);
        op.center.x = double(rng() % 1000);
        doc.setStep(i, op);
        break;
    }
    }
}

void soakEditor(long edits, const QString& seeds) {
    std::mt19937_64 rng(11);
    EditorDocument doc(startDesign(11));
    long done = 0;
    for (long mark : {100L, 1000L, 10000L, 100000L}) {
        if (mark > edits) break;
        while (done < mark) {
            randomEdit(doc, rng);
            ++done;
        }
        // The history's own bytes where the document counts them (built against an older
        // EditorDocument for the "before" figures, the bench prints the resident sizes only).
        const auto history = [](const auto& d) {
            if constexpr (requires { d.historyBytes(); })
                return double(d.historyBytes()) / 1048576.0;
            else
                return -1.0;
        };
        row("editor: edits", done, history(doc));
    }
    if (!seeds.isEmpty()) {
        // A recovery file with muted steps, as the autosave writes it.
        QDir().mkpath(seeds + "/recovery");
        for (std::size_t i = 0; i < doc.stepCount() && i < 3; ++i)
            doc.setMuted(i * 2, true);
        QTemporaryDir dir;
        EditorAutosave autosave(&doc, dir.path());
        autosave.flush();
        QFile::copy(autosave.file(), seeds + "/recovery/editor-muted.recovery.json");
        EditorDocument small(startDesign(3));
        small.setBleed(2.0);
        EditorAutosave second(&small, dir.path());
        second.flush();
        QFile::copy(second.file(), seeds + "/recovery/editor-small.recovery.json");
        autosave.discard();
        second.discard();
    }
}

void soakWorkbench(long generations, long breedEvery, const QString& seeds) {
    QTemporaryDir dir;
    PopulationModel model;
    model.setSessionSeed(5);
    model.newRandomPopulation(2);
    model.setSessionFile(dir.filePath("session.json"));
    std::mt19937_64 rng(5);
    long done = 0;
    row("workbench: generations", 0, -1);
    for (long mark : {10L, 100L, 1000L, 10000L}) {
        if (mark > generations) break;
        while (done < mark) {
            model.clearSelection();
            const bool alter = rng() % 3 == 0;
            const int a = int(rng() % CellCount);
            model.setSelected(a, true);
            if (!alter) model.setSelected((a + 1 + int(rng() % (CellCount - 1))) % CellCount, true);
            // Breeding the generator's designs takes seconds a generation here: --breed-every N
            // breeds every Nth generation and fills the others with placed designs.
            if (done % breedEvery == 0)
                model.apply(alter ? GeneticOperator::Alter : GeneticOperator::Recombine, 0.5);
            else
                test::placeVariants(model, rng);
            if (rng() % 10 == 0) model.goBack(); // branches, as a user trying again makes
            ++done;
            if (!seeds.isEmpty() && done == 3) {
                QDir().mkpath(seeds + "/session");
                // One document (version 2, what parseSession reads): the autosave's version 3
                // keeps its generations in files of their own.
                writeText(seeds + "/session/flat-3-generations.json", serializeSession(model));
            }
        }
        // The model's own bytes where it counts them (PopulationModel::historyBytes; built against
        // an older model for the "before" figures, the bench prints the resident sizes only).
        const auto held = [](const auto& m) {
            if constexpr (requires { m.historyBytes(); })
                return double(m.historyBytes()) / 1048576.0;
            else
                return -1.0;
        };
        row("workbench: generations", done, held(model));
        // One autosave as the window makes after each change, timed alone.
        QElapsedTimer clock;
        clock.start();
        model.saveSession();
        const double ms = double(clock.nsecsElapsed()) / 1e6;
        qint64 bytes = 0;
        QDirIterator files(dir.path(), QDir::Files, QDirIterator::Subdirectories);
        while (files.hasNext())
            bytes += QFileInfo(files.next()).size();
        std::printf("|   autosave %.1f ms, session on disk %.1f MiB\n", ms, double(bytes) / 1048576.0);
        std::fflush(stdout);
    }
    if (!seeds.isEmpty()) {
        PopulationModel solid;
        solid.setSessionSeed(9);
        solid.newRandomPopulation(3);
        solid.setSessionFile(dir.filePath("solid.json"));
        writeText(seeds + "/session/solid-1-generation.json", serializeSession(solid));
    }
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    long edits = 10000, generations = 1000, breedEvery = 1;
    QString seeds;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--edits")
            edits = std::stol(argv[i + 1]);
        else if (flag == "--generations")
            generations = std::stol(argv[i + 1]);
        else if (flag == "--breed-every")
            breedEvery = std::max(1L, std::stol(argv[i + 1]));
        else if (flag == "--seeds")
            seeds = QString::fromLocal8Bit(argv[i + 1]);
        else {
            std::fprintf(stderr, "soak_memory: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    std::printf("| %-22s | %8s | %9s | %9s | %12s |\n", "what", "steps", "VmRSS MiB", "VmHWM MiB",
                "history MiB");
    std::printf("|%s|%s|%s|%s|%s|\n", std::string(24, '-').c_str(), std::string(10, '-').c_str(),
                std::string(11, '-').c_str(), std::string(11, '-').c_str(), std::string(14, '-').c_str());
    row("start", 0, -1);
    soakEditor(edits, seeds);
    soakWorkbench(generations, breedEvery, seeds);
    return 0;
}

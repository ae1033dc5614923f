#include "workbench/Workbench.h"

#include "editor/EditorWindow.h"
#include "editor/Recovery.h"
#include "marbler/Error.h"
#include "marbler/GenomeImage.h"
#include "shared/ErrorReport.h"
#include "shared/Language.h"
#include "shared/RenderService.h"
#include "shared/StartDialog.h"
#include "workbench/Session.h"
#include "workbench/SessionStore.h"
#include "workbench/SessionsController.h"
#include "workbench/WorkbenchWindow.h"

#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QStatusBar>
#include <QStringList>
#include <QTimer>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <time.h>
#include <unistd.h>

namespace marbler::ui {

namespace {

/// `--screenshot FILE`: breed from the middle design, wait for every final image, save the
/// window and quit. Used to make docs/screenshot.png reproducibly.
void takeScreenshot(WorkbenchWindow& window, RenderService& service, const QString& file, int* status) {
    auto done = std::make_shared<bool>(false);
    auto grab = [&window, &service, file, status, done] {
        // Wait for the shelf's thumbnails too, not only the grid.
        if (*done || !window.renderingDone() || !service.idle()) return;
        *done = true;
        if (!window.grab().save(file)) {
            std::cerr << "marbler: cannot write " << file.toStdString() << "\n";
            *status = 1;
        }
        QApplication::quit();
    };
    auto breedThenGrab = [&window, &service, grab] {
        if (window.model()->cell(4)) {
            // Two generations: two random designs recombined, then one offspring altered.
            window.model()->clearSelection();
            window.model()->setSelected(0, true);
            window.model()->setSelected(4, true);
            window.applyOperator(GeneticOperator::Recombine);
            window.model()->clearSelection();
            window.model()->setSelected(2, true);
            window.applyOperator(GeneticOperator::Alter);
            // Show a stocked shelf, but only into a folder chosen for the picture.
            if (!qEnvironmentVariableIsEmpty("MARBLER_FAVOURITES_DIR")) {
                window.keepFavourite(0);
                window.keepFavourite(5);
                window.keepFavourite(8);
            }
        }
        // Rendering restarts with the new generation; grab when it all has its final image.
        QObject::connect(&service, &RenderService::becameIdle, &window, grab);
    };
    // Let the window settle at its size (the resize debounce) before breeding.
    QObject::connect(
        &service, &RenderService::backendReady, &window,
        [breedThenGrab] { QTimer::singleShot(500, breedThenGrab); }, Qt::SingleShotConnection);
}

/// MARBLER_EDITOR_SCREENSHOT=FILE with a design file: open the design in the editor with its
/// first stroke selected (its parameters in the form, its handles on the canvas), wait for every
/// final image, save a picture of the editor window and quit. Makes the README's pictures of
/// the editor from the real window.
void takeEditorScreenshot(WorkbenchWindow& window, RenderService& service, const QString& design,
                          const QString& file, int* status) {
    auto open = [&window, &service, design, file, status] {
        Genome g;
        try {
            g = loadDesign(design.toStdString());
        } catch (const Error& e) {
            std::cerr << "marbler: " << e.what() << "\n";
            *status = 1;
            QApplication::quit();
            return;
        }
        EditorWindow* editor = window.openEditor(g, design);
        editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
        // MARBLER_EDITOR_SCREENSHOT_SIZE=WxH: the window's size (a laptop's 1366x768, say).
        const QStringList size =
            qEnvironmentVariable("MARBLER_EDITOR_SCREENSHOT_SIZE").split(QLatin1Char('x'));
        if (size.size() == 2 && size[0].toInt() > 0 && size[1].toInt() > 0)
            editor->resize(size[0].toInt(), size[1].toInt());
        else
            editor->resize(1680, 960);
        if (!g.operations.empty()) editor->selectStep(g.initial.size());
        auto grab = [editor, &service, file, status] {
            if (!service.idle()) return;
            if (!editor->grab().save(file)) {
                std::cerr << "marbler: cannot write " << file.toStdString() << "\n";
                *status = 1;
            }
            QApplication::quit();
        };
        // Grab once the renders settle (a short wait lets the docks take their sizes first).
        QObject::connect(&service, &RenderService::becameIdle, editor,
                         [grab] { QTimer::singleShot(700, grab); });
    };
    QObject::connect(
        &service, &RenderService::backendReady, &window, [open] { QTimer::singleShot(300, open); },
        Qt::SingleShotConnection);
}

/// Seconds since this process started (the kernel's start time, so the dynamic loading before
/// main() counts too).
double secondsSinceLaunch() {
    QFile stat(QStringLiteral("/proc/self/stat"));
    timespec now{};
    if (!stat.open(QIODevice::ReadOnly) || ::clock_gettime(CLOCK_BOOTTIME, &now) != 0) return -1.0;
    // Field 22, after the parenthesised command name (which may hold spaces): start time in ticks.
    const QByteArray text = stat.readAll();
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 20) return -1.0;
    const double started = fields[19].toDouble() / double(::sysconf(_SC_CLK_TCK));
    return double(now.tv_sec) + double(now.tv_nsec) * 1e-9 - started;
}

/// MARBLER_EXIT_WHEN_SHOWN=1: print how long after launch the first population was shown
/// sharp (every cell's final image) and quit; the window's start-up benchmark
/// (tests/bench/process) runs the whole process this way.
void exitWhenShown(WorkbenchWindow& window) {
    QObject::connect(
        &window, &WorkbenchWindow::renderingFinished, &window,
        [] {
            std::cout << "first population shown " << secondsSinceLaunch() << " s after launch" << std::endl;
            QApplication::quit();
        },
        Qt::SingleShotConnection);
}

} // namespace

void startSession(WorkbenchWindow& window, const StartOptions& options) {
    std::optional<SessionStore> store;
    std::vector<KeptSession> kept;
    if (!options.sessionFolder.empty()) {
        store.emplace(QString::fromStdString(options.sessionFolder));
        QStringList problems;
        store->migrate(&problems);
        if (!problems.isEmpty())
            reportError(
                &window, WorkbenchWindow::tr("Cannot move the saved sessions"),
                WorkbenchWindow::tr("Sessions saved by an earlier Marbler could not be moved into the "
                                    "list of kept sessions; they are left where they are.\n\n%1")
                    .arg(problems.join(QStringLiteral("\n"))));
        // Deleted sessions can be brought back for 30 days; older ones go at start.
        store->emptyTrash(30);
        kept = store->list();
        window.setSessionStore(store->sessionFolder());
    }
    // A kept session that does not load is reported once, moved aside as `.bad` and taken off
    // the list; it never stops the start.
    const auto load = [&window, &kept](const KeptSession& session) -> std::optional<SavedSession> {
        try {
            return loadSession(session.file);
        } catch (const std::exception& e) {
            reportBadSession(&window, session.file, QString::fromUtf8(e.what()));
            std::erase_if(kept, [&](const KeptSession& k) { return k.id == session.id; });
            return std::nullopt;
        }
    };
    // The last session is offered only to a start that names neither files nor a kind; one that
    // does starts a new session, and the last one stays kept.
    std::optional<SavedSession> saved;
    std::optional<KeptSession> last;
    if (options.files.empty() && !options.dimension) {
        for (const KeptSession& candidate : std::vector<KeptSession>(kept)) {
            if ((saved = load(candidate))) {
                last = candidate;
                break;
            }
        }
    }

    if (!options.files.empty()) {
        QStringList files;
        for (const std::string& f : options.files)
            files << QString::fromStdString(f);
        window.openFiles(files);
    }
    // Opened designs are generation 1; with none (no files, or none that loaded) the saved
    // session or a random population is.
    std::optional<KeptSession> resumed;
    if (window.model()->isEmptyWorkbench()) {
        StartChoice choice = lastStartChoice();
        if (saved) {
            choice.resume = true;
            choice.resumeGeneration = saved->history[std::size_t(saved->current)].number;
            choice.resumeDimension = saved->dimension;
            choice.resumeName = last->name;
        }
        for (const KeptSession& k : kept)
            if (!last || k.id != last->id)
                choice.otherSessions.append(
                    {k.id, QStringLiteral("%1 — %2").arg(k.name, describeSession(k))});
        if (options.dimension) {
            choice.dimension = *options.dimension;
        } else if (options.ask && askStartChoice()) {
            if (const auto chosen = chooseStart(&window, choice)) choice = *chosen;
        }
        if (choice.resume && !choice.resumeId.isEmpty() && (!last || choice.resumeId != last->id)) {
            // Another kept session than the last.
            saved.reset();
            const auto other = std::find_if(kept.begin(), kept.end(),
                                            [&](const KeptSession& k) { return k.id == choice.resumeId; });
            if (other != kept.end()) {
                last = *other;
                saved = load(*other);
            }
        }
        if (saved && choice.resume) {
            window.resumeSession(std::move(*saved));
            resumed = last;
        } else {
            if (choice.dimension == 3) window.setMesh(choice.mesh);
            window.newRandomPopulation(choice.dimension);
        }
    }
    if (!store) return;
    if (resumed) {
        window.model()->setSessionFile(resumed->file);
        return;
    }
    // A new session: a file of its own beside the kept ones, which stay as they are.
    const KeptSession fresh = store->create(window.model()->populationDimension());
    window.model()->setSessionLabel({fresh.name, fresh.created});
    window.model()->setSessionFile(fresh.file);
    if (!kept.empty())
        window.statusBar()->showMessage(
            WorkbenchWindow::tr(
                "Started a new session; your previous session “%1” is kept under File ▸ Sessions")
                .arg(kept.front().name),
            15000);
}

int runWorkbench(int argc, char** argv) {
    const std::vector<std::string> words(argv + std::min(argc, 1), argv + argc);
    const WorkbenchArgs args = parseWorkbenchArgs(words);
    if (!args.error.empty()) {
        std::cerr << args.error << "\n";
        return 2;
    }

    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Marbler"));
    QApplication::setApplicationName(QStringLiteral("Marbler"));
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));
    // Ties the window to the installed launcher (app/desktop/marbler.desktop): its icon and name
    // in docks and task switchers (Wayland's app id).
    QGuiApplication::setDesktopFileName(QStringLiteral("marbler"));
    installLanguage(chosenLanguage()); // issue 25: the window's words (MARBLER_LANGUAGE=tr|de|en)

    // The hidden options can also come from the environment: MARBLER_SCREENSHOT=FILE,
    // MARBLER_SEED=N, MARBLER_SOLID=1 (or 0 for flat), MARBLER_NO_START_DIALOG=1, and
    // MARBLER_EDITOR_SCREENSHOT=FILE with a design file (takeEditorScreenshot).
    QString screenshotFile = QString::fromStdString(args.screenshot);
    if (screenshotFile.isEmpty()) screenshotFile = qEnvironmentVariable("MARBLER_SCREENSHOT");
    // The editor's picture: like the window's, a fresh session with no questions.
    const QString editorShot =
        args.files.empty() ? QString() : qEnvironmentVariable("MARBLER_EDITOR_SCREENSHOT");
    if (!editorShot.isEmpty()) screenshotFile = editorShot;
    std::optional<unsigned long long> seed = args.seed;
    if (!seed && !qEnvironmentVariableIsEmpty("MARBLER_SEED"))
        seed = qEnvironmentVariable("MARBLER_SEED").toULongLong();
    StartOptions start;
    start.files = args.files;
    start.dimension = args.dimension;
    if (!start.dimension && !qEnvironmentVariableIsEmpty("MARBLER_SOLID"))
        start.dimension = qEnvironmentVariableIntValue("MARBLER_SOLID") == 1 ? 3 : 2;
    start.ask = screenshotFile.isEmpty() && qEnvironmentVariableIntValue("MARBLER_NO_START_DIALOG") != 1;
    // A screenshot is made from a fresh, reproducible session and leaves the saved one alone.
    if (screenshotFile.isEmpty()) start.sessionFolder = defaultSessionFolder().toStdString();

    RenderService service;
    WorkbenchWindow window(&service);
    if (seed) window.model()->setSessionSeed(*seed);
    int status = 0;
    if (!editorShot.isEmpty()) {
        takeEditorScreenshot(window, service, QString::fromStdString(args.files.front()), editorShot,
                             &status);
    } else if (!screenshotFile.isEmpty()) {
        window.resize(1280, 900);
        takeScreenshot(window, service, screenshotFile, &status);
    }
    if (qEnvironmentVariableIntValue("MARBLER_EXIT_WHEN_SHOWN") == 1) exitWhenShown(window);
    window.show();
    // Asked over the shown window, so the question sits on the workbench it sets up.
    startSession(window, start);
    // Designs an editor left unsaved when Marbler stopped are offered back, after the session.
    if (screenshotFile.isEmpty() && qEnvironmentVariableIntValue("MARBLER_EXIT_WHEN_SHOWN") != 1)
        QTimer::singleShot(0, &window, [&window] { window.offerRecoveries(defaultRecoveryFolder()); });
    const int result = QApplication::exec();
    return status != 0 ? status : result;
}

} // namespace marbler::ui

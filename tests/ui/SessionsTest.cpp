// Kept sessions (SessionStore): starting differently never discards a session, the single-session
// layout migrates, sessions are resumed, renamed and deleted (undoably) from the window; and
// removed favourites go to a trash they can be restored from.

#include "TestUtil.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "shared/ErrorReport.h"
#include "shared/RenderService.h"
#include "shared/StartDialog.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/SessionStore.h"
#include "workbench/SessionsDialog.h"
#include "workbench/Trash.h"
#include "workbench/Workbench.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace marbler;
using namespace marbler::ui;
using marbler::test::ErrorCapture;

namespace {

/// Every generation's designs as text, for exact comparisons of whole sessions.
std::vector<std::string> designs(const PopulationModel& model) {
    std::vector<std::string> result;
    for (int k = 0; k < int(model.history().size()); ++k)
        for (const auto& cell : model.generation(k).cells)
            result.push_back(cell ? serializeGenome(*cell) : std::string("(empty)"));
    return result;
}

/// A start in a session folder of its own, with the start question answered by the test.
class SessionsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(mFavourites.isValid());
        ASSERT_TRUE(mSession.isValid());
        QSettings().clear();
        qputenv("MARBLER_FAVOURITES_DIR", mFavourites.path().toLocal8Bit());
        options.sessionFolder = mSession.path().toStdString();
        setStartChooser([this](QWidget*, const StartChoice& defaults) -> std::optional<StartChoice> {
            ++asked;
            offered = defaults;
            if (!answer) return std::nullopt;
            return answer(defaults);
        });
    }
    void TearDown() override {
        setStartChooser({});
        qunsetenv("MARBLER_FAVOURITES_DIR");
    }
    SessionStore store() const { return SessionStore(mSession.path()); }
    /// Answers the start question with a new population of a kind.
    void answerNew(int dimension) {
        answer = [dimension](const StartChoice&) { return StartChoice{dimension, QStringLiteral("vase")}; };
    }
    /// Breeds `generations` generations from the first design.
    static void breed(WorkbenchWindow& window, int generations) {
        for (int k = 0; k < generations; ++k) {
            window.model()->clearSelection();
            window.model()->setSelected(k % 9, true);
            ASSERT_TRUE(window.applyOperator(GeneticOperator::Alter));
        }
    }

    QTemporaryDir mFavourites;
    QTemporaryDir mSession;
    StartOptions options;
    RenderService service{RenderService::Backend::Cpu};
    int asked = 0;
    StartChoice offered;
    std::function<StartChoice(const StartChoice&)> answer;
};

TEST_F(SessionsTest, StartingWithAKindOrFilesKeepsTheLastSessionResumable) {
    answerNew(2);
    std::vector<std::string> bred;
    QString bredFile;
    const int generations = test::fullOrSanitized(25, 6); // the user who lost 25 generations
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        breed(window, generations);
        bred = designs(*window.model());
        bredFile = window.model()->sessionFile();
    }
    const QString bredName = store().list().front().name;
    EXPECT_TRUE(bredName.startsWith(QStringLiteral("Flat session, "))) << bredName.toStdString();

    // `marbler --solid`: a new session, and the bred one stays, said so on the status bar.
    {
        WorkbenchWindow window(&service);
        StartOptions solid = options;
        solid.dimension = 3;
        startSession(window, solid);
        EXPECT_EQ(window.model()->populationDimension(), 3);
        EXPECT_NE(window.model()->sessionFile(), bredFile);
        EXPECT_EQ(
            window.statusBar()->currentMessage(),
            QStringLiteral("Started a new session; your previous session “%1” is kept under File ▸ Sessions")
                .arg(bredName));
        EXPECT_TRUE(window.model()->sessionLabel().name.startsWith(QStringLiteral("Solid session, ")));
    }
    // `marbler a.marble.json`: another new one.
    const std::string file = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    {
        WorkbenchWindow window(&service);
        StartOptions files = options;
        files.files = {file};
        startSession(window, files);
        EXPECT_EQ(*window.model()->cell(0), loadGenome(file));
        EXPECT_EQ(window.model()->history().size(), 1u);
    }
    EXPECT_EQ(asked, 1) << "only the first start asked: a kind or files skip the question";
    ASSERT_EQ(store().list().size(), 3u) << "no session was discarded";
    PopulationModel reread;
    reread.restoreSession(loadSession(bredFile));
    ASSERT_EQ(designs(reread), bred) << "the bred session's file is untouched";

    // A plain start offers the last session (the opened file) and the others, and resumes the
    // one picked: every generation of it.
    answer = [](const StartChoice& offer) {
        StartChoice choice = offer;
        choice.resume = true;
        choice.resumeId = offer.otherSessions.back().first; // the oldest: the bred one
        return choice;
    };
    WorkbenchWindow window(&service);
    startSession(window, options);
    EXPECT_EQ(asked, 2);
    EXPECT_EQ(offered.resumeGeneration, 1);
    ASSERT_EQ(offered.otherSessions.size(), 2);
    EXPECT_TRUE(offered.otherSessions.back().second.startsWith(
        bredName + QStringLiteral(" — generation %1").arg(generations + 1)))
        << offered.otherSessions.back().second.toStdString();
    EXPECT_EQ(designs(*window.model()), bred);
    EXPECT_EQ(window.model()->currentIndex(), generations);
    EXPECT_EQ(window.model()->sessionFile(), bredFile) << "it goes on saving to its own file";
    EXPECT_EQ(window.model()->sessionLabel().name, bredName);
    EXPECT_EQ(store().list().size(), 3u) << "resuming makes no new session";
    EXPECT_EQ(store().list().front().file, bredFile) << "and makes it the last one";
}

TEST_F(SessionsTest, TheSingleSessionLayoutMigratesIntoTheStore) {
    // What the Marbler before kept sessions left: session.json and session.previous.json.
    const auto writeOld = [&](const QString& name, int dimension, const QDateTime& modified) {
        PopulationModel model;
        model.setSessionSeed(dimension * 10);
        model.newRandomPopulation(dimension);
        model.newRandomPopulation(dimension);
        model.setSessionFile(QDir(mSession.path()).filePath(name));
        QFile f(model.sessionFile());
        EXPECT_TRUE(f.open(QIODevice::ReadWrite));
        EXPECT_TRUE(f.setFileTime(modified, QFileDevice::FileModificationTime));
        return designs(model);
    };
    const QDateTime now = QDateTime::currentDateTime();
    const auto current = writeOld(QStringLiteral("session.json"), 2, now.addSecs(-3600));
    const auto previous = writeOld(QStringLiteral("session.previous.json"), 3, now.addDays(-2));

    answer = [](const StartChoice& offer) { return offer; }; // the default: resume the last one
    WorkbenchWindow window(&service);
    startSession(window, options);
    EXPECT_FALSE(QFileInfo::exists(mSession.filePath(QStringLiteral("session.json"))));
    EXPECT_FALSE(QFileInfo::exists(mSession.filePath(QStringLiteral("session.previous.json"))));
    const auto kept = store().list();
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_EQ(designs(*window.model()), current) << "session.json was the last session";
    EXPECT_EQ(window.model()->sessionFile(), kept[0].file);
    EXPECT_EQ(kept[0].name, defaultSessionName(2, now.addSecs(-3600)));
    EXPECT_EQ(kept[1].name, defaultSessionName(3, now.addDays(-2)));
    EXPECT_EQ(kept[1].dimension, 3);
    EXPECT_EQ(kept[1].generation, 2);
    EXPECT_LT(std::abs(kept[1].modified.secsTo(now.addDays(-2))), 2) << "its time is kept";
    ASSERT_EQ(offered.otherSessions.size(), 1);
    EXPECT_EQ(offered.otherSessions.front().first, kept[1].id);
    EXPECT_EQ(loadSession(kept[1].file).label.name, kept[1].name) << "named in its file";

    // The older one resumes from the window, whole.
    ASSERT_TRUE(window.resumeKeptSession(kept[1].id));
    EXPECT_EQ(designs(*window.model()), previous);
    EXPECT_EQ(window.model()->populationDimension(), 3);
    EXPECT_TRUE(
        window.statusBar()->currentMessage().contains(QStringLiteral("is kept under File ▸ Sessions")));

    // A second start migrates nothing more.
    QStringList problems;
    EXPECT_TRUE(store().migrate(&problems).isEmpty());
    EXPECT_TRUE(problems.isEmpty());
}

TEST_F(SessionsTest, SessionsAreRenamedDeletedAndBroughtBackFromTheDialog) {
    ErrorCapture errors;
    answerNew(2);
    QString firstId;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        breed(window, 2);
        firstId = window.currentSessionId();
    }
    const std::vector<std::string> first = [&] {
        PopulationModel m;
        m.restoreSession(loadSession(store().find(firstId)->file));
        return designs(m);
    }();
    WorkbenchWindow window(&service);
    StartOptions solid = options;
    solid.dimension = 3;
    startSession(window, solid);
    const QString currentId = window.currentSessionId();
    ASSERT_NE(currentId, firstId);
    ASSERT_TRUE(window.sessionsAction()->isEnabled());

    SessionsDialog* dialog = window.openSessionsDialog();
    ASSERT_NE(dialog, nullptr);
    QTreeWidget* list = dialog->list();
    ASSERT_EQ(list->topLevelItemCount(), 2);
    EXPECT_EQ(list->topLevelItem(0)->data(0, Qt::UserRole).toString(), currentId) << "the newest first";
    EXPECT_TRUE(list->topLevelItem(0)->text(1).startsWith(QStringLiteral("being bred now")));

    // The session being bred: renamed (saved with it), never deleted.
    ASSERT_TRUE(dialog->select(currentId));
    EXPECT_FALSE(dialog->deleteButton()->isEnabled());
    EXPECT_FALSE(dialog->resumeButton()->isEnabled());
    list->currentItem()->setText(0, QStringLiteral("Vases for Anna"));
    EXPECT_EQ(window.model()->sessionLabel().name, QStringLiteral("Vases for Anna"));
    EXPECT_EQ(loadSession(window.model()->sessionFile()).label.name, QStringLiteral("Vases for Anna"));
    EXPECT_EQ(window.deleteSession(currentId), QString());
    EXPECT_TRUE(QFileInfo::exists(window.model()->sessionFile()));

    // A kept one: renamed in its file, keeping its time (so it does not become the last one).
    MARBLER_WAIT(dialog->select(firstId), 5000);
    const QDateTime firstModified = store().find(firstId)->modified;
    list->currentItem()->setText(0, QStringLiteral("  Blue combs  "));
    EXPECT_EQ(store().find(firstId)->name, QStringLiteral("Blue combs"));
    EXPECT_EQ(loadSession(store().find(firstId)->file).label.name, QStringLiteral("Blue combs"));
    EXPECT_EQ(store().find(firstId)->modified, firstModified);
    MARBLER_WAIT(dialog->select(firstId), 5000);
    list->currentItem()->setText(0, QStringLiteral("   ")); // an empty name is refused
    MARBLER_WAIT_EQ(list->currentItem()->text(0), QStringLiteral("Blue combs"), 5000);
    EXPECT_EQ(store().find(firstId)->name, QStringLiteral("Blue combs"));

    // Deleted into the trash, and back with Undo delete.
    ASSERT_TRUE(dialog->select(firstId));
    ASSERT_TRUE(dialog->deleteButton()->isEnabled());
    EXPECT_FALSE(dialog->undoDeleteButton()->isEnabled());
    dialog->deleteButton()->click();
    EXPECT_EQ(list->topLevelItemCount(), 1);
    EXPECT_FALSE(store().find(firstId));
    EXPECT_EQ(QDir(store().trashFolder()).entryList(QDir::Files).size(), 1);
    EXPECT_TRUE(dialog->messageLabel()->text().contains(QStringLiteral("Blue combs")));
    ASSERT_TRUE(dialog->undoDeleteButton()->isEnabled());
    dialog->undoDeleteButton()->click();
    EXPECT_EQ(list->topLevelItemCount(), 2);
    ASSERT_TRUE(store().find(firstId));
    EXPECT_TRUE(QDir(store().trashFolder()).entryList(QDir::Files).isEmpty());

    // Resumed from the dialog, which closes; the solid one stays kept.
    ASSERT_TRUE(dialog->select(firstId));
    dialog->resumeButton()->click();
    MARBLER_WAIT(!window.findChild<SessionsDialog*>(), 5000);
    EXPECT_EQ(window.currentSessionId(), firstId);
    EXPECT_EQ(designs(*window.model()), first);
    EXPECT_EQ(window.model()->sessionLabel().name, QStringLiteral("Blue combs"));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("“Vases for Anna” is kept")))
        << window.statusBar()->currentMessage().toStdString();
    EXPECT_EQ(store().list().size(), 2u);
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join('\n').toStdString();
}

TEST_F(SessionsTest, RecentSessionsMenuResumesAKeptSession) {
    answerNew(3);
    QString solidId;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        solidId = window.currentSessionId();
    }
    WorkbenchWindow window(&service);
    StartOptions flat = options;
    flat.dimension = 2;
    startSession(window, flat);
    QMenu* menu = window.recentSessionsMenu();
    ASSERT_TRUE(menu->isEnabled());
    emit menu->aboutToShow();
    QAction* entry = nullptr;
    for (QAction* a : menu->actions())
        if (a->data().toString() == solidId) entry = a;
    ASSERT_NE(entry, nullptr) << "the kept session is listed";
    for (QAction* a : menu->actions())
        EXPECT_NE(a->data().toString(), window.currentSessionId()) << "the current one is not";
    entry->trigger();
    EXPECT_EQ(window.currentSessionId(), solidId);
    EXPECT_EQ(window.model()->populationDimension(), 3);
}

TEST_F(SessionsTest, AKeptSessionThatDoesNotLoadIsReportedAndSetAside) {
    ErrorCapture errors;
    answerNew(2);
    QString keptId;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        keptId = window.currentSessionId();
    }
    WorkbenchWindow window(&service);
    StartOptions flat = options;
    flat.dimension = 2;
    startSession(window, flat);
    const std::vector<std::string> before = designs(*window.model());
    const QString file = store().find(keptId)->file;
    test::writeFile(file.toStdString(), "{\"format\":\"marbler-session\",\"version\":1,");
    EXPECT_FALSE(window.resumeKeptSession(keptId));
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(QFileInfo(file).fileName() + QStringLiteral(".bad")));
    EXPECT_TRUE(QFileInfo::exists(file + QStringLiteral(".bad")));
    EXPECT_FALSE(store().find(keptId)) << "no longer listed";
    EXPECT_EQ(designs(*window.model()), before) << "the current session goes on";
}

TEST_F(SessionsTest, SessionLabelIsAnOptionalPartOfTheDocument) {
    PopulationModel model;
    model.newRandomPopulation(2);
    const QDateTime created = QDateTime::fromString(QStringLiteral("2026-12-02T14:05:12Z"), Qt::ISODate);
    model.setSessionLabel({QStringLiteral("Marble study"), created});
    const std::string text = serializeSession(model);
    EXPECT_LT(text.find("\"name\":\"Marble study\""), text.find("\"generations\"")) << "in the head";
    const SavedSession saved = parseSession(text, "s.json");
    EXPECT_EQ(saved.label.name, QStringLiteral("Marble study"));
    EXPECT_EQ(saved.label.created, created);

    PopulationModel unnamed;
    unnamed.newRandomPopulation(2);
    const std::string plain = serializeSession(unnamed);
    EXPECT_FALSE(nlohmann::json::parse(plain).contains("name"));
    EXPECT_EQ(parseSession(plain, "s.json").label, SessionLabel{});
    std::string badName = plain;
    badName.insert(1, "\"name\":7,");
    try {
        parseSession(badName, "s.json");
        ADD_FAILURE() << "a name that is no string is an error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "s.json: name: must be a string");
    }
}

TEST_F(SessionsTest, StartDialogOffersTheOtherKeptSessions) {
    StartChoice offer{2, QStringLiteral("vase"), true, 4, 3};
    offer.resumeName = QStringLiteral("Vases for Anna");
    offer.otherSessions = {{QStringLiteral("a"), QStringLiteral("Blue combs — generation 3, flat")},
                           {QStringLiteral("b"), QStringLiteral("Old one — generation 9, flat")}};
    StartDialog dialog(offer);
    ASSERT_NE(dialog.resumeButton(), nullptr);
    EXPECT_TRUE(
        dialog.resumeButton()->text().contains(QStringLiteral("“Vases for Anna” (generation 4, solid)")))
        << dialog.resumeButton()->text().toStdString();
    ASSERT_NE(dialog.otherSessionsBox(), nullptr);
    EXPECT_EQ(dialog.otherSessionsBox()->count(), 2);
    dialog.otherSessionsBox()->setCurrentIndex(1);
    dialog.resumeOtherButton()->click();
    EXPECT_TRUE(dialog.choice().resume);
    EXPECT_EQ(dialog.choice().resumeId, QStringLiteral("b"));

    StartDialog last(offer);
    last.resumeButton()->click();
    EXPECT_TRUE(last.choice().resume);
    EXPECT_TRUE(last.choice().resumeId.isEmpty()) << "the last session";

    StartDialog alone(StartChoice{2, QStringLiteral("vase"), true, 4, 3});
    EXPECT_EQ(alone.otherSessionsBox(), nullptr);
    EXPECT_EQ(alone.resumeOtherButton(), nullptr);
}

/// What a button or menu entry shows of its text: "&&" as "&", other '&'s (mnemonics) gone.
QString shownLabel(QString text) {
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    return text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
}

// Issue 29: "&" in a session's name made a keyboard mnemonic of the next letter on the start
// dialog's resume button (and in File ▸ Resume session) and vanished from the label.
TEST_F(SessionsTest, AnAmpersandInASessionNameIsShownAndMakesNoMnemonic) {
    StartChoice offer{2, QStringLiteral("vase"), true, 4, 3};
    offer.resumeName = QStringLiteral("Tom & Jerry");
    StartDialog dialog(offer);
    ASSERT_NE(dialog.resumeButton(), nullptr);
    EXPECT_TRUE(shownLabel(dialog.resumeButton()->text()).contains(QStringLiteral("“Tom & Jerry”")))
        << dialog.resumeButton()->text().toStdString();
    EXPECT_EQ(QKeySequence::mnemonic(dialog.resumeButton()->text()), QKeySequence(Qt::ALT | Qt::Key_R));

    answerNew(2);
    QString keptId;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        keptId = window.currentSessionId();
        ASSERT_TRUE(window.renameSession(keptId, QStringLiteral("Salt & Pepper")));
    }
    WorkbenchWindow window(&service);
    StartOptions flat = options;
    flat.dimension = 2;
    startSession(window, flat);
    emit window.recentSessionsMenu()->aboutToShow();
    QAction* entry = nullptr;
    for (QAction* a : window.recentSessionsMenu()->actions())
        if (a->data().toString() == keptId) entry = a;
    ASSERT_NE(entry, nullptr);
    EXPECT_TRUE(shownLabel(entry->text()).contains(QStringLiteral("Salt & Pepper")))
        << entry->text().toStdString();
    EXPECT_EQ(QKeySequence::mnemonic(entry->text()), QKeySequence(Qt::ALT | Qt::Key_1));
}

// Issue 29: File ▸ Sessions had no "New session"; starting afresh meant quitting.
TEST_F(SessionsTest, NewSessionStartsAFreshPopulationAndKeepsTheCurrentOne) {
    answerNew(2);
    WorkbenchWindow window(&service);
    startSession(window, options);
    breed(window, 2);
    const QString oldId = window.currentSessionId();
    const std::vector<std::string> oldDesigns = designs(*window.model());
    ASSERT_EQ(window.model()->history().size(), 3u);

    auto* action = window.findChild<QAction*>(QStringLiteral("newSessionAction"));
    ASSERT_NE(action, nullptr);
    ASSERT_TRUE(action->isEnabled());
    EXPECT_FALSE(action->text().isEmpty());
    action->trigger();

    const QString newId = window.currentSessionId();
    EXPECT_FALSE(newId.isEmpty());
    EXPECT_NE(newId, oldId);
    ASSERT_EQ(window.model()->history().size(), 1u) << "a first generation of its own";
    EXPECT_EQ(window.model()->populationDimension(), 2);
    for (const std::string& design : designs(*window.model()))
        EXPECT_EQ(std::count(oldDesigns.begin(), oldDesigns.end(), design), 0) << "new designs";
    const QString said = window.statusBar()->currentMessage();
    EXPECT_TRUE(said.contains(QStringLiteral("new session"))) << said.toStdString();

    // Both are kept on disk; the old one whole, with its three generations.
    QStringList ids;
    for (const KeptSession& k : store().list())
        ids << k.id;
    EXPECT_TRUE(ids.contains(oldId)) << ids.join(',').toStdString();
    MARBLER_WAIT(store().find(newId).has_value() && QFileInfo::exists(store().find(newId)->file), 10000);
    EXPECT_EQ(loadSession(store().find(oldId)->file).history.size(), 3u);
    // And the old one can be resumed from the menu.
    EXPECT_TRUE(window.resumeKeptSession(oldId));
    EXPECT_EQ(designs(*window.model()), oldDesigns);
}

// Favourites: removing one is undoable.

TEST_F(SessionsTest, RemovedFavouriteCanBeRestoredAndItsFileComesBack) {
    WorkbenchWindow window(&service);
    window.model()->setSessionSeed(7);
    window.newRandomPopulation(2);
    ASSERT_TRUE(window.keepFavourite(2));
    ASSERT_TRUE(window.keepFavourite(5));
    ASSERT_EQ(window.favouritesList()->count(), 2);
    const QString file = window.model()->favourites().front().file;
    const Genome genome = window.model()->favourites().front().genome;
    EXPECT_FALSE(window.restoreFavouriteAction()->isEnabled()) << "nothing removed yet";

    ASSERT_TRUE(window.removeFavourite(0));
    EXPECT_FALSE(QFileInfo::exists(file));
    EXPECT_EQ(window.favouritesList()->count(), 1);
    const QString trash = window.model()->favouritesTrashFolder();
    EXPECT_TRUE(trash.startsWith(mFavourites.path()));
    const QStringList trashed = QDir(trash).entryList(QDir::Files);
    ASSERT_EQ(trashed.size(), 1);
    EXPECT_TRUE(trashed.front().endsWith(QFileInfo(file).fileName()));
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith(QStringLiteral("Removed “")));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("from favourites — Undo")));
    EXPECT_TRUE(window.undoRemoveButton()->isVisibleTo(&window));
    EXPECT_TRUE(window.restoreFavouriteAction()->isEnabled());

    // The shelf never reads the trash: a new start does not bring it back by itself.
    PopulationModel reread;
    EXPECT_TRUE(reread.setFavouritesFolder(mFavourites.path()).isEmpty());
    EXPECT_EQ(reread.favourites().size(), 1u);

    window.undoRemoveButton()->click();
    EXPECT_TRUE(QFileInfo::exists(file)) << "the file is back";
    EXPECT_TRUE(QDir(trash).entryList(QDir::Files).isEmpty());
    ASSERT_EQ(window.model()->favourites().size(), 2u);
    EXPECT_EQ(window.favouritesList()->count(), 2);
    const auto& favourites = window.model()->favourites();
    const auto back = std::find_if(favourites.begin(), favourites.end(),
                                   [&](const Favourite& f) { return f.file == file; });
    ASSERT_NE(back, favourites.end());
    EXPECT_EQ(back->genome, genome);
    EXPECT_FALSE(window.undoRemoveButton()->isVisibleTo(&window));
    EXPECT_FALSE(window.restoreFavouriteAction()->isEnabled());
    EXPECT_TRUE(
        window.statusBar()->currentMessage().contains(QStringLiteral("is back on the favourites shelf")));

    // Edit ▸ Restore removed favourite (Ctrl+Shift+R) brings back the last removed first.
    const QString first = favourites[0].file;
    const QString second = favourites[1].file;
    ASSERT_TRUE(window.removeFavourite(1));
    ASSERT_TRUE(window.removeFavourite(0));
    EXPECT_EQ(favourites.size(), 0u);
    EXPECT_EQ(window.restoreFavouriteAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    window.restoreFavouriteAction()->trigger();
    ASSERT_EQ(favourites.size(), 1u);
    EXPECT_EQ(favourites.front().file, first);
    window.restoreFavouriteAction()->trigger();
    EXPECT_EQ(favourites.size(), 2u);
    EXPECT_TRUE(QFileInfo::exists(second));
}

TEST_F(SessionsTest, TrashOlderThanThirtyDaysIsEmptiedAtStart) {
    const QString trash = QDir(mFavourites.path()).filePath(QStringLiteral(".trash"));
    ASSERT_TRUE(QDir().mkpath(trash));
    const QString stamp =
        QDateTime::currentDateTimeUtc().addDays(-31).toString(QStringLiteral("yyyyMMdd'T'HHmmss'Z'"));
    const QString recent =
        QDateTime::currentDateTimeUtc().addDays(-29).toString(QStringLiteral("yyyyMMdd'T'HHmmss'Z'"));
    test::writeFile(QDir(trash).filePath(stamp + QStringLiteral("-old.marble.json")).toStdString(), "{}");
    test::writeFile(QDir(trash).filePath(recent + QStringLiteral("-recent.marble.json")).toStdString(), "{}");
    test::writeFile(QDir(trash).filePath(QStringLiteral("mine.txt")).toStdString(), "not trashed by Marbler");
    PopulationModel model;
    model.setFavouritesFolder(mFavourites.path());
    EXPECT_EQ(QDir(trash).entryList(QDir::Files),
              (QStringList{recent + QStringLiteral("-recent.marble.json"), QStringLiteral("mine.txt")}));

    // Sessions' trash too, at each start of a session.
    const QString sessionsTrash = store().trashFolder();
    ASSERT_TRUE(QDir().mkpath(sessionsTrash));
    test::writeFile(
        QDir(sessionsTrash).filePath(stamp + QStringLiteral("-20261001-101010.json")).toStdString(), "{}");
    test::writeFile(
        QDir(sessionsTrash).filePath(recent + QStringLiteral("-20261101-101010.json")).toStdString(), "{}");
    answerNew(2);
    WorkbenchWindow window(&service);
    startSession(window, options);
    EXPECT_EQ(QDir(sessionsTrash).entryList(QDir::Files),
              QStringList{recent + QStringLiteral("-20261101-101010.json")});
    // A restored file gets its name back, with no stamp.
    EXPECT_EQ(originalTrashName(recent + QStringLiteral(".2-20261101-101010.json")),
              QStringLiteral("20261101-101010.json"));
}

} // namespace

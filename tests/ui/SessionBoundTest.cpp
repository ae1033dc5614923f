// Breeding keeps memory bounded (issue 28): a long session holds only a few generations' designs
// in memory and writes one file per generation; nothing is lost (navigation back to the first
// generation, resume after a crash, sessions saved by earlier releases).

#include "PlacedVariants.h"
#include "TestUtil.h"

#include "WaitFor.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "shared/RenderService.h"
#include "workbench/LineagePanel.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/SessionStore.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMainWindow>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <random>
#include <set>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// One generation's designs as text ("(empty)" for an empty cell).
std::vector<std::string> designsOf(const Generation& g) {
    std::vector<std::string> result;
    for (const auto& cell : g.cells)
        result.push_back(cell ? serializeGenome(*cell) : std::string("(empty)"));
    return result;
}

/// Makes one generation as a person does: mostly designs put into the grid (opened, brought
/// back: variants of a few random designs, each named anew so no two are the same), and every
/// `breedEvery`th generation bred from a parent (breeding is slow with the generator's designs,
/// seconds a generation here); going back now and then starts a branch.
void makeGeneration(PopulationModel& model, std::mt19937_64& rng, int breedEvery = 25) {
    model.clearSelection();
    model.setSelected(int(rng() % CellCount), true);
    if (model.history().size() % std::size_t(breedEvery) == 0)
        model.apply(GeneticOperator::Alter, 0.5);
    else
        test::placeVariants(model, rng);
    if (rng() % 10 == 0) model.goBack();
}

std::uint64_t inodeOf(const QString& file) {
    struct stat st {};
    return ::stat(QFile::encodeName(file).constData(), &st) == 0 ? std::uint64_t(st.st_ino) : 0;
}

/// 300 generations; fewer under the sanitisers, still far more than the model holds.
constexpr int Generations = marbler::test::fullOrSanitized(300, 40);

/// One long session shared by the tests below (breeding 300 generations takes a while): bred
/// with its session autosaved, every generation's designs recorded as they were made.
class LongSession : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder = new QTemporaryDir;
        model = new PopulationModel;
        model->setSessionSeed(5);
        model->newRandomPopulation(2);
        model->setSessionFile(folder->filePath(QStringLiteral("long.json")));
        made.push_back(designsOf(model->current()));
        std::mt19937_64 rng(5);
        while (int(model->history().size()) < Generations) {
            const std::size_t before = model->history().size();
            makeGeneration(*model, rng);
            ASSERT_EQ(model->history().size(), before + 1);
            made.push_back(designsOf(model->history().back()));
        }
    }
    static void TearDownTestSuite() {
        delete model;
        delete folder;
        made.clear();
    }
    static QTemporaryDir* folder;
    static PopulationModel* model;
    static std::vector<std::vector<std::string>> made; ///< per generation, as made
};
QTemporaryDir* LongSession::folder = nullptr;
PopulationModel* LongSession::model = nullptr;
std::vector<std::vector<std::string>> LongSession::made;

TEST_F(LongSession, HoldsFewGenerationsInMemory) {
    // What holding every generation would take: the designs' text of all of them (read back).
    std::size_t all = 0, largest = 0;
    for (int k = 0; k < Generations; ++k) {
        const std::size_t bytes = serializeGeneration(model->generation(k)).size();
        all += bytes;
        largest = std::max(largest, bytes);
    }
    int held = 0;
    for (const Generation& g : model->history())
        held += g.held ? 1 : 0;
    EXPECT_LE(held, PopulationModel::HeldGenerations + 1);
    // The designs of the current generation and the few last used, at most, and the tree's own
    // fields for the others (the Generation struct with its empty design slots, some 10 KB, where
    // a generation's designs are 100 KB and more here).
    const std::size_t bound =
        std::size_t(PopulationModel::HeldGenerations + 1) * largest + std::size_t(Generations) * 24 * 1024;
    EXPECT_LE(model->historyBytes(), bound) << "of " << all << " bytes of designs in the session";
    // Far less than all of them: a fifth of 300 generations; under the sanitisers' 40, of which
    // the nine held are already more than a fifth, a half.
    EXPECT_LT(model->historyBytes(), all / (Generations >= 100 ? 5 : 2));
}

TEST_F(LongSession, WritesOneFileForANewGeneration) {
    const QString head = folder->filePath(QStringLiteral("long.json"));
    const QString generations = generationsFolder(head);
    ASSERT_EQ(QDir(generations).entryList({QStringLiteral("g*.json")}, QDir::Files).size(), Generations);
    // The head is small: it names the generations, it does not hold them.
    EXPECT_LT(QFileInfo(head).size(), 2048);
    const std::uint64_t first = inodeOf(generationFile(generations, 1));
    const std::uint64_t middle = inodeOf(generationFile(generations, Generations / 2));
    ASSERT_NE(first, 0u);
    std::mt19937_64 rng(77);
    makeGeneration(*model, rng);
    made.push_back(designsOf(model->history().back()));
    EXPECT_EQ(inodeOf(generationFile(generations, 1)), first) << "an old generation's file was written again";
    EXPECT_EQ(inodeOf(generationFile(generations, Generations / 2)), middle);
    EXPECT_TRUE(QFileInfo::exists(generationFile(generations, int(model->history().size()) - 1)));
}

TEST_F(LongSession, GoesBackToTheFirstGenerationWithTheSameDesigns) {
    // Back along the lineage, one generation at a time, to the first: every grid as it was made.
    model->goTo(int(model->history().size()) - 1);
    int steps = 0;
    while (model->canGoBack()) {
        model->goBack();
        ++steps;
        const int k = model->currentIndex();
        for (int i = 0; i < CellCount; ++i) {
            const Genome* shown = model->cell(i);
            ASSERT_EQ(shown ? serializeGenome(*shown) : std::string("(empty)"),
                      made[std::size_t(k)][std::size_t(i)])
                << "generation " << k << ", design " << i + 1;
        }
    }
    EXPECT_EQ(model->currentIndex(), 0);
    EXPECT_GT(steps, 10);
    // And any generation, in any order, read back.
    for (int k : {Generations - 1, 1, Generations / 2, 2, 0})
        EXPECT_EQ(designsOf(model->generation(k)), made[std::size_t(k)]) << "generation " << k;
    // Steering's rounds reach the root too: one per bred generation on the way, and the grid.
    model->goTo(Generations - 1);
    int bred = 0;
    for (int k = model->currentIndex(); model->history()[std::size_t(k)].parent >= 0;
         k = model->history()[std::size_t(k)].parent)
        bred += model->history()[std::size_t(k)].parentCells.empty() ? 0 : 1;
    EXPECT_EQ(int(model->pickRounds().size()), bred + 1);
}

TEST_F(LongSession, ResumesExactly) {
    const QString head = folder->filePath(QStringLiteral("long.json"));
    ASSERT_TRUE(model->saveSession());
    PopulationModel resumed;
    resumed.restoreSession(loadSession(head));
    ASSERT_EQ(resumed.history().size(), made.size());
    EXPECT_EQ(resumed.currentIndex(), model->currentIndex());
    for (int k = 0; k < int(made.size()); ++k)
        ASSERT_EQ(designsOf(resumed.generation(k)), made[std::size_t(k)]) << "generation " << k;
    // Saved elsewhere, the generations read back from the first folder go along.
    QTemporaryDir other;
    resumed.setSessionFile(other.filePath(QStringLiteral("copy.json")));
    PopulationModel copy;
    copy.restoreSession(loadSession(other.filePath(QStringLiteral("copy.json"))));
    ASSERT_EQ(copy.history().size(), made.size());
    for (int k : {0, 1, int(made.size()) / 2, int(made.size()) - 1})
        EXPECT_EQ(designsOf(copy.generation(k)), made[std::size_t(k)]) << "generation " << k;
}

/// Whether an icon shows more than one colour (a thumbnail, not a blank).
bool iconHasDetail(const QIcon& icon) {
    const QImage image = icon.pixmap(QSize(44, 44)).toImage();
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            colours.insert(image.pixel(x, y));
    return colours.size() > 1;
}

TEST(SessionLineage, ShowsAGenerationNotInMemory) {
    QTemporaryDir dir;
    RenderService service(RenderService::Backend::Cpu);
    QMainWindow window;
    PopulationModel model;
    model.setSessionSeed(4);
    LineagePanel panel(&window, &model, &service, [] { return QStringLiteral("vase"); });
    window.addDockWidget(Qt::RightDockWidgetArea, panel.dock());
    model.newRandomPopulation(2);
    model.setSessionFile(dir.filePath(QStringLiteral("s.json")));
    const std::vector<std::string> first = designsOf(model.current());
    std::mt19937_64 rng(4);
    while (model.history().size() < std::size_t(2 * PopulationModel::HeldGenerations + 4))
        makeGeneration(model, rng, 1000);
    ASSERT_FALSE(model.history()[0].held) << "the first generation is on disk only";
    panel.update();
    window.resize(900, 900);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));

    // Its row, unfolded: its nine designs, read back, named as they were made.
    QTreeWidget* tree = panel.tree();
    const QList<QTreeWidgetItem*> rows =
        tree->findItems(QStringLiteral("Generation 1"), Qt::MatchExactly | Qt::MatchRecursive, 0);
    ASSERT_EQ(rows.size(), 1);
    QTreeWidgetItem* row = rows.front();
    row->setExpanded(true);
    MARBLER_WAIT(row->childCount() == CellCount, 10000);
    for (int i = 0; i < CellCount; ++i) {
        const Genome design = parseGenome(first[std::size_t(i)], "first");
        EXPECT_TRUE(row->child(i)->text(0).contains(QString::fromStdString(*design.meta.name)))
            << row->child(i)->text(0).toStdString();
    }
    // Scrolled into view, its designs' thumbnails and its mosaic are rendered.
    tree->scrollToItem(row, QAbstractItemView::PositionAtTop);
    MARBLER_WAIT(iconHasDetail(row->child(0)->icon(0)), 120000);
    MARBLER_WAIT(iconHasDetail(row->icon(0)), 120000);
    MARBLER_WAIT(service.idle(), 120000);
}

TEST(SessionCrash, KilledWhileBreedingReopensWithEveryGeneration) {
    QTemporaryDir dir;
    const QString head = dir.filePath(QStringLiteral("crash.json"));
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // Breeds until killed: the kill lands at some point of some autosave.
        PopulationModel model;
        model.setSessionSeed(17);
        model.newRandomPopulation(2);
        model.setSessionFile(head);
        std::mt19937_64 rng(17);
        for (int n = 0; n < 400; ++n)
            makeGeneration(model, rng);
        _exit(0);
    }
    const auto count = [&] {
        QFile in(head);
        if (!in.open(QIODevice::ReadOnly)) return 0;
        const auto doc = nlohmann::json::parse(in.readAll().toStdString(), nullptr, false);
        return doc.is_object() && doc.contains("count") ? doc["count"].get<int>() : 0;
    };
    // Polls the file: the breeding runs in the other process, there is no event to wait on.
    const bool started = QTest::qWaitFor([&] { return count() >= 12; }, 120000);
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(started) << "the child made no generations";

    // What it reopens with: every generation whose head was written, each exactly as made.
    PopulationModel resumed;
    resumed.restoreSession(loadSession(head));
    const int n = int(resumed.history().size());
    EXPECT_GE(n, 12);
    PopulationModel again;
    again.setSessionSeed(17);
    again.newRandomPopulation(2);
    std::mt19937_64 rng(17);
    while (int(again.history().size()) < n)
        makeGeneration(again, rng);
    for (int k = 0; k < n; ++k)
        ASSERT_EQ(designsOf(resumed.generation(k)), designsOf(again.generation(k))) << "generation " << k;
    for (int k = 0; k < n; ++k)
        ASSERT_EQ(resumed.history()[std::size_t(k)].parent, again.history()[std::size_t(k)].parent);
}

TEST(SessionFormat, OpensASessionSavedByTheRelease) {
    // tests/data/sessions/v2-flat-3-generations.json: written by the release before version 3
    // (soak_memory --seeds), one document with every generation.
    const QString original = QString::fromStdString(
        (marbler::test::dataDir() / "sessions" / "v2-flat-3-generations.json").string());
    QFile in(original);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly)) << original.toStdString();
    const QByteArray text = in.readAll();
    const SavedSession expected =
        parseSession(std::string_view(text.constData(), std::size_t(text.size())), "v2");
    ASSERT_GE(expected.history.size(), 3u);

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("old.json"));
    ASSERT_TRUE(QFile::copy(original, file));
    PopulationModel model;
    model.restoreSession(loadSession(file));
    model.setSessionFile(file); // as the window resumes it: the next autosave writes version 3
    ASSERT_EQ(model.history().size(), expected.history.size());
    for (std::size_t k = 0; k < expected.history.size(); ++k)
        EXPECT_EQ(designsOf(model.generation(int(k))), designsOf(expected.history[k])) << "generation " << k;

    QFile head(file);
    ASSERT_TRUE(head.open(QIODevice::ReadOnly));
    const auto doc = nlohmann::json::parse(head.readAll().toStdString());
    EXPECT_EQ(doc["version"], 3);
    EXPECT_EQ(doc["count"], expected.history.size());
    const SavedSession reread = loadSession(file);
    ASSERT_EQ(reread.history.size(), expected.history.size());
    EXPECT_EQ(reread.current, expected.current);
    for (std::size_t k = 0; k < expected.history.size(); ++k)
        EXPECT_EQ(designsOf(readGeneration(reread.folder, int(k))), designsOf(expected.history[k]));
}

TEST(SessionFormat, AMissingGenerationFileIsNamed) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("s.json"));
    {
        PopulationModel model;
        model.setSessionSeed(3);
        model.newRandomPopulation(2);
        model.setSessionFile(file);
        std::mt19937_64 rng(3);
        makeGeneration(model, rng);
        makeGeneration(model, rng);
    }
    const QString gone = generationFile(generationsFolder(file), 1);
    ASSERT_TRUE(QFile::remove(gone));
    try {
        loadSession(file);
        FAIL() << "a session with a generation file missing loaded";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(gone.toStdString()), std::string::npos) << e.what();
    }
}

TEST(SessionFormat, TheGenerationsFolderGoesWithItsSession) {
    // Deleted (into the trash), brought back, and deleted for good: the folder follows the file.
    QTemporaryDir dir;
    SessionStore store(dir.path());
    const KeptSession kept = store.create(2);
    std::vector<std::vector<std::string>> made;
    {
        PopulationModel model;
        model.setSessionSeed(6);
        model.newRandomPopulation(2);
        model.setSessionFile(kept.file);
        std::mt19937_64 rng(6);
        for (int n = 0; n < 3; ++n)
            makeGeneration(model, rng, 1000);
        for (int k = 0; k < int(model.history().size()); ++k)
            made.push_back(designsOf(model.generation(k)));
    }
    ASSERT_TRUE(QFileInfo(generationsFolder(kept.file)).isDir());
    ASSERT_EQ(store.list().size(), 1u) << "the folder is no session of its own";

    const QString trashed = store.remove(kept.id);
    EXPECT_FALSE(QFileInfo::exists(generationsFolder(kept.file)));
    EXPECT_TRUE(QFileInfo(generationsFolder(trashed)).isDir());
    EXPECT_EQ(store.restore(trashed), kept.id);
    const SavedSession back = loadSession(kept.file);
    ASSERT_EQ(back.history.size(), made.size());
    for (int k = 0; k < int(made.size()); ++k)
        EXPECT_EQ(designsOf(readGeneration(back.folder, k)), made[std::size_t(k)]);

    const QString again = store.remove(kept.id);
    store.emptyTrash(-1); // everything trashed before tomorrow
    EXPECT_FALSE(QFileInfo::exists(again));
    EXPECT_FALSE(QFileInfo::exists(generationsFolder(again))) << "the trash keeps no orphan folder";
}

TEST(SessionMemory, PackedGenerationsComeBackWithoutASessionFile) {
    // No session file: generations let go are packed in memory, and come back the same.
    PopulationModel model;
    model.setSessionSeed(8);
    model.newRandomPopulation(2);
    std::vector<std::vector<std::string>> made{designsOf(model.current())};
    std::mt19937_64 rng(8);
    while (model.history().size() < std::size_t(3 * PopulationModel::HeldGenerations)) {
        const std::size_t before = model.history().size();
        makeGeneration(model, rng);
        ASSERT_EQ(model.history().size(), before + 1);
        made.push_back(designsOf(model.history().back()));
    }
    EXPECT_FALSE(model.history()[0].held);
    for (int k = 0; k < int(made.size()); ++k)
        EXPECT_EQ(designsOf(model.generation(k)), made[std::size_t(k)]) << "generation " << k;
    // Its selection is kept with it: picked, let go and brought back, still picked.
    model.goTo(1);
    model.clearSelection();
    model.setSelected(4, true);
    for (int k = 2; k < int(made.size()); ++k)
        model.generation(k);
    model.goTo(int(made.size()) - 1);
    model.goTo(1);
    EXPECT_TRUE(model.isSelected(4));
    EXPECT_EQ(model.selectedCount(), 1);
}

} // namespace

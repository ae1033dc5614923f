// The workbench window: selection, operators, generations, favourites, bad files, and the
// render service (CPU always, GL when a context can be made).

#include "TestUtil.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/gl/GlRenderer.h"
#include "ui/DesignCell.h"
#include "ui/ErrorReport.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"
#include "ui/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QDropEvent>
#include <QFileInfo>
#include <QMimeData>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUrl>

#include <gtest/gtest.h>

#include <cstdlib>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// The genomes of the grid as text, for exact comparisons of whole generations.
std::vector<std::string> snapshot(const PopulationModel& model) {
    std::vector<std::string> result;
    for (int i = 0; i < CellCount; ++i) result.push_back(model.cell(i) ? serializeGenome(*model.cell(i)) : "");
    return result;
}

/// Captures errors instead of showing a modal message box.
struct ErrorCapture {
    QStringList messages;
    ErrorCapture() {
        setErrorHandler([this](QWidget*, const QString& title, const QString& message) {
            messages << title + QStringLiteral(": ") + message;
        });
    }
    ~ErrorCapture() { setErrorHandler({}); }
};

/// Drags files onto a widget the way the platform does: an enter (which picks the drop
/// target), then the drop.
void dropFiles(QWidget* target, const QStringList& files) {
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& f : files) urls << QUrl::fromLocalFile(f);
    mime.setUrls(urls);
    const QPoint pos = target->rect().center();
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &enter);
    ASSERT_TRUE(enter.isAccepted());
    QDropEvent drop(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &drop);
}

class WorkbenchTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(mFavourites.isValid());
        qputenv("MARBLER_FAVOURITES_DIR", mFavourites.path().toLocal8Bit());
        mService = std::make_unique<RenderService>(RenderService::Backend::Cpu);
        mWindow = std::make_unique<WorkbenchWindow>(mService.get());
        mWindow->model()->setSessionSeed(42);
        mWindow->newRandomPopulation(2);
    }
    void TearDown() override {
        mWindow.reset();
        mService.reset();
        qunsetenv("MARBLER_FAVOURITES_DIR");
    }
    PopulationModel& model() { return *mWindow->model(); }

    QTemporaryDir mFavourites;
    std::unique_ptr<RenderService> mService;
    std::unique_ptr<WorkbenchWindow> mWindow;
};

TEST_F(WorkbenchTest, RandomPopulationFillsNineValidCells) {
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_NE(model().cell(i), nullptr) << "cell " << i;
        EXPECT_EQ(model().cell(i)->dimension, 2);
        EXPECT_NO_THROW(validateGenome(*model().cell(i), "cell"));
    }
    EXPECT_EQ(model().selectedCount(), 0);
}

TEST_F(WorkbenchTest, ClickSelectsAndClickAgainDeselects) {
    DesignCell* cell = mWindow->cell(4);
    QTest::mouseClick(cell, Qt::LeftButton);
    EXPECT_TRUE(model().isSelected(4));
    EXPECT_TRUE(cell->isSelectedParent());
    EXPECT_EQ(model().selectedCells(), std::vector<int>{4});
    QTest::mouseClick(cell, Qt::LeftButton);
    EXPECT_FALSE(model().isSelected(4));
    EXPECT_FALSE(cell->isSelectedParent());
}

TEST_F(WorkbenchTest, SpaceTogglesSelection) {
    QTest::keyClick(mWindow->cell(2), Qt::Key_Space);
    EXPECT_TRUE(model().isSelected(2));
    QTest::keyClick(mWindow->cell(2), Qt::Key_Space);
    EXPECT_FALSE(model().isSelected(2));
}

TEST_F(WorkbenchTest, OperatorButtonsFollowParentCount) {
    auto enabled = [&](GeneticOperator op) { return mWindow->operatorAction(op)->isEnabled(); };
    using Op = GeneticOperator;
    EXPECT_FALSE(enabled(Op::Alter) || enabled(Op::Recombine) || enabled(Op::Swap) || enabled(Op::Reinit));

    QTest::mouseClick(mWindow->cell(0), Qt::LeftButton);
    EXPECT_TRUE(enabled(Op::Alter));
    EXPECT_TRUE(enabled(Op::Reinit));
    EXPECT_FALSE(enabled(Op::Recombine));
    EXPECT_FALSE(enabled(Op::Swap));

    QTest::mouseClick(mWindow->cell(1), Qt::LeftButton);
    EXPECT_FALSE(enabled(Op::Alter));
    EXPECT_FALSE(enabled(Op::Reinit));
    EXPECT_TRUE(enabled(Op::Recombine));
    EXPECT_TRUE(enabled(Op::Swap));

    QTest::mouseClick(mWindow->cell(2), Qt::LeftButton);
    EXPECT_TRUE(enabled(Op::Recombine));
    EXPECT_FALSE(enabled(Op::Swap));
    EXPECT_FALSE(enabled(Op::Alter));
}

TEST_F(WorkbenchTest, OperatorKeepsParentsAndFillsNineCells) {
    model().setSelected(0, true);
    model().setSelected(4, true);
    const auto before = snapshot(model());
    const std::string idA = genomeId(*model().cell(0)), idB = genomeId(*model().cell(4));
    mWindow->operatorAction(GeneticOperator::Recombine)->trigger();

    const auto after = snapshot(model());
    EXPECT_EQ(after[0], before[0]);
    EXPECT_EQ(after[4], before[4]);
    EXPECT_TRUE(model().isSelected(0) && model().isSelected(4)) << "parents stay selected";
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_NE(model().cell(i), nullptr);
        EXPECT_NO_THROW(validateGenome(*model().cell(i), "cell"));
        if (i == 0 || i == 4) continue;
        EXPECT_NE(after[std::size_t(i)], before[std::size_t(i)]) << "cell " << i << " holds offspring";
        const LineageInfo info = lineageOf(*model().cell(i));
        EXPECT_EQ(info.op, QStringLiteral("recombine"));
        EXPECT_TRUE(info.parents.contains(QString::fromStdString(idA)) || info.parents.contains(QString::fromStdString(idB)));
    }
    EXPECT_EQ(model().history().size(), 3u);
}

TEST_F(WorkbenchTest, BreedingIsReproducibleFromTheSessionSeed) {
    model().setSelected(3, true);
    mWindow->applyOperator(GeneticOperator::Alter);
    const auto first = snapshot(model());

    RenderService service(RenderService::Backend::Cpu);
    WorkbenchWindow other(&service);
    other.model()->setSessionSeed(42);
    other.newRandomPopulation(2);
    other.model()->setSelected(3, true);
    other.applyOperator(GeneticOperator::Alter);
    EXPECT_EQ(snapshot(*other.model()), first);
}

TEST_F(WorkbenchTest, BackAndForwardRestoreGenerationsExactly) {
    const auto gen0 = snapshot(model());
    model().setSelected(1, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    const auto gen1 = snapshot(model());
    model().clearSelection();
    model().setSelected(5, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Reinit));
    const auto gen2 = snapshot(model());
    ASSERT_NE(gen1, gen0);
    ASSERT_NE(gen2, gen1);

    EXPECT_FALSE(mWindow->forwardAction()->isEnabled());
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen1);
    EXPECT_TRUE(model().isSelected(5)) << "a generation keeps the selection it was left with";
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen0);
    mWindow->forwardAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen1);
    mWindow->forwardAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen2);
    EXPECT_FALSE(mWindow->forwardAction()->isEnabled());
    EXPECT_TRUE(mWindow->backAction()->isEnabled());
}

TEST_F(WorkbenchTest, UndoShortcutsAreCtrlZAndCtrlShiftZ) {
    EXPECT_EQ(mWindow->backAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Z));
    EXPECT_EQ(mWindow->forwardAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
}

TEST_F(WorkbenchTest, SavedFavouriteLoadsAgain) {
    ASSERT_TRUE(mWindow->keepFavourite(6));
    ASSERT_EQ(model().favourites().size(), 1u);
    const QString file = model().favourites().front().file;
    EXPECT_TRUE(QFileInfo::exists(file));
    EXPECT_TRUE(file.startsWith(mFavourites.path()));

    // A new session (a new model reading the same folder) finds it again.
    PopulationModel reread;
    EXPECT_TRUE(reread.setFavouritesFolder(mFavourites.path()).isEmpty());
    ASSERT_EQ(reread.favourites().size(), 1u);
    EXPECT_EQ(reread.favourites().front().genome, *model().cell(6));

    // Brought back into the grid, it becomes a new generation.
    model().setSelected(0, true);
    mWindow->restoreFavourite(0);
    EXPECT_EQ(*model().cell(0), reread.favourites().front().genome);
    mWindow->backAction()->trigger();
    EXPECT_NE(serializeGenome(*model().cell(0)), serializeGenome(reread.favourites().front().genome));
}

TEST_F(WorkbenchTest, OpenFileLoadsIntoSelectedCell) {
    const QString file = QString::fromStdString((test::dataDir() / "examples" / "five-stones.marble.json").string());
    model().setSelected(7, true);
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(*model().cell(7), loadGenome(file.toStdString()));
}

TEST_F(WorkbenchTest, BadFileShowsErrorAndKeepsPopulation) {
    ErrorCapture errors;
    const auto before = snapshot(model());
    const std::size_t generations = model().history().size();
    const QString bad = QString::fromStdString((test::dataDir() / "ui" / "negative-radius.marble.json").string());

    EXPECT_FALSE(mWindow->openFiles({bad}));
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(QStringLiteral("negative-radius.marble.json")));
    EXPECT_TRUE(errors.messages.front().contains(QStringLiteral("radius"))) << errors.messages.front().toStdString();
    EXPECT_EQ(snapshot(model()), before);
    EXPECT_EQ(model().history().size(), generations);

    // The same file dropped onto a cell (a drop site is registered once the window exists).
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(3), {bad});
    EXPECT_EQ(errors.messages.size(), 2);
    EXPECT_EQ(snapshot(model()), before);
    EXPECT_EQ(model().history().size(), generations);
}

TEST_F(WorkbenchTest, DroppedGoodFileReplacesThatCell) {
    const QString file = QString::fromStdString((test::dataDir() / "examples" / "slate-block.marble.json").string());
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(8), {file});
    ASSERT_NE(model().cell(8), nullptr);
    EXPECT_EQ(*model().cell(8), loadGenome(file.toStdString()));
}

TEST_F(WorkbenchTest, LocksAreStoredInTheGenome) {
    Locks locks;
    locks.palette = true;
    model().setCellLocks(2, locks);
    EXPECT_EQ(locksOf(*model().cell(2)), locks);
}

TEST_F(WorkbenchTest, LineageListsEveryCellAndGeneration) {
    model().setSelected(0, true);
    mWindow->applyOperator(GeneticOperator::Alter);
    QTreeWidget* tree = mWindow->lineageTree();
    ASSERT_EQ(tree->topLevelItemCount(), 2);
    EXPECT_EQ(tree->topLevelItem(0)->childCount(), CellCount);
    EXPECT_EQ(tree->topLevelItem(1)->childCount(), int(model().history().size()));
}

TEST_F(WorkbenchTest, WindowRendersEveryCellOnTheCpu) {
    mWindow->resize(600, 500);
    mWindow->show();
    QSignalSpy finished(mWindow.get(), &WorkbenchWindow::renderingFinished);
    // Resizing restarts renders after a debounce; wait until all nine have final images.
    while (!mWindow->renderingDone() || finished.isEmpty()) ASSERT_TRUE(finished.wait(120000));
    for (int i = 0; i < CellCount; ++i) EXPECT_FALSE(mWindow->cell(i)->image().isNull()) << "cell " << i;
}

// The render service on its own.

TEST(RenderServiceTest, NewerRequestSupersedesOlder) {
    RenderService service(RenderService::Backend::Cpu);
    const Genome a = randomGenome(1, 2), b = randomGenome(2, 2);
    QSignalSpy idle(&service, &RenderService::becameIdle);
    QImage finalImage;
    int finals = 0;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t key, const QImage& image, bool final) {
        EXPECT_EQ(key, 7u);
        if (final) {
            finalImage = image;
            ++finals;
        }
    });
    RenderRequest first;
    first.genome = a;
    first.size = QSize(64, 64);
    service.request(7, first);
    RenderRequest second = first;
    second.genome = b;
    service.request(7, second);
    ASSERT_TRUE(idle.wait(120000));
    EXPECT_EQ(finals, 1);
    RenderSettings settings;
    settings.width = settings.height = 64;
    settings.aa = "rgss";
    EXPECT_EQ(finalImage, toQImage(CpuRenderer(b).render(settings)));
}

TEST(RenderServiceTest, GlRendersSolidOnAnObject) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    RenderService service(RenderService::Backend::Auto);
    QSignalSpy ready(&service, &RenderService::backendReady);
    ASSERT_TRUE(ready.wait(60000));
    EXPECT_TRUE(service.backendName().startsWith(QStringLiteral("OpenGL"))) << service.backendName().toStdString();
    QSignalSpy idle(&service, &RenderService::becameIdle);
    QImage finalImage;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage& image, bool final) {
        if (final) finalImage = image;
    });
    RenderRequest request;
    request.genome = randomGenome(5, 3);
    request.size = QSize(96, 80);
    service.request(1, request);
    ASSERT_TRUE(idle.wait(120000));
    ASSERT_FALSE(finalImage.isNull());
    EXPECT_EQ(finalImage.size(), QSize(96, 80));
    // Not all one colour: the object and its marbling are there.
    const QRgb corner = finalImage.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < finalImage.height() && !varied; ++y)
        for (int x = 0; x < finalImage.width() && !varied; ++x) varied = finalImage.pixel(x, y) != corner;
    EXPECT_TRUE(varied);
}

} // namespace

int main(int argc, char** argv) {
    // Headless by default: with no display, Qt's offscreen platform (the CPU fallback renders).
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")
        && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Keep the user's settings and data out of the tests.
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("MarblerTest"));
    QApplication::setApplicationName(QStringLiteral("MarblerTest"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

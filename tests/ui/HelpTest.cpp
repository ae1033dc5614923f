// Dialogs and feedback: where saved files went (and "Show in folder"), the names offered to save
// and export, the Help menu (guide, About), the strength label, the status bar's task, opening
// designs into the grid (the placement question, the kind rule) and why an operator is disabled.
// Runs in ui_workbench_test, whose main() sets up the application and private settings.

#include "TestUtil.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/Help.h"
#include "shared/RenderService.h"
#include "shared/SavedFiles.h"
#include "workbench/DesignCell.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialog>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>
#include <QToolButton>
#include <QUrl>

#include <gtest/gtest.h>

#include <functional>

using namespace marbler;
using namespace marbler::ui;
using marbler::test::dropFiles;

namespace {

QString example(const char* name) {
    return QString::fromStdString((test::dataDir() / "examples" / name).string());
}

/// Captures errors instead of showing a modal message box.
struct Errors {
    QStringList messages;
    Errors() {
        setErrorHandler([this](QWidget*, const QString& title, const QString& message) {
            messages << title + QStringLiteral(": ") + message;
        });
    }
    ~Errors() { setErrorHandler({}); }
};

/// Answers the next modal dialog that opens (polling, since it opens inside the caller's
/// nested event loop), then stops.
void answerModal(std::function<void(QWidget*)> answer) {
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, answer] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            timer->stop();
            timer->deleteLater();
            answer(modal);
        }
    });
    timer->start();
}

class HelpTest : public test::WindowTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(mFiles.isValid());
        QSettings().remove(QStringLiteral("files"));
        QSettings().remove(QStringLiteral("open"));
        setUrlOpener([this](const QUrl& url) {
            opened << url;
            return true;
        });
        // Every question about where opened designs go is counted and answered from `answer`.
        setOpenChooser([this](QWidget*, const OpenQuestion& question) {
            ++asked;
            lastQuestion = question;
            return answer;
        });
        WindowTest::SetUp();
    }
    void TearDown() override {
        WindowTest::TearDown();
        setUrlOpener({});
        setOpenChooser({});
        setSaveFileAsker({});
        QSettings().remove(QStringLiteral("files"));
        QSettings().remove(QStringLiteral("open"));
    }
    void showWindow() {
        mWindow->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    }

    QTemporaryDir mFiles;
    QList<QUrl> opened;
    int asked = 0;
    OpenQuestion lastQuestion;
    std::optional<OpenChoice> answer = OpenChoice::NewGeneration;
};

// Saying where things were saved.

TEST_F(HelpTest, SavedGenomeShowsItsPathAndShowInFolderOpensItsFolder) {
    showWindow();
    SavedFileNotice* notice = mWindow->savedFileNotice();
    ASSERT_NE(notice, nullptr);
    EXPECT_FALSE(notice->isVisible()) << "nothing saved yet";

    DesignDialog* dialog = mWindow->openDesign(3);
    ASSERT_NE(dialog, nullptr);
    QDir(mFiles.path()).mkpath(QStringLiteral("kept"));
    const QString file = mFiles.filePath(QStringLiteral("kept/stone.marble.json"));
    ASSERT_TRUE(dialog->saveTo(file));
    dialog->close();

    EXPECT_TRUE(notice->isVisible());
    EXPECT_EQ(notice->file(), QFileInfo(file).absoluteFilePath());
    EXPECT_TRUE(
        notice->pathLabel()->text().contains(QDir::toNativeSeparators(QFileInfo(file).absoluteFilePath())))
        << notice->pathLabel()->text().toStdString();
    EXPECT_TRUE(notice->isVisibleTo(mWindow->statusBar()));

    QTest::mouseClick(notice->showInFolderButton(), Qt::LeftButton);
    ASSERT_EQ(opened.size(), 1);
    EXPECT_EQ(opened.front(), QUrl::fromLocalFile(QFileInfo(file).absolutePath()));
    EXPECT_TRUE(opened.front().toLocalFile().endsWith(QStringLiteral("/kept")));

    // A favourite is a file too: the notice moves to it.
    ASSERT_TRUE(mWindow->keepFavourite(5));
    ASSERT_EQ(model().favourites().size(), 1u);
    EXPECT_EQ(notice->file(), QFileInfo(model().favourites().front().file).absoluteFilePath());
    opened.clear();
    QTest::mouseClick(notice->showInFolderButton(), Qt::LeftButton);
    ASSERT_EQ(opened.size(), 1);
    EXPECT_EQ(QFileInfo(opened.front().toLocalFile()), QFileInfo(mFavourites.path()));
}

TEST_F(HelpTest, FileNamesOfferedAreTheDesignsNameMadeSafe) {
    EXPECT_EQ(safeFileName(QStringLiteral("Slate block: stones / a \"vortex\"?")),
              QStringLiteral("Slate block stones a vortex"));
    EXPECT_EQ(safeFileName(QStringLiteral("Cobalt Tide (g3 #7)")), QStringLiteral("Cobalt Tide (g3 #7)"));
    EXPECT_EQ(safeFileName(QStringLiteral("..hidden. ")), QStringLiteral("hidden"));
    EXPECT_EQ(safeFileName(QStringLiteral("<>|*")), QString());

    // Save: the design's name, safe, in the folder used last; the folder is remembered.
    const Genome slate = loadGenome(example("slate-block.marble.json").toStdString());
    QSettings().setValue(QStringLiteral("files/saveDir"), mFiles.path());
    QString offered;
    const QString chosen = mFiles.filePath(QStringLiteral("sub/picked"));
    QDir(mFiles.path()).mkpath(QStringLiteral("sub"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return chosen;
    });
    const QString written = saveGenomeWithDialog(mWindow.get(), slate);
    EXPECT_EQ(offered, QDir(mFiles.path())
                           .filePath(QStringLiteral("Slate block stones combed twice, egg-crate wave, a "
                                                    "sphere stroke and a tilted vortex.marble.json")));
    EXPECT_EQ(written, chosen + QStringLiteral(".marble.json"));
    // A file name typed, not the one offered, names the design (issue 29); the rest is as it was.
    Genome named = slate;
    named.meta.name = "picked";
    EXPECT_EQ(loadGenome(written.toStdString()), named);
    EXPECT_EQ(QSettings().value(QStringLiteral("files/saveDir")).toString(),
              mFiles.filePath(QStringLiteral("sub")));

    // A design without a name is offered under its short id.
    Genome unnamed = slate;
    unnamed.meta.erase(MetaKey::Name);
    EXPECT_EQ(suggestedFile(unnamed, mFiles.path(), QStringLiteral(".png")),
              QDir(mFiles.path()).filePath(lineageOf(unnamed).id.left(8) + QStringLiteral(".png")));
}

TEST_F(HelpTest, ExportOffersTheDesignsNameInTheLastFolderAndFormat) {
    Errors errors;
    showWindow();
    model().placeDesigns({loadGenome(example("five-stones.marble.json").toStdString())},
                         QStringLiteral("Opened"));
    const int cell = 0;
    ASSERT_EQ(lineageOf(*model().cell(cell)).name, QStringLiteral("Five stones, combed and swirled"));
    DesignDialog* dialog = mWindow->openDesign(cell);
    ASSERT_NE(dialog, nullptr);
    // The first time: PNG, in the current folder.
    EXPECT_EQ(dialog->suggestedExportFile(),
              QDir::current().filePath(QStringLiteral("Five stones, combed and swirled.png")));
    QSettings().setValue(QStringLiteral("files/exportDir"), mFiles.path());
    QSettings().setValue(QStringLiteral("files/exportExtension"), QStringLiteral(".tif"));
    EXPECT_EQ(dialog->suggestedExportFile(),
              QDir(mFiles.path()).filePath(QStringLiteral("Five stones, combed and swirled.tif")));

    // The whole way through the Export button: settings accepted at a small size, a name typed
    // without a format; the format offered is used, and folder and format are remembered.
    QTemporaryDir other;
    ASSERT_TRUE(other.isValid());
    QString offered;
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return other.filePath(QStringLiteral("poster"));
    });
    QPushButton* exportButton = nullptr;
    for (QPushButton* b : dialog->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("&Export image…")) exportButton = b;
    ASSERT_NE(exportButton, nullptr);
    answerModal([](QWidget* modal) {
        auto* width = modal->findChild<QDoubleSpinBox*>(QStringLiteral("exportWidth"));
        ASSERT_NE(width, nullptr);
        width->setValue(48);
        qobject_cast<QDialog*>(modal)->accept();
    });
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    exportButton->click();
    MARBLER_WAIT_EQ(finished.size(), 1, 120000);
    const QString file = other.filePath(QStringLiteral("poster.tif"));
    EXPECT_EQ(offered, QDir(mFiles.path()).filePath(QStringLiteral("Five stones, combed and swirled.tif")));
    EXPECT_EQ(finished.front().at(0).toString(), file);
    EXPECT_TRUE(finished.front().at(1).toBool()) << finished.front().at(2).toString().toStdString();
    QFile written(file);
    ASSERT_TRUE(written.open(QIODevice::ReadOnly));
    const QByteArray magic = written.read(4);
    EXPECT_TRUE(magic == QByteArray("II*\0", 4) || magic == QByteArray("MM\0*", 4)) << "a TIFF file";
    EXPECT_EQ(QSettings().value(QStringLiteral("files/exportDir")).toString(), other.path());
    EXPECT_EQ(QSettings().value(QStringLiteral("files/exportExtension")).toString(), QStringLiteral(".tif"));
    // The window says where it went.
    EXPECT_EQ(mWindow->savedFileNotice()->file(), file);
    EXPECT_TRUE(mWindow->savedFileNotice()->isVisible());
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("\n")).toStdString();
    dialog->close();
}

// Help: the guide, About, About Qt.

TEST_F(HelpTest, F1OpensTheGuideWhichListsEveryShortcutOfTheWindow) {
    showWindow();
    ASSERT_TRUE(test::activate(mWindow.get()));
    EXPECT_EQ(mWindow->guideAction()->shortcut(), QKeySequence(QKeySequence::HelpContents));
    QTest::keyClick(mWindow.get(), Qt::Key_F1);
    QDialog* guide = nullptr;
    MARBLER_WAIT((guide = mWindow->findChild<QDialog*>(QStringLiteral("guideDialog"))) && guide->isVisible(),
                 5000);
    auto* browser = guide->findChild<QTextBrowser*>(QStringLiteral("guideBrowser"));
    ASSERT_NE(browser, nullptr);
    const QString text = browser->toPlainText();

    // The four operators by the window's exact words, and what else the guide must teach.
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit}) {
        EXPECT_TRUE(text.contains(operatorLabel(op))) << operatorLabel(op).toStdString();
        EXPECT_TRUE(text.contains(plainActionText(mWindow->operatorAction(op))));
    }
    for (const char* topic : {"Pick parents", "Back and forward", "Favourites", "The large view", "Keyboard"})
        EXPECT_TRUE(text.contains(QString::fromLatin1(topic))) << topic;

    // Every action with a shortcut is in the table, keys and words.
    const QList<QAction*> actions = shortcutActions(mWindow.get());
    EXPECT_GE(actions.size(), 12);
    for (QAction* action : mWindow->findChildren<QAction*>()) {
        if (action->shortcut().isEmpty()) continue;
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        EXPECT_TRUE(text.contains(keys)) << keys.toStdString();
        EXPECT_TRUE(text.contains(plainActionText(action))) << plainActionText(action).toStdString();
    }
    EXPECT_TRUE(text.contains(QStringLiteral("F1")));
    EXPECT_TRUE(text.contains(QStringLiteral("Ctrl+Shift+Z")));

    // Built from the actions, so a new one is listed without touching the guide.
    guide->close();
    MARBLER_WAIT(!mWindow->findChild<QDialog*>(QStringLiteral("guideDialog")), 5000);
    auto* extra = new QAction(QStringLiteral("Polish the stones"), mWindow.get());
    extra->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_P));
    QDialog* again = mWindow->showGuide();
    const QString newer = again->findChild<QTextBrowser*>()->toPlainText();
    EXPECT_TRUE(newer.contains(QStringLiteral("Polish the stones")));
    EXPECT_TRUE(newer.contains(extra->shortcut().toString(QKeySequence::NativeText)));
    again->close();
}

TEST_F(HelpTest, AboutNamesVersionsAndTheRenderer) {
    if (mService->backendName().isEmpty()) {
        QSignalSpy ready(mService.get(), &RenderService::backendReady);
        ASSERT_TRUE(ready.wait(60000));
    }
    const auto aboutText = [this] {
        QDialog* about = mWindow->showAbout();
        const QString text = about->findChild<QLabel*>(QStringLiteral("aboutText"))->text();
        about->close();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        return text;
    };
    const bool loadedBefore = loadedOpenImageIoVersion().has_value();
    QString text = aboutText();
    EXPECT_TRUE(text.contains(QStringLiteral("Marbler ") + marblerVersion())) << text.toStdString();
    EXPECT_FALSE(marblerVersion().isEmpty());
    EXPECT_TRUE(text.contains(QString::fromLatin1(qVersion()))) << text.toStdString();
    EXPECT_TRUE(text.contains(mWindow->rendererDescription().toHtmlEscaped())) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Rendering on the CPU"))) << text.toStdString();
    if (!loadedBefore) {
        EXPECT_TRUE(text.contains(QStringLiteral("not loaded"))) << text.toStdString();
    }
    // Once OpenImageIO's module is loaded (the test build has it), About names its version.
    std::string version;
    try {
        version = openImageIoVersion();
    } catch (const Error& e) {
        FAIL() << "the OpenImageIO module is built with the tests but did not load: " << e.what();
    }
    ASSERT_TRUE(loadedOpenImageIoVersion().has_value());
    EXPECT_EQ(*loadedOpenImageIoVersion(), version);
    text = aboutText();
    EXPECT_TRUE(text.contains(QString::fromStdString(version))) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("not loaded")));

    // About Qt is Qt's own box.
    bool sawQt = false;
    answerModal([&](QWidget* modal) {
        auto* box = qobject_cast<QMessageBox*>(modal);
        sawQt = box && box->text().contains(QStringLiteral("Qt"));
        qobject_cast<QDialog*>(modal)->done(0);
    });
    mWindow->aboutQtAction()->trigger();
    EXPECT_TRUE(sawQt);
}

TEST_F(HelpTest, StrengthLabelFollowsTheSlider) {
    auto* label = mWindow->findChild<QLabel*>(QStringLiteral("strengthLabel"));
    auto* slider = mWindow->findChild<QSlider*>(QStringLiteral("strengthSlider"));
    ASSERT_NE(label, nullptr);
    ASSERT_NE(slider, nullptr);
    mWindow->setStrength(0.4);
    EXPECT_EQ(label->text().trimmed(), QStringLiteral("Strength 40 %"));
    QTest::keyClick(slider, Qt::Key_Right);
    EXPECT_EQ(label->text().trimmed(), QStringLiteral("Strength 41 %"));
    EXPECT_DOUBLE_EQ(mWindow->strength(), 0.41);
    QTest::keyClick(slider, Qt::Key_End);
    EXPECT_EQ(label->text().trimmed(), QStringLiteral("Strength 100 %"));
    EXPECT_FALSE(label->toolTip().isEmpty());
    EXPECT_TRUE(slider->toolTip().contains(QStringLiteral("Alter")));
}

TEST_F(HelpTest, StatusBarSpeaksOfTheTask) {
    showWindow();
    auto* task = mWindow->findChild<QLabel*>(QStringLiteral("taskLabel"));
    ASSERT_NE(task, nullptr);
    // Past the resize debounce, which renders the shown cells anew at their size.
    QTest::qWait(400);
    MARBLER_WAIT_EQ(task->text(), QStringLiteral("Ready"), 120000);
    model().setSelected(4, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    EXPECT_EQ(mWindow->statusBar()->currentMessage(), QStringLiteral("Bred generation 2 with Alter"));
    // Eight new designs to render (the parent's image is cached).
    EXPECT_EQ(task->text(), QStringLiteral("Rendering 1 of 8…"));
    MARBLER_WAIT_EQ(task->text(), QStringLiteral("Ready"), 120000);
    EXPECT_TRUE(mWindow->renderingDone());
    // The generation's summary stays under passing messages.
    auto* generation = mWindow->findChild<QLabel*>(QStringLiteral("generationLabel"));
    ASSERT_NE(generation, nullptr);
    EXPECT_TRUE(generation->text().startsWith(QStringLiteral("Generation 2: Alter")))
        << generation->text().toStdString();
}

// Opening designs into the grid.

TEST_F(HelpTest, OpeningOverASelectedParentAsksAndNewGenerationKeepsIt) {
    const QString file = example("five-stones.marble.json");
    const Genome opened = loadGenome(file.toStdString());
    model().setSelected(4, true);
    const Genome parent = *model().cell(4);
    const std::size_t generations = model().history().size();

    // Cancel: nothing changes.
    answer.reset();
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(lastQuestion.replaced, std::vector<int>{4});
    EXPECT_EQ(lastQuestion.parents, std::vector<int>{4});
    EXPECT_EQ(lastQuestion.names, QStringList{QStringLiteral("five-stones.marble.json")});
    EXPECT_EQ(model().history().size(), generations);
    EXPECT_EQ(*model().cell(4), parent);

    // A new generation keeps the parent, still picked, and puts the design in a non-parent cell.
    answer = OpenChoice::NewGeneration;
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(asked, 2);
    EXPECT_EQ(model().history().size(), generations + 1);
    EXPECT_EQ(*model().cell(4), parent);
    EXPECT_TRUE(model().isSelected(4));
    EXPECT_EQ(*model().cell(0), opened);
    EXPECT_TRUE(mWindow->operatorAction(GeneticOperator::Alter)->isEnabled());

    // Replace: into the selected cell, as a generation of its own (Back undoes it).
    answer = OpenChoice::Replace;
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(asked, 3);
    EXPECT_EQ(*model().cell(4), opened);
    EXPECT_FALSE(model().isSelected(4));
    mWindow->backAction()->trigger();
    EXPECT_EQ(*model().cell(4), parent);

    // Dropped on a cell that is no parent: that cell, without a question; on the parent: asked.
    showWindow();
    model().setSelected(4, true);
    dropFiles(mWindow->cell(7), {file});
    EXPECT_EQ(asked, 3);
    EXPECT_EQ(*model().cell(7), opened);
    model().setSelected(4, true);
    answer = OpenChoice::NewGeneration;
    dropFiles(mWindow->cell(4), {file});
    EXPECT_EQ(asked, 4);
    EXPECT_EQ(*model().cell(4), parent);

    // Dropped on the window, not on a cell: like File ▸ Open.
    const std::size_t before = model().history().size();
    dropFiles(mWindow.get(), {file});
    EXPECT_EQ(asked, 5);
    EXPECT_EQ(model().history().size(), before + 1);
    EXPECT_EQ(*model().cell(4), parent);
}

TEST_F(HelpTest, NoQuestionWhenNothingWouldBeReplaced) {
    // A grid with free cells: opened designs go there and nothing is asked.
    const Genome a = loadGenome(example("five-stones.marble.json").toStdString());
    model().startGenerationOf({a}, QStringLiteral("one design"));
    ASSERT_EQ(model().cell(1), nullptr);
    ASSERT_TRUE(mWindow->openFiles({example("flame-comb-vortex.marble.json")}));
    EXPECT_EQ(asked, 0);
    ASSERT_NE(model().cell(1), nullptr);
    EXPECT_EQ(*model().cell(1), loadGenome(example("flame-comb-vortex.marble.json").toStdString()));
    EXPECT_EQ(*model().cell(0), a);
}

TEST_F(HelpTest, PlacementDialogAsksAndRemembersNotAsking) {
    // The real dialog, answered as a user would: "Add as a new generation", don't ask again.
    setOpenChooser({});
    const QString file = example("five-stones.marble.json");
    model().setSelected(2, true);
    const Genome parent = *model().cell(2);
    QString replaceText;
    answerModal([&](QWidget* modal) {
        auto* dialog = qobject_cast<OpenPlacementDialog*>(modal);
        ASSERT_NE(dialog, nullptr);
        replaceText = dialog->replaceButton()->text();
        EXPECT_TRUE(dialog->newGenerationButton()->isDefault()) << "keeping the parents is the safe default";
        dialog->dontAskBox()->setChecked(true);
        dialog->newGenerationButton()->click();
    });
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(replaceText, QStringLiteral("&Replace the selected cell"));
    EXPECT_EQ(*model().cell(2), parent);
    EXPECT_TRUE(model().isSelected(2));
    EXPECT_FALSE(askOpenChoice());
    EXPECT_EQ(lastOpenChoice(), OpenChoice::NewGeneration);

    // Remembered: the next open over the parent does the same without any dialog (a dialog
    // would block this test).
    const std::size_t before = model().history().size();
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(model().history().size(), before + 1);
    EXPECT_EQ(*model().cell(2), parent);

    // Cancel is never remembered.
    rememberOpenChoice(OpenChoice::Replace, true);
    OpenPlacementDialog dialog(OpenQuestion{{QStringLiteral("a"), QStringLiteral("b")}, {0, 1}, {}});
    EXPECT_EQ(dialog.replaceButton()->text(), QStringLiteral("&Replace designs 1 and 2"));
    dialog.cancelButton()->click();
    EXPECT_FALSE(dialog.choice().has_value());
    EXPECT_TRUE(askOpenChoice());
}

TEST_F(HelpTest, FlatDesignIntoSolidGridStartsAGenerationOfItsKind) {
    Errors errors;
    mWindow->newRandomPopulation(3);
    model().setSelected(0, true);
    model().setSelected(1, true);
    const auto solidGrid = model().current().cells;
    const std::size_t generations = model().history().size();
    const QString flat = example("five-stones.marble.json");
    ASSERT_EQ(loadGenome(flat.toStdString()).dimension, 2);

    ASSERT_TRUE(mWindow->openFiles({flat}));
    EXPECT_EQ(asked, 0) << "nothing of the solid grid is replaced: it stays a generation back";
    EXPECT_EQ(model().history().size(), generations + 1);
    EXPECT_EQ(model().populationDimension(), 2);
    for (int i = 0; i < CellCount; ++i)
        if (model().cell(i)) {
            EXPECT_EQ(model().cell(i)->dimension, 2) << "cell " << i;
        }
    EXPECT_EQ(*model().cell(0), loadGenome(flat.toStdString()));
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("generation of their own")))
        << mWindow->statusBar()->currentMessage().toStdString();

    // The operators work on it: no mystery greying-out.
    model().setSelected(0, true);
    EXPECT_TRUE(mWindow->operatorAction(GeneticOperator::Alter)->isEnabled());
    ASSERT_TRUE(mWindow->openFiles({example("flame-comb-vortex.marble.json")}));
    model().clearSelection();
    for (int i = 0; i < CellCount; ++i)
        if (model().cell(i)) model().setSelected(i, true);
    ASSERT_EQ(model().selectedCount(), 2);
    EXPECT_TRUE(mWindow->operatorAction(GeneticOperator::Recombine)->isEnabled());
    EXPECT_TRUE(mWindow->operatorAction(GeneticOperator::Swap)->isEnabled());
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Swap));
    for (int i = 0; i < CellCount; ++i)
        EXPECT_EQ(model().cell(i)->dimension, 2);

    // Back through the flat generations to the solid grid, intact.
    model().goTo(int(generations) - 1);
    EXPECT_TRUE(model().current().cells == solidGrid);

    // A mixed set opens both kinds (issue 29: the flat one was refused). The solid design goes
    // into a new generation grown from the solid grid (a branch beside the flat ones: history is
    // a tree), the flat one into a generation of its own after it, shown now.
    ASSERT_TRUE(mWindow->openFiles({example("slate-block.marble.json"), flat}));
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("\n")).toStdString();
    EXPECT_EQ(model().populationDimension(), 2);
    EXPECT_EQ(*model().cell(0), loadGenome(flat.toStdString()));
    const int solidGeneration = model().current().parent;
    ASSERT_GE(solidGeneration, 0);
    const Generation& solid = model().history()[std::size_t(solidGeneration)];
    EXPECT_EQ(solid.parent, int(generations) - 1);
    for (const auto& cell : solid.cells)
        if (cell) {
            EXPECT_EQ(cell->dimension, 3);
        }
}

TEST_F(HelpTest, DisabledOperatorsSayWhy) {
    using Op = GeneticOperator;
    const auto tip = [this](Op op) { return mWindow->operatorAction(op)->toolTip(); };
    for (Op op : {Op::Alter, Op::Recombine, Op::Swap, Op::Reinit}) {
        EXPECT_FALSE(mWindow->operatorAction(op)->isEnabled());
        EXPECT_TRUE(tip(op).startsWith(operatorLabel(op) + QStringLiteral(" needs")))
            << tip(op).toStdString();
        EXPECT_TRUE(tip(op).contains(QStringLiteral("click"))) << tip(op).toStdString();
    }
    EXPECT_EQ(tip(Op::Recombine), QStringLiteral("Recombine needs 2 or more parents: click two designs"));
    EXPECT_EQ(tip(Op::Swap), QStringLiteral("Swap needs exactly 2 parents: click two designs"));

    // The tooltips follow the selection as it changes.
    QTest::mouseClick(mWindow->cell(0), Qt::LeftButton);
    EXPECT_TRUE(mWindow->operatorAction(Op::Alter)->isEnabled());
    EXPECT_TRUE(tip(Op::Alter).contains(QStringLiteral("Ctrl+1")))
        << "the ready tooltip is back: " << tip(Op::Alter).toStdString();
    EXPECT_EQ(tip(Op::Swap),
              QStringLiteral("Swap needs exactly 2 parents: 1 is picked, click another design"));
    QTest::mouseClick(mWindow->cell(1), Qt::LeftButton);
    QTest::mouseClick(mWindow->cell(2), Qt::LeftButton);
    EXPECT_EQ(tip(Op::Alter), QStringLiteral("Alter needs 1 parent: 3 are picked, click one to let it go"));
    EXPECT_EQ(tip(Op::Swap),
              QStringLiteral("Swap needs exactly 2 parents: 3 are picked, click one to let it go"));
    EXPECT_TRUE(mWindow->operatorAction(Op::Recombine)->isEnabled());

    // A grid that mixes kinds (an older session could hold one): Swap says so.
    model().clearSelection();
    model().setCell(1, loadGenome(example("slate-block.marble.json").toStdString()), QStringLiteral("mixed"));
    model().setSelected(0, true);
    model().setSelected(1, true);
    EXPECT_FALSE(mWindow->operatorAction(Op::Swap)->isEnabled());
    EXPECT_TRUE(
        tip(Op::Swap).startsWith(QStringLiteral("Swap needs two parents of the same kind (flat/solid)")))
        << tip(Op::Swap).toStdString();
    EXPECT_TRUE(tip(Op::Recombine).contains(QStringLiteral("same kind"))) << tip(Op::Recombine).toStdString();
    // The status bar says the same when the operator is asked for anyway.
    EXPECT_FALSE(mWindow->applyOperator(Op::Swap));
    EXPECT_EQ(mWindow->statusBar()->currentMessage(), tip(Op::Swap));

    // Every design a parent: no room.
    for (int i = 0; i < CellCount; ++i)
        model().setSelected(i, true);
    EXPECT_TRUE(tip(Op::Recombine).contains(QStringLiteral("no room"))) << tip(Op::Recombine).toStdString();
}

} // namespace

namespace {

// The large view's keys fire from the keyboard while it is the active window, whichever of its
// widgets has the focus (as buttons' own shortcuts, they did not): Ctrl+S saves the genome, R
// shows the repeat swatch.
TEST_F(HelpTest, LargeViewKeysSaveAndShowTheSwatch) {
    DesignDialog* dialog = mWindow->openDesign(0);
    ASSERT_NE(dialog, nullptr);
    dialog->show();
    ASSERT_TRUE(test::activate(dialog));
    int asked = 0;
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) {
        ++asked;
        return QString(); // cancelled: nothing written
    });
    QTest::keyClick(dialog, Qt::Key_S, Qt::ControlModifier);
    EXPECT_EQ(asked, 1);
    // R turns the repeat swatch on and off.
    auto* swatch = dialog->findChild<QToolButton*>(QStringLiteral("repeatSwatch"));
    ASSERT_NE(swatch, nullptr);
    const bool before = swatch->isChecked();
    QTest::keyClick(dialog, Qt::Key_R);
    EXPECT_EQ(swatch->isChecked(), !before);
    QTest::keyClick(dialog, Qt::Key_R);
    EXPECT_EQ(swatch->isChecked(), before);
    dialog->close();
}

} // namespace

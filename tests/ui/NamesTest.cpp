// Naming designs (issue 29, "Names and collections"): F2 and Rename… in the grid, the favourites,
// the large view and the editor; names unique in a session; Save As under a typed name names the
// design; a note in the tooltip and the file.
#include "UiTestSupport.h"
#include "WaitFor.h"

#include "editor/EditorWindow.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "shared/DesignDialog.h"
#include "shared/RenameDialog.h"
#include "shared/SavedFiles.h"
#include "workbench/DesignCell.h"

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

namespace marbler::test {
namespace {

using ui::RenameDialog;

/// The rename dialog open over `parent` (any window), once it shows; null when it does not.
RenameDialog* openRenameDialog(QWidget* parent) {
    RenameDialog* dialog = nullptr;
    const bool shown = QTest::qWaitFor(
        [&] {
            dialog = parent->findChild<RenameDialog*>();
            return dialog && dialog->isVisible();
        },
        5000);
    return shown ? dialog : nullptr;
}

/// Types a name (replacing the one offered) and, when given, a note, then presses Enter.
void typeNameAndNote(RenameDialog* dialog, const QString& name, const QString& note = {}) {
    QLineEdit* nameEdit = dialog->nameEdit();
    nameEdit->setFocus();
    nameEdit->selectAll();
    QTest::keyClicks(nameEdit, name);
    if (!note.isEmpty()) {
        dialog->noteEdit()->setFocus();
        QTest::keyClicks(dialog->noteEdit(), note);
    }
    QTest::keyClick(nameEdit, Qt::Key_Return);
}

/// A design bred by recombination as the grid shows it: "Russet Current (g3 #5) · Recombine".
Genome bredDesign() {
    Genome g = randomGenome(7, 2);
    g.meta.name = "Russet Current (g3 #5)";
    MetaLineage lineage;
    lineage.op = "recombine";
    lineage.generation = 3;
    lineage.child = 5;
    g.meta.lineage = lineage;
    return g;
}

class Names : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(mFolder.isValid());
        mWindow->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    }
    void TearDown() override {
        ui::setSaveFileAsker({});
        WindowTest::TearDown();
    }
    QTemporaryDir mFolder;
};

TEST_F(Names, F2OnACellNamesItAndTheSavedFileKeepsNameAndNote) {
    ui::DesignCell* cell = mWindow->cell(2);
    ASSERT_TRUE(test::activate(mWindow.get()));
    cell->setFocus();
    QTest::keyClick(cell, Qt::Key_F2);
    RenameDialog* dialog = openRenameDialog(mWindow.get());
    ASSERT_NE(dialog, nullptr) << "F2 on a cell opens the rename dialog";
    typeNameAndNote(dialog, QStringLiteral("Harbour Green"), QStringLiteral("for the scarf"));

    MARBLER_WAIT(cell->caption() == QStringLiteral("Harbour Green"), 5000);
    EXPECT_TRUE(cell->toolTip().contains(QStringLiteral("for the scarf"))) << cell->toolTip().toStdString();

    // Saved with the name offered: the file is called, and holds, what the cell shows.
    QString offered;
    ui::setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return QDir(mFolder.path()).filePath(QFileInfo(suggested).fileName());
    });
    ui::DesignDialog* large = mWindow->openDesign(2);
    ASSERT_NE(large, nullptr);
    large->findChild<QAction*>(QStringLiteral("saveGenomeAction"))->trigger();
    EXPECT_EQ(QFileInfo(offered).fileName(), QStringLiteral("Harbour Green.marble.json"));
    const Genome saved =
        loadGenome(QDir(mFolder.path()).filePath(QStringLiteral("Harbour Green.marble.json")).toStdString());
    EXPECT_EQ(saved.meta.name.value_or(""), "Harbour Green");
    EXPECT_EQ(saved.meta.note.value_or(""), "for the scarf");
    large->close();
}

TEST_F(Names, TheMenuItemRenamesTheFocusedDesign) {
    // Clicked: the design the window's actions act on.
    QTest::mouseClick(mWindow->cell(4), Qt::LeftButton);
    ASSERT_NE(mWindow->renameAction(), nullptr);
    EXPECT_EQ(mWindow->renameAction()->shortcut(), QKeySequence(Qt::Key_F2));
    mWindow->renameAction()->trigger();
    RenameDialog* dialog = openRenameDialog(mWindow.get());
    ASSERT_NE(dialog, nullptr);
    typeNameAndNote(dialog, QStringLiteral("Tide Pool"));
    MARBLER_WAIT(mWindow->cell(4)->caption() == QStringLiteral("Tide Pool"), 5000);
}

TEST_F(Names, ASecondDesignOfTheSameNameGetsANumber) {
    for (int index : {0, 1}) {
        RenameDialog* dialog = mWindow->renameDesign(index);
        ASSERT_NE(dialog, nullptr);
        typeNameAndNote(dialog, QStringLiteral("Harbour Green"));
    }
    MARBLER_WAIT_EQ(mWindow->cell(0)->caption(), QStringLiteral("Harbour Green"), 5000);
    MARBLER_WAIT_EQ(mWindow->cell(1)->caption(), QStringLiteral("Harbour Green 2"), 5000);
    // Renamed again to its own name, a design keeps it (it is not taken by itself).
    typeNameAndNote(mWindow->renameDesign(0), QStringLiteral("Harbour Green"));
    MARBLER_WAIT_EQ(mWindow->cell(0)->caption(), QStringLiteral("Harbour Green"), 5000);
}

TEST_F(Names, SaveAsUnderATypedNameNamesTheDesignAndDropsTheStaleOperator) {
    model().setCell(0, bredDesign(), QStringLiteral("a bred design"));
    MARBLER_WAIT(mWindow->cell(0)->caption().contains(QStringLiteral("· Recombine")), 5000);
    const QString file = QDir(mFolder.path()).filePath(QStringLiteral("Harbour Green.marble.json"));
    ui::setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return file; });
    ui::DesignDialog* large = mWindow->openDesign(0);
    ASSERT_NE(large, nullptr);
    large->findChild<QAction*>(QStringLiteral("saveGenomeAction"))->trigger();
    EXPECT_EQ(large->windowTitle(), QStringLiteral("Design Harbour Green"));
    large->close();

    const Genome reopened = loadGenome(file.toStdString());
    EXPECT_EQ(reopened.meta.name.value_or(""), "Harbour Green");
    EXPECT_EQ(ui::designCaption(reopened), QStringLiteral("Harbour Green"));
    EXPECT_EQ(mWindow->cell(0)->caption(), QStringLiteral("Harbour Green"));
    // Opened again into the grid, it is shown under its new name, no operator after it.
    mWindow->openFiles({file}, 3);
    MARBLER_WAIT_EQ(mWindow->cell(3)->caption(), QStringLiteral("Harbour Green"), 5000);
}

TEST_F(Names, TheLargeViewRenamesTheCellsDesign) {
    ui::DesignDialog* large = mWindow->openDesign(5);
    ASSERT_NE(large, nullptr);
    ASSERT_NE(large->findChild<QAction*>(QStringLiteral("renameDesignAction")), nullptr);
    EXPECT_EQ(large->findChild<QAction*>(QStringLiteral("renameDesignAction"))->shortcut(),
              QKeySequence(Qt::Key_F2));
    RenameDialog* dialog = large->askName();
    ASSERT_NE(dialog, nullptr);
    typeNameAndNote(dialog, QStringLiteral("Quarry Light"));
    EXPECT_EQ(large->windowTitle(), QStringLiteral("Design Quarry Light"));
    MARBLER_WAIT_EQ(mWindow->cell(5)->caption(), QStringLiteral("Quarry Light"), 5000);
    large->close();
}

TEST_F(Names, AFavouriteIsRenamedOnTheShelfAndInItsFile) {
    ASSERT_TRUE(mWindow->keepFavourite(0));
    QListWidget* list = mWindow->favouritesList();
    MARBLER_WAIT_EQ(list->count(), 1, 5000);
    list->setCurrentRow(0);
    // Rename acts on the focused shelf: the window must be active for the list to take focus,
    // and without a window manager activation can take more than one request.
    ASSERT_TRUE(test::activate(mWindow.get()));
    list->setFocus();
    MARBLER_WAIT(list->hasFocus(), 5000);
    mWindow->renameAction()->trigger();
    RenameDialog* dialog = openRenameDialog(mWindow.get());
    ASSERT_NE(dialog, nullptr);
    typeNameAndNote(dialog, QStringLiteral("Keeper"), QStringLiteral("print at 64 cm"));
    MARBLER_WAIT_EQ(list->item(0)->text(), QStringLiteral("Keeper"), 5000);
    EXPECT_TRUE(list->item(0)->toolTip().contains(QStringLiteral("print at 64 cm")));
    const Genome kept = loadGenome(model().favourites().front().file.toStdString());
    EXPECT_EQ(kept.meta.name.value_or(""), "Keeper");
    EXPECT_EQ(kept.meta.note.value_or(""), "print at 64 cm");
}

class EditorNames : public EditorTest {
protected:
    void TearDown() override {
        ui::setSaveFileAsker({});
        EditorTest::TearDown();
    }
};

TEST_F(EditorNames, RenameIsOneUndoStepAndTheTitleFollows) {
    ui::EditorWindow* editor = open(randomGenome(11, 2));
    const QString before = editor->windowTitle();
    RenameDialog* dialog = editor->renameDesign();
    ASSERT_NE(dialog, nullptr);
    typeNameAndNote(dialog, QStringLiteral("Harbour Green"), QStringLiteral("a note"));
    EXPECT_TRUE(editor->windowTitle().startsWith(QStringLiteral("Harbour Green")))
        << editor->windowTitle().toStdString();
    EXPECT_EQ(editor->document()->design().meta.note.value_or(""), "a note");
    editor->document()->undoStack()->undo();
    EXPECT_EQ(editor->windowTitle(), before);
    editor->document()->undoStack()->redo();
    EXPECT_TRUE(editor->windowTitle().startsWith(QStringLiteral("Harbour Green")));
}

TEST_F(EditorNames, SaveAsUnderATypedNameNamesTheDesign) {
    QTemporaryDir folder;
    Genome design = bredDesign();
    ui::EditorWindow* editor = open(design);
    const QString file = QDir(folder.path()).filePath(QStringLiteral("Harbour Green.marble.json"));
    ui::setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return file; });
    ASSERT_TRUE(editor->saveAs());
    EXPECT_EQ(loadGenome(file.toStdString()).meta.name.value_or(""), "Harbour Green");
    EXPECT_TRUE(editor->windowTitle().contains(QStringLiteral("Harbour Green.marble.json")));
    EXPECT_FALSE(editor->windowTitle().contains(QStringLiteral("Russet")));
    // Saved again under the name offered (its own), the name stays.
    ui::setSaveFileAsker(
        [&](QWidget*, const QString&, const QString& suggested, const QString&) { return suggested; });
    ASSERT_TRUE(editor->saveAs());
    EXPECT_EQ(loadGenome(file.toStdString()).meta.name.value_or(""), "Harbour Green");
}

TEST(RenameDialogTest, AnEmptyNameCannotBeGiven) {
    RenameDialog dialog(QStringLiteral("Cobalt Tide"), {});
    auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    EXPECT_TRUE(ok->isEnabled());
    dialog.nameEdit()->setText(QStringLiteral("   "));
    EXPECT_FALSE(ok->isEnabled());
    dialog.nameEdit()->setText(QStringLiteral("  Harbour   Green "));
    EXPECT_EQ(dialog.name(), QStringLiteral("Harbour Green"));
}

TEST(RenameDialogTest, AdoptFileNameTakesOnlyANameOfTheUsersOwn) {
    Genome g = bredDesign();
    EXPECT_FALSE(ui::adoptFileName(g, QStringLiteral("/tmp/Russet Current (g3 #5).marble.json")));
    EXPECT_EQ(g.meta.name.value_or(""), "Russet Current (g3 #5)");
    EXPECT_TRUE(ui::adoptFileName(g, QStringLiteral("/tmp/Harbour Green.marble.json")));
    EXPECT_EQ(g.meta.name.value_or(""), "Harbour Green");
    EXPECT_FALSE(ui::adoptFileName(g, QStringLiteral("/tmp/.marble.json")));
}

} // namespace
} // namespace marbler::test

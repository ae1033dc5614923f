// The editor's document (EditorDocument.h): every edit undoes and redoes to the exact genome,
// editing a past step gives the genome edited by hand, a drag is one undo step, muted steps
// survive a save, saves are atomic and a failed one changes nothing; and its autosave and crash
// recovery (Recovery.h).

#include "editor/EditorDocument.h"
#include "WaitFor.h"
#include "editor/Recovery.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <memory>

using namespace marbler;
using namespace marbler::ui;

namespace {

Operation drop(double x, double y, double r, int color) {
    Operation op = defaultOperation(Tool::Drop, 2, {x, y, 0.0});
    op.radius = r;
    op.color = color;
    return op;
}

Operation comb(double angle, double spacing) {
    Operation op = defaultOperation(Tool::Comb, 2, {0.0, 0.0, 0.0});
    op.angle = angle;
    op.spacing = spacing;
    op.alpha = 40.0;
    op.lambda = 12.0;
    return op;
}

Operation wave(double amplitude) {
    Operation op = defaultOperation(Tool::Wave, 2, {0.0, 0.0, 0.0});
    op.amplitude = {amplitude, 0.0};
    op.wavelength = {300.0, 1.0};
    return op;
}

/// Three drops, a comb, a wave and a comb.
Genome sample() {
    Genome g;
    g.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    g.initial = {drop(500, 500, 140, 0), drop(500, 500, 90, 1), drop(300, 700, 60, 2)};
    g.operations = {comb(0, 80), wave(25), comb(90, 60)};
    g.meta.name = "Sample";
    validateGenome(g, "sample");
    return g;
}

/// One state of a document as the tests compare it.
struct Snapshot {
    Genome design;
    Genome rendered;
    std::vector<bool> muted;
};

Snapshot snapshot(const EditorDocument& doc) {
    Snapshot s{doc.design(), doc.renderedDesign(), {}};
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        s.muted.push_back(doc.isMuted(i));
    return s;
}

void expectSame(const Snapshot& a, const Snapshot& b, const std::string& where) {
    EXPECT_TRUE(a.design == b.design) << where << ": design\n"
                                      << serializeGenome(a.design) << "\nvs\n"
                                      << serializeGenome(b.design);
    EXPECT_TRUE(a.rendered == b.rendered) << where << ": rendered design";
    EXPECT_EQ(a.muted, b.muted) << where << ": muted flags";
}

std::string text(const QString& s) {
    return s.toStdString();
}

} // namespace

TEST(EditorDocument, UndoAndRedoRestoreTheExactGenomeAcrossEveryKindOfEdit) {
    EditorDocument doc(sample());
    QUndoStack& stack = *doc.undoStack();
    EXPECT_EQ(stack.count(), 0);
    EXPECT_FALSE(doc.isModified());
    EXPECT_EQ(doc.stepCount(), 6u);
    EXPECT_EQ(text(doc.stepName(0)), "drop 1");
    EXPECT_EQ(text(doc.stepName(4)), "wave 5");

    std::vector<Snapshot> states{snapshot(doc)};
    std::vector<std::string> texts;
    const auto record = [&] {
        states.push_back(snapshot(doc));
        texts.push_back(text(stack.text(stack.index() - 1)));
        EXPECT_EQ(stack.index(), static_cast<int>(states.size()) - 1) << "each edit is one undo step";
    };

    // A drop added within the initial state stays in it; steps added with no place go last.
    EXPECT_EQ(doc.addStep(drop(200, 200, 50, 1), 3), 3u);
    record();
    EXPECT_TRUE(doc.isInitial(3));
    EXPECT_EQ(doc.addStep(comb(45, 30)), 7u);
    record();
    EXPECT_EQ(doc.addSteps({drop(100, 100, 20, 0), wave(10), drop(900, 900, 20, 2)},
                           QStringLiteral("Drop pattern")),
              8u);
    record();
    EXPECT_EQ(doc.stepCount(), 11u);
    EXPECT_EQ(doc.design().initial.size(), 4u);
    EXPECT_EQ(doc.step(8).tool, Tool::Drop) << "after the strokes, where it was put";
    Operation edited = doc.step(7);
    edited.spacing = 23;
    doc.setStep(7, edited);
    record();
    doc.removeStep(1);
    record();
    EXPECT_EQ(doc.duplicateStep(4), 5u);
    record();
    EXPECT_EQ(doc.step(5).tool, Tool::Wave);
    EXPECT_EQ(doc.step(5), doc.step(4));
    EXPECT_FALSE(doc.moveStep(7, 2)) << "a comb has no place in the initial state";
    EXPECT_TRUE(doc.moveStep(7, 3));
    record();
    EXPECT_FALSE(doc.isInitial(3)) << "at the boundary a stroke stays a stroke";
    doc.setMuted(2, true);
    record();
    doc.setMuted(8, true);
    record();
    EXPECT_EQ(doc.renderedDesign().initial.size() + doc.renderedDesign().operations.size(),
              doc.stepCount() - 2);
    doc.setPaletteColor(1, {0x11, 0x22, 0x33});
    record();
    EXPECT_EQ(doc.addPaletteColor({0xaa, 0, 0}), 3);
    record();
    doc.setBackground({0xff, 0xff, 0xff});
    record();
    doc.setBleed(2.5);
    record();
    Genome other = sample();
    other.operations.pop_back();
    doc.replaceDesign(other, QStringLiteral("New design"));
    record();
    doc.setMuted(0, false); // not muted: no edit
    EXPECT_EQ(stack.count(), static_cast<int>(states.size()) - 1);

    EXPECT_EQ(texts[0], "Add drop 4");
    EXPECT_EQ(texts[1], "Add comb 8");
    EXPECT_EQ(texts[2], "Drop pattern");
    EXPECT_EQ(texts[3], "comb 8: spacing 30 → 23");
    EXPECT_EQ(texts[4], "Delete drop 2");
    EXPECT_EQ(texts[5], "Duplicate wave 5");
    EXPECT_EQ(texts[6], "Move comb 8 to 4");
    EXPECT_EQ(texts[7], "Mute drop 3");
    EXPECT_EQ(texts[8], "Mute drop 9");
    EXPECT_EQ(texts[9], "Ink 2: #b8412c → #112233");
    EXPECT_EQ(texts[10], "Add ink 4: #aa0000");
    EXPECT_EQ(texts[11], "Background: #f3ecdc → #ffffff");
    EXPECT_EQ(texts[12], "Bleed: 0 → 2.5");
    EXPECT_TRUE(doc.isModified());

    for (std::size_t k = states.size() - 1; k-- > 0;) {
        stack.undo();
        expectSame(snapshot(doc), states[k], "undo to state " + std::to_string(k));
    }
    EXPECT_FALSE(doc.isModified());
    for (std::size_t k = 1; k < states.size(); ++k) {
        stack.redo();
        expectSame(snapshot(doc), states[k], "redo to state " + std::to_string(k));
    }
    // Jumping as the history view does.
    stack.setIndex(3);
    expectSame(snapshot(doc), states[3], "jump to 3");
    stack.setIndex(static_cast<int>(states.size()) - 1);
    expectSame(snapshot(doc), states.back(), "jump to the end");
}

TEST(EditorDocument, SignalsSayWhatChanged) {
    EditorDocument doc(sample());
    QSignalSpy changed(&doc, &EditorDocument::changed);
    QSignalSpy steps(&doc, &EditorDocument::stepsChanged);
    QSignalSpy modified(&doc, &EditorDocument::modifiedChanged);
    Operation op = doc.step(3);
    op.alpha = 70;
    doc.setStep(3, op);
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(steps.count(), 0) << "a parameter edit keeps the list";
    ASSERT_EQ(modified.count(), 1);
    EXPECT_TRUE(modified.at(0).at(0).toBool());
    doc.setMuted(3, true);
    EXPECT_EQ(changed.count(), 2);
    EXPECT_EQ(steps.count(), 1);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    EXPECT_EQ(changed.count(), 4);
    EXPECT_EQ(steps.count(), 2);
    ASSERT_EQ(modified.count(), 2);
    EXPECT_FALSE(modified.at(1).at(0).toBool());
}

TEST(EditorDocument, EditingAPastStepGivesTheGenomeEditedByHand) {
    const Genome original = sample();
    EditorDocument doc(original);
    // The first comb, with every step after it kept.
    Operation comb1 = doc.step(3);
    comb1.spacing = 18;
    comb1.angle = 30;
    doc.setStep(3, comb1);
    // The first drop of the initial state.
    Operation drop1 = doc.step(0);
    drop1.center = {420, 380, 0};
    drop1.radius = 150;
    doc.setStep(0, drop1);

    Genome byHand = original;
    byHand.operations[0].spacing = 18;
    byHand.operations[0].angle = 30;
    byHand.initial[0].center = {420, 380, 0};
    byHand.initial[0].radius = 150;
    EXPECT_TRUE(doc.design() == byHand) << serializeGenome(doc.design());
    EXPECT_TRUE(doc.renderedDesign() == byHand);
    EXPECT_TRUE(doc.fileGenome() == byHand) << "nothing muted: the file holds the design as it is";
    EXPECT_EQ(text(doc.undoStack()->text(0)).rfind("comb 4: ", 0), 0u) << text(doc.undoStack()->text(0));
    EXPECT_NE(text(doc.undoStack()->text(0)).find("spacing 80 → 18"), std::string::npos);
    EXPECT_EQ(text(doc.undoStack()->text(1)), "drop 1: moved 144 units, radius 140 → 150");

    // A tool the initial state may not hold is refused there.
    doc.setStep(0, comb(0, 10));
    EXPECT_TRUE(doc.design() == byHand);
    EXPECT_EQ(doc.undoStack()->count(), 2);
}

TEST(EditorDocument, ADragMergesIntoOneUndoStep) {
    const Genome original = sample();
    EditorDocument doc(original);
    QUndoStack& stack = *doc.undoStack();
    Operation op = doc.step(3);
    for (double spacing : {82.0, 90.0, 101.0, 123.0}) {
        op.spacing = spacing;
        doc.setStep(3, op, 7);
    }
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(text(stack.text(0)), "comb 4: spacing 80 → 123");
    EXPECT_EQ(doc.step(3).spacing, 123.0);

    // Another step, or no merge id, is a step of its own.
    Operation other = doc.step(5);
    other.spacing = 10;
    doc.setStep(5, other, 7);
    EXPECT_EQ(stack.count(), 2);
    other.spacing = 11;
    doc.setStep(5, other);
    other.spacing = 12;
    doc.setStep(5, other);
    EXPECT_EQ(stack.count(), 4);

    // A palette drag and a background drag merge the same way.
    for (std::uint8_t r : {0x20, 0x40, 0x60})
        doc.setPaletteColor(0, {r, 0, 0}, 9);
    EXPECT_EQ(stack.count(), 5);
    EXPECT_EQ(text(stack.text(4)), "Ink 1: #1f3b5a → #600000");
    for (std::uint8_t g : {0x20, 0x40})
        doc.setBackground({0, g, 0}, 9);
    EXPECT_EQ(stack.count(), 6) << "the same id on another target does not merge";

    while (stack.canUndo())
        stack.undo();
    EXPECT_TRUE(doc.design() == original);
}

TEST(EditorDocument, ADragThatEndsWhereItBeganLeavesNoStepAndNoChange) {
    // A colour dialog moved about, then cancelled: its last colour is the first one again.
    const Genome original = sample();
    EditorDocument doc(original);
    QUndoStack& stack = *doc.undoStack();
    const Color first = original.palette[0];
    for (Color c : {Color{0x20, 0, 0}, Color{0x40, 0, 0}, first})
        doc.setPaletteColor(0, c, 11);
    EXPECT_EQ(stack.count(), 0) << (stack.count() ? text(stack.text(0)) : std::string());
    EXPECT_FALSE(doc.isModified());
    EXPECT_TRUE(doc.design() == original);
    // A real change after it is an entry as usual.
    doc.setPaletteColor(0, Color{1, 2, 3}, 12);
    EXPECT_EQ(stack.count(), 1);
    EXPECT_TRUE(doc.isModified());
}

TEST(EditorDocument, MutedStepsRoundTripThroughAFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    EditorDocument doc(sample());
    doc.setMuted(2, true); // the last drop: next to the boundary of the parts
    doc.setMuted(3, true); // the first comb
    doc.setMuted(5, true); // the last comb
    const Genome file = doc.fileGenome();
    EXPECT_EQ(file.initial.size(), 2u);
    EXPECT_EQ(file.operations.size(), 1u);
    ASSERT_TRUE(file.meta.toJson().contains("editor"));
    EXPECT_EQ(file.meta.toJson()["editor"]["muted"].size(), 3u);
    EXPECT_EQ(file.meta.toJson()["name"], "Sample");
    EXPECT_FALSE(doc.design().meta.toJson().contains("editor"));

    const QString path = dir.filePath(QStringLiteral("muted.marble.json"));
    QString error;
    ASSERT_TRUE(doc.saveAs(path, &error)) << text(error);
    EXPECT_FALSE(doc.isModified());
    EXPECT_EQ(doc.fileName(), path);

    const Genome loaded = loadGenome(QFile::encodeName(path).toStdString());
    EXPECT_TRUE(loaded == file);
    EditorDocument reopened(loaded);
    EXPECT_TRUE(reopened.design() == doc.design()) << serializeGenome(reopened.design());
    EXPECT_TRUE(reopened.renderedDesign() == doc.renderedDesign());
    EXPECT_TRUE(reopened.fileGenome() == file);
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        EXPECT_EQ(reopened.isMuted(i), doc.isMuted(i)) << "step " << i;
    EXPECT_FALSE(reopened.isModified());
    EXPECT_EQ(reopened.undoStack()->count(), 0);
}

TEST(EditorDocument, SaveIsAtomicAndAFailedSaveChangesNothing) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    EditorDocument doc(sample());
    const QString path = dir.filePath(QStringLiteral("design.marble.json"));
    QString error;
    ASSERT_TRUE(doc.saveAs(path, &error)) << text(error);
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
              QStringList{QStringLiteral("design.marble.json")})
        << "no temporary left";
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray saved = f.readAll();
    f.close();
    EXPECT_EQ(saved.toStdString(), serializeGenome(doc.fileGenome()));

    doc.setBleed(3);
    ASSERT_TRUE(doc.isModified());
    QSignalSpy fileNames(&doc, &EditorDocument::fileNameChanged);
    const auto expectUnchanged = [&](const std::string& where) {
        EXPECT_FALSE(error.isEmpty()) << where << ": the reason is given";
        EXPECT_TRUE(doc.isModified()) << where;
        EXPECT_EQ(doc.fileName(), path) << where;
        EXPECT_EQ(fileNames.count(), 0) << where;
        QFile again(path);
        ASSERT_TRUE(again.open(QIODevice::ReadOnly));
        EXPECT_EQ(again.readAll(), saved) << where << ": the old file is kept";
    };

    // A folder that is not there (under a file).
    error.clear();
    EXPECT_FALSE(doc.saveAs(path + QStringLiteral("/sub/x.marble.json"), &error));
    expectUnchanged("no folder");
    // A target that is a folder: the rename fails after the temporary is written; it goes.
    ASSERT_TRUE(QDir(dir.path()).mkdir(QStringLiteral("folder")));
    error.clear();
    EXPECT_FALSE(doc.saveAs(dir.filePath(QStringLiteral("folder")), &error));
    expectUnchanged("folder target");
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
              QStringList{QStringLiteral("design.marble.json")});
    // A design the format refuses is not written.
    Operation bad = doc.step(0);
    bad.color = 9;
    doc.setStep(0, bad);
    error.clear();
    EXPECT_FALSE(doc.saveAs(path, &error));
    expectUnchanged("invalid design");
    EXPECT_TRUE(error.contains(QStringLiteral("color"))) << text(error);
    doc.undoStack()->undo();
    // An unwritable folder (root may write anywhere, so only as another user).
    if (::geteuid() != 0) {
        ASSERT_TRUE(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
        error.clear();
        EXPECT_FALSE(doc.saveAs(path, &error));
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        expectUnchanged("unwritable folder");
    }

    error.clear();
    ASSERT_TRUE(doc.saveAs(path, &error)) << text(error);
    EXPECT_FALSE(doc.isModified());
    EXPECT_TRUE(loadGenome(QFile::encodeName(path).toStdString()) == doc.fileGenome());
}

TEST(EditorRecovery, TheRecoveredDesignIsTheOneBeingEdited) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("recovery"));
    EditorDocument doc(sample());
    doc.setFileName(QStringLiteral("/somewhere/design.marble.json"));
    auto autosave = std::make_unique<EditorAutosave>(&doc, folder);
    autosave->flush();
    EXPECT_FALSE(QFileInfo::exists(autosave->file())) << "nothing to recover before an edit";

    autosave->setDelay(20);
    doc.addStep(wave(40));
    doc.setMuted(1, true);
    doc.setMuted(6, true);
    Operation op = doc.step(3);
    op.lambda = 33;
    doc.setStep(3, op, 1);
    MARBLER_WAIT(QFileInfo::exists(autosave->file()), 5000);
    EXPECT_TRUE(pendingRecoveries(folder).empty()) << "an editor still open is not offered";

    // A crash: the autosave goes without a word, and its lock stays, naming a process that is
    // gone. The same lock naming a running process keeps the file from being offered.
    const QString file = autosave->file();
    QFile lockFile(file + QStringLiteral(".lock"));
    ASSERT_TRUE(lockFile.open(QIODevice::ReadOnly));
    const QByteArray lock = lockFile.readAll();
    lockFile.close();
    const QByteArray ownPid = QByteArray::number(QCoreApplication::applicationPid());
    ASSERT_TRUE(lock.startsWith(ownPid + '\n')) << lock.toStdString();
    autosave.reset();
    ASSERT_TRUE(QFileInfo::exists(file));
    const auto writeLock = [&](const QByteArray& contents) {
        QFile f(file + QStringLiteral(".lock"));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(contents);
    };
    writeLock(lock);
    EXPECT_TRUE(pendingRecoveries(folder).empty()) << "locked by a running process";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) ::_exit(0);
    ASSERT_EQ(::waitpid(child, nullptr, 0), child);
    writeLock(QByteArray::number(child) + lock.mid(ownPid.size()));
    QStringList warnings;
    const auto found = pendingRecoveries(folder, &warnings);
    EXPECT_TRUE(warnings.isEmpty()) << text(warnings.join('\n'));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].recoveryFile, QFileInfo(file).absoluteFilePath());
    EXPECT_EQ(found[0].originalFile, QStringLiteral("/somewhere/design.marble.json"));
    EXPECT_TRUE(found[0].saved.isValid());
    EXPECT_TRUE(found[0].design == doc.fileGenome());
    EditorDocument recovered(found[0].design);
    EXPECT_TRUE(recovered.design() == doc.design()) << serializeGenome(recovered.design());
    EXPECT_TRUE(recovered.renderedDesign() == doc.renderedDesign());
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        EXPECT_EQ(recovered.isMuted(i), doc.isMuted(i)) << "step " << i;
    recovered.markModified();
    EXPECT_TRUE(recovered.isModified()) << "its changes never reached the file";

    EXPECT_FALSE(QFileInfo::exists(file + QStringLiteral(".lock"))) << "the stale lock is gone";
    EXPECT_TRUE(discardRecovery(found[0].recoveryFile));
    EXPECT_TRUE(pendingRecoveries(folder).empty());
}

TEST(EditorRecovery, ACorruptRecoveryFileIsSkipped) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString folder = dir.path();
    EditorDocument doc(sample());
    {
        EditorAutosave autosave(&doc, folder);
        doc.setBleed(1);
        autosave.flush();
    }
    const auto writeText = [&](const QString& name, const QByteArray& bytes) {
        QFile f(QDir(folder).filePath(name));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes);
    };
    writeText(QStringLiteral("a.recovery.json"), "{ not json");
    writeText(QStringLiteral("b.recovery.json"),
              R"({"format": "marbler-recovery", "genome": {"format": "marbler-genome"}})");
    writeText(QStringLiteral("c.recovery.json"), R"([1, 2, 3])");
    writeText(QStringLiteral("d.recovery.json"), "");
    QStringList warnings;
    const auto found = pendingRecoveries(folder, &warnings);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_TRUE(found[0].design == doc.fileGenome());
    EXPECT_EQ(warnings.size(), 4) << text(warnings.join('\n'));
    EXPECT_TRUE(warnings.join('\n').contains(QStringLiteral("a.recovery.json")));
    EXPECT_TRUE(QFileInfo::exists(QDir(folder).filePath(QStringLiteral("a.recovery.json"))))
        << "left for the user";
    EXPECT_TRUE(pendingRecoveries(QDir(folder).filePath(QStringLiteral("missing"))).empty());
}

TEST(EditorRecovery, DiscardRemovesTheFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    EditorDocument doc(sample());
    EditorAutosave autosave(&doc, dir.path());
    doc.setBackground({1, 2, 3});
    autosave.flush();
    ASSERT_TRUE(QFileInfo::exists(autosave.file()));
    autosave.discard();
    EXPECT_FALSE(QFileInfo::exists(autosave.file()));
    EXPECT_TRUE(pendingRecoveries(dir.path()).empty());
}

TEST(EditorRecovery, ACleanSavedDocumentLeavesNoRecovery) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("recovery"));
    EditorDocument doc(sample());
    {
        EditorAutosave autosave(&doc, folder);
        doc.setMuted(4, true);
        autosave.flush();
        ASSERT_TRUE(QFileInfo::exists(autosave.file()));
        QString error;
        ASSERT_TRUE(doc.saveAs(dir.filePath(QStringLiteral("saved.marble.json")), &error)) << text(error);
        EXPECT_FALSE(QFileInfo::exists(autosave.file())) << "saved clean: nothing to recover";
        // Undone past the save and back: modified, then clean again.
        doc.undoStack()->undo();
        autosave.flush();
        EXPECT_TRUE(QFileInfo::exists(autosave.file()));
        doc.undoStack()->redo();
        EXPECT_FALSE(QFileInfo::exists(autosave.file()));
    }
    EXPECT_TRUE(pendingRecoveries(folder).empty());
    EXPECT_TRUE(QDir(folder).entryList(QDir::Files | QDir::Hidden).isEmpty()) << "no file and no lock left";
}

TEST(EditorRecovery, TheDefaultFolderIsInTheApplicationData) {
    EXPECT_TRUE(defaultRecoveryFolder().endsWith(QStringLiteral("/recovery")));
    EXPECT_FALSE(defaultRecoveryFolder().startsWith(QStringLiteral("/recovery")));
}

TEST(EditorDocument, AFoldedGroupIsMutedAsOneEdit) {
    EditorDocument doc(sample());
    doc.setMuted(1, 4, true);
    EXPECT_EQ(doc.undoStack()->count(), 1);
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        EXPECT_EQ(doc.isMuted(i), i >= 1 && i <= 4) << i;
    EXPECT_EQ(text(doc.undoStack()->text(0)), "Mute steps 2–5");
    doc.undoStack()->undo();
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        EXPECT_FALSE(doc.isMuted(i)) << i;
    doc.setMuted(3, 9, true); // past the end: nothing
    EXPECT_EQ(doc.undoStack()->count(), 1);
}

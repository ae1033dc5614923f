// The editor's history over a long session (EditorDocument.h): thousands of random edits undo
// back to the opened design and redo to the last one exactly, branches made on the way switch to
// their own newest design, and the history's bytes grow with the edits, not with the design's
// size (it holds what each edit changed, not whole designs).

#include "editor/EditorDocument.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <QUndoStack>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

using namespace marbler;
using namespace marbler::ui;

namespace history_bound_test {

/// A design of `steps` drops and combs, their parameters drawn from `rng`.
Genome randomDesign(std::mt19937_64& rng, std::size_t steps) {
    Genome g;
    g.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    for (std::size_t i = 0; i < steps; ++i) {
        const double u = static_cast<double>(rng() % 1000);
        Operation op = defaultOperation(i % 3 == 2 ? Tool::Comb : Tool::Drop, 2, {u, 1000.0 - u, 0.0});
        op.radius = 20.0 + static_cast<double>(rng() % 100);
        op.color = static_cast<int>(rng() % 3);
        (op.tool == Tool::Drop ? g.initial : g.operations).push_back(op);
    }
    g.meta.name = "Long session";
    validateGenome(g, "long session");
    return g;
}

/// One random edit of any kind the editor makes (some of them merged drags).
void randomEdit(EditorDocument& doc, std::mt19937_64& rng) {
    const std::size_t n = doc.stepCount();
    const auto pick = [&] { return static_cast<std::size_t>(rng() % n); };
    switch (rng() % 10) {
    case 0:
    case 1: {
        Operation op =
            defaultOperation(rng() % 2 ? Tool::Drop : Tool::Line, 2,
                             {static_cast<double>(rng() % 1000), static_cast<double>(rng() % 1000), 0.0});
        op.radius = 10.0 + static_cast<double>(rng() % 50);
        doc.addStep(op, pick());
        break;
    }
    case 2:
        if (n > 4) doc.removeStep(pick());
        break;
    case 3:
        doc.moveStep(pick(), pick());
        break;
    case 4:
        doc.setMuted(pick(), rng() % 2 == 0);
        break;
    case 5:
        doc.setPaletteColor(static_cast<int>(rng() % 3),
                            {std::uint8_t(rng() % 256), std::uint8_t(rng() % 256), std::uint8_t(rng() % 256)},
                            static_cast<int>(rng() % 3) - 1);
        break;
    case 6:
        doc.setBleed(static_cast<double>(rng() % 5), static_cast<int>(rng() % 2) - 1);
        break;
    default: {
        const std::size_t i = pick();
        Operation op = doc.step(i);
        op.center.x = static_cast<double>(rng() % 1000);
        op.radius = 5.0 + static_cast<double>(rng() % 200);
        doc.setStep(i, op, static_cast<int>(rng() % 3) - 1);
        break;
    }
    }
}

struct Seen {
    Genome file;
    std::vector<bool> muted;
};

Seen seen(const EditorDocument& doc) {
    Seen s{doc.fileGenome(), {}};
    for (std::size_t i = 0; i < doc.stepCount(); ++i)
        s.muted.push_back(doc.isMuted(i));
    return s;
}

} // namespace history_bound_test

using namespace history_bound_test;

TEST(EditorHistoryBound, TwoThousandRandomEditsUndoToTheFirstDesignAndRedoToTheLast) {
    std::mt19937_64 rng(20261203);
    EditorDocument doc(randomDesign(rng, 40));
    const Seen first = seen(doc);
    const std::string firstFile = serializeGenome(doc.fileGenome());

    // Now and then a few edits are undone and the next edit starts a branch.
    std::vector<Seen> branchTips;
    for (int k = 0; k < 2000; ++k) {
        if (k % 97 == 50) {
            branchTips.push_back(seen(doc));
            for (int u = 0; u < 3; ++u)
                doc.undoStack()->undo();
        }
        randomEdit(doc, rng);
    }
    const Seen last = seen(doc);
    const std::string lastFile = serializeGenome(doc.fileGenome());
    ASSERT_GT(doc.undoStack()->count(), 1000);
    ASSERT_GE(doc.branches().size(), 10u);

    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    EXPECT_TRUE(doc.fileGenome() == first.file);
    EXPECT_EQ(seen(doc).muted, first.muted);
    EXPECT_EQ(serializeGenome(doc.fileGenome()), firstFile);
    EXPECT_FALSE(doc.isModified());

    while (doc.undoStack()->canRedo())
        doc.undoStack()->redo();
    EXPECT_TRUE(doc.fileGenome() == last.file);
    EXPECT_EQ(seen(doc).muted, last.muted);
    EXPECT_EQ(serializeGenome(doc.fileGenome()), lastFile);

    // Each branch is the line left at its tip, whose newest design was the one seen there.
    const auto infos = doc.branches();
    for (std::size_t b = 0; b < branchTips.size() && b < infos.size(); ++b) {
        doc.switchToBranch(0); // the oldest branch comes first; the line left goes last
        const Seen tip = seen(doc);
        EXPECT_TRUE(tip.file == branchTips[b].file) << "branch " << b;
        EXPECT_EQ(tip.muted, branchTips[b].muted) << "branch " << b;
    }
}

TEST(EditorHistoryBound, TheHistoryGrowsWithTheEditsNotWithTheDesign) {
    // The same kind of edits on a small and on a large design: with whole designs kept per edit
    // the large design's history would be 25 times larger (some 400 bytes a step, 2,000 steps,
    // 1,000 edits: 800 MB); what each edit changed is a few steps at most.
    const auto historyAfterEdits = [](std::size_t steps) {
        std::mt19937_64 rng(7);
        EditorDocument doc(randomDesign(rng, steps));
        for (int k = 0; k < 1000; ++k) {
            const std::size_t i = static_cast<std::size_t>(rng() % doc.stepCount());
            Operation op = doc.step(i);
            (op.tool == Tool::Drop ? op.radius : op.spacing) = 5.0 + static_cast<double>(rng() % 200);
            doc.setStep(i, op);
            if (k % 5 == 0) doc.addStep(op);
            if (k % 5 == 1) doc.removeStep(static_cast<std::size_t>(rng() % doc.stepCount()));
        }
        EXPECT_GE(doc.undoStack()->count(), 1200); // a few edits change nothing
        return doc.historyBytes();
    };
    const std::size_t small = historyAfterEdits(80);
    const std::size_t large = historyAfterEdits(2000);
    const std::size_t cap = 1000 * 4 * 1024; // 4 KiB an edit, whatever the design's size
    EXPECT_GT(small, 0u);
    EXPECT_LT(small, cap);
    EXPECT_LT(large, cap);
    EXPECT_LT(large, small * 2) << "small " << small << " large " << large;
}

// AtomicFile (marbler/AtomicFile.h): the one write-to-a-temporary-then-rename. What the person
// keeps is the folder's contents: the whole new file, or the old one and nothing else.

#include "TestUtil.h"

#include "marbler/AtomicFile.h"
#include "marbler/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace marbler;
namespace fs = std::filesystem;

namespace {

/// Every entry of a folder, recursively, by path relative to it, sorted.
std::vector<std::string> contents(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        names.push_back(fs::relative(entry.path(), dir).string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST(AtomicFile, TemporaryIsHiddenBesideTheTargetWithItsExtension) {
    fs::path dir = test::outputDir("AtomicFile.Temporary");
    AtomicFile file(dir / "picture.png");
    EXPECT_EQ(file.temporary().parent_path(), dir);
    EXPECT_EQ(file.temporary().extension(), ".png");
    EXPECT_EQ(file.temporary().filename().string().front(), '.');
    EXPECT_TRUE(fs::is_regular_file(file.temporary())) << "the name is reserved";
    EXPECT_FALSE(fs::exists(dir / "picture.png"));

    AtomicFile other(dir / "picture.png");
    EXPECT_NE(other.temporary(), file.temporary()) << "two writers never share a temporary";
}

TEST(AtomicFile, CommitReplacesTheTargetAndLeavesNoTemporary) {
    fs::path dir = test::outputDir("AtomicFile.Commit");
    test::writeFile(dir / "a.json", "old");
    {
        AtomicFile file(dir / "a.json");
        file.write("new text");
        EXPECT_EQ(test::readFile(dir / "a.json"), "old") << "the target is untouched until commit";
        file.commit();
    }
    EXPECT_EQ(test::readFile(dir / "a.json"), "new text");
    EXPECT_EQ(contents(dir), std::vector<std::string>{"a.json"});

    writeFileAtomically(dir / "b.txt", "bee");
    EXPECT_EQ(test::readFile(dir / "b.txt"), "bee");
    EXPECT_EQ(contents(dir), (std::vector<std::string>{"a.json", "b.txt"}));
}

TEST(AtomicFile, UncommittedLeavesTheOldFileAndNoTemporary) {
    fs::path dir = test::outputDir("AtomicFile.Uncommitted");
    test::writeFile(dir / "a.json", "old");
    try {
        AtomicFile file(dir / "a.json");
        file.write("half");
        throw RuntimeFailure("stopped half way");
    } catch (const RuntimeFailure&) {
    }
    EXPECT_EQ(test::readFile(dir / "a.json"), "old");
    EXPECT_EQ(contents(dir), std::vector<std::string>{"a.json"});
}

TEST(AtomicFile, FailuresNameTheTargetAndLeaveNothing) {
    fs::path dir = test::outputDir("AtomicFile.Failures");
    try {
        AtomicFile file(dir / "missing-folder" / "a.png");
        ADD_FAILURE() << "a missing folder must throw";
    } catch (const RuntimeFailure& e) {
        EXPECT_NE(std::string(e.what()).find("missing-folder/a.png"), std::string::npos) << e.what();
    }

    // The rename fails (the target is a folder): the temporary goes, the folder stays.
    fs::create_directories(dir / "target-is-folder" / "inside");
    AtomicFile file(dir / "target-is-folder");
    file.write("x");
    EXPECT_THROW(file.commit(), RuntimeFailure);
    EXPECT_EQ(contents(dir), (std::vector<std::string>{"target-is-folder", "target-is-folder/inside"}));
}

TEST(AtomicFile, FolderIsRenamedWholeOrRemovedWithItsFiles) {
    fs::path dir = test::outputDir("AtomicFile.Folder");
    {
        AtomicFile folder(dir / "frames", AtomicFile::Kind::Folder);
        EXPECT_TRUE(fs::is_directory(folder.temporary()));
        test::writeFile(folder.temporary() / "frame-0000.png", "png");
    }
    EXPECT_TRUE(contents(dir).empty()) << "uncommitted: the folder and its files are gone";

    AtomicFile folder(dir / "frames", AtomicFile::Kind::Folder);
    test::writeFile(folder.temporary() / "frame-0000.png", "png");
    folder.commit();
    EXPECT_EQ(contents(dir), (std::vector<std::string>{"frames", "frames/frame-0000.png"}));
}

TEST(AtomicFileSet, AllOrNothing) {
    fs::path dir = test::outputDir("AtomicFileSet.AllOrNothing");
    {
        AtomicFileSet files;
        files.add(dir / "texture.png").write("png");
        files.add(dir / "model.gltf").write("gltf");
        EXPECT_EQ(files.commit(), (std::vector<fs::path>{dir / "texture.png", dir / "model.gltf"}));
    }
    EXPECT_EQ(contents(dir), (std::vector<std::string>{"model.gltf", "texture.png"}));
    EXPECT_EQ(test::readFile(dir / "model.gltf"), "gltf");

    // The second rename fails: the first file, already renamed, is removed too.
    fs::path fresh = test::outputDir("AtomicFileSet.Fails");
    fs::create_directories(fresh / "model.gltf" / "inside");
    {
        AtomicFileSet files;
        files.add(fresh / "texture.png").write("png");
        files.add(fresh / "model.gltf").write("gltf");
        EXPECT_THROW(files.commit(), RuntimeFailure);
    }
    EXPECT_EQ(contents(fresh), (std::vector<std::string>{"model.gltf", "model.gltf/inside"}));
}

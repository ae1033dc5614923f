// The rule of a genome's `source` image (SourcePath.h, cli.md): read from the genome's folder or
// below it, or from a data: URI; an absolute path, `..` or a link leading out is refused (exit 2,
// one line naming the genome and `source.image`) unless --allow-external-source is given. On
// the code before the rule, the refused cases rendered the outside file.

#include "marbler/SourcePath.h"
#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace marbler {
namespace {

namespace fs = std::filesystem;
using test::runMarbler;

/// A design folder holding genomes whose sources lie in every place the rule distinguishes,
/// and a folder beside it with a "private" image.
struct SourceFolders {
    fs::path root, design, outside;
    SourceFolders() {
        // A folder of each test's own: ctest runs the cases of this file side by side.
        root = test::outputDir(std::string("source-paths-") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        design = root / "design";
        outside = root / "private";
        fs::create_directories(design / "sub");
        fs::create_directories(outside);
        const fs::path image = test::dataDir() / "render" / "source-4x2.png";
        fs::copy_file(image, outside / "secret.png");
        fs::copy_file(image, design / "inside.png");
        fs::copy_file(image, design / "sub" / "below.png");
        fs::create_symlink(fs::path("..") / "private" / "secret.png", design / "link-out.png");
        fs::create_symlink("inside.png", design / "link-in.png");
    }
    /// Writes design/NAME.marble.json with `image` as its source; returns its path.
    fs::path genome(const std::string& name, const std::string& image) const {
        Genome g = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
        g.source = SourceImage{image};
        const fs::path file = design / (name + ".marble.json");
        saveGenome(g, file);
        return file;
    }
};

TEST(SourcePath, LocatesEveryKindOfSource) {
    SourceFolders f;
    auto kindOf = [&](const std::string& image) {
        return locateSource(loadGenome(f.genome("g", image))).kind;
    };
    using Kind = SourceLocation::Kind;
    EXPECT_EQ(kindOf("inside.png"), Kind::Inside);
    EXPECT_EQ(kindOf("sub/below.png"), Kind::Inside);
    EXPECT_EQ(kindOf("sub/../inside.png"), Kind::Inside);
    EXPECT_EQ(kindOf("link-in.png"), Kind::Inside);
    EXPECT_EQ(kindOf("data:image/png;base64,AAAA"), Kind::DataUri);
    EXPECT_EQ(kindOf("../private/secret.png"), Kind::Outside);
    EXPECT_EQ(kindOf("link-out.png"), Kind::Outside);
    EXPECT_EQ(kindOf((f.outside / "secret.png").string()), Kind::Outside);
    // Absolute is refused even where it names a file inside: the rule is about what a shared
    // file may name, not where the receiver happens to keep it.
    EXPECT_EQ(kindOf(fs::absolute(f.design / "inside.png").string()), Kind::Outside);
    EXPECT_EQ(kindOf("../design-sibling/x.png"), Kind::Outside);
    // A design from no file (pasted as text) has no folder: whatever file it names is outside,
    // even one that happens to lie in the folder Marbler runs in.
    Genome pasted = loadGenome(f.genome("g", "inside.png"));
    pasted.baseDirectory.clear();
    EXPECT_EQ(locateSource(pasted).kind, Kind::Outside);
    pasted.source = SourceImage{"data:image/png;base64,AAAA"};
    EXPECT_EQ(locateSource(pasted).kind, Kind::DataUri);
    // The link is seen for where it points.
    EXPECT_EQ(locateSource(loadGenome(f.genome("g", "link-out.png"))).file,
              fs::canonical(f.outside / "secret.png"));
}

TEST(SourcePath, TheRendererRefusesWhatLiesOutsideAndNamesTheGenome) {
    SourceFolders f;
    for (const std::string& image : std::vector<std::string>{"../private/secret.png", "link-out.png",
                                                             (f.outside / "secret.png").string()}) {
        const fs::path file = f.genome("out", image);
        Genome g = loadGenome(file);
        try {
            CpuRenderer renderer(g);
            ADD_FAILURE() << image << " was read";
        } catch (const GenomeError& e) {
            EXPECT_EQ(e.file(), file.string());
            EXPECT_EQ(e.location(), "source.image");
            EXPECT_NE(std::string(e.what()).find("outside the genome's folder"), std::string::npos)
                << e.what();
        }
        g.allowExternalSource = true;
        EXPECT_NO_THROW(CpuRenderer{g}) << image;
    }
    for (const std::string& image : std::vector<std::string>{"inside.png", "sub/below.png", "link-in.png"})
        EXPECT_NO_THROW(CpuRenderer{loadGenome(f.genome("in", image))}) << image;
}

TEST(SourcePath, AMissingFileIsAnErrorNamingIt) {
    SourceFolders f;
    for (const std::string& image : std::vector<std::string>{"nowhere.png", "sub/nowhere.png"}) {
        Genome g = loadGenome(f.genome("missing", image));
        try {
            CpuRenderer renderer(g);
            ADD_FAILURE() << image << " was read";
        } catch (const GenomeError& e) {
            EXPECT_EQ(e.location(), "source.image");
            EXPECT_NE(std::string(e.what()).find(image), std::string::npos) << e.what();
        }
    }
    // Outside and missing: allowed, it is still missing.
    Genome g = loadGenome(f.genome("missing", "../private/nowhere.png"));
    g.allowExternalSource = true;
    EXPECT_THROW(CpuRenderer{g}, GenomeError);
}

TEST(SourcePathCli, RenderRefusesOutsideSourcesUnlessAllowed) {
    SourceFolders f;
    const fs::path out = f.root / "out.png";
    for (const std::string& image : std::vector<std::string>{"../private/secret.png", "link-out.png",
                                                             (f.outside / "secret.png").string()}) {
        const fs::path file = f.genome("shared", image);
        auto r = runMarbler({"render", file.string(), "-o", out.string(), "--width", "40"});
        EXPECT_EQ(r.exitCode, 2) << image << ": " << r.err;
        EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
        EXPECT_EQ(r.err.find("marbler render: " + file.string() + ": source.image: "), 0u) << r.err;
        EXPECT_NE(r.err.find("outside the genome's folder"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out)) << image;

        r = runMarbler(
            {"render", file.string(), "-o", out.string(), "--width", "40", "--allow-external-source"});
        EXPECT_EQ(r.exitCode, 0) << image << ": " << r.err;
        EXPECT_TRUE(fs::exists(out)) << image;
        fs::remove(out);
    }
    const fs::path data = test::dataDir() / "render" / "source-dataurl-2d.marble.json";
    for (const fs::path& file : {f.genome("near", "inside.png"), f.genome("below", "sub/below.png"), data}) {
        auto r = runMarbler({"render", file.string(), "-o", out.string(), "--width", "40"});
        EXPECT_EQ(r.exitCode, 0) << file << ": " << r.err;
        EXPECT_TRUE(fs::exists(out)) << file;
        fs::remove(out);
    }
    auto r = runMarbler({"render", "--help"});
    EXPECT_NE(r.out.find("--allow-external-source"), std::string::npos);
}

TEST(SourcePathCli, InfoWarnsWithoutReadingTheImage) {
    SourceFolders f;
    auto r = runMarbler({"info", f.genome("shared", "../private/gone.png").string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("source.image: '../private/gone.png'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--allow-external-source"), std::string::npos) << r.err;
    r = runMarbler({"info", f.genome("near", "inside.png").string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

} // namespace
} // namespace marbler

// The window and outside source images (SourcePermissions.h): the question is asked once per
// image for the session, a refusal shows a message in the cell; and the large view's export
// formats (16-bit TIFF, EXR) and a solid's object view or cross-section.

#include "TestUtil.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/HybridMesh.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/RenderService.h"
#include "shared/SourcePermissions.h"
#include "workbench/DesignCell.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>

using namespace marbler;
using namespace marbler::ui;
namespace fs = std::filesystem;

namespace {

/// A design folder whose genomes name images inside it, above it and through a link leading out.
struct Folders {
    fs::path design, outside;
    Folders() {
        // A folder of each test's own: ctest runs the cases of this file side by side.
        const fs::path root = test::outputDir(
            std::string("ui-sources-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        design = root / "design";
        outside = root / "private";
        fs::create_directories(design);
        fs::create_directories(outside);
        const fs::path image = test::dataDir() / "render" / "source-4x2.png";
        fs::copy_file(image, outside / "secret.png");
        fs::copy_file(image, design / "inside.png");
        fs::create_symlink(fs::path("..") / "private" / "secret.png", design / "link-out.png");
    }
    Genome genome(const std::string& name, const std::string& image) const {
        Genome g = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
        g.source = SourceImage{image};
        const fs::path file = design / (name + ".marble.json");
        saveGenome(g, file);
        return loadGenome(file);
    }
};

/// Answers the question without a dialog and counts it.
struct Asker {
    bool answer = false;
    QStringList asked;
    Asker() {
        SourcePermissions::session().clear();
        setExternalSourceAsker([this](QWidget*, const QString&, const QString& image) {
            asked << image;
            return answer;
        });
    }
    ~Asker() {
        setExternalSourceAsker({});
        SourcePermissions::session().clear();
    }
};

RenderRequest requestFor(const Genome& genome) {
    RenderRequest request;
    request.genome = genome;
    request.size = QSize(40, 20);
    request.aa = QStringLiteral("none");
    return request;
}

TEST(SourcePermissionsTest, AskedOncePerImageAndRefusalFailsWithAMessage) {
    Folders folders;
    Asker asker;
    RenderService service(RenderService::Backend::Cpu);
    QSignalSpy failed(&service, &RenderService::failed);
    QSignalSpy rendered(&service, &RenderService::rendered);
    const Genome outside = folders.genome("shared", "../private/secret.png");
    // Two cells of one image: one question.
    service.request(1, requestFor(outside));
    service.request(2, requestFor(outside));
    EXPECT_FALSE(service.idle()) << "waiting for the answer is work outstanding";
    MARBLER_WAIT(service.idle(), 10000);
    ASSERT_EQ(asker.asked.size(), 1);
    EXPECT_EQ(asker.asked.front(),
              QString::fromStdString(fs::canonical(folders.outside / "secret.png").string()));
    ASSERT_EQ(failed.size(), 2);
    EXPECT_TRUE(failed.at(0).at(1).toString().contains(QStringLiteral("outside its folder")))
        << failed.at(0).at(1).toString().toStdString();
    EXPECT_EQ(rendered.size(), 0);

    // Remembered: the same image through a link is not asked about again.
    service.request(3, requestFor(folders.genome("linked", "link-out.png")));
    MARBLER_WAIT(service.idle(), 10000);
    EXPECT_EQ(asker.asked.size(), 1);
    EXPECT_EQ(failed.size(), 3);

    // Inside the folder: never asked, rendered.
    service.request(4, requestFor(folders.genome("near", "inside.png")));
    MARBLER_WAIT(service.idle(), 10000);
    EXPECT_EQ(asker.asked.size(), 1);
    EXPECT_EQ(failed.size(), 3);
    EXPECT_GE(rendered.size(), 1);
}

TEST(SourcePermissionsTest, AllowedImagesRenderAndTheAnswerLastsOnlyTheSession) {
    Folders folders;
    Asker asker;
    asker.answer = true;
    RenderService service(RenderService::Backend::Cpu);
    QSignalSpy failed(&service, &RenderService::failed);
    QSignalSpy rendered(&service, &RenderService::rendered);
    const Genome outside = folders.genome("shared", "../private/secret.png");
    service.request(1, requestFor(outside));
    MARBLER_WAIT(service.idle(), 10000);
    EXPECT_EQ(asker.asked.size(), 1);
    EXPECT_EQ(failed.size(), 0);
    ASSERT_GE(rendered.size(), 1);
    // Rendered from the outside image: the same pixels as a render allowed directly.
    Genome allowed = outside;
    allowed.allowExternalSource = true;
    RenderSettings settings;
    settings.width = 40;
    settings.height = 20;
    const QImage expected = toQImage(CpuRenderer(allowed).render(settings));
    EXPECT_EQ(rendered.last().at(1).value<QImage>(), expected);

    // The answers live in memory only: nothing is written to the settings.
    EXPECT_TRUE(QSettings().allKeys().filter(QStringLiteral("source"), Qt::CaseInsensitive).isEmpty());
    SourcePermissions::session().clear(); // a new run
    service.request(2, requestFor(outside));
    MARBLER_WAIT(service.idle(), 10000);
    EXPECT_EQ(asker.asked.size(), 2);
}

TEST(SourcePermissionsTest, ARefusedDesignShowsWhyInItsCell) {
    Folders folders;
    Asker asker;
    QTemporaryDir favourites;
    qputenv("MARBLER_FAVOURITES_DIR", favourites.path().toLocal8Bit());
    setOpenChooser(
        [](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> { return OpenChoice::Replace; });
    {
        RenderService service(RenderService::Backend::Cpu);
        WorkbenchWindow window(&service);
        window.model()->setSessionSeed(42);
        window.newRandomPopulation(2);
        folders.genome("shared", "../private/secret.png");
        ASSERT_TRUE(
            window.openFiles({QString::fromStdString((folders.design / "shared.marble.json").string())}, 0));
        MARBLER_WAIT(!window.cell(0)->error().isEmpty(), 20000);
        EXPECT_TRUE(window.cell(0)->error().contains(QStringLiteral("outside its folder")));
        EXPECT_EQ(asker.asked.size(), 1);
        MARBLER_WAIT(service.idle(), 20000);
        EXPECT_EQ(asker.asked.size(), 1) << "the thumbnails of the same design ask nothing more";
    }
    setOpenChooser({});
    qunsetenv("MARBLER_FAVOURITES_DIR");
}

// --- Export ---------------------------------------------------------------------------------

struct ExportFixture : ::testing::Test {
    void SetUp() override {
        ASSERT_TRUE(favourites.isValid());
        qputenv("MARBLER_FAVOURITES_DIR", favourites.path().toLocal8Bit());
        service = std::make_unique<RenderService>(RenderService::Backend::Auto);
        MARBLER_WAIT(!service->backendName().isEmpty(), 20000);
    }
    void TearDown() override {
        service.reset();
        qunsetenv("MARBLER_FAVOURITES_DIR");
    }
    /// Exports and waits; returns the error, empty on success.
    QString exportAndWait(DesignDialog& dialog, const QString& file, QSize size,
                          std::optional<SolidExport> solid = {}, int bits = 8) {
        QSignalSpy finished(&dialog, &DesignDialog::exportFinished);
        if (!dialog.exportTo(file, size, QStringLiteral("none"), std::nullopt, solid, bits))
            return QStringLiteral("refused");
        if (!QTest::qWaitFor([&] { return finished.size() == 1; }, 60000)) return QStringLiteral("timed out");
        return finished.front().at(2).toString();
    }
    QTemporaryDir favourites, dir;
    std::unique_ptr<RenderService> service;
};

/// Reads an image with OpenImageIO: its spec and 8-bit pixels.
struct ReadBack {
    OIIO::ImageSpec spec;
    Image image;
};
ReadBack readBack(const QString& file) {
    ReadBack r;
    auto in = OIIO::ImageInput::open(file.toStdString());
    if (!in) return r;
    r.spec = in->spec();
    r.image.width = r.spec.width;
    r.image.height = r.spec.height;
    r.image.rgb.resize(std::size_t(r.spec.width) * std::size_t(r.spec.height) * 3);
    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, r.image.rgb.data());
    in->close();
    return r;
}

TEST_F(ExportFixture, SixteenBitTiffAndExrAreOffered) {
    const Genome genome = loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
    ExportSettingsDialog settings(genome);
    auto* format = settings.findChild<QComboBox*>(QStringLiteral("exportFormat"));
    ASSERT_NE(format, nullptr);
    QStringList offered;
    for (int i = 0; i < format->count(); ++i)
        offered << format->itemText(i);
    for (const char* name : {"PNG", "JPEG", "TIFF (16-bit", "OpenEXR"})
        EXPECT_FALSE(offered.filter(QString::fromLatin1(name)).isEmpty())
            << name << " in " << offered.join(',').toStdString();
    settings.setFormat(QStringLiteral(".tif"), 16);
    EXPECT_EQ(settings.extension(), QStringLiteral(".tif"));
    EXPECT_EQ(settings.bitsPerSample(), 16);
    settings.setFormat(QStringLiteral(".exr"));
    EXPECT_EQ(settings.extension(), QStringLiteral(".exr"));

    DesignDialog dialog(genome, service.get(), QStringLiteral("vase"));
    const QString tiff = dir.filePath(QStringLiteral("deep.tif"));
    ASSERT_EQ(exportAndWait(dialog, tiff, QSize(64, 40), std::nullopt, 16), QString());
    ReadBack deep = readBack(tiff);
    EXPECT_EQ(deep.spec.format, OIIO::TypeDesc::UINT16);
    EXPECT_EQ(deep.spec.width, 64);
    // The same picture as the 8-bit one, in finer steps.
    const QString flat = dir.filePath(QStringLiteral("flat.tif"));
    ASSERT_EQ(exportAndWait(dialog, flat, QSize(64, 40)), QString());
    ReadBack eight = readBack(flat);
    EXPECT_EQ(eight.spec.format, OIIO::TypeDesc::UINT8);
    ASSERT_EQ(deep.image.rgb.size(), eight.image.rgb.size());
    int worst = 0;
    for (std::size_t k = 0; k < deep.image.rgb.size(); ++k)
        worst = std::max(worst, std::abs(int(deep.image.rgb[k]) - int(eight.image.rgb[k])));
    EXPECT_LE(worst, 1);

    const QString exr = dir.filePath(QStringLiteral("linear.exr"));
    ASSERT_EQ(exportAndWait(dialog, exr, QSize(64, 40)), QString());
    ReadBack half = readBack(exr);
    EXPECT_EQ(half.spec.format, OIIO::TypeDesc::HALF);
}

TEST_F(ExportFixture, ASolidExportsItsObjectViewOrAnyCrossSection) {
    const Genome genome = loadGenome(test::dataDir() / "examples" / "slate-block.marble.json");
    ASSERT_EQ(genome.dimension, 3);
    ExportSettingsDialog settings(genome);
    ASSERT_NE(settings.findChild<QComboBox*>(QStringLiteral("exportSolidView")), nullptr);
    ASSERT_TRUE(settings.solidExport());
    EXPECT_TRUE(settings.solidExport()->objectView);
    settings.setSolidExport(SolidExport{false, Slice{1, 300.0}});
    EXPECT_FALSE(settings.solidExport()->objectView);
    EXPECT_EQ(settings.solidExport()->slice.axis, 1);
    EXPECT_DOUBLE_EQ(settings.solidExport()->slice.value, 300.0);
    // A y cross-section is an x-z plane: its proportions set the height.
    settings.setUnit(QStringLiteral("pixels"));
    settings.setWidthValue(200.0);
    EXPECT_EQ(settings.pixels(), QSize(200, int(std::round(200.0 * genome.size.z / genome.size.x))));

    DesignDialog dialog(genome, service.get(), QStringLiteral("sphere"));
    // The cross-section asked for, not the middle z one.
    const QString slice = dir.filePath(QStringLiteral("slice.png"));
    ASSERT_EQ(exportAndWait(dialog, slice, QSize(48, 48), SolidExport{false, Slice{1, 300.0}}), QString());
    RenderSettings at;
    at.width = at.height = 48;
    at.aa = "none";
    at.slice = Slice{1, 300.0};
    const Image expectedSlice = CpuRenderer(genome).render(at);
    EXPECT_EQ(readBack(slice).image.rgb, expectedSlice.rgb);
    at.slice = Slice{2, genome.size.z / 2.0};
    EXPECT_NE(readBack(slice).image.rgb, CpuRenderer(genome).render(at).rgb) << "not the middle z slice";

    std::string why;
    if (!gl::GlRenderer::available(&why)) {
        if (qEnvironmentVariable("MARBLER_REQUIRE_GL") == QStringLiteral("1")) FAIL() << "no GL: " << why;
        GTEST_SKIP() << "the object view needs OpenGL: " << why;
    }
    const QString object = dir.filePath(QStringLiteral("object.png"));
    ASSERT_EQ(exportAndWait(dialog, object, QSize(64, 64), SolidExport{true, {}}), QString());
    const ReadBack shown = readBack(object);
    EXPECT_EQ(shown.image.width, 64);
    EXPECT_EQ(shown.image.height, 64);
    EXPECT_NE(shown.image.rgb, readBack(slice).image.rgb);
    // What the cell shows of the object at that size: the same mesh, angle and framing.
    gl::GlRenderer renderer;
    gl::MeshSettings mesh;
    mesh.width = mesh.height = 64;
    mesh.mesh = "sphere";
    mesh.yaw = dialog.viewAngle().yaw;
    mesh.pitch = dialog.viewAngle().pitch;
    const Image cell =
        service->usesGl() ? renderer.renderMesh(genome, mesh) : gl::renderMeshHybrid(renderer, genome, mesh);
    ASSERT_EQ(cell.rgb.size(), shown.image.rgb.size());
    std::size_t off = 0;
    for (std::size_t k = 0; k < cell.rgb.size(); ++k)
        off += std::abs(int(cell.rgb[k]) - int(shown.image.rgb[k])) > 2;
    EXPECT_LE(off, cell.rgb.size() / 200) << "the export is the object the view shows";
}

} // namespace

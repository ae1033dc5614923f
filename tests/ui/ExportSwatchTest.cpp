// The large view's parts of vector output and of print and textile: SVG export through the
// library's tracer (the same file as `marbler svg`), the mirror repeat tile export (as `marbler
// render --repeat mirror`) and the repeat swatch in the view.

#include "TestUtil.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Paper.h"
#include "marbler/Separations.h"
#include "marbler/Vector.h"
#include "shared/DesignDialog.h"
#include "shared/RenderService.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>

#include <gtest/gtest.h>

#include <sstream>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// The large view on the window fixture's render service (no population needed).
struct ExportSwatchTest : test::WindowTest {
    ExportSwatchTest()
        : WindowTest(false) {}

    /// Waits for the export started by `start` to finish; returns its error, empty on success.
    template <typename Start> QString exportAndWait(DesignDialog& dialog, Start start) {
        QSignalSpy finished(&dialog, &DesignDialog::exportFinished);
        if (!start()) return QStringLiteral("refused");
        if (!QTest::qWaitFor([&] { return finished.size() == 1; }, 60000)) return QStringLiteral("timed out");
        if (!finished.front().at(1).toBool() && finished.front().at(2).toString().isEmpty())
            return QStringLiteral("not written");
        return finished.front().at(2).toString();
    }
    QTemporaryDir dir;
};

/// The vertices of every path in an SVG written by toSvg ("M x yLx y x y …Z").
std::size_t pathVertices(const std::string& svg) {
    std::size_t count = 0;
    // Found by hand, not std::regex: libstdc++'s regex recurses per character and overflows the
    // stack on paths this long (seen under AddressSanitizer).
    for (std::size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
        const std::size_t end = svg.find('>', at);
        const std::size_t attribute = svg.find(" d=\"", at);
        if (attribute == std::string::npos || attribute > end) continue;
        const std::size_t begin = attribute + 4;
        std::string d = svg.substr(begin, svg.find('"', begin) - begin);
        for (char& c : d)
            if (c == 'M' || c == 'L' || c == 'Z') c = ' ';
        std::istringstream in(d);
        std::size_t numbers = 0;
        for (double v; in >> v;)
            ++numbers;
        EXPECT_EQ(numbers % 2, 0u) << "an odd coordinate count in a path";
        count += numbers / 2;
    }
    return count;
}

TEST_F(ExportSwatchTest, SvgExportWritesWhatMarblerSvgWrites) {
    const Genome genome = test::loadExample("five-stones.marble.json");
    ExportSettingsDialog settings(genome);
    auto* format = settings.findChild<QComboBox*>(QStringLiteral("exportFormat"));
    auto* width = settings.findChild<QDoubleSpinBox*>(QStringLiteral("exportWidth"));
    auto* tolerance = settings.findChild<QDoubleSpinBox*>(QStringLiteral("exportTolerance"));
    ASSERT_TRUE(format && width && tolerance);
    ASSERT_GE(format->findData(QStringLiteral(".svg")), 0) << "a flat design offers SVG";
    EXPECT_TRUE(format->itemText(format->findData(QStringLiteral(".svg"))).contains(QStringLiteral("SVG")));
    EXPECT_DOUBLE_EQ(settings.tolerance(), 1.0);
    EXPECT_FALSE(tolerance->toolTip().isEmpty());
    settings.setFormat(QStringLiteral(".png"));
    EXPECT_TRUE(width->isEnabled());
    EXPECT_FALSE(tolerance->isEnabled());
    settings.setFormat(QStringLiteral(".svg"));
    EXPECT_EQ(settings.extension(), QStringLiteral(".svg"));
    EXPECT_FALSE(width->isEnabled()) << "an SVG has no pixel size";
    EXPECT_TRUE(tolerance->isEnabled());

    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    QSignalSpy saved(&dialog, &DesignDialog::fileSaved);
    const QString file = dir.filePath(QStringLiteral("stones.svg"));
    const double t = 2.0;
    ASSERT_EQ(exportAndWait(dialog, [&] { return dialog.exportSvgTo(file, t); }), QString());
    ASSERT_EQ(saved.size(), 1);
    EXPECT_EQ(saved.front().at(0).toString(), file);
    const std::string written = test::readFile(file.toStdString());

    VectorOptions options;
    options.tolerance = t;
    const VectorDesign traced = traceDesign(genome, options);
    ASSERT_GT(traced.vertexCount, 0u);
    // The printer's layers (Separations.h), as marbler svg writes by default.
    std::size_t layered = 0;
    for (const InkLayer& layer : knockOut(traced, decimalsFor(t)).layers)
        for (const auto& ring : layer.rings)
            layered += ring.size();
    EXPECT_EQ(pathVertices(written), layered);

    const QString genomeFile = dir.filePath(QStringLiteral("stones.marble.json"));
    saveGenome(genome, genomeFile.toStdString());
    const QString cliFile = dir.filePath(QStringLiteral("cli.svg"));
    const test::RunResult run =
        test::runMarbler({"svg", genomeFile.toStdString(), "-o", cliFile.toStdString(), "--tolerance", "2"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(test::readFile(cliFile.toStdString()) == written)
        << "the window's SVG differs from marbler svg's";
    // No temporary left beside it (the write is atomic).
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files).size(), 3);
}

TEST_F(ExportSwatchTest, SolidsDoNotOfferSvgAndAreRefusedWithTheLibrarysReason) {
    const Genome genome = test::loadExample("slate-block.marble.json");
    ASSERT_EQ(genome.dimension, 3);
    ExportSettingsDialog settings(genome);
    auto* format = settings.findChild<QComboBox*>(QStringLiteral("exportFormat"));
    ASSERT_NE(format, nullptr);
    EXPECT_LT(format->findData(QStringLiteral(".svg")), 0);
    EXPECT_EQ(settings.findChild<QCheckBox*>(QStringLiteral("exportRepeat")), nullptr);
    settings.setFormat(QStringLiteral(".svg"));
    EXPECT_NE(settings.extension(), QStringLiteral(".svg"));

    std::string reason;
    try {
        traceDesign(genome);
    } catch (const InputError& e) {
        reason = e.what();
    }
    ASSERT_FALSE(reason.empty());
    test::ErrorCapture errors;
    DesignDialog dialog(genome, mService.get(), QStringLiteral("sphere"));
    QSignalSpy saved(&dialog, &DesignDialog::fileSaved);
    const QString file = dir.filePath(QStringLiteral("block.svg"));
    EXPECT_EQ(exportAndWait(dialog, [&] { return dialog.exportSvgTo(file); }).toStdString(), reason);
    EXPECT_FALSE(QFileInfo::exists(file));
    EXPECT_EQ(saved.size(), 0);
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(QString::fromStdString(reason)));
}

TEST_F(ExportSwatchTest, RepeatExportIsTheMirrorTileOfAPlainExport) {
    const Genome genome = test::loadExample("five-stones.marble.json");
    ExportSettingsDialog settings(genome);
    auto* repeat = settings.findChild<QCheckBox*>(QStringLiteral("exportRepeat"));
    ASSERT_NE(repeat, nullptr);
    EXPECT_TRUE(repeat->text().contains(QStringLiteral("twice")));
    settings.setUnit(QStringLiteral("pixels"));
    settings.setWidthValue(100.0);
    settings.setMirrorRepeatTile(true);
    EXPECT_TRUE(settings.mirrorRepeatTile());
    const QSize one = settings.pixels();
    auto* summary = settings.findChild<QLabel*>(QStringLiteral("exportPixels"));
    ASSERT_NE(summary, nullptr);
    EXPECT_TRUE(
        summary->text().contains(QStringLiteral("%L1 × %L2").arg(2 * one.width()).arg(2 * one.height())))
        << summary->text().toStdString();
    settings.setFormat(QStringLiteral(".svg"));
    EXPECT_FALSE(repeat->isEnabled());
    EXPECT_FALSE(settings.mirrorRepeatTile()) << "an SVG is never a raster tile";

    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    const QSize size(40, 26);
    const QString plainFile = dir.filePath(QStringLiteral("plain.png"));
    const QString tileFile = dir.filePath(QStringLiteral("tile.png"));
    ASSERT_EQ(exportAndWait(dialog, [&] { return dialog.exportTo(plainFile, size, QStringLiteral("none")); }),
              QString());
    ASSERT_EQ(exportAndWait(dialog,
                            [&] {
                                return dialog.exportTo(tileFile, size, QStringLiteral("none"), std::nullopt,
                                                       std::nullopt, 8, true);
                            }),
              QString());
    const QImage plain(plainFile), tile(tileFile);
    ASSERT_EQ(plain.size(), size);
    ASSERT_EQ(tile.size(), size * 2);
    const int w = size.width(), h = size.height();
    int mismatches = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const QRgb p = plain.pixel(x, y);
            mismatches += tile.pixel(x, y) != p;
            mismatches += tile.pixel(2 * w - 1 - x, y) != p;
            mismatches += tile.pixel(x, 2 * h - 1 - y) != p;
            mismatches += tile.pixel(2 * w - 1 - x, 2 * h - 1 - y) != p;
        }
    EXPECT_EQ(mismatches, 0);
    // Not trivially symmetric: the design itself is no mirror of itself.
    EXPECT_NE(plain, plain.mirrored(true, false));
}

TEST_F(ExportSwatchTest, StraightRepeatIsOfferedWhereTheBathWrapsAndRepeatsTheDesign) {
    // A design whose bath does not wrap has the mirror repeat only.
    ExportSettingsDialog plainSettings(test::loadExample("five-stones.marble.json"));
    EXPECT_EQ(plainSettings.findChild<QCheckBox*>(QStringLiteral("exportStraightRepeat")), nullptr);
    EXPECT_FALSE(plainSettings.straightRepeatTile());
    // A half-drop or brick bath (issue 29): copying the tile 2 x 2 would make seams, so only
    // the mirror repeat is offered, and the plain export is the tile.
    for (Lattice lattice : {Lattice::HalfDrop, Lattice::Brick}) {
        PaperOptions options;
        options.width = 60.0;
        options.height = 40.0;
        options.lattice = lattice;
        ExportSettingsDialog latticeSettings(paperGenome(3, options));
        EXPECT_EQ(latticeSettings.findChild<QCheckBox*>(QStringLiteral("exportStraightRepeat")), nullptr);
        EXPECT_NE(latticeSettings.findChild<QCheckBox*>(QStringLiteral("exportRepeat")), nullptr);
        EXPECT_FALSE(latticeSettings.straightRepeatTile());
    }

    // marbler paper's default recipe wraps: both are offered, one at a time.
    PaperOptions options;
    options.width = 60.0;
    options.height = 40.0;
    const Genome genome = paperGenome(3, options);
    ASSERT_TRUE(genome.wrap);
    ExportSettingsDialog settings(genome);
    auto* straight = settings.findChild<QCheckBox*>(QStringLiteral("exportStraightRepeat"));
    auto* mirror = settings.findChild<QCheckBox*>(QStringLiteral("exportRepeat"));
    ASSERT_NE(straight, nullptr);
    ASSERT_NE(mirror, nullptr);
    EXPECT_TRUE(straight->text().contains(QStringLiteral("Straight repeat")));
    EXPECT_FALSE(straight->toolTip().isEmpty());
    settings.setUnit(QStringLiteral("pixels"));
    settings.setWidthValue(90.0);
    straight->click();
    EXPECT_TRUE(settings.straightRepeatTile());
    const QSize one = settings.pixels();
    auto* summary = settings.findChild<QLabel*>(QStringLiteral("exportPixels"));
    EXPECT_TRUE(
        summary->text().contains(QStringLiteral("%L1 × %L2").arg(2 * one.width()).arg(2 * one.height())))
        << summary->text().toStdString();
    mirror->click();
    EXPECT_TRUE(settings.mirrorRepeatTile());
    EXPECT_FALSE(settings.straightRepeatTile()) << "the two repeats exclude each other";
    straight->click();
    EXPECT_FALSE(settings.mirrorRepeatTile());

    // The tile on disk is the plain export 2 x 2 (whose opposite edges meet without a seam:
    // tests/render/WrapTest.cpp).
    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    const QSize size(60, 40);
    const QString plainFile = dir.filePath(QStringLiteral("plain.png"));
    const QString tileFile = dir.filePath(QStringLiteral("straight.png"));
    ASSERT_EQ(exportAndWait(dialog, [&] { return dialog.exportTo(plainFile, size, QStringLiteral("none")); }),
              QString());
    ASSERT_EQ(exportAndWait(dialog,
                            [&] {
                                return dialog.exportTo(tileFile, size, QStringLiteral("none"), std::nullopt,
                                                       std::nullopt, 8, false, true);
                            }),
              QString());
    const QImage plain(plainFile), tile(tileFile);
    ASSERT_EQ(plain.size(), size);
    ASSERT_EQ(tile.size(), size * 2);
    int mismatches = 0;
    for (int y = 0; y < tile.height(); ++y)
        for (int x = 0; x < tile.width(); ++x)
            mismatches += tile.pixel(x, y) != plain.pixel(x % size.width(), y % size.height());
    EXPECT_EQ(mismatches, 0);
    EXPECT_NE(plain, plain.mirrored(true, false));
}

/// Whether an image's left half mirrors its right half and its top half its bottom half.
bool isMirrorTiled(const QImage& image) {
    if (image.width() % 2 || image.height() % 2) return false;
    return image == image.mirrored(true, false) && image == image.mirrored(false, true);
}

TEST_F(ExportSwatchTest, SwatchShowsTheWholeDesignTiledAndIsRemembered) {
    const Genome genome = test::loadExample("five-stones.marble.json");
    QSettings().remove(QStringLiteral("view/repeatSwatch"));
    {
        DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
        dialog.show();
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull(), 30000);
        EXPECT_FALSE(dialog.repeatSwatch());
        EXPECT_FALSE(isMirrorTiled(dialog.image()));
        // Zoomed in: the swatch still shows the whole design.
        dialog.zoomIn();
        dialog.zoomIn();
        auto* button = dialog.findChild<QToolButton*>(QStringLiteral("repeatSwatch"));
        ASSERT_NE(button, nullptr);
        EXPECT_TRUE(button->isCheckable());
        EXPECT_TRUE(button->toolTip().contains(QStringLiteral("(R)")));
        button->click();
        EXPECT_TRUE(dialog.repeatSwatch());
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull(), 30000);
        const QImage swatch = dialog.image();
        EXPECT_TRUE(isMirrorTiled(swatch));
        // One tile is the whole design, fitted into half the canvas.
        const QSize canvas = dialog.canvas()->size() * dialog.canvas()->devicePixelRatioF();
        EXPECT_LE(swatch.width(), canvas.width());
        EXPECT_LE(swatch.height(), canvas.height());
        EXPECT_NEAR(double(swatch.height()) / swatch.width(), genome.size.y / genome.size.x, 0.05);
        // The canvas shows it: its left half mirrors its right half about the middle.
        const QImage shown = dialog.canvas()->grab().toImage();
        const QPoint c = shown.rect().center();
        const int dx = std::min(swatch.width(), canvas.width()) / 4;
        EXPECT_EQ(shown.pixel(c.x() - dx, c.y() - 10), shown.pixel(c.x() + 1 + dx, c.y() - 10));
        EXPECT_TRUE(QSettings().value(QStringLiteral("view/repeatSwatch")).toBool());
    }
    {
        // Remembered: the next large view opens with the swatch.
        DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
        dialog.show();
        EXPECT_TRUE(dialog.repeatSwatch());
        EXPECT_TRUE(dialog.findChild<QToolButton*>(QStringLiteral("repeatSwatch"))->isChecked());
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull(), 30000);
        EXPECT_TRUE(isMirrorTiled(dialog.image()));
        dialog.setRepeatSwatch(false);
        EXPECT_FALSE(QSettings().value(QStringLiteral("view/repeatSwatch")).toBool());
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull(), 30000);
        EXPECT_FALSE(isMirrorTiled(dialog.image()));
    }
    // A solid has no repeat: the toggle is off and greyed out, whatever was remembered.
    QSettings().setValue(QStringLiteral("view/repeatSwatch"), true);
    DesignDialog solid(test::loadExample("slate-block.marble.json"), mService.get(),
                       QStringLiteral("sphere"));
    EXPECT_FALSE(solid.repeatSwatch());
    EXPECT_FALSE(solid.findChild<QToolButton*>(QStringLiteral("repeatSwatch"))->isEnabled());
}

TEST_F(ExportSwatchTest, ACrossSectionTakesItsPlanesProportions) {
    // The plane of a slice (SlicePlane, Sampling.h): y-z across x, x-z across y, x-y across z.
    Genome genome = test::loadExample("slate-block.marble.json");
    genome.size = {100, 200, 300};
    ExportSettingsDialog settings(genome);
    auto* summary = settings.findChild<QLabel*>(QStringLiteral("exportPixels"));
    ASSERT_NE(summary, nullptr);
    const std::pair<int, int> expected[] = {{0, 3072}, {1, 6144}, {2, 4096}};
    for (const auto& [axis, height] : expected) {
        settings.setSolidExport(SolidExport{false, Slice{axis, 50.0}});
        EXPECT_EQ(settings.pixels(), QSize(2048, height)) << "axis " << axis;
        EXPECT_TRUE(summary->text().contains(QLocale().toString(height))) << summary->text().toStdString();
    }
    settings.setSolidExport(SolidExport{true, Slice{}});
    EXPECT_EQ(settings.pixels(), QSize(2048, 2048)) << "the object view is square";
}

} // namespace

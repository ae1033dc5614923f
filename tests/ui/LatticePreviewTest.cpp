// The repeat previews by the design's own lattice (issue 29): a design whose bath wraps, straight,
// half-drop or brick, is shown repeated as it repeats on fabric, in the editor's repeat preview
// (Plain) and in the large view's swatch; the pixels are the CPU render of that part of the
// plane, which the wrap fills with the design on its lattice (as `render --yardage` does).

#include "TestUtil.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/EditorCanvas.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Paper.h"
#include "shared/DesignDialog.h"
#include "shared/DesignView.h"
#include "shared/RenderService.h"

#include <QSettings>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace marbler;
using namespace marbler::ui;

namespace lattice_preview_test {

/// marbler paper's post recipe on `lattice`: a small sheet whose bath wraps.
Genome wrappedPaper(Lattice lattice) {
    PaperOptions options;
    options.width = 60.0;
    options.height = 40.0;
    options.colors = 3;
    options.lattice = lattice;
    Genome genome = paperGenome(5, options);
    EXPECT_TRUE(genome.wrap);
    EXPECT_EQ(genome.lattice, lattice);
    return genome;
}

/// The CPU render of `region` at `size`, as the render service's final pass makes it.
QImage tiledRender(const Genome& genome, const Region& region, QSize size) {
    RenderSettings settings;
    settings.width = size.width();
    settings.height = size.height();
    settings.aa = "rgss";
    settings.region = region;
    return toQImage(CpuRenderer(genome).render(settings));
}

/// Pixels of `a` and `b` that differ (each channel compared).
int differingPixels(const QImage& a, const QImage& b) {
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size()) return x.width() * x.height() + 1;
    int differ = 0;
    for (int j = 0; j < x.height(); ++j)
        for (int i = 0; i < x.width(); ++i)
            differ += x.pixel(i, j) != y.pixel(i, j);
    return differ;
}

/// How far the image is from repeating as plain copies one tile across (`dx` pixels) and down:
/// zero for a straight lattice, much more for half-drop and brick.
double plainCopyMismatch(const QImage& image, int dx, int dy) {
    const QImage x = image.convertToFormat(QImage::Format_RGB32);
    int differ = 0, count = 0;
    for (int j = 0; j + dy < x.height(); j += 3)
        for (int i = 0; i + dx < x.width(); i += 3) {
            differ += x.pixel(i, j) != x.pixel(i + dx, j + dy);
            ++count;
        }
    return count ? double(differ) / count : 0.0;
}

/// The lattice's name as the genome writes it ("half-drop").
std::string nameOf(Lattice lattice) {
    return std::string(latticeName(lattice));
}

class LatticePreviewTest : public test::WindowTest {
protected:
    LatticePreviewTest()
        : WindowTest(false) {}
};

TEST_F(LatticePreviewTest, EditorRepeatPreviewShowsAWrappedDesignOnItsOwnLattice) {
    for (Lattice lattice : {Lattice::Straight, Lattice::HalfDrop, Lattice::Brick}) {
        SCOPED_TRACE(nameOf(lattice));
        const Genome genome = wrappedPaper(lattice);
        RenderService service(RenderService::Backend::Cpu);
        EditorCanvas canvas(&service);
        canvas.resize(450, 300);
        canvas.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&canvas));
        canvas.setDesign(genome);
        canvas.setRepeatPreview(EditorCanvas::RepeatPreview::Plain);
        EXPECT_TRUE(canvas.tilesByLattice());
        MARBLER_WAIT(canvas.imageFinal() && !canvas.image().isNull() &&
                         canvas.image().width() > canvas.image().height(),
                     30000);
        // The plane three tiles a side about the design, as the lattice repeats it.
        const double w = genome.size.x, h = genome.size.y;
        const QImage shown = canvas.image();
        EXPECT_NEAR(double(shown.width()) / shown.height(), w / h, 0.02);
        EXPECT_EQ(differingPixels(shown, tiledRender(genome, Region{-w, -h, 2 * w, 2 * h}, shown.size())), 0);
        const int dx = shown.width() / 3, dy = shown.height() / 3;
        if (lattice == Lattice::Straight)
            EXPECT_LT(plainCopyMismatch(shown, dx, dy), 0.05) << "a straight repeat is its plain copies";
        else
            EXPECT_GT(plainCopyMismatch(shown, dx, dy), 0.2) << "a half-drop or brick is no plain copy";
        // What the canvas shows: its middle tile is the design, drawn where the view puts it.
        const QImage grabbed = canvas.grab().toImage();
        const QPointF middle = canvas.toWidget({0.5 * w, 0.5 * h, 0.0});
        EXPECT_TRUE(QRectF(grabbed.rect()).contains(middle));
        // The mirror preview stays the mirror repeat of the design alone.
        canvas.setRepeatPreview(EditorCanvas::RepeatPreview::Mirror);
        EXPECT_FALSE(canvas.tilesByLattice());
        MARBLER_WAIT(canvas.imageFinal() && !canvas.image().isNull() &&
                         std::abs(double(canvas.image().width()) / shown.width() - 1.0 / 3.0) < 0.05,
                     30000);
    }
}

TEST_F(LatticePreviewTest, LargeViewSwatchShowsAWrappedDesignOnItsOwnLattice) {
    QSettings().remove(QStringLiteral("view/repeatSwatch"));
    for (Lattice lattice : {Lattice::Straight, Lattice::HalfDrop, Lattice::Brick}) {
        SCOPED_TRACE(nameOf(lattice));
        const Genome genome = wrappedPaper(lattice);
        DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
        dialog.show();
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull(), 30000);
        auto* button = dialog.findChild<QToolButton*>(QStringLiteral("repeatSwatch"));
        ASSERT_NE(button, nullptr);
        EXPECT_TRUE(button->toolTip().contains(QString::fromStdString(nameOf(lattice))))
            << button->toolTip().toStdString();
        button->click();
        ASSERT_TRUE(dialog.repeatSwatch());
        MARBLER_WAIT(dialog.imageIsFinal() && !dialog.image().isNull() && dialog.image().width() > 100,
                     30000);
        const QImage swatch = dialog.image();
        const Region region = swatchRegion(genome);
        EXPECT_DOUBLE_EQ(region.x1, 2 * genome.size.x);
        EXPECT_EQ(differingPixels(swatch, tiledRender(genome, region, swatch.size())), 0);
        const int dx = swatch.width() / 2, dy = swatch.height() / 2;
        if (lattice == Lattice::Straight)
            EXPECT_LT(plainCopyMismatch(swatch, dx, dy), 0.05);
        else
            EXPECT_GT(plainCopyMismatch(swatch, dx, dy), 0.2);
        // Not the mirror repeat, which an unwrapped design keeps.
        EXPECT_NE(swatch, swatch.mirrored(true, false));
        // The canvas shows it as it is, centred and never scaled.
        const QImage shown = dialog.canvas()->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const QImage tile = swatch.convertToFormat(QImage::Format_RGB32);
        ASSERT_GE(shown.width(), tile.width());
        double best = 1.0;
        for (int ox : {(shown.width() - tile.width()) / 2, (shown.width() - tile.width() + 1) / 2})
            for (int oy : {(shown.height() - tile.height()) / 2, (shown.height() - tile.height() + 1) / 2}) {
                int differ = 0, count = 0;
                for (int j = 0; j < tile.height(); j += 5)
                    for (int i = 0; i < tile.width(); i += 5, ++count)
                        differ += tile.pixel(i, j) != shown.pixel(ox + i, oy + j);
                best = std::min(best, double(differ) / count);
            }
        EXPECT_LT(best, 0.01) << "the canvas shows the swatch";
        dialog.setRepeatSwatch(false);
    }
    QSettings().remove(QStringLiteral("view/repeatSwatch"));
}

} // namespace lattice_preview_test

// Print files from the large view's Export image (issue 29): a CMYK TIFF converted to a printer's
// ICC profile (as `marbler render --icc`), and separations into a folder (as `marbler render
// --separations`), through the dialog as a person uses it, in the background with its progress.

#include "CmykTestProfile.h"
#include "TestUtil.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Separations.h"
#include "shared/DesignDialog.h"
#include "shared/ExportSettingsDialog.h"
#include "shared/SavedFiles.h"

#include <OpenImageIO/imageio.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>

using namespace marbler;
using namespace marbler::ui;

namespace print_export_test {

struct PrintExportTest : test::WindowTest {
    PrintExportTest()
        : WindowTest(false) {}
    void SetUp() override {
        WindowTest::SetUp();
        QSettings().clear();
        // The flat render without antialiasing: every pixel one ink, so separations are exact.
        QSettings().setValue(QStringLiteral("files/exportAa"), QStringLiteral("none"));
    }
    void TearDown() override {
        setSaveFileAsker({});
        setProfileChooser({});
        QSettings().clear();
        WindowTest::TearDown();
    }

    /// Runs Export image on `dialog` (Ctrl+E) as a person does: `fill` sets up the settings
    /// dialog, then OK is clicked; waits until the export has finished and returns its error.
    QString exportThroughDialog(DesignDialog& dialog,
                                const std::function<void(ExportSettingsDialog&)>& fill) {
        QSignalSpy finished(&dialog, &DesignDialog::exportFinished);
        bool filled = false;
        std::function<void()> answer;
        answer = [&] {
            auto* settings = qobject_cast<ExportSettingsDialog*>(QApplication::activeModalWidget());
            if (!settings) {
                QTimer::singleShot(10, answer);
                return;
            }
            fill(*settings);
            filled = true;
            QTest::mouseClick(settings->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                              Qt::LeftButton);
        };
        QTimer::singleShot(0, answer);
        // Ctrl+E, the action the key and the Export button share.
        dialog.findChild<QAction*>(QStringLiteral("exportImageAction"))->trigger();
        if (!filled) return QStringLiteral("no settings dialog");
        if (!QTest::qWaitFor([&] { return finished.size() == 1; }, 60000)) return QStringLiteral("timed out");
        if (!finished.front().at(1).toBool() && finished.front().at(2).toString().isEmpty())
            return QStringLiteral("not written");
        return finished.front().at(2).toString();
    }

    QTemporaryDir dir;
    Genome genome = test::loadExample("five-stones.marble.json");
};

TEST_F(PrintExportTest, CmykTiffWithTheChosenProfileIsLittleCmsOwnTransformAndIsRemembered) {
    const std::vector<unsigned char> icc = test::makeCmykProfile("Window test press");
    const QString profile = dir.filePath(QStringLiteral("press.icc"));
    test::writeBytes(profile.toStdString(), icc);
    setProfileChooser([&](QWidget*, const QString&) { return profile; });
    const QString file = dir.filePath(QStringLiteral("stones.tif"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return file; });

    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    dialog.show();
    const int width = 120;
    const QString error = exportThroughDialog(dialog, [&](ExportSettingsDialog& settings) {
        settings.setFormat(QStringLiteral(".tif"));
        settings.setUnit(QStringLiteral("pixels"));
        settings.setWidthValue(width);
        auto* cmyk = settings.findChild<QCheckBox*>(QStringLiteral("exportCmyk"));
        auto* choose = settings.findChild<QPushButton*>(QStringLiteral("exportChooseProfile"));
        ASSERT_TRUE(cmyk && choose);
        EXPECT_TRUE(cmyk->isEnabled()) << "offered for a TIFF";
        EXPECT_FALSE(cmyk->toolTip().isEmpty());
        EXPECT_TRUE(cmyk->text().startsWith(QStringLiteral("Convert to printer profile (CMYK TIFF)")));
        EXPECT_TRUE(choose->isEnabled());
        QTest::mouseClick(choose, Qt::LeftButton);
        EXPECT_TRUE(cmyk->isChecked()) << "choosing a profile ticks the conversion";
        EXPECT_EQ(settings.findChild<QLineEdit*>(QStringLiteral("exportProfile"))->text(), profile);
    });
    ASSERT_EQ(error, QString());

    // Read back as stored: 4 channels, the profile byte for byte, LittleCMS's own numbers.
    OIIO::ImageSpec config;
    config.attribute("oiio:RawColor", 1);
    auto in = OIIO::ImageInput::open(file.toStdString(), &config);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.nchannels, 4);
    EXPECT_EQ(spec.get_string_attribute("tiff:ColorSpace"), "CMYK");
    const OIIO::ParamValue* embedded = spec.find_attribute("ICCProfile");
    ASSERT_TRUE(embedded);
    const auto* bytes = static_cast<const unsigned char*>(embedded->data());
    EXPECT_EQ(std::vector<unsigned char>(bytes, bytes + embedded->type().size()), icc);
    std::vector<std::uint8_t> cmyk(std::size_t(spec.width) * spec.height * 4);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, cmyk.data()));
    ASSERT_EQ(spec.width, width);
    RenderSettings render;
    render.width = spec.width;
    render.height = spec.height;
    render.aa = "none";
    const std::vector<std::uint8_t> expected = test::lcmsCmykOf(CpuRenderer(genome).render(render).rgb, icc);
    ASSERT_EQ(cmyk.size(), expected.size());
    int worst = 0;
    for (std::size_t k = 0; k < cmyk.size(); ++k)
        worst = std::max(worst, std::abs(int(cmyk[k]) - int(expected[k])));
    EXPECT_LE(worst, 1);

    // The next Export image starts with the same profile, ticked.
    ExportSettingsDialog again(genome);
    again.setFormat(QStringLiteral(".tif"));
    ASSERT_TRUE(again.printProfile().has_value());
    EXPECT_EQ(*again.printProfile(), profile);
}

TEST_F(PrintExportTest, AProfileThatIsNoCmykPrinterProfileIsRefusedInTheDialog) {
    const QString screen = dir.filePath(QStringLiteral("screen.icc"));
    test::writeBytes(screen.toStdString(), test::makeDisplayProfile());
    test::ErrorCapture errors;
    ExportSettingsDialog settings(genome);
    settings.setFormat(QStringLiteral(".tif"));
    settings.setPrintProfile(screen);
    settings.accept();
    EXPECT_NE(settings.result(), QDialog::Accepted);
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(
        errors.messages.front().contains(QStringLiteral("screen.icc': a display profile, not a printer's")))
        << errors.messages.front().toStdString();
    // Not offered for other formats, where it would mean nothing.
    settings.setFormat(QStringLiteral(".png"));
    EXPECT_FALSE(settings.findChild<QCheckBox*>(QStringLiteral("exportCmyk"))->isEnabled());
    EXPECT_FALSE(settings.printProfile().has_value());
}

TEST_F(PrintExportTest, SeparationsIntoAFolderAreTheCommandLinesAndRecombineToTheRaster) {
    const QString folder = dir.filePath(QStringLiteral("stones separations"));
    QString asked;
    setSaveFileAsker([&](QWidget*, const QString& caption, const QString&, const QString&) {
        asked = caption;
        return folder;
    });
    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    dialog.show();
    const int width = 140;
    const QString error = exportThroughDialog(dialog, [&](ExportSettingsDialog& settings) {
        auto* format = settings.findChild<QComboBox*>(QStringLiteral("exportFormat"));
        const int item = format->findText(QStringLiteral("Separations"), Qt::MatchStartsWith);
        ASSERT_GE(item, 0) << "a flat design offers separations";
        format->setCurrentIndex(item);
        EXPECT_TRUE(settings.separations());
        EXPECT_TRUE(settings.findChild<QComboBox*>(QStringLiteral("exportMaskBits"))->isEnabled());
        settings.setUnit(QStringLiteral("pixels"));
        settings.setWidthValue(width);
    });
    ASSERT_EQ(error, QString());
    EXPECT_TRUE(asked.contains(QStringLiteral("folder")));

    // The files marbler render --separations writes, byte for byte.
    const QString genomeFile = dir.filePath(QStringLiteral("stones.marble.json"));
    saveGenome(genome, genomeFile.toStdString());
    const QString cliFolder = dir.filePath(QStringLiteral("cli"));
    const test::RunResult run =
        test::runMarbler({"render", genomeFile.toStdString(), "--separations", cliFolder.toStdString(),
                          "--width", std::to_string(width), "--dpi", "300"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> names = separationFileNames(genome.palette.size());
    for (const std::string& name : names) {
        const std::string written = (folder + QLatin1Char('/') + QString::fromStdString(name)).toStdString();
        ASSERT_TRUE(std::filesystem::exists(written)) << name;
        EXPECT_TRUE(test::readFile(written) == test::readFile(cliFolder.toStdString() + "/" + name)) << name;
    }

    // Recombined with the inks' colours, the masks are the raster exactly (no antialiasing).
    RenderSettings render;
    render.width = width;
    render.height = int(std::round(width * genome.size.y / genome.size.x));
    render.aa = "none";
    const Image raster = CpuRenderer(genome).render(render);
    std::vector<Color> colors = {genome.background};
    colors.insert(colors.end(), genome.palette.begin(), genome.palette.end());
    std::vector<QImage> masks;
    for (std::size_t k = 0; k + 1 < names.size(); ++k)
        masks.push_back(QImage(folder + QLatin1Char('/') + QString::fromStdString(names[k]))
                            .convertToFormat(QImage::Format_Grayscale8));
    ASSERT_EQ(masks.front().width(), raster.width);
    ASSERT_EQ(masks.front().height(), raster.height);
    const QImage indexed =
        QImage(folder + QStringLiteral("/indexed.png")).convertToFormat(QImage::Format_RGB888);
    std::size_t differ = 0, notOne = 0, indexedDiffer = 0;
    for (int y = 0; y < raster.height; ++y)
        for (int x = 0; x < raster.width; ++x) {
            int on = 0;
            std::size_t ink = 0;
            for (std::size_t k = 0; k < masks.size(); ++k)
                if (masks[k].constScanLine(y)[x] == 255) ++on, ink = k;
            notOne += on != 1;
            const std::uint8_t* px = raster.row(y) + std::size_t(x) * 3;
            differ += px[0] != colors[ink].r || px[1] != colors[ink].g || px[2] != colors[ink].b;
            const uchar* ix = indexed.constScanLine(y) + x * 3;
            indexedDiffer += ix[0] != px[0] || ix[1] != px[1] || ix[2] != px[2];
        }
    EXPECT_EQ(notOne, 0u);
    EXPECT_EQ(differ, 0u);
    EXPECT_EQ(indexedDiffer, 0u);
}

TEST_F(PrintExportTest, OneBitMasksForScreensAreChosenAndRemembered) {
    const QString folder = dir.filePath(QStringLiteral("screens"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return folder; });
    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    dialog.show();
    const QString error = exportThroughDialog(dialog, [&](ExportSettingsDialog& settings) {
        auto* format = settings.findChild<QComboBox*>(QStringLiteral("exportFormat"));
        format->setCurrentIndex(format->findText(QStringLiteral("Separations"), Qt::MatchStartsWith));
        auto* masks = settings.findChild<QComboBox*>(QStringLiteral("exportMaskBits"));
        masks->setCurrentIndex(masks->findData(1));
        settings.setUnit(QStringLiteral("pixels"));
        settings.setWidthValue(64);
    });
    ASSERT_EQ(error, QString());
    // Each mask a 1-bit grey PNG (IHDR: bit depth 1, colour type 0).
    for (const std::string& name : separationFileNames(genome.palette.size())) {
        if (name == "indexed.png") continue;
        const std::string png =
            test::readFile((folder + QLatin1Char('/') + QString::fromStdString(name)).toStdString());
        ASSERT_GT(png.size(), 26u) << name;
        EXPECT_EQ(int(png[24]), 1) << name << ": bit depth";
        EXPECT_EQ(int(png[25]), 0) << name << ": colour type";
    }
    // The next Export image starts with separations of 1-bit masks.
    ExportSettingsDialog again(genome);
    EXPECT_TRUE(again.separations());
    EXPECT_EQ(again.maskBits(), 1);
}

TEST_F(PrintExportTest, SeparationsCanBeCancelledLeavingNoFolder) {
    DesignDialog dialog(genome, mService.get(), QStringLiteral("vase"));
    QSignalSpy finished(&dialog, &DesignDialog::exportFinished);
    const QString folder = dir.filePath(QStringLiteral("cancelled"));
    // Large enough to be running when the cancel comes.
    ASSERT_TRUE(dialog.exportSeparationsTo(folder, QSize(6000, 6000), QStringLiteral("grid4")));
    EXPECT_TRUE(dialog.isExporting());
    dialog.cancelExport();
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.size() == 1; }, 60000));
    EXPECT_FALSE(finished.front().at(1).toBool());
    EXPECT_FALSE(QFileInfo::exists(folder)) << "nothing is left behind";
}

} // namespace print_export_test

// Export image's summary line with Mirror repeat ticked (issue 27): the longer text, the tile and
// the render it is made from, is shown whole, not cut off at the line's first height.

#include "TestUtil.h"
#include "shared/DesignDialog.h"

#include <QCheckBox>
#include <QLabel>
#include <QTest>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace export_image_line_test {

/// Whether the label has the height its text needs at its width, and lies inside its dialog.
void expectWhole(const QLabel* label, const QWidget* dialog) {
    EXPECT_GE(label->height(), label->heightForWidth(label->width())) << label->text().toStdString();
    const QRect inDialog(label->mapTo(dialog, QPoint(0, 0)), label->size());
    EXPECT_TRUE(dialog->rect().contains(inDialog)) << label->text().toStdString();
}

TEST(ExportImageLineTest, TheMirrorRepeatLineIsShownWhole) {
    const Genome genome = test::loadExample("five-stones.marble.json");
    ExportSettingsDialog settings(genome);
    // In pixels the line also gives the print size: its longest text.
    settings.setUnit(QStringLiteral("pixels"));
    settings.setWidthValue(3750);
    settings.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&settings));
    auto* summary = settings.findChild<QLabel*>(QStringLiteral("exportPixels"));
    auto* repeat = settings.findChild<QCheckBox*>(QStringLiteral("exportRepeat"));
    ASSERT_NE(summary, nullptr);
    ASSERT_NE(repeat, nullptr);
    QCoreApplication::processEvents();
    expectWhole(summary, &settings);
    repeat->click();
    ASSERT_TRUE(summary->text().contains(QStringLiteral("tile"))) << summary->text().toStdString();
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
    expectWhole(summary, &settings);
}

} // namespace export_image_line_test

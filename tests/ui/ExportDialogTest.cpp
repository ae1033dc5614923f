// Export image's dialog as issue 29 found it: the over-size message cut off with OK greyed and
// no way out said, the size and unit forgotten between exports, jargon for antialiasing.

#include "TestUtil.h"
#include "marbler/Sampling.h"
#include "shared/ExportSettingsDialog.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTest>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace export_dialog_test {

/// Whether the label has the height its text needs at its width, and lies inside its dialog.
void expectShownWhole(const QLabel* label, const QWidget* dialog) {
    EXPECT_GE(label->height(), label->heightForWidth(label->width())) << label->text().toStdString();
    const QRect inDialog(label->mapTo(dialog, QPoint(0, 0)), label->size());
    EXPECT_TRUE(dialog->rect().contains(inDialog)) << label->text().toStdString();
}

/// The number the message offers after "widest that fits is ", as the locale wrote it.
double offeredWidth(const QString& text) {
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("widest that fits is ([0-9][0-9.,]*)")).match(text);
    EXPECT_TRUE(m.hasMatch()) << text.toStdString();
    bool ok = false;
    const double value = QLocale().toDouble(m.captured(1), &ok);
    EXPECT_TRUE(ok) << m.captured(1).toStdString();
    return value;
}

class ExportDialogTest : public ::testing::Test {
protected:
    void SetUp() override { QSettings().clear(); }
    void TearDown() override { QSettings().clear(); }
    Genome genome = test::loadExample("five-stones.marble.json");
};

TEST_F(ExportDialogTest, TheOverSizeMessageIsShownWholeAndSaysWhatWidthFits) {
    for (const char* unit : {"pixels", "cm"}) {
        ExportSettingsDialog settings(genome);
        settings.setUnit(QString::fromLatin1(unit));
        settings.setDpi(300);
        settings.setWidthValue(QString::fromLatin1(unit) == QStringLiteral("pixels") ? 1000 : 10);
        settings.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&settings));
        auto* summary = settings.findChild<QLabel*>(QStringLiteral("exportPixels"));
        QPushButton* ok = settings.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        ASSERT_NE(summary, nullptr);
        settings.setWidthValue(QString::fromLatin1(unit) == QStringLiteral("pixels") ? 300000 : 3000);
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
        EXPECT_FALSE(ok->isEnabled());
        expectShownWhole(summary, &settings);
        // What to do: the width offered is one OK takes, and a little more is not.
        const double widest = offeredWidth(summary->text());
        settings.setWidthValue(widest);
        EXPECT_TRUE(ok->isEnabled()) << unit << ": " << summary->text().toStdString();
        settings.setWidthValue(widest * 1.01);
        EXPECT_FALSE(ok->isEnabled()) << unit;
    }
}

TEST_F(ExportDialogTest, SizeUnitResolutionAndAntialiasingAreRememberedOnOk) {
    auto* first = new ExportSettingsDialog(genome);
    first->setUnit(QStringLiteral("cm"));
    first->setDpi(150);
    first->setWidthValue(20.0);
    auto* aa = first->findChild<QComboBox*>(QStringLiteral("exportAa"));
    ASSERT_NE(aa, nullptr);
    aa->setCurrentIndex(aa->findData(QStringLiteral("grid4")));
    const QSize chosen = first->pixels();
    first->accept();
    delete first;

    ExportSettingsDialog again(genome);
    EXPECT_EQ(again.unit(), QStringLiteral("cm"));
    EXPECT_NEAR(again.widthValue(), 20.0, 1e-3);
    EXPECT_EQ(again.dpi().value_or(0), 150.0);
    EXPECT_EQ(again.aa(), "grid4");
    EXPECT_EQ(again.pixels(), chosen);

    // Cancel keeps nothing of what was typed.
    again.setUnit(QStringLiteral("pixels"));
    again.setWidthValue(777);
    again.reject();
    ExportSettingsDialog third(genome);
    EXPECT_EQ(third.unit(), QStringLiteral("cm"));
    EXPECT_EQ(third.pixels(), chosen);
}

TEST_F(ExportDialogTest, AntialiasingChoicesArePlainWordsWithTheCommandLineNameInTheTooltip) {
    ExportSettingsDialog settings(genome);
    auto* aa = settings.findChild<QComboBox*>(QStringLiteral("exportAa"));
    ASSERT_NE(aa, nullptr);
    ASSERT_EQ(aa->count(), int(aaPatternNames().size()));
    for (int i = 0; i < aa->count(); ++i) {
        const QString name = aa->itemData(i).toString();
        EXPECT_EQ(name.toStdString(), aaPatternNames()[std::size_t(i)]);
        EXPECT_FALSE(aa->itemText(i).contains(name)) << aa->itemText(i).toStdString();
        EXPECT_TRUE(aa->itemText(i).contains(QStringLiteral("sample"))) << aa->itemText(i).toStdString();
        EXPECT_TRUE(aa->itemData(i, Qt::ToolTipRole).toString().contains(QStringLiteral("--aa ") + name));
        aa->setCurrentIndex(i);
        EXPECT_EQ(settings.aa(), name.toStdString()) << "the renderer gets the command line's name";
    }
    ExportSettingsDialog fresh(genome);
    EXPECT_EQ(fresh.aa(), "rgss") << "the default";
}

} // namespace export_dialog_test

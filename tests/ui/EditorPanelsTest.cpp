// The editor's panels: the list of steps, the parameter form built from the tool registry, the
// palette, the timeline and Export animation (app/editor).

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/AnimationExport.h"
#include "editor/PaletteEditor.h"
#include "editor/ParamForm.h"
#include "editor/StepList.h"
#include "editor/Timeline.h"
#include "editor/ToolOptions.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "marbler/Video.h"

#include <QAction>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QVBoxLayout>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>

using namespace marbler;
using namespace marbler::ui;

namespace {

Genome designOf(int dimension) {
    Genome g;
    g.dimension = dimension;
    g.size = {1000.0, 800.0, dimension == 3 ? 600.0 : 1000.0};
    g.palette = {Color{200, 30, 30}, Color{20, 40, 160}, Color{240, 200, 40}};
    return g;
}

/// Whether `op` is a valid step of `design`.
bool validStep(const Genome& design, const Operation& op, std::string* why = nullptr) {
    Genome g = design;
    g.operations = {op};
    try {
        validateGenome(g, "step");
        return true;
    } catch (const Error& e) {
        if (why) *why = e.what();
        return false;
    }
}

QString keyOf(const ParamSpec& spec) {
    return QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size()));
}

/// Whether `a` and `b` hold the same value of `spec`.
bool sameParam(const ParamSpec& spec, const Operation& a, const Operation& b, int dimension) {
    if (spec.kind == ParamKind::Teeth) return a.teeth == b.teeth;
    // A 3D wave's pairs hold one number or two by its shape: the numbers both hold.
    const int n = std::min(componentCount(spec, a, dimension), componentCount(spec, b, dimension));
    for (int i = 0; i < n; ++i)
        if (getComponent(spec, a, i) != getComponent(spec, b, i)) return false;
    return true;
}

/// Changes the widget of `spec` in `form` to another valid value.
void changeWidget(ParamForm& form, const ParamSpec& spec, const Operation& op) {
    const QString key = keyOf(spec);
    if (spec.kind == ParamKind::Color || spec.kind == ParamKind::Choice) {
        auto* combo = form.findChild<QComboBox*>(QStringLiteral("edit-%1-0").arg(key));
        ASSERT_NE(combo, nullptr) << key.toStdString();
        combo->setCurrentIndex((combo->currentIndex() + 1) % combo->count());
        return;
    }
    if (spec.kind == ParamKind::Teeth) {
        auto* text = form.findChild<QLineEdit*>(QStringLiteral("edit-%1-0").arg(key));
        ASSERT_NE(text, nullptr);
        QStringList words;
        for (double t : op.teeth)
            words << QString::number(t * 0.5);
        text->setText(words.join(QStringLiteral(", ")));
        emit text->editingFinished();
        return;
    }
    if (spec.kind == ParamKind::Path || spec.kind == ParamKind::Pressure) {
        // A stylus's path as "x y; x y" (drawn a little shorter) and its pressure as "p p".
        auto* text = form.findChild<QLineEdit*>(QStringLiteral("edit-%1-0").arg(key));
        ASSERT_NE(text, nullptr) << key.toStdString();
        QStringList words;
        for (const glm::dvec2& p : op.path)
            words << (spec.kind == ParamKind::Path ? QStringLiteral("%1 %2").arg(p.x * 0.9).arg(p.y * 0.9)
                                                   : QStringLiteral("0.5"));
        text->setText(words.join(spec.kind == ParamKind::Path ? QStringLiteral("; ") : QStringLiteral(" ")));
        emit text->editingFinished();
        return;
    }
    if (spec.kind == ParamKind::Count) {
        auto* spin = form.findChild<QSpinBox*>(QStringLiteral("edit-%1-0").arg(key));
        ASSERT_NE(spin, nullptr);
        spin->setValue(spin->value() + 1);
        return;
    }
    if (spec.kind == ParamKind::Direction) {
        // Kept unit: a component the vector lacks turns it (the first that does).
        for (int i = 0; i < 3; ++i) {
            auto* spin = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-%1-%2").arg(key).arg(i));
            ASSERT_NE(spin, nullptr);
            if (std::abs(spin->value()) > 0.5) continue;
            const Operation before = form.step();
            spin->setValue(spin->value() + 0.5);
            if (!sameParam(spec, form.step(), before, 3)) return;
        }
        return;
    }
    auto* spin = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-%1-0").arg(key));
    ASSERT_NE(spin, nullptr) << key.toStdString();
    // Smaller where it can be (a flow's speed and time need no more steps), else larger.
    const double v = spin->value();
    double next = spec.kind == ParamKind::Direction ? v + 0.5 : v > 0 ? v * 0.75 : v - 10.0;
    if (spec.kind == ParamKind::Extent) next = v * 1.25; // a flow's cells: larger needs no more steps
    if (next < spin->minimum() || next > spin->maximum() || next == v) next = v + 1.0;
    spin->setValue(next);
}

struct Edit {
    Operation op;
    QString key;
    bool dragging;
};

} // namespace

TEST(ParamForm, OneWidgetPerParameterAndEachEditChangesExactlyThatParameter) {
    for (int dimension : {2, 3}) {
        const Genome design = designOf(dimension);
        for (const ToolSpec& tool : allTools()) {
            if (!tool.available(dimension)) continue;
            SCOPED_TRACE(std::string(tool.name) + " in " + std::to_string(dimension) + "D");
            const Operation original = defaultOperation(tool.tool, dimension, design.size * 0.5);
            ASSERT_TRUE(validStep(design, original));
            ParamForm form;
            std::vector<Edit> edits;
            QObject::connect(&form, &ParamForm::edited,
                             [&](const Operation& op, const QString& key, bool dragging) {
                                 edits.push_back({op, key, dragging});
                             });
            form.setStep(original, dimension, design);
            const auto params = tool.params(dimension);
            EXPECT_EQ(form.findChildren<QWidget*>(QRegularExpression(QStringLiteral("^param-"))).size(),
                      qsizetype(params.size()));
            for (const ParamSpec& spec : params) {
                SCOPED_TRACE(std::string(spec.key));
                QWidget* box = form.findChild<QWidget*>(QStringLiteral("param-") + keyOf(spec));
                ASSERT_NE(box, nullptr);
                EXPECT_TRUE(box->toolTip().startsWith(
                    QString::fromUtf8(spec.help.data(), qsizetype(spec.help.size()))));
                edits.clear();
                form.setStep(original, dimension, design);
                changeWidget(form, spec, original);
                ASSERT_EQ(edits.size(), 1u);
                const Edit& e = edits.front();
                EXPECT_EQ(e.key, keyOf(spec));
                EXPECT_FALSE(e.dragging);
                std::string why;
                EXPECT_TRUE(validStep(design, e.op, &why)) << why;
                if (spec.kind == ParamKind::Direction) {
                    EXPECT_NEAR(glm::length(e.op.direction), 1.0, 1e-9);
                    EXPECT_NEAR(glm::length(e.op.axis), 1.0, 1e-9);
                    if (dimension == 3 && tool.tool != Tool::Cylinder && tool.tool != Tool::Circle &&
                        tool.tool != Tool::Sphere && tool.tool != Tool::Vortex) {
                        EXPECT_NEAR(glm::dot(e.op.direction, e.op.normal), 0.0, 1e-9);
                    }
                }
                EXPECT_FALSE(sameParam(spec, e.op, original, dimension)) << "the edit changed nothing";
                for (const ParamSpec& other : params) {
                    // Turning a direction turns its normal with it.
                    const bool turned =
                        spec.field == ParamField::Direction && other.field == ParamField::Normal;
                    if (&other != &spec && !turned) {
                        EXPECT_TRUE(sameParam(other, e.op, original, dimension))
                            << "also changed " << other.key;
                    }
                }
            }
        }
    }
}

TEST(ParamForm, NeverEmitsAValueOutsideTheRules) {
    const Genome design = designOf(2);
    Operation flow = defaultOperation(Tool::Flow, 2, design.size * 0.5);
    ParamForm form;
    std::vector<Edit> edits;
    QObject::connect(&form, &ParamForm::edited, [&](const Operation& op, const QString& key, bool dragging) {
        edits.push_back({op, key, dragging});
    });
    form.setStep(flow, 2, design);
    // A much faster flow would need more steps than it has: the speed stops where it still fits.
    auto* speed = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-speed-0"));
    ASSERT_NE(speed, nullptr);
    speed->setValue(speed->maximum());
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_TRUE(validStep(design, edits.back().op));
    EXPECT_LE(minimumFlowSteps(edits.back().op), edits.back().op.steps);
    EXPECT_GE(std::abs(edits.back().op.speed), std::abs(flow.speed));
    // A radius of 0 or less becomes the least positive one.
    const Operation drop = defaultOperation(Tool::Drop, 2, design.size * 0.5);
    form.setStep(drop, 2, design);
    edits.clear();
    auto* radius = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-radius-0"));
    ASSERT_NE(radius, nullptr);
    radius->setValue(-5.0);
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_GT(edits.back().op.radius, 0.0);
    // Teeth that do not increase are refused: nothing emitted, the field shows the teeth again.
    const Operation stretch = defaultOperation(Tool::Stretch, 2, design.size * 0.5);
    form.setStep(stretch, 2, design);
    edits.clear();
    auto* teeth = form.findChild<QLineEdit*>(QStringLiteral("edit-teeth-0"));
    ASSERT_NE(teeth, nullptr);
    const QString before = teeth->text();
    teeth->setText(QStringLiteral("5 4 3"));
    emit teeth->editingFinished();
    EXPECT_TRUE(edits.empty());
    EXPECT_EQ(teeth->text(), before);
}

TEST(ParamForm, ASliderDragEmitsDraggingEditsThenAFinalOne) {
    const Genome design = designOf(2);
    const Operation drop = defaultOperation(Tool::Drop, 2, design.size * 0.5);
    ParamForm form;
    std::vector<Edit> edits;
    QObject::connect(&form, &ParamForm::edited, [&](const Operation& op, const QString& key, bool dragging) {
        edits.push_back({op, key, dragging});
    });
    form.setStep(drop, 2, design);
    auto* slider = form.findChild<QSlider*>(QStringLiteral("slider-radius-0"));
    ASSERT_NE(slider, nullptr);
    slider->setSliderDown(true);
    slider->setValue(300);
    slider->setValue(400);
    // The window sets the step it got back while the slider is held: the drag goes on.
    form.setStep(edits.back().op, 2, design);
    EXPECT_EQ(form.findChild<QSlider*>(QStringLiteral("slider-radius-0")), slider);
    slider->setValue(450);
    slider->setSliderDown(false);
    ASSERT_EQ(edits.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_TRUE(edits[i].dragging) << i;
    EXPECT_FALSE(edits.back().dragging);
    EXPECT_LT(edits[0].op.radius, edits[1].op.radius);
    EXPECT_EQ(edits.back().op.radius, edits[2].op.radius);
    EXPECT_NE(edits.back().op.radius, drop.radius);
    for (const Edit& e : edits)
        EXPECT_EQ(e.key, QStringLiteral("radius"));
}

TEST(StepList, KeysMenuChecksAndDragsAskForChanges) {
    StepList list;
    std::vector<StepRow> rows = {{QStringLiteral("Drop"), false, true, {}, {}},
                                 {QStringLiteral("Drop"), false, true, {}, {}},
                                 {QStringLiteral("Comb"), true, false, QStringLiteral("spacing 80"), {}},
                                 {QStringLiteral("Wave"), false, false, {}, {}}};
    list.setRows(rows);
    ASSERT_EQ(list.rowCount(), 4u);
    EXPECT_EQ(list.list()->item(2)->checkState(), Qt::Unchecked) << "a muted step is unticked";
    QSignalSpy current(&list, &StepList::currentChanged);
    QSignalSpy moved(&list, &StepList::moveRequested);
    QSignalSpy muted(&list, &StepList::mutedToggled);
    QSignalSpy duplicated(&list, &StepList::duplicateRequested);
    QSignalSpy deleted(&list, &StepList::deleteRequested);

    list.show();
    ASSERT_TRUE(test::activate(&list));
    list.list()->setFocus();
    current.clear(); // focus may have made row 0 current
    list.list()->setCurrentRow(1);
    ASSERT_EQ(current.count(), 1);
    EXPECT_EQ(current.last().at(0).value<std::optional<std::size_t>>(), std::optional<std::size_t>(1));
    QTest::keyClick(list.list(), Qt::Key_D, Qt::ControlModifier);
    ASSERT_EQ(duplicated.count(), 1);
    EXPECT_EQ(duplicated.last().at(0).value<std::size_t>(), 1u);
    QTest::keyClick(list.list(), Qt::Key_Delete);
    ASSERT_EQ(deleted.count(), 1);
    EXPECT_EQ(deleted.last().at(0).value<std::size_t>(), 1u);
    QTest::keyClick(list.list(), Qt::Key_M);
    ASSERT_EQ(muted.count(), 1);
    EXPECT_EQ(muted.last().at(0).value<std::size_t>(), 1u);
    EXPECT_TRUE(muted.last().at(1).toBool());
    // Ticking the muted comb puts it back.
    list.list()->item(2)->setCheckState(Qt::Checked);
    ASSERT_EQ(muted.count(), 2);
    EXPECT_EQ(muted.last().at(0).value<std::size_t>(), 2u);
    EXPECT_FALSE(muted.last().at(1).toBool());

    // A drag of a row asks to move it (the drop calls requestMove) and moves nothing itself.
    EXPECT_EQ(list.list()->dragDropMode(), QAbstractItemView::InternalMove);
    list.list()->setCurrentRow(0);
    list.requestMove(0, 3);
    ASSERT_EQ(moved.count(), 1);
    EXPECT_EQ(moved.last().at(0).value<std::size_t>(), 0u);
    EXPECT_EQ(moved.last().at(1).value<std::size_t>(), 3u);
    EXPECT_EQ(list.list()->item(0)->text(), QStringLiteral("1. Drop"));
    list.requestMove(2, 4); // no row 4
    list.requestMove(2, 2);
    EXPECT_EQ(moved.count(), 1);

    // New rows keep the current row and emit nothing.
    const int changes = current.count();
    list.setRows(rows);
    EXPECT_EQ(list.current(), std::optional<std::size_t>(0));
    EXPECT_EQ(current.count(), changes);
    for (const char* name : {"duplicateStepAction", "deleteStepAction", "muteStepAction"}) {
        auto* action = list.findChild<QAction*>(QString::fromLatin1(name));
        ASSERT_NE(action, nullptr) << name;
        EXPECT_FALSE(action->toolTip().isEmpty());
    }
}

TEST(PaletteEditor, ColoursChangeLiveThenFinally) {
    PaletteEditor palette;
    Genome design = designOf(2);
    palette.setDesign(design);
    QSignalSpy colour(&palette, &PaletteEditor::colorChanged);
    QSignalSpy background(&palette, &PaletteEditor::backgroundChanged);
    QSignalSpy ink(&palette, &PaletteEditor::currentInkChanged);
    QSignalSpy added(&palette, &PaletteEditor::inkAdded);

    palette.editColor(1);
    QColorDialog* dialog = palette.colorDialog();
    ASSERT_NE(dialog, nullptr);
    dialog->setCurrentColor(QColor(10, 200, 30));
    ASSERT_EQ(colour.count(), 1);
    EXPECT_EQ(colour.last().at(0).toInt(), 1);
    EXPECT_EQ(colour.last().at(1).value<Color>(), (Color{10, 200, 30}));
    EXPECT_TRUE(colour.last().at(2).toBool());
    dialog->accept();
    ASSERT_EQ(colour.count(), 2);
    EXPECT_EQ(colour.last().at(1).value<Color>(), (Color{10, 200, 30}));
    EXPECT_FALSE(colour.last().at(2).toBool());

    // Cancelling the background's dialog puts its colour back.
    palette.editColor(-1);
    palette.colorDialog()->setCurrentColor(QColor(0, 0, 0));
    palette.colorDialog()->reject();
    ASSERT_GE(background.count(), 2);
    EXPECT_EQ(background.last().at(0).value<Color>(), design.background);
    EXPECT_FALSE(background.last().at(1).toBool());

    auto* swatch = palette.findChild<QToolButton*>(QStringLiteral("inkSwatch2"));
    ASSERT_NE(swatch, nullptr);
    swatch->click();
    ASSERT_EQ(ink.count(), 1);
    EXPECT_EQ(palette.currentInk(), 2);
    palette.findChild<QToolButton*>(QStringLiteral("addInkButton"))->click();
    EXPECT_EQ(added.count(), 1);
    // A new design with fewer inks keeps the current ink within the palette.
    design.palette.resize(2);
    palette.setDesign(design);
    EXPECT_EQ(palette.currentInk(), 1);
}

TEST(Timeline, ScrubsPlaysAndCompares) {
    Timeline timeline;
    QSignalSpy growth(&timeline, &Timeline::growthChanged);
    timeline.setStepCount(3);
    EXPECT_TRUE(timeline.atEnd()) << "a new design is shown whole";
    EXPECT_EQ(timeline.growth(), 3.0);
    auto* slider = timeline.findChild<QSlider*>(QStringLiteral("timelineSlider"));
    ASSERT_NE(slider, nullptr);
    slider->setValue(slider->maximum() / 2);
    ASSERT_FALSE(growth.isEmpty());
    EXPECT_DOUBLE_EQ(growth.last().at(0).toDouble(), 1.5);
    EXPECT_FALSE(timeline.atEnd());
    timeline.setStepCount(5);
    EXPECT_DOUBLE_EQ(timeline.growth(), 1.5) << "not at the end: stays where it was";
    timeline.setGrowth(5.0);
    timeline.setStepCount(6);
    EXPECT_EQ(timeline.growth(), 6.0) << "at the end: stays at the end";
    timeline.setStepCount(3);
    EXPECT_EQ(timeline.growth(), 3.0);

    std::vector<double> played;
    QObject::connect(&timeline, &Timeline::growthChanged, [&](double g) { played.push_back(g); });
    timeline.play();
    EXPECT_TRUE(timeline.playing());
    MARBLER_WAIT(!timeline.playing(), 20000);
    ASSERT_GE(played.size(), 3u);
    EXPECT_EQ(played.front(), 0.0);
    EXPECT_EQ(played.back(), 3.0);
    for (std::size_t i = 1; i < played.size(); ++i)
        EXPECT_LE(played[i - 1], played[i]);
    EXPECT_TRUE(timeline.atEnd());

    QSignalSpy compare(&timeline, &Timeline::compareChanged);
    timeline.findChild<QCheckBox*>(QStringLiteral("compareBox"))->setChecked(true);
    ASSERT_EQ(compare.count(), 1);
    EXPECT_TRUE(compare.last().at(0).toBool());
    EXPECT_TRUE(timeline.comparing());
    auto* other = timeline.findChild<QSlider*>(QStringLiteral("compareSlider"));
    ASSERT_NE(other, nullptr);
    other->setValue(100);
    ASSERT_EQ(compare.count(), 2);
    EXPECT_DOUBLE_EQ(compare.last().at(1).toDouble(), 1.0);
    EXPECT_DOUBLE_EQ(timeline.compareGrowth(), 1.0);

    QSignalSpy exportRequested(&timeline, &Timeline::exportAnimationRequested);
    timeline.findChild<QToolButton*>(QStringLiteral("exportAnimationButton"))->click();
    EXPECT_EQ(exportRequested.count(), 1);
}

namespace {

Genome animatedDesign() {
    Genome g = designOf(2);
    Operation a = defaultOperation(Tool::Drop, 2, {400.0, 400.0, 0.0});
    a.radius = 200.0;
    a.color = 0;
    Operation b = defaultOperation(Tool::Drop, 2, {600.0, 450.0, 0.0});
    b.radius = 150.0;
    b.color = 1;
    g.initial = {a, b};
    Operation line = defaultOperation(Tool::Line, 2, {500.0, 400.0, 0.0});
    line.alpha = 80.0;
    line.angle = 30.0;
    g.operations = {line};
    return g;
}

/// The mean absolute difference of two RGB images of the same size, per channel.
double meanDifference(const std::uint8_t* a, const std::uint8_t* b, std::size_t bytes) {
    double sum = 0;
    for (std::size_t i = 0; i < bytes; ++i)
        sum += std::abs(int(a[i]) - int(b[i]));
    return sum / double(bytes);
}

Image framePixels(const QString& file) {
    QImage image(file);
    image = image.convertToFormat(QImage::Format_RGB888);
    Image out;
    out.width = image.width();
    out.height = image.height();
    for (int y = 0; y < image.height(); ++y)
        out.rgb.insert(out.rgb.end(), image.constScanLine(y), image.constScanLine(y) + image.width() * 3);
    return out;
}

} // namespace

TEST(AnimationExport, PngFramesRunFromTheBareBathToTheDesign) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const Genome design = animatedDesign();
    AnimationExportSettings settings;
    settings.format = AnimationFormat::PngFrames;
    settings.path = dir.filePath(QStringLiteral("frames"));
    settings.width = 50;
    settings.height = 40;
    settings.frames = 4;
    AnimationExportJob job;
    QSignalSpy finished(&job, &AnimationExportJob::finished);
    QSignalSpy progress(&job, &AnimationExportJob::progress);
    ASSERT_TRUE(job.start(design, settings));
    EXPECT_FALSE(job.start(design, settings)) << "one job at a time";
    MARBLER_WAIT(finished.count() == 1, 60000);
    EXPECT_TRUE(finished.last().at(0).toBool()) << finished.last().at(1).toString().toStdString();
    EXPECT_FALSE(job.running());
    EXPECT_FALSE(progress.isEmpty());
    RenderSettings render;
    render.width = 50;
    render.height = 40;
    const Image bare = CpuRenderer(designAfterSteps(design, 0)).render(render);
    const Image whole = CpuRenderer(design).render(render);
    const Image first = framePixels(dir.filePath(QStringLiteral("frames/frame-0000.png")));
    const Image last = framePixels(dir.filePath(QStringLiteral("frames/frame-0003.png")));
    EXPECT_EQ(first.rgb, bare.rgb) << "frame 0 is the bare bath";
    EXPECT_EQ(last.rgb, whole.rgb) << "the last frame is the whole design";
    EXPECT_NE(first.rgb, last.rgb);
    EXPECT_EQ(QDir(settings.path).entryList(QDir::Files).size(), 4);
}

TEST(AnimationExport, GifHoldsEveryFrameFromBathToDesign) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const Genome design = animatedDesign();
    AnimationExportSettings settings;
    settings.format = AnimationFormat::Gif;
    settings.path = dir.filePath(QStringLiteral("making")); // the extension is added
    settings.width = 48;
    settings.height = 40;
    settings.frames = 5;
    settings.fps = 10;
    AnimationExportJob job;
    QSignalSpy finished(&job, &AnimationExportJob::finished);
    ASSERT_TRUE(job.start(design, settings));
    MARBLER_WAIT(finished.count() == 1, 60000);
    ASSERT_TRUE(finished.last().at(0).toBool()) << finished.last().at(1).toString().toStdString();
    auto reader = openVideoReader(dir.filePath(QStringLiteral("making.gif")).toStdString());
    ASSERT_EQ(reader->width(), 48);
    ASSERT_EQ(reader->height(), 40);
    std::vector<std::vector<std::uint8_t>> frames;
    std::vector<std::uint8_t> rgb;
    while (reader->nextFrame(rgb))
        frames.push_back(rgb);
    ASSERT_EQ(frames.size(), 5u);
    RenderSettings render;
    render.width = 48;
    render.height = 40;
    const Image bare = CpuRenderer(designAfterSteps(design, 0)).render(render);
    const Image whole = CpuRenderer(design).render(render);
    // One 256-colour palette and dithering: close, not equal.
    EXPECT_LT(meanDifference(frames.front().data(), bare.rgb.data(), bare.rgb.size()), 6.0);
    EXPECT_LT(meanDifference(frames.back().data(), whole.rgb.data(), whole.rgb.size()), 6.0);
    EXPECT_GT(meanDifference(frames.front().data(), whole.rgb.data(), whole.rgb.size()), 10.0);
}

TEST(AnimationExport, CancelLeavesNoFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    for (AnimationFormat format : {AnimationFormat::Gif, AnimationFormat::PngFrames}) {
        AnimationExportSettings settings;
        settings.format = format;
        settings.path = dir.filePath(format == AnimationFormat::Gif ? QStringLiteral("long.gif")
                                                                    : QStringLiteral("long"));
        settings.width = 400;
        settings.height = 400;
        settings.frames = 2000;
        AnimationExportJob job;
        QSignalSpy finished(&job, &AnimationExportJob::finished);
        QSignalSpy progress(&job, &AnimationExportJob::progress);
        ASSERT_TRUE(job.start(animatedDesign(), settings));
        MARBLER_WAIT(!progress.isEmpty(), 30000);
        job.cancel();
        MARBLER_WAIT(finished.count() == 1, 30000);
        EXPECT_FALSE(finished.last().at(0).toBool());
        EXPECT_TRUE(finished.last().at(1).toString().isEmpty()) << "a cancel is no error";
        EXPECT_TRUE(
            QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden).isEmpty())
            << QDir(dir.path())
                   .entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)
                   .join(' ')
                   .toStdString();
    }
}

TEST(AnimationExport, AFramesFolderMustBeNewOrEmptyAndTheDialogSaysWhatToWrite) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QDir(dir.path()).mkdir(QStringLiteral("full"));
    QFile keep(dir.filePath(QStringLiteral("full/keep.txt")));
    ASSERT_TRUE(keep.open(QIODevice::WriteOnly));
    keep.close();
    AnimationExportSettings settings;
    settings.format = AnimationFormat::PngFrames;
    settings.path = dir.filePath(QStringLiteral("full"));
    settings.width = settings.height = 16;
    settings.frames = 2;
    AnimationExportJob job;
    QSignalSpy finished(&job, &AnimationExportJob::finished);
    ASSERT_TRUE(job.start(animatedDesign(), settings));
    MARBLER_WAIT(finished.count() == 1, 30000);
    EXPECT_FALSE(finished.last().at(0).toBool());
    EXPECT_TRUE(finished.last().at(1).toString().contains(QStringLiteral("already exists")));
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("full/keep.txt"))));

    AnimationExportSettings start;
    start.path = dir.filePath(QStringLiteral("making.gif"));
    start.width = 300;
    AnimationExportDialog dialog(animatedDesign(), start);
    auto* format = dialog.findChild<QComboBox*>(QStringLiteral("animationFormat"));
    ASSERT_NE(format, nullptr);
    EXPECT_EQ(dialog.settings().format, AnimationFormat::Gif);
    EXPECT_EQ(dialog.settings().height, 240) << "the design's aspect, 1000 x 800";
    format->setCurrentIndex(format->findData(int(AnimationFormat::Mp4)));
    EXPECT_EQ(dialog.settings().format, AnimationFormat::Mp4);
    EXPECT_EQ(dialog.settings().path, dir.filePath(QStringLiteral("making.mp4")));
    format->setCurrentIndex(format->findData(int(AnimationFormat::PngFrames)));
    EXPECT_EQ(dialog.settings().path, dir.filePath(QStringLiteral("making")));
    // A name typed without its extension gets it: the file said written is the file written.
    auto* path = dialog.findChild<QLineEdit*>(QStringLiteral("animationPath"));
    ASSERT_NE(path, nullptr);
    format->setCurrentIndex(format->findData(int(AnimationFormat::WebM)));
    path->setText(dir.filePath(QStringLiteral("typed")));
    EXPECT_EQ(dialog.settings().path, dir.filePath(QStringLiteral("typed.webm")));
    EXPECT_EQ(withAnimationExtension(QStringLiteral("a/b.GIF"), AnimationFormat::Gif),
              QStringLiteral("a/b.GIF"));
    EXPECT_EQ(withAnimationExtension(QStringLiteral("a/b.gif"), AnimationFormat::Mp4),
              QStringLiteral("a/b.gif.mp4"));
    EXPECT_EQ(withAnimationExtension(QStringLiteral("a/frames"), AnimationFormat::PngFrames),
              QStringLiteral("a/frames"));
}

namespace {

QString labelText(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

/// The caption a form layout shows beside `field`.
QString captionOf(QWidget* field) {
    for (QWidget* w = field; w; w = w->parentWidget())
        if (auto* form =
                qobject_cast<QFormLayout*>(w->parentWidget() ? w->parentWidget()->layout() : nullptr))
            if (auto* label = qobject_cast<QLabel*>(form->labelForField(w))) return label->text();
    return {};
}

} // namespace

// Issue 27, item 12: Ctrl+Z in a parameter field is the window's Undo, not the field's own text
// undo; Enter commits the field and says so (the window then gives the canvas the focus).
TEST(ParamForm, UndoKeysReachTheWindowAndEnterCommits) {
    QWidget window;
    auto* layout = new QVBoxLayout(&window);
    auto* form = new ParamForm(&window);
    layout->addWidget(form);
    auto* undo = new QAction(QStringLiteral("Undo"), &window);
    undo->setShortcut(QKeySequence::Undo);
    auto* redo = new QAction(QStringLiteral("Redo"), &window);
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    window.addActions({undo, redo});
    QSignalSpy undone(undo, &QAction::triggered);
    QSignalSpy redone(redo, &QAction::triggered);
    QSignalSpy committed(form, &ParamForm::committed);
    std::vector<Edit> edits;
    QObject::connect(form, &ParamForm::edited, form,
                     [&](const Operation& op, const QString& key, bool dragging) {
                         edits.push_back({op, key, dragging});
                     });
    const Genome design = designOf(2);
    form->setStep(defaultOperation(Tool::Circle, 2, {500, 400, 0}), 2, design);
    window.show();
    ASSERT_TRUE(test::activate(&window));

    for (const char* name : {"edit-alpha-0", "edit-steps-0"}) {
        if (QString::fromLatin1(name) == QStringLiteral("edit-steps-0"))
            form->setStep(defaultOperation(Tool::Flow, 2, {500, 400, 0}), 2, design);
        auto* field = form->findChild<QAbstractSpinBox*>(QString::fromLatin1(name));
        ASSERT_NE(field, nullptr) << name;
        field->setFocus();
        ASSERT_TRUE(QTest::qWaitFor([&] { return field->hasFocus(); }));
        const int undos = undone.count(), redos = redone.count();
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
        EXPECT_EQ(undone.count(), undos + 1) << name << ": Ctrl+Z in a field is the window's Undo";
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTest::keyClick(field, Qt::Key_Y, Qt::ControlModifier);
        EXPECT_EQ(redone.count(), redos + 2) << name << ": Ctrl+Shift+Z and Ctrl+Y are the window's Redo";
    }

    // Typed text and Enter: the value is committed, then `committed` says so.
    form->setStep(defaultOperation(Tool::Circle, 2, {500, 400, 0}), 2, design);
    auto* alpha = form->findChild<QDoubleSpinBox*>(QStringLiteral("edit-alpha-0"));
    ASSERT_NE(alpha, nullptr);
    alpha->setFocus();
    alpha->selectAll();
    edits.clear();
    committed.clear();
    QTest::keyClicks(alpha, QStringLiteral("35"));
    EXPECT_TRUE(edits.empty()) << "nothing is committed while typing";
    QTest::keyClick(alpha, Qt::Key_Return);
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits[0].op.alpha, 35.0);
    EXPECT_EQ(committed.count(), 1);
    EXPECT_EQ(alpha->text(), QStringLiteral("35 design units"));
    // The stretch's teeth text commits on Enter too.
    form->setStep(defaultOperation(Tool::Stretch, 2, {500, 400, 0}), 2, design);
    auto* teeth = form->findChild<QLineEdit*>(QStringLiteral("edit-teeth-0"));
    ASSERT_NE(teeth, nullptr);
    teeth->setFocus();
    teeth->setText(QStringLiteral("-100 0 100"));
    committed.clear();
    QTest::keyClick(teeth, Qt::Key_Enter);
    EXPECT_EQ(committed.count(), 1);
    EXPECT_EQ(form->step().teeth, (std::vector<double>{-100, 0, 100}));
    const int undos = undone.count();
    QTest::keyClick(teeth, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(undone.count(), undos + 1);
}

// Issue 27, item 14: huge and tiny values show compactly, and showing a value never rounds it.
TEST(ParamForm, NumbersShowCompactlyAndStayExact) {
    ParamForm form;
    std::vector<Edit> edits;
    QObject::connect(&form, &ParamForm::edited, &form,
                     [&](const Operation& op, const QString& key, bool dragging) {
                         edits.push_back({op, key, dragging});
                     });
    Operation circle = defaultOperation(Tool::Circle, 2, {500, 400, 0});
    circle.alpha = 1e308;
    circle.lambda = 123.456789;
    circle.radius = 2.5e-7;
    form.setStep(circle, 2, designOf(2));
    form.show();
    auto* alpha = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-alpha-0"));
    auto* lambda = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-lambda-0"));
    auto* radius = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-radius-0"));
    ASSERT_TRUE(alpha && lambda && radius);
    EXPECT_EQ(alpha->text(), QStringLiteral("1e+308 design units"));
    EXPECT_EQ(lambda->text(), QStringLiteral("123.457 design units"));
    EXPECT_EQ(radius->text(), QStringLiteral("2.5e-07 design units"));
    EXPECT_EQ(alpha->value(), 1e308);
    // Re-reading the text shown (what Enter and leaving the field do) keeps the exact value.
    for (QDoubleSpinBox* box : {alpha, lambda, radius}) {
        QString shown = box->text();
        int pos = 0;
        EXPECT_EQ(box->validate(shown, pos), QValidator::Acceptable) << shown.toStdString();
        EXPECT_EQ(box->valueFromText(shown), box->value()) << shown.toStdString();
        box->interpretText();
    }
    EXPECT_TRUE(edits.empty()) << "showing a value changes nothing";
    EXPECT_EQ(form.step().lambda, 123.456789);
    // Exponents are read back; text that is no number is refused, the value kept.
    lambda->findChild<QLineEdit*>()->setText(QStringLiteral("2.5e3 design units"));
    lambda->interpretText();
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits[0].op.lambda, 2500.0);
    QString junk = QStringLiteral("abc design units");
    int pos = 0;
    EXPECT_EQ(lambda->validate(junk, pos), QValidator::Invalid);
    // The teeth's positions are compact too.
    Operation stretch = defaultOperation(Tool::Stretch, 2, {500, 400, 0});
    stretch.teeth = {-1e300, 0.0, 1e300};
    form.setStep(stretch, 2, designOf(2));
    auto* teeth = form.findChild<QLineEdit*>(QStringLiteral("edit-teeth-0"));
    ASSERT_NE(teeth, nullptr);
    EXPECT_EQ(teeth->text(), QStringLiteral("-1e+300 0 1e+300"));
}

// Issue 27, item 14: one vocabulary. Every row of the form is named by the registry's label, the
// tool panel names its rows by the same labels, and no caption repeats its unit ("time (time)").
TEST(ParamForm, RowsAreNamedAsTheToolPanelNamesThem) {
    for (const ToolSpec& tool : allTools())
        for (int dimension : {2, 3}) {
            if (!tool.available(dimension)) continue;
            ParamForm form;
            form.setStep(defaultOperation(tool.tool, dimension, {500, 400, 300}), dimension,
                         designOf(dimension));
            for (const ParamSpec& spec : tool.params(dimension)) {
                auto* box = form.findChild<QWidget*>(QStringLiteral("param-") + keyOf(spec));
                ASSERT_NE(box, nullptr) << keyOf(spec).toStdString();
                const QString caption = captionOf(box);
                EXPECT_EQ(caption, labelText(spec.label)) << tool.name << " " << spec.key;
                EXPECT_FALSE(caption.contains(QLatin1Char('('))) << caption.toStdString();
            }
        }
    ParamForm form;
    form.setStep(defaultOperation(Tool::Circle, 2, {500, 400, 0}), 2, designOf(2));
    ToolOptions panel;
    struct Pair {
        const char* panelField;
        Tool tool;
        ParamField field;
    };
    for (const Pair& p :
         {Pair{"toolAlpha", Tool::Circle, ParamField::Alpha},
          Pair{"toolLambda", Tool::Circle, ParamField::Lambda},
          Pair{"toolCore", Tool::Circle, ParamField::Core},
          Pair{"toolRadius", Tool::Circle, ParamField::Radius},
          Pair{"toolSpacing", Tool::Comb, ParamField::Spacing},
          Pair{"toolWavelength", Tool::Wave, ParamField::Wavelength},
          Pair{"toolPower", Tool::Stretch, ParamField::Power},
          Pair{"toolSpeed", Tool::Flow, ParamField::Speed}, Pair{"toolTime", Tool::Flow, ParamField::Time}}) {
        auto* field = panel.findChild<QWidget*>(QString::fromLatin1(p.panelField));
        ASSERT_NE(field, nullptr) << p.panelField;
        const ParamSpec* spec = findParam(p.tool, p.field);
        ASSERT_NE(spec, nullptr);
        EXPECT_EQ(captionOf(field), labelText(spec->label)) << p.panelField;
    }
    // The circle's alpha and lambda: "Shift" and "Sharpness" in both places.
    EXPECT_EQ(captionOf(form.findChild<QWidget*>(QStringLiteral("param-alpha"))), QStringLiteral("Shift"));
    EXPECT_EQ(captionOf(panel.findChild<QWidget*>(QStringLiteral("toolAlpha"))), QStringLiteral("Shift"));
    EXPECT_EQ(captionOf(form.findChild<QWidget*>(QStringLiteral("param-lambda"))),
              QStringLiteral("Sharpness"));
    EXPECT_EQ(captionOf(panel.findChild<QWidget*>(QStringLiteral("toolLambda"))),
              QStringLiteral("Sharpness"));
    // A flow's time: "Time", its unit once, in the box.
    form.setStep(defaultOperation(Tool::Flow, 2, {500, 400, 0}), 2, designOf(2));
    auto* time = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-time-0"));
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(captionOf(form.findChild<QWidget*>(QStringLiteral("param-time"))), QStringLiteral("Time"));
    EXPECT_EQ(time->suffix(), QStringLiteral(" time units"));
}

// Issue 27, item 14: a stretch's teeth have an editor, a count and a spacing.
TEST(ParamForm, StretchTeethByCountAndSpacing) {
    ParamForm form;
    std::vector<Edit> edits;
    QObject::connect(&form, &ParamForm::edited, &form,
                     [&](const Operation& op, const QString& key, bool dragging) {
                         edits.push_back({op, key, dragging});
                     });
    Operation stretch = defaultOperation(Tool::Stretch, 2, {500, 400, 0});
    stretch.teeth = {-100, 0, 100, 200, 300};
    form.setStep(stretch, 2, designOf(2));
    auto* count = form.findChild<QSpinBox*>(QStringLiteral("edit-teeth-count"));
    auto* spacing = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-teeth-spacing"));
    ASSERT_TRUE(count && spacing);
    EXPECT_EQ(count->value(), 5);
    EXPECT_EQ(spacing->value(), 100.0);
    EXPECT_EQ(spacing->text(), QStringLiteral("100 design units"));
    // More teeth over the same span.
    count->setValue(9);
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits[0].key, QStringLiteral("teeth"));
    EXPECT_EQ(edits[0].op.teeth, (std::vector<double>{-100, -50, 0, 50, 100, 150, 200, 250, 300}));
    EXPECT_EQ(spacing->value(), 50.0);
    // A wider spacing about the same middle.
    spacing->setValue(80.0);
    ASSERT_EQ(edits.size(), 2u);
    const std::vector<double>& teeth = edits[1].op.teeth;
    ASSERT_EQ(teeth.size(), 9u);
    EXPECT_DOUBLE_EQ(teeth.front(), 100.0 - 4 * 80.0);
    EXPECT_DOUBLE_EQ(teeth.back(), 100.0 + 4 * 80.0);
    auto* text = form.findChild<QLineEdit*>(QStringLiteral("edit-teeth-0"));
    ASSERT_NE(text, nullptr);
    EXPECT_TRUE(text->text().startsWith(QStringLiteral("-220 -140 -60"))) << text->text().toStdString();
    EXPECT_TRUE(validStep(designOf(2), form.step()));
}

namespace {

std::vector<StepRow> sprayDesignRows() {
    // Two drops, one spray stroke of 40 droplets, then three combs and a wave.
    std::vector<StepRow> rows;
    auto add = [&rows](const char* tool, bool initial, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            rows.push_back({QString::fromLatin1(tool), false, initial, {}, QString::fromLatin1(tool)});
    };
    add("drop", true, 2);
    add("spray", true, 40);
    add("comb", false, 3);
    add("wave", false, 1);
    return rows;
}

/// The texts of the rows shown, top to bottom.
QStringList shownRows(const StepList& list) {
    QStringList texts;
    for (int i = 0; i < list.list()->count(); ++i)
        if (!list.list()->item(i)->isHidden()) texts << list.list()->item(i)->text().trimmed();
    return texts;
}

} // namespace

// Issue 27, item 17: one spray stroke is one row, which opens to show its droplets; the indices
// in and out are still the document's steps.
TEST(StepList, ARunOfOneToolIsOneRowThatOpens) {
    StepList list;
    list.setRows(sprayDesignRows());
    ASSERT_EQ(list.rowCount(), 46u) << "every step keeps its index";
    EXPECT_EQ(shownRows(list),
              (QStringList{QStringLiteral("1. drop"), QStringLiteral("2. drop"),
                           QStringLiteral("▸ 40 sprays (steps 3–42)"),
                           QStringLiteral("▸ 3 combs (steps 43–45)"), QStringLiteral("46. wave")}));
    QSignalSpy current(&list, &StepList::currentChanged);
    list.show();
    ASSERT_TRUE(test::activate(&list));
    list.list()->setFocus();
    current.clear();

    // Selecting the group's row selects its first step.
    list.list()->setCurrentItem(list.list()->item(2));
    ASSERT_EQ(current.count(), 1);
    EXPECT_EQ(current.last().at(0).value<std::optional<std::size_t>>(), std::optional<std::size_t>(2));
    EXPECT_TRUE(list.isGroupHead(2));
    // → opens it: its 40 steps are rows, numbered as the document's.
    QTest::keyClick(list.list(), Qt::Key_Right);
    EXPECT_TRUE(list.isGroupExpanded(2));
    QStringList rows = shownRows(list);
    ASSERT_EQ(rows.size(), 44);
    EXPECT_EQ(rows[2], QStringLiteral("▾ 3. spray"));
    EXPECT_EQ(rows[41], QStringLiteral("42. spray"));
    EXPECT_TRUE(list.isRowShown(30));
    list.list()->setCurrentRow(30);
    EXPECT_EQ(list.current(), std::optional<std::size_t>(30));
    // ← folds it again, and the group's row (step 3) is selected.
    QTest::keyClick(list.list(), Qt::Key_Left);
    EXPECT_FALSE(list.isGroupExpanded(2));
    EXPECT_FALSE(list.isRowShown(30));
    EXPECT_EQ(list.current(), std::optional<std::size_t>(2));
    EXPECT_EQ(current.last().at(0).value<std::optional<std::size_t>>(), std::optional<std::size_t>(2));
    // Double-click opens it too.
    const QPoint groupRow = list.list()->visualItemRect(list.list()->item(2)).center();
    QTest::mouseClick(list.list()->viewport(), Qt::LeftButton, {}, groupRow);
    QTest::mouseDClick(list.list()->viewport(), Qt::LeftButton, {}, groupRow);
    EXPECT_TRUE(list.isGroupExpanded(2));
    list.setGroupExpanded(2, false);

    // The window selecting a step inside a folded group (a pick on the canvas) opens it.
    list.setCurrent(20);
    EXPECT_EQ(list.current(), std::optional<std::size_t>(20));
    EXPECT_TRUE(list.isRowShown(20));
    // New rows (an edit) keep it open and the step selected.
    list.setRows(sprayDesignRows());
    EXPECT_TRUE(list.isGroupExpanded(2));
    EXPECT_EQ(list.current(), std::optional<std::size_t>(20));

    // A folded group's box mutes all its steps, as one edit; the keys act on the step selected.
    list.setGroupExpanded(43, false);
    QSignalSpy muted(&list, &StepList::rangeMutedToggled);
    list.list()->item(42)->setCheckState(Qt::Unchecked);
    ASSERT_EQ(muted.count(), 1);
    EXPECT_EQ(muted.at(0).at(0).value<std::size_t>(), 42u);
    EXPECT_EQ(muted.at(0).at(1).value<std::size_t>(), 44u);
    EXPECT_TRUE(muted.at(0).at(2).toBool());
    QSignalSpy deleted(&list, &StepList::deleteRequested);
    list.setCurrent(42);
    QTest::keyClick(list.list(), Qt::Key_Delete);
    ASSERT_EQ(deleted.count(), 1);
    EXPECT_EQ(deleted.last().at(0).value<std::size_t>(), 42u);
    // Two steps of one tool stay two rows.
    std::vector<StepRow> two = sprayDesignRows();
    two.resize(2);
    list.setRows(two);
    EXPECT_EQ(shownRows(list), (QStringList{QStringLiteral("1. drop"), QStringLiteral("2. drop")}));
}

// Issue 27, item 17: the filter shows the steps of one tool.
TEST(StepList, TheFilterShowsOneToolsSteps) {
    StepList list;
    list.setRows(sprayDesignRows());
    QComboBox* filter = list.filter();
    ASSERT_NE(filter, nullptr);
    EXPECT_EQ(filter->objectName(), QStringLiteral("stepFilter"));
    EXPECT_FALSE(filter->toolTip().isEmpty());
    QStringList entries;
    for (int i = 0; i < filter->count(); ++i)
        entries << filter->itemText(i);
    EXPECT_EQ(entries, (QStringList{QStringLiteral("All steps"), QStringLiteral("drops (2)"),
                                    QStringLiteral("sprays (40)"), QStringLiteral("combs (3)"),
                                    QStringLiteral("waves (1)")}));
    filter->setCurrentIndex(filter->findData(QStringLiteral("comb")));
    EXPECT_EQ(shownRows(list), (QStringList{QStringLiteral("▸ 3 combs (steps 43–45)")}));
    list.setGroupExpanded(42, true);
    EXPECT_EQ(shownRows(list), (QStringList{QStringLiteral("▾ 43. comb"), QStringLiteral("44. comb"),
                                            QStringLiteral("45. comb")}));
    // New rows keep the filter; a step selected outside it clears it.
    list.setRows(sprayDesignRows());
    EXPECT_EQ(filter->currentData().toString(), QStringLiteral("comb"));
    list.setCurrent(45);
    EXPECT_EQ(filter->currentIndex(), 0);
    EXPECT_TRUE(list.isRowShown(45));
    EXPECT_EQ(list.current(), std::optional<std::size_t>(45));
}

// The editor reads the tool registry (Params.h): every registry tool is offered on the editor's
// tool bar with its name, tooltip and key, and its gesture makes a valid step of that tool in
// every dimension it exists in; the tool panel starts at the registry's values. A tool added to
// the registry without its editor half fails here, not in a user's hands.

#include "editor/EditorWindow.h"
#include "editor/Gestures.h"
#include "editor/ToolOptions.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "shared/RenderService.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// Registry tools the editor's tool bar leaves out on purpose: solids' own tools, made in the
/// step form. A tool lands here by a decision, never by being forgotten.
constexpr Tool NotOnToolBar[] = {Tool::Cylinder};

bool leftOut(Tool tool) {
    return std::find(std::begin(NotOnToolBar), std::end(NotOnToolBar), tool) != std::end(NotOnToolBar);
}

Genome designOf(int dimension) {
    Genome g;
    g.dimension = dimension;
    g.size = dimension == 3 ? glm::dvec3(600, 600, 600) : glm::dvec3(1000, 1000, 0);
    g.palette = {{200, 30, 30}, {30, 30, 200}};
    g.initial.push_back(defaultOperation(Tool::Drop, dimension, g.size * 0.5));
    return g;
}

std::string name(Tool tool) {
    return std::string(toolSpec(tool).name);
}

} // namespace

TEST(EditorRegistryTest, EveryRegistryToolHasAGestureThatMakesAValidStep) {
    const std::vector<EditorTool> bar = editorTools();
    for (const ToolSpec& spec : allTools()) {
        const bool offered = std::find(bar.begin(), bar.end(), EditorTool(spec.tool)) != bar.end();
        if (leftOut(spec.tool)) {
            EXPECT_FALSE(offered) << name(spec.tool);
            continue;
        }
        ASSERT_TRUE(offered) << name(spec.tool)
                             << " has no gesture in the editor (Params.cpp, its row's `editor`)";
        EXPECT_EQ(toolId(spec.tool), spec.name);
        EXPECT_EQ(genomeTool(spec.tool), spec.tool);
        EXPECT_EQ(laysInk(spec.tool), spec.laysInk) << name(spec.tool);
        for (int dimension : {2, 3}) {
            const Genome design = designOf(dimension);
            EXPECT_EQ(toolAvailable(spec.tool, dimension), spec.available(dimension)) << name(spec.tool);
            if (!spec.available(dimension)) {
                EXPECT_TRUE(gestureSteps(spec.tool, {}, {100, 200, 300}, {400, 380, 300}, design).empty());
                continue;
            }
            const glm::dvec3 press{200, 250, 300}, release{420, 400, 300};
            const std::vector<Operation> ops =
                gestureSteps(spec.tool, ToolSettings{}, press, release, design);
            ASSERT_FALSE(ops.empty()) << name(spec.tool) << " in " << dimension << "D makes nothing";
            for (const Operation& op : ops)
                EXPECT_EQ(op.tool, spec.tool) << name(spec.tool);
            EXPECT_NO_THROW(validateGenome(withSteps(design, ops), "gesture"))
                << name(spec.tool) << " " << dimension << "D";
        }
    }
}

TEST(EditorRegistryTest, TheToolBarShowsEachRegistryToolsNameTooltipAndKey) {
    RenderService service(RenderService::Backend::Cpu);
    QTemporaryDir recovery;
    for (int dimension : {2, 3}) {
        EditorWindow editor(designOf(dimension), &service, {}, nullptr, recovery.path());
        editor.setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
        std::vector<QKeySequence> keys;
        for (const ToolSpec& spec : allTools()) {
            const QString id =
                QStringLiteral("tool-") + QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size()));
            auto* action = editor.findChild<QAction*>(id);
            if (leftOut(spec.tool) || !spec.available(dimension)) {
                EXPECT_EQ(action, nullptr) << name(spec.tool) << " in " << dimension << "D";
                continue;
            }
            ASSERT_NE(action, nullptr)
                << name(spec.tool) << " is not on the " << dimension << "D editor's tool bar";
            // The words the person reads are the registry's.
            EXPECT_EQ(action->text(),
                      QString::fromUtf8(spec.editor.name.data(), qsizetype(spec.editor.name.size())));
            EXPECT_EQ(action->toolTip(),
                      QString::fromUtf8(spec.editor.tooltip.data(), qsizetype(spec.editor.tooltip.size())));
            EXPECT_EQ(action->shortcut(), QKeySequence(QString(QChar(spec.editor.shortcut))));
            keys.push_back(action->shortcut());
            action->trigger();
            EXPECT_EQ(editor.tool(), EditorTool(spec.tool)) << name(spec.tool);
        }
        std::sort(keys.begin(), keys.end());
        EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end()) << "two tools share a key";
        editor.close();
    }
}

TEST(EditorRegistryTest, ThePanelStartsAtTheRegistrysValues) {
    // Where the editor starts elsewhere than a design's default (a broader stroke, a faster flow)
    // the registry's row says so; the panel shows it.
    ToolOptions options;
    options.setPalette(designOf(2).palette);
    const struct {
        const char* box;
        Tool tool;
        ParamField field;
    } rows[] = {
        {"toolRadius", Tool::Drop, ParamField::Radius},
        {"toolSpacing", Tool::Comb, ParamField::Spacing},
        {"toolWavelength", Tool::Wave, ParamField::Wavelength},
        {"toolAlpha", Tool::Circle, ParamField::Alpha},
        {"toolLambda", Tool::Line, ParamField::Lambda},
        {"toolCore", Tool::Circle, ParamField::Core},
        {"toolPower", Tool::Stretch, ParamField::Power},
        {"toolSpeed", Tool::Flow, ParamField::Speed},
        {"toolTime", Tool::Flow, ParamField::Time},
    };
    for (const auto& row : rows) {
        auto* box = options.findChild<QDoubleSpinBox*>(QString::fromLatin1(row.box));
        ASSERT_NE(box, nullptr) << row.box;
        EXPECT_DOUBLE_EQ(box->value(), findParam(row.tool, row.field)->editorValue()) << row.box;
    }
    // The values the editor has always started with.
    EXPECT_DOUBLE_EQ(options.findChild<QDoubleSpinBox*>(QStringLiteral("toolLambda"))->value(), 24.0);
    EXPECT_DOUBLE_EQ(options.findChild<QDoubleSpinBox*>(QStringLiteral("toolSpeed"))->value(), 200.0);
    EXPECT_DOUBLE_EQ(options.findChild<QDoubleSpinBox*>(QStringLiteral("toolWavelength"))->value(), 250.0);
    EXPECT_DOUBLE_EQ(options.findChild<QDoubleSpinBox*>(QStringLiteral("toolPower"))->value(), 2.0);
    EXPECT_DOUBLE_EQ(options.findChild<QDoubleSpinBox*>(QStringLiteral("toolTime"))->value(), 1.0);
    // A design's own defaults are untouched.
    EXPECT_DOUBLE_EQ(findParam(Tool::Line, ParamField::Lambda)->defaultValue, 12.0);
    EXPECT_DOUBLE_EQ(findParam(Tool::Flow, ParamField::Speed)->defaultValue, 40.0);
}

TEST(EditorRegistryTest, PanelRowsFollowTheGestureKind) {
    // A row shows for every tool whose gesture takes that parameter from the panel, read from the
    // registry: the comb's spacing, not the line's (it has none); the sharpness for both.
    ToolOptions options;
    options.show();
    auto* spacing = options.findChild<QDoubleSpinBox*>(QStringLiteral("toolSpacing"));
    auto* lambda = options.findChild<QDoubleSpinBox*>(QStringLiteral("toolLambda"));
    auto* speed = options.findChild<QDoubleSpinBox*>(QStringLiteral("toolSpeed"));
    ASSERT_TRUE(spacing && lambda && speed);
    options.setTool(Tool::Line);
    EXPECT_FALSE(spacing->isVisible());
    EXPECT_TRUE(lambda->isVisible());
    options.setTool(Tool::Comb);
    EXPECT_TRUE(spacing->isVisible());
    EXPECT_TRUE(lambda->isVisible());
    EXPECT_FALSE(speed->isVisible());
    options.setTool(Tool::Flow);
    EXPECT_TRUE(speed->isVisible());
    EXPECT_FALSE(lambda->isVisible());
    options.setTool(EditorTool::Pick);
    EXPECT_FALSE(spacing->isVisible() || lambda->isVisible() || speed->isVisible());
}

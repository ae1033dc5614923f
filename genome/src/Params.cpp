#include "marbler/Params.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace marbler {
namespace {

using K = ParamKind;
using F = ParamField;
using G = EditorGesture;

/// `spec` with the editor's own starting value (ParamSpec::editorDefault).
constexpr ParamSpec startingAt(ParamSpec spec, double editorValue) {
    spec.editorDefault = editorValue;
    return spec;
}

// The table keeps one row a line, to be read as a table: not reflowed.
// clang-format off
// Shared rows. Mutation scales: positions and lengths as a fraction of the design's largest
// side, angles and phases in degrees.
constexpr ParamSpec Center{"center", "Centre", F::Center, K::Position, "design units", "centre of the tool", AnyNumber, 0.0, 0.08};
constexpr ParamSpec Origin{"origin", "Origin", F::Center, K::Position, "design units", "a point on the stroke's path", AnyNumber, 0.0, 0.08};
constexpr ParamSpec Radius{"radius", "Radius", F::Radius, K::Length, "design units", "radius", PositiveNumber, 60.0, 0.03};
constexpr ParamSpec ColorRow{"color", "Ink", F::Color, K::Color, "", "palette index of the ink", AnyNumber, 0.0, 0.0};
constexpr ParamSpec Axis{"axis", "Axis", F::Axis, K::Direction, "", "axis (turned by the right-hand rule)", AnyNumber, 0.0, 0.25};
constexpr ParamSpec Angle{"angle", "Angle", F::Angle, K::Angle, "degrees", "direction of motion, clockwise from +x", AnyNumber, 0.0, 25.0};
constexpr ParamSpec Direction{"direction", "Direction", F::Direction, K::Direction, "", "direction of motion", AnyNumber, 0.0, 0.25};
constexpr ParamSpec Normal{"normal", "Normal", F::Normal, K::Direction, "", "across the plane the tine sweeps", AnyNumber, 0.0, 0.25};
constexpr ParamSpec Alpha{"alpha", "Shift", F::Alpha, K::Shift, "design units", "largest shift, at the tine", AnyNumber, 60.0, 0.03};
constexpr ParamSpec Lambda = startingAt({"lambda", "Sharpness", F::Lambda, K::Length, "design units", "sharpness: smaller concentrates the shift near the tine", PositiveNumber, 12.0, 0.01}, 24.0);
constexpr ParamSpec Spacing{"spacing", "Spacing", F::Spacing, K::Length, "design units", "distance between tines", PositiveNumber, 80.0, 0.02};
constexpr ParamSpec Amplitude{"amplitude", "Amplitude", F::Amplitude, K::Shift, "design units", "largest shift of the wave", AnyNumber, 25.0, 0.02};
constexpr ParamSpec Wavelength = startingAt({"wavelength", "Wavelength", F::Wavelength, K::Length, "design units", "length of one period", PositiveNumber, 300.0, 0.05}, 250.0);
constexpr ParamSpec Phase{"phase", "Phase", F::Phase, K::Phase, "degrees", "phase of the wave", AnyNumber, 0.0, 45.0};
// In the order of WaveShape.
constexpr std::array<std::string_view, 2> WaveShapes{"eggcrate", "ripple"};
static_assert(WaveShapes.size() == static_cast<std::size_t>(WaveShape::Ripple) + 1);
constexpr ParamSpec Shape{"shape", "Shape", F::Shape, K::Choice, "", "shape of the wave", AnyNumber, 0.0, 0.0, false, WaveShapes};
constexpr ParamSpec AmplitudePair{"amplitude", "Amplitude", F::Amplitude, K::Shift, "design units", "largest shift of the wave", AnyNumber, 25.0, 0.02, true};
constexpr ParamSpec WavelengthPair = startingAt({"wavelength", "Wavelength", F::Wavelength, K::Length, "design units", "length of one period", PositiveNumber, 300.0, 0.05, true}, 250.0);
constexpr ParamSpec PhasePair{"phase", "Phase", F::Phase, K::Phase, "degrees", "phase of the wave", AnyNumber, 0.0, 45.0, true};

// Version 2.
constexpr ParamSpec Core{"core", "Core", F::Core, K::Length, "design units", "finite centre: 0 winds without end, larger keeps the swirl's eye clean", NonNegativeNumber, 0.0, 0.01, false, {}, 2, true};
constexpr ParamSpec Teeth{"teeth", "Teeth", F::Teeth, K::Teeth, "design units", "tooth positions along the normal, from the origin, increasing", AnyNumber, 0.0, 0.01, false, {}, 2};
constexpr ParamSpec ShiftRow{"shift", "Shift", F::Shift, K::Shift, "design units", "largest shift, midway between two teeth; its sign is the direction", AnyNumber, 40.0, 0.03, false, {}, 2};
constexpr ParamSpec Power = startingAt({"power", "Profile", F::Power, K::Number, "", "tooth profile |sin|^p: small is blunt, large is pointed", PositiveNumber, 0.5, 0.15, false, {}, 2}, 2.0);
// In the order of FlowField.
constexpr std::array<std::string_view, 2> FlowFields{"cells", "cavity"};
static_assert(FlowFields.size() == static_cast<std::size_t>(FlowField::Cavity) + 1);
constexpr ParamSpec FieldRow{"field", "Field", F::Field, K::Choice, "", "the velocity field: a lattice of cells or one cavity", AnyNumber, 0.0, 0.0, false, FlowFields, 2};
constexpr ParamSpec SizeRow{"size", "Size", F::Size, K::Extent, "design units", "size of a cell (cells) or of the box (cavity)", PositiveNumber, 250.0, 0.05, false, {}, 2};
constexpr ParamSpec Speed = startingAt({"speed", "Speed", F::Speed, K::Number, "design units per time unit", "speed of the flow; its sign is the sense of turning", AnyNumber, 40.0, 10.0, false, {}, 2}, 200.0);
constexpr ParamSpec Time = startingAt({"time", "Time", F::Time, K::Number, "time units", "how long the flow runs", PositiveNumber, 2.0, 0.3, false, {}, 2}, 1.0);
constexpr ParamSpec Steps{"steps", "Steps", F::Steps, K::Count, "", "implicit midpoint steps (at least 32 |speed| time max(size) / min(size)^2)", ParamRange{1.0, double(MaxFlowSteps)}, 32.0, 0.0, false, {}, 2};

// Version 3.
constexpr ParamSpec PathRow{"path", "Path", F::Path, K::Path, "design units", "the polyline the stylus is drawn along", AnyNumber, 0.0, 0.02, false, {}, 3};
constexpr ParamSpec Pull{"alpha", "Pull", F::Alpha, K::Shift, "design units", "strength of the pull along the path, about the shift on the track", AnyNumber, 40.0, 0.03, false, {}, 3};
constexpr ParamSpec StylusLambda{"lambda", "Sharpness", F::Lambda, K::Length, "design units", "how far to the side the pull reaches", PositiveNumber, 8.0, 0.01, false, {}, 3};
constexpr ParamSpec Reach{"reach", "Reach", F::Reach, K::Length, "design units", "how far ahead of and behind the stylus the bath moves", PositiveNumber, 40.0, 0.02, false, {}, 3};
constexpr ParamSpec Tines{"tines", "Tines", F::Tines, K::Count, "", "1 a stylus, more a rake", ParamRange{1.0, double(MaxTines)}, 1.0, 0.0, false, {}, 3, true};
constexpr ParamSpec RakeSpacing{"spacing", "Spacing", F::Spacing, K::Length, "design units", "distance between the rake's tines (required with more than one)", PositiveNumber, 40.0, 0.02, false, {}, 3, true};
constexpr ParamSpec Pressure{"pressure", "Pressure", F::Pressure, K::Pressure, "", "a pen's pressure, one value in [0, 1] per path point", ParamRange{0.0, 1.0}, 1.0, 0.0, false, {}, 3, true};
constexpr ParamSpec StylusSteps{"steps", "Steps", F::Steps, K::Count, "", "integration steps (at least 4 L / reach and the contraction rule)", ParamRange{1.0, double(MaxStylusSteps)}, 1.0, 0.0, false, {}, 3};

constexpr std::array Ink{Center, Radius, ColorRow};
constexpr std::array Cylinder3{Center, Axis, Radius, ColorRow};
constexpr std::array Line2{Origin, Angle, Alpha, Lambda};
constexpr std::array Line3{Origin, Direction, Normal, Alpha, Lambda};
constexpr std::array Comb2{Origin, Angle, Alpha, Lambda, Spacing};
constexpr std::array Comb3{Origin, Direction, Normal, Alpha, Lambda, Spacing};
constexpr std::array Wave2{Origin, Angle, Amplitude, Wavelength, Phase};
constexpr std::array Wave3{Origin, Direction, Normal, Shape, AmplitudePair, WavelengthPair, PhasePair};
constexpr std::array Circle2{Center, Radius, Alpha, Lambda, Core};
constexpr std::array Circle3{Center, Axis, Radius, Alpha, Lambda, Core};
constexpr std::array Vortex2{Center, Alpha, Lambda, Core};
constexpr std::array Vortex3{Center, Axis, Alpha, Lambda, Core};
constexpr std::array Stretch2{Origin, Angle, Teeth, ShiftRow, Power};
constexpr std::array Flow2{FieldRow, Origin, Angle, SizeRow, Speed, Time, Steps};
constexpr std::array Stylus2{PathRow, Pull, StylusLambda, Reach, Tines, RakeSpacing, Pressure, StylusSteps};

using SF = ShaderForm;

/// The registry, in the order of enum Tool. The editor's words stay as its tool bar has always
/// shown them; cylinder has no gesture (made in the step form only).
constexpr std::array<ToolSpec, ToolCount> Tools{{
    {.tool = Tool::Drop, .name = "drop", .plural = "drops", .in2D = true, .in3D = true, .laysInk = true, .movesInk = true,
     .form2D = SF::PushArea, .form3D = SF::PushVolume, .params2D = Ink, .params3D = Ink, .outline = StepOutline::Radius,
     .editor = {.gesture = G::Drop,
                .name = "Drop",
                .tooltip = "Click to drop ink of the current colour; drag to set its radius. A drop in a drop "
                           "pushes the older ink into a ring",
                .shortcut = 'D'}},
    {.tool = Tool::Spray, .name = "spray", .plural = "sprays", .in2D = true, .in3D = true, .laysInk = true, .movesInk = false,
     .form2D = SF::PushArea, .form3D = SF::PushArea, .params2D = Ink, .params3D = Ink, .outline = StepOutline::Radius,
     .editor = {.gesture = G::Spray,
                .name = "Spray",
                .tooltip = "Drag a brush that sprinkles small droplets along its path",
                .shortcut = 'S'}},
    {.tool = Tool::Cylinder, .name = "cylinder", .plural = "cylinders", .in2D = false, .in3D = true, .laysInk = true, .movesInk = true,
     .form2D = SF::PushArea, .form3D = SF::PushArea, .params2D = {}, .params3D = Cylinder3, .outline = StepOutline::Radius,
     .editor = {}}, // no gesture: made in the step form only
    {.tool = Tool::Line, .name = "line", .plural = "lines", .in2D = true, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::Shift, .form3D = SF::Shift, .params2D = Line2, .params3D = Line3,
     .editor = {.gesture = G::Stroke,
                .name = "Line",
                .tooltip = "Drag a stylus through the ink: the drag's direction and length",
                .shortcut = 'N'}},
    {.tool = Tool::Comb, .name = "comb", .plural = "combs", .in2D = true, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::Shift, .form3D = SF::Shift, .params2D = Comb2, .params3D = Comb3,
     .editor = {.gesture = G::Stroke,
                .name = "Comb",
                .tooltip = "Drag a comb through the ink: the drag's direction and length",
                .shortcut = 'C'}},
    {.tool = Tool::Wave, .name = "wave", .plural = "waves", .in2D = true, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::WaveShift, .form3D = SF::WaveShift, .params2D = Wave2, .params3D = Wave3,
     .editor = {.gesture = G::Wave,
                .name = "Wave",
                .tooltip = "Drag a wavy comb: the drag gives its direction and amplitude",
                .shortcut = 'W'}},
    {.tool = Tool::Circle, .name = "circle", .plural = "circles", .in2D = true, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::Turn, .form3D = SF::Turn, .params2D = Circle2, .params3D = Circle3, .outline = StepOutline::Radius,
     .editor = {.gesture = G::Ring,
                .name = "Circle",
                .tooltip = "Drag from the centre: a circular stroke of that radius",
                .shortcut = 'O'}},
    {.tool = Tool::Sphere, .name = "sphere", .plural = "spheres", .in2D = false, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::Turn, .form3D = SF::Turn, .params2D = {}, .params3D = Circle3, .outline = StepOutline::Radius,
     .editor = {.gesture = G::Ring,
                .name = "Sphere",
                .tooltip = "Drag from the centre on the section: a tine moved round a sphere of that "
                           "radius, turning about the panel's axis",
                .shortcut = 'H'}},
    {.tool = Tool::Vortex, .name = "vortex", .plural = "vortices", .in2D = true, .in3D = true, .laysInk = false, .movesInk = true,
     .form2D = SF::Turn, .form3D = SF::Turn, .params2D = Vortex2, .params3D = Vortex3, .outline = StepOutline::Alpha,
     .editor = {.gesture = G::Swirl,
                .name = "Vortex",
                .tooltip = "Drag from the centre: a swirl, the drag's length its strength",
                .shortcut = 'V'}},
    {.tool = Tool::Stretch, .name = "stretch", .plural = "stretches", .in2D = true, .in3D = false, .laysInk = false, .movesInk = true,
     .form2D = SF::Stretch, .form3D = SF::Stretch, .params2D = Stretch2, .params3D = {}, .version = 2,
     .editor = {.gesture = G::Teeth,
                .name = "Stretch",
                .tooltip = "Drag to stretch the ink between teeth across the design",
                .shortcut = 'T'}},
    {.tool = Tool::Flow, .name = "flow", .plural = "flows", .in2D = true, .in3D = false, .laysInk = false, .movesInk = true,
     .form2D = SF::Flow, .form3D = SF::Flow, .params2D = Flow2, .params3D = {}, .outline = StepOutline::Extent, .version = 2,
     .editor = {.gesture = G::Cell,
                .name = "Flow",
                .tooltip = "Drag out a cell of a steady flow (cells or one cavity)",
                .shortcut = 'F'}},
    {.tool = Tool::Stylus, .name = "stylus", .plural = "stylus strokes", .in2D = true, .in3D = false, .laysInk = false, .movesInk = true,
     .form2D = SF::Stylus, .form3D = SF::Stylus, .params2D = Stylus2, .params3D = {}, .version = 3,
     .editor = {.gesture = G::Path,
                .name = "Stylus",
                .tooltip = "Draw a free-hand stroke: a stylus (or a rake) pulled along the path",
                .shortcut = 'Y'}},
}};
// clang-format on

/// A tool on the editor's tool bar has a name, a tooltip and a key; one without a gesture has none.
constexpr bool editorRowsComplete() {
    for (const ToolSpec& tool : Tools) {
        const bool offered = tool.editor.gesture != G::None;
        if (offered != !tool.editor.name.empty() || offered != !tool.editor.tooltip.empty() ||
            offered != (tool.editor.shortcut >= 'A' && tool.editor.shortcut <= 'Z'))
            return false;
    }
    return true;
}
static_assert(editorRowsComplete(),
              "an editor gesture comes with a name, a tooltip and a capital-letter shortcut");

constexpr bool inEnumOrder() {
    for (std::size_t i = 0; i < Tools.size(); ++i)
        if (Tools[i].tool != static_cast<Tool>(i) || Tools[i].name.empty()) return false;
    return true;
}
static_assert(inEnumOrder(), "the registry holds every tool once, in the order of enum Tool");

/// Only choice parameters have choices, and every choice parameter has some.
constexpr bool choicesWhereChosen() {
    for (const ToolSpec& tool : Tools)
        for (std::span<const ParamSpec> params : {tool.params2D, tool.params3D})
            for (const ParamSpec& spec : params)
                if ((spec.kind == K::Choice) != !spec.choices.empty()) return false;
    return true;
}
static_assert(choicesWhereChosen(), "a Choice parameter lists its choices, no other parameter has any");

/// Every parameter has a word for the editor to show.
constexpr bool everyParamLabelled() {
    for (const ToolSpec& tool : Tools)
        for (std::span<const ParamSpec> params : {tool.params2D, tool.params3D})
            for (const ParamSpec& spec : params)
                if (spec.label.empty()) return false;
    return true;
}
static_assert(everyParamLabelled(), "every parameter has a label");

constexpr bool everyToolHasAPlural() {
    for (const ToolSpec& spec : Tools)
        if (spec.plural.empty()) return false;
    return true;
}
static_assert(everyToolHasAPlural(), "every tool has its English plural");

/// The parameters newer than their tool are optional: a newer parameter may be left out of an
/// older tool. Before version 3 exactly those were; a version-3 tool (stylus) also has optional
/// parameters of its own (tines, spacing, pressure), to which the spec gives defaults.
constexpr bool versionsConsistent() {
    for (const ToolSpec& tool : Tools)
        for (std::span<const ParamSpec> params : {tool.params2D, tool.params3D})
            for (const ParamSpec& spec : params) {
                if (spec.version > tool.version && !spec.optional) return false;
                if (tool.version < 3 && spec.optional != (spec.version > tool.version)) return false;
                if (spec.version > FormatVersion) return false;
            }
    return true;
}
static_assert(versionsConsistent(), "optional parameters are those newer than their tool (and, from "
                                    "version 3, those the spec gives a default)");

glm::dvec3* vectorField(const ParamSpec& spec, Operation& op) {
    switch (spec.field) {
    case F::Center:
        return &op.center;
    case F::Axis:
        return &op.axis;
    case F::Direction:
        return &op.direction;
    case F::Normal:
        return &op.normal;
    case F::Angle:
    case F::Radius:
    case F::Alpha:
    case F::Lambda:
    case F::Spacing:
    case F::Amplitude:
    case F::Wavelength:
    case F::Phase:
    case F::Shape:
    case F::Color:
    case F::Core:
    case F::Teeth:
    case F::Shift:
    case F::Power:
    case F::Field:
    case F::Size:
    case F::Speed:
    case F::Time:
    case F::Steps:
    case F::Path:
    case F::Reach:
    case F::Tines:
    case F::Pressure:
        return nullptr;
    }
    return nullptr;
}

glm::dvec2* pairField(const ParamSpec& spec, Operation& op) {
    switch (spec.field) {
    case F::Amplitude:
        return &op.amplitude;
    case F::Wavelength:
        return &op.wavelength;
    case F::Phase:
        return &op.phase;
    case F::Center:
    case F::Axis:
    case F::Direction:
    case F::Normal:
    case F::Angle:
    case F::Radius:
    case F::Alpha:
    case F::Lambda:
    case F::Spacing:
    case F::Shape:
    case F::Color:
    case F::Core:
    case F::Teeth:
    case F::Shift:
    case F::Power:
    case F::Field:
    case F::Size:
    case F::Speed:
    case F::Time:
    case F::Steps:
    case F::Path:
    case F::Reach:
    case F::Tines:
    case F::Pressure:
        return nullptr;
    }
    return nullptr;
}

double* scalarField(const ParamSpec& spec, Operation& op) {
    switch (spec.field) {
    case F::Core:
        return &op.core;
    case F::Shift:
        return &op.shift;
    case F::Power:
        return &op.power;
    case F::Speed:
        return &op.speed;
    case F::Time:
        return &op.time;
    case F::Reach:
        return &op.reach;
    case F::Angle:
        return &op.angle;
    case F::Radius:
        return &op.radius;
    case F::Alpha:
        return &op.alpha;
    case F::Lambda:
        return &op.lambda;
    case F::Spacing:
        return &op.spacing;
    case F::Amplitude:
        return &op.amplitude[0];
    case F::Wavelength:
        return &op.wavelength[0];
    case F::Phase:
        return &op.phase[0];
    case F::Center:
    case F::Axis:
    case F::Direction:
    case F::Normal:
    case F::Shape:
    case F::Color:
    case F::Teeth:
    case F::Field:
    case F::Size:
    case F::Steps:
    case F::Path:
    case F::Tines:
    case F::Pressure:
        return nullptr;
    }
    return nullptr;
}

} // namespace

std::string ParamRange::describe() const {
    auto number = [](double v) {
        std::string text = std::to_string(v);
        text.erase(text.find_last_not_of('0') + 1);
        if (!text.empty() && text.back() == '.') text.pop_back();
        return text;
    };
    bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
    if (hasMin && hasMax)
        return "must be in " + std::string(minOpen ? "(" : "[") + number(min) + ", " + number(max) + "]";
    if (hasMin) return std::string("must be ") + (minOpen ? "> " : ">= ") + number(min);
    if (hasMax) return "must be <= " + number(max);
    return "must be finite";
}

const ToolSpec& toolSpec(Tool tool) {
    return Tools[static_cast<std::size_t>(tool)];
}

std::span<const ToolSpec> allTools() {
    return Tools;
}

const ToolSpec* findTool(std::string_view name) {
    for (const ToolSpec& spec : Tools)
        if (spec.name == name) return &spec;
    return nullptr;
}

const ParamSpec* findParam(Tool tool, ParamField field) {
    const ToolSpec& spec = toolSpec(tool);
    for (std::span<const ParamSpec> params : {spec.params2D, spec.params3D})
        for (const ParamSpec& p : params)
            if (p.field == field) return &p;
    return nullptr;
}

double editorStart(Tool tool, ParamField field) {
    const ParamSpec* spec = findParam(tool, field);
    assert(spec && "the tool has a parameter in that field");
    return spec ? spec->editorValue() : 0.0;
}

bool allowedInInitial(Tool tool, int dimension) {
    const ToolSpec& spec = toolSpec(tool);
    return spec.laysInk && spec.available(dimension);
}

std::string initialToolsText() {
    std::string both, only3D;
    for (const ToolSpec& spec : Tools) {
        if (!spec.laysInk) continue;
        std::string& list = spec.in2D ? both : only3D;
        list += (list.empty() ? "" : ", ") + std::string(spec.name);
    }
    if (only3D.empty()) return both;
    if (both.empty()) return "in 3D, " + only3D;
    // "drop, spray and, in 3D, cylinder": the last tool of both dimensions loses its comma.
    return both + " and, in 3D, " + only3D;
}

int ParamSpec::choiceIndex(std::string_view value) const {
    for (std::size_t i = 0; i < choices.size(); ++i)
        if (choices[i] == value) return static_cast<int>(i);
    return -1;
}

std::string ParamSpec::describeChoices() const {
    std::string text = "must be ";
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (i > 0) text += i + 1 == choices.size() ? " or " : ", ";
        text += "\"" + std::string(choices[i]) + "\"";
    }
    return text;
}

int componentCount(const ParamSpec& spec, const Operation& op, int dimension) {
    if (spec.kind == K::Position || spec.kind == K::Direction) return dimension;
    if (spec.kind == K::Extent) return 2;
    if (spec.kind == K::Teeth) return static_cast<int>(op.teeth.size());
    if (spec.kind == K::Path) return 2 * static_cast<int>(op.path.size());
    if (spec.kind == K::Pressure) return static_cast<int>(op.path.size());
    if (spec.pair) return op.shape == WaveShape::Eggcrate ? 2 : 1;
    return 1;
}

double getComponent(const ParamSpec& spec, const Operation& op, int index) {
    auto& mutableOp = const_cast<Operation&>(op); // the field lookups do not write
    if (glm::dvec3* v = vectorField(spec, mutableOp)) return (*v)[index];
    if (spec.pair) return (*pairField(spec, mutableOp))[index];
    if (spec.kind == K::Color) return op.color;
    if (spec.kind == K::Choice)
        return spec.field == F::Field ? static_cast<double>(op.field) : static_cast<double>(op.shape);
    if (spec.kind == K::Extent) return op.extent[index];
    if (spec.kind == K::Teeth) return op.teeth[static_cast<std::size_t>(index)];
    if (spec.kind == K::Count) return spec.field == F::Tines ? op.tines : op.steps;
    if (spec.kind == K::Path) return op.path[static_cast<std::size_t>(index / 2)][index % 2];
    if (spec.kind == K::Pressure) {
        auto at = static_cast<std::size_t>(index);
        return at < op.pressure.size() ? op.pressure[at] : spec.defaultValue;
    }
    return *scalarField(spec, mutableOp);
}

void setComponent(const ParamSpec& spec, Operation& op, int index, double value) {
    if (glm::dvec3* v = vectorField(spec, op)) {
        (*v)[index] = value;
    } else if (spec.pair) {
        (*pairField(spec, op))[index] = value;
    } else if (spec.kind == K::Color) {
        op.color = static_cast<int>(value);
    } else if (spec.kind == K::Choice) {
        // The nearest choice: an index within the table's list.
        double last = static_cast<double>(spec.choices.size()) - 1.0;
        int index = static_cast<int>(std::clamp(std::round(value), 0.0, std::max(0.0, last)));
        if (spec.field == F::Field)
            op.field = static_cast<FlowField>(index);
        else
            op.shape = static_cast<WaveShape>(index);
    } else if (spec.kind == K::Extent) {
        op.extent[index] = value;
    } else if (spec.kind == K::Teeth) {
        auto at = static_cast<std::size_t>(index);
        if (at >= op.teeth.size()) op.teeth.resize(at + 1, value);
        op.teeth[at] = value;
    } else if (spec.kind == K::Count) {
        // Clamped before the cast so that no value can overflow an int.
        (spec.field == F::Tines ? op.tines : op.steps) =
            static_cast<int>(std::clamp(std::round(value), spec.range.min, spec.range.max));
    } else if (spec.kind == K::Path) {
        auto at = static_cast<std::size_t>(index / 2);
        if (at >= op.path.size()) op.path.resize(at + 1, glm::dvec2(value));
        op.path[at][index % 2] = value;
    } else if (spec.kind == K::Pressure) {
        // Pressure is all the default until a value is set; then it holds one per path point.
        auto at = static_cast<std::size_t>(index);
        if (op.pressure.size() < std::max(op.path.size(), at + 1))
            op.pressure.resize(std::max(op.path.size(), at + 1), spec.defaultValue);
        op.pressure[at] = value;
    } else {
        *scalarField(spec, op) = value;
    }
}

Operation defaultOperation(Tool tool, int dimension, const glm::dvec3& center) {
    Operation op;
    op.tool = tool;
    op.center = dimension == 3 ? center : glm::dvec3(center.x, center.y, 0.0);
    for (const ParamSpec& spec : toolSpec(tool).params(dimension)) {
        if (spec.kind == K::Position || spec.kind == K::Direction || spec.kind == K::Choice ||
            spec.kind == K::Teeth || spec.kind == K::Path || spec.kind == K::Pressure)
            continue;
        for (int i = 0; i < componentCount(spec, op, dimension); ++i)
            setComponent(spec, op, i, spec.defaultValue);
    }
    if (tool == Tool::Stretch) {
        // Ten equal intervals across a square of twice the larger half-side about the centre,
        // so the teeth cover the design at any angle.
        double half = std::max({std::abs(center.x), std::abs(center.y), 1.0}) * std::numbers::sqrt2;
        for (int i = 0; i <= 10; ++i)
            op.teeth.push_back(-half + 2.0 * half * i / 10.0);
    }
    if (tool == Tool::Flow) {
        // The cells' lattice starts at the design's corner, so the default flow is symmetric.
        op.center = {0.0, 0.0, 0.0};
        op.steps = std::max(op.steps, minimumFlowSteps(op));
    }
    if (tool == Tool::Stylus) {
        // A straight stroke through the centre, two fifths of its larger coordinate long.
        double half = std::max({std::abs(center.x), std::abs(center.y), 1.0}) * 0.2;
        op.path = {{center.x - half, center.y}, {center.x + half, center.y}};
        // Steps enough for a rake of two: the step form can add a tine without more steps.
        Operation rake = op;
        rake.tines = 2;
        op.steps = std::max(op.steps, minimumStylusSteps(rake));
    }
    return op;
}

double pathLength(const Operation& op) {
    double length = 0.0;
    for (std::size_t i = 1; i < op.path.size(); ++i)
        length += glm::length(op.path[i] - op.path[i - 1]);
    return length;
}

int minimumStylusSteps(const Operation& op) {
    double largest = op.pressure.empty() ? 1.0 : 0.0;
    for (double p : op.pressure)
        largest = std::max(largest, p);
    const double length = pathLength(op), l = op.reach, lambda = op.lambda;
    const double cMax = 15.0 * std::abs(op.alpha) * largest / (16.0 * l);
    const double needed = std::max(4.0 * length / l, 2.0 * length * op.tines * cMax *
                                                         (3.1 / l + 0.65 / lambda + 6.3 * lambda / (l * l)));
    if (!std::isfinite(needed) || needed > double(MaxStylusSteps)) return MaxStylusSteps + 1;
    return std::max(1, static_cast<int>(std::ceil(needed)));
}

int minimumFlowSteps(const Operation& op) {
    double smaller = std::min(op.extent.x, op.extent.y), larger = std::max(op.extent.x, op.extent.y);
    double needed = 32.0 * std::abs(op.speed) * op.time * larger / (smaller * smaller);
    if (!std::isfinite(needed) || needed > double(MaxFlowSteps)) return MaxFlowSteps + 1;
    return std::max(1, static_cast<int>(std::ceil(needed)));
}

bool usesVersion2(const ParamSpec& spec, const Operation& op) {
    if (spec.version < 2) return false;
    if (!spec.optional) return true;
    return writtenWhenOptional(spec, op);
}

bool writtenWhenOptional(const ParamSpec& spec, const Operation& op) {
    if (spec.kind == K::Pressure)
        return std::any_of(op.pressure.begin(), op.pressure.end(),
                           [&](double p) { return p != spec.defaultValue; });
    // A rake says its spacing (the spec requires it with more than one tine).
    if (spec.field == F::Spacing && op.tines > 1) return true;
    return getComponent(spec, op, 0) != spec.defaultValue;
}

int requiredVersion(const Genome& genome) {
    int version = genome.bleed != 0.0 ? 2 : 1;
    if (genome.wrap) version = 3; // a wrapping bath (docs/genome-format.md)
    for (const std::vector<Operation>* list : {&genome.initial, &genome.operations})
        for (const Operation& op : *list) {
            const ToolSpec& tool = toolSpec(op.tool);
            version = std::max(version, tool.version);
            for (const ParamSpec& spec : tool.params(genome.dimension))
                if (usesVersion2(spec, op)) version = std::max(version, spec.version);
        }
    return version;
}

} // namespace marbler

#pragma once
/// The registry of tools: one entry per tool (its name, the dimensions it exists in, whether it
/// lays ink, the shader form it is packed into, its parameters with kind, unit, range, default,
/// mutation scale and enumerated choices, and how the editor offers it: gesture, name, tooltip,
/// shortcut, the tool panel's starting values). The loader and validator, the saver, the random
/// generator, the genetic operators, the scalar maps, the vector kernel, the shader packing and
/// the editor read it; the tests iterate it, so a tool added here without its maps, kernel,
/// shader, conformance cases or editor gesture fails the build or the tests.

#include "marbler/Genome.h"

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace marbler {

/// What kind of value a parameter holds; decides its JSON form and how it is mutated.
enum class ParamKind : std::uint8_t {
    Position,  ///< a point of the design space (`dimension` numbers)
    Direction, ///< a non-zero vector (`dimension` numbers, 3D only), normalised on load
    Angle,     ///< degrees
    Length,    ///< design units, > 0 where the range says so
    Shift,     ///< signed design units (alpha, amplitude)
    Phase,     ///< degrees, any value
    Color,     ///< integer index into the palette
    Choice,    ///< one of the spec's `choices` (a 3D wave's shape, a flow's field), held as its index
    Extent,    ///< two lengths [x, y] (a flow's `size`), each in `range`
    Teeth,     ///< 2 to MaxTeeth strictly increasing positions (a stretch's `teeth`)
    Count,     ///< an integer in `range` (a flow's `steps`)
    Number,    ///< a plain number in its own unit (power, speed, time); mutated by absolute steps
    Path,      ///< 2 to MaxPathPoints points [[x, y], ...], consecutive ones different (a stylus's path)
    Pressure,  ///< one number in `range` per path point (a stylus's pressure); empty: all the default
};

/// Which field of Operation a parameter lives in.
enum class ParamField : std::uint8_t {
    Center,
    Axis,
    Direction,
    Normal,
    Angle,
    Radius,
    Alpha,
    Lambda,
    Spacing,
    Amplitude,
    Wavelength,
    Phase,
    Shape,
    Color,
    Core,
    Teeth,
    Shift,
    Power,
    Field,
    Size,
    Speed,
    Time,
    Steps, // version 2
    Path,
    Reach,
    Tines,
    Pressure, // version 3
};

/// The values a parameter may take: [min, max], or (min, max] where `minOpen`.
struct ParamRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minOpen = false;

    bool contains(double v) const { return (minOpen ? v > min : v >= min) && v <= max; }
    /// What the validator says when a value is outside, e.g. "must be > 0".
    std::string describe() const;
};

/// Any finite number.
inline constexpr ParamRange AnyNumber{};
/// Strictly positive numbers (radius, lambda, spacing, wavelength).
inline constexpr ParamRange PositiveNumber{0.0, std::numeric_limits<double>::infinity(), true};
/// Numbers >= 0 (a swirl's core, the bleed).
inline constexpr ParamRange NonNegativeNumber{0.0, std::numeric_limits<double>::infinity(), false};

/// One row of a tool's parameter table.
struct ParamSpec {
    std::string_view key; ///< JSON key
    /// The word the editor shows for it, in its parameter form and its tool panel alike ("Shift"
    /// for a stroke's alpha): one vocabulary, read from here by both.
    std::string_view label;
    ParamField field;
    ParamKind kind;
    std::string_view unit; ///< shown by the editor
    std::string_view help; ///< one line, for tooltips and --help
    ParamRange range;      ///< the values the validator accepts (every number must also be finite)
    double defaultValue;   ///< scalars; positions default to the design's centre
    /// How far a mutation of strength 1 moves the value: for positions, lengths and shifts a
    /// fraction of the design's largest side; for angles and phases, degrees.
    double mutationScale;
    bool positive() const { return range.minOpen && range.min == 0.0; }
    /// True for a 3D wave's per-axis pairs: two numbers for an egg-crate, one for a ripple.
    bool pair = false;
    /// A Choice's JSON values, in the order of the enum they stand for.
    std::span<const std::string_view> choices = {};
    /// The format version that introduced the parameter (a file of an older version may not use it).
    int version = 1;
    /// May be left out of a file (then it has `defaultValue`); written only when it differs.
    bool optional = false;
    /// The value the editor's tool panel starts with, where it differs on purpose from
    /// `defaultValue` (a drawn stroke starts broader, a dragged flow faster); none: the default.
    std::optional<double> editorDefault = {};

    /// What the editor's tool panel starts with: `editorDefault`, else `defaultValue`.
    constexpr double editorValue() const { return editorDefault.value_or(defaultValue); }

    /// The index of `value` among the choices; -1 when it is none of them.
    int choiceIndex(std::string_view value) const;
    /// What the validator says when a choice is none of them, e.g. `must be "eggcrate" or "ripple"`.
    std::string describeChoices() const;
};

/// The shared forms of the branch-free shader body (shaders/tools.glsl), numbered as its
/// classes: the GL back end packs each tool into the coefficients of its form.
enum class ShaderForm : std::uint8_t {
    PushArea = 0,   ///< radial push by the area law, from a centre or across an axis
    PushVolume = 1, ///< radial push by the volume law (3D drop)
    Shift = 2,      ///< translation by the distance-dependent shift (line, comb)
    WaveShift = 3,  ///< translation by a wave's shift
    Turn = 4,       ///< turn about a centre or an axis (circle, sphere, vortex)
    Stretch = 5,    ///< translation by a |sin|^p profile between teeth (stretch)
    Flow = 6,       ///< implicit midpoint steps through a stream function's velocity (flow)
    /// Implicit midpoint steps through the velocity of a moving stylus along its path (stylus)
    Stylus = 7,
};

/// What a click or a drag on the editor's canvas makes of a tool. The registry names each
/// tool's kind; the editor (app/editor/Gestures.cpp) holds each kind's geometry once, so a new
/// tool of a known kind needs nothing in the editor's code.
enum class EditorGesture : std::uint8_t {
    None,   ///< not on the editor's tool bar: its steps are made in the step form only
    Drop,   ///< ink at the press, the drag's length its radius (a click: the panel's)
    Spray,  ///< droplets of the panel's size strewn within a brush of the drag
    Stroke, ///< a stroke along the drag, its length the largest shift (line, comb)
    Wave,   ///< a wavy stroke along the drag, its length the amplitude
    Ring,   ///< a turn about the press, the drag's length its radius (circle)
    Swirl,  ///< a swirl about the press, the drag's length its strength (vortex)
    Teeth,  ///< a stretch along the drag between teeth across the design
    Cell,   ///< the drag spans one cell (or the cavity) of a steady flow
    Path,   ///< a free-hand path: the drag's smoothed polyline (stylus)
};

/// How the editor outlines a step of a tool on its canvas (while it is made or selected).
enum class StepOutline : std::uint8_t {
    None,   ///< a stroke across the whole design: its handles say enough
    Radius, ///< a circle of its radius about its centre
    Alpha,  ///< a circle of |alpha| about its centre (a vortex's reach)
    Extent, ///< the box of its extent from its origin (a flow's cell)
};

/// How the editor offers a tool: its gesture and its tool bar button's words and key.
struct EditorSpec {
    EditorGesture gesture = EditorGesture::None;
    std::string_view name;    ///< on its button and in menus ("Comb")
    std::string_view tooltip; ///< what a click or a drag does
    char shortcut = 0;        ///< its key on the tool bar, a capital letter
};

/// One entry of the registry.
struct ToolSpec {
    Tool tool;
    std::string_view name;   ///< as in JSON
    std::string_view plural; ///< in English, for what changed ("3 vortices added")
    bool in2D, in3D;
    /// Lays ink (drop, spray, cylinder): has a colour, is seen where a point lies in it, and is
    /// the only kind of tool `initial` holds.
    bool laysInk;
    bool movesInk; ///< everything but spray
    ShaderForm form2D, form3D;
    std::span<const ParamSpec> params2D;
    std::span<const ParamSpec> params3D;
    /// How the editor's canvas outlines one of its steps.
    StepOutline outline = StepOutline::None;
    /// The format version that introduced the tool.
    int version = 1;
    /// The editor's gesture, name, tooltip and shortcut.
    EditorSpec editor = {};

    std::span<const ParamSpec> params(int dimension) const { return dimension == 3 ? params3D : params2D; }
    bool available(int dimension) const { return dimension == 3 ? in3D : in2D; }
    ShaderForm form(int dimension) const { return dimension == 3 ? form3D : form2D; }
};

/// The entry of a tool.
const ToolSpec& toolSpec(Tool tool);
/// All tools, in enum order.
std::span<const ToolSpec> allTools();
/// The tool of a JSON name; nullptr when unknown.
const ToolSpec* findTool(std::string_view name);
/// The parameter of `tool` held in `field` (its 2D row, else its 3D one); nullptr when it has none.
const ParamSpec* findParam(Tool tool, ParamField field);
/// What the editor's tool panel starts with for the parameter of `tool` held in `field`
/// (ParamSpec::editorValue); the tool must have one.
double editorStart(Tool tool, ParamField field);
/// Whether a tool may appear in `initial`: the ink-laying tools of that dimension.
bool allowedInInitial(Tool tool, int dimension);
/// The tools `initial` may hold, for messages: "drop, spray and, in 3D, cylinder".
std::string initialToolsText();

/// Read or write the scalar components of a parameter. A Position/Direction has `dimension`
/// components, a pair 2 (egg-crate) or 1, an Extent 2, Teeth as many as the stretch has,
/// everything else 1. Setting tooth `index` past the end grows the list.
int componentCount(const ParamSpec& spec, const Operation& op, int dimension);
double getComponent(const ParamSpec& spec, const Operation& op, int index);
void setComponent(const ParamSpec& spec, Operation& op, int index, double value);

/// An operation of the given tool with every parameter at its default, placed at `center`
/// (a design's centre: a stretch's teeth then span the design whatever its angle).
Operation defaultOperation(Tool tool, int dimension, const glm::dvec3& center);

/// The fewest steps a flow may take: ceil(32 |U| T max(Lx, Ly) / min(Lx, Ly)^2), at least 1
/// (genome-format.md, flow), so that each step's fixed-point iteration contracts.
int minimumFlowSteps(const Operation& op);

/// The arc length L of a stylus's path.
double pathLength(const Operation& op);

/// The fewest steps a stylus may take (genome-format.md, stylus): the larger of 4 L / reach and
/// 2 L k c_max (3.1 / reach + 0.65 / lambda + 6.3 lambda / reach^2), c_max = 15 |alpha|
/// max(pressure) / (16 reach), rounded up, at least 1; MaxStylusSteps + 1 when more are needed.
int minimumStylusSteps(const Operation& op);

/// Whether a parameter holds a value a file of `version` 1 could not say: a version-2
/// parameter away from its default.
bool usesVersion2(const ParamSpec& spec, const Operation& op);

/// Whether an optional parameter is written: it is away from its default (a rake's spacing
/// whenever it has more than one tine).
bool writtenWhenOptional(const ParamSpec& spec, const Operation& op);

/// The lowest format version that holds the design: 3 when it uses a version-3 tool, 2 when it
/// uses a version-2 tool, parameter or `bleed`, else 1. Writers write this version.
int requiredVersion(const Genome& genome);

} // namespace marbler

#pragma once
/// The editor's tools as gestures: what a click or a drag on the canvas makes, as operations of
/// the genome. No widgets and no Qt: the canvas maps the mouse to design points and hands them
/// here, and tests check the steps alone.

#include "marbler/Genome.h"
#include "marbler/Params.h"
#include "marbler/Sampling.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marbler::ui {

/// The editor's own tools, what no genome tool is: the ink picker and the patterns of drops.
enum class EditorOnly : std::uint8_t { Pick, DropLine, DropRings, DropScatter };

/// A tool of the editor's tool bar: a registry tool (its gesture, name, tooltip and shortcut
/// come from its row in Params.h) or one of the editor's own. Converts from either.
class EditorTool {
public:
    constexpr EditorTool(Tool tool)
        : mRegistry(true)
        , mTool(tool) {}
    constexpr EditorTool(EditorOnly own)
        : mOwn(own) {}
    static const EditorTool Pick, DropLine, DropRings, DropScatter;

    /// Whether it is a registry tool (else one of the editor's own).
    constexpr bool inRegistry() const { return mRegistry; }
    /// The registry tool; only where inRegistry().
    constexpr Tool tool() const { return mTool; }
    /// The editor's own tool; only where !inRegistry().
    constexpr EditorOnly own() const { return mOwn; }
    /// A number for an action's data: the registry tools' indices, then the editor's own.
    constexpr int index() const { return mRegistry ? int(mTool) : ToolCount + int(mOwn); }
    friend constexpr bool operator==(EditorTool a, EditorTool b) { return a.index() == b.index(); }

private:
    bool mRegistry = false;
    Tool mTool = Tool::Drop;
    EditorOnly mOwn = EditorOnly::Pick;
};
inline constexpr EditorTool EditorTool::Pick{EditorOnly::Pick};
inline constexpr EditorTool EditorTool::DropLine{EditorOnly::DropLine};
inline constexpr EditorTool EditorTool::DropRings{EditorOnly::DropRings};
inline constexpr EditorTool EditorTool::DropScatter{EditorOnly::DropScatter};

/// The tool bar, in its order: Pick, every registry tool with a gesture (the drop patterns right
/// after the ink-laying ones). Whatever the dimension; see toolAvailable.
std::vector<EditorTool> editorTools();

/// What a drag does not set: the tool panel's values (ToolOptions.h). Those that are a genome
/// parameter start as the registry's row says (ParamSpec::editorValue); the rest are the
/// editor's own (spray, patterns, teeth, seed).
struct ToolSettings {
    int color = 0;                                               ///< palette index of the ink laid
    double radius = editorStart(Tool::Drop, ParamField::Radius); ///< a clicked drop's radius (a drag sets it)
    double alpha =
        editorStart(Tool::Circle, ParamField::Alpha); ///< a circle's largest shift (its turn along the rim)
    double spacing = editorStart(Tool::Comb, ParamField::Spacing);       ///< comb
    double lambda = editorStart(Tool::Line, ParamField::Lambda);         ///< line, comb, circle, vortex
    double wavelength = editorStart(Tool::Wave, ParamField::Wavelength); ///< wave
    double core = editorStart(Tool::Circle, ParamField::Core);           ///< circle, vortex
    double sprayRadius = 4;                                              ///< a sprayed droplet's radius
    int sprayCount = 40;                                                 ///< droplets a spray stroke lays
    double brush = 60;                                            ///< how far from the stroke droplets land
    int patternCount = 8;                                         ///< drops in a line, rings, scattered drops
    int teeth = 12;                                               ///< stretch: teeth across the design
    double power = editorStart(Tool::Stretch, ParamField::Power); ///< stretch: tooth profile
    double speed = editorStart(Tool::Flow, ParamField::Speed);    ///< flow
    double time = editorStart(Tool::Flow, ParamField::Time);      ///< flow
    int field = int(editorStart(Tool::Flow, ParamField::Field));  ///< flow: 0 cells, 1 cavity
    double pull = editorStart(Tool::Stylus, ParamField::Alpha);   ///< stylus: its pull (alpha)
    double stylusLambda = editorStart(Tool::Stylus, ParamField::Lambda); ///< stylus: how far to the side
    double reach = editorStart(Tool::Stylus, ParamField::Reach);         ///< stylus: ahead and behind
    int tines = int(editorStart(Tool::Stylus, ParamField::Tines));       ///< stylus: 1, or a rake's tines
    double rakeSpacing = editorStart(Tool::Stylus, ParamField::Spacing); ///< stylus: between a rake's tines
    std::uint64_t seed = 1; ///< spray and scatter positions (the same seed, the same drops)
    /// A solid's circle and sphere: the axis they turn about (any length but 0); none: across
    /// the section they are drawn on.
    std::optional<glm::dvec3> axis;
    friend bool operator==(const ToolSettings&, const ToolSettings&) = default;
};

/// The steps a drag from `press` to `release` makes (design coordinates; for a solid, points in
/// the volume on the section plane across `sliceAxis`). A click is press == release. Returns
/// empty when the gesture makes nothing (a stroke too short to have a direction, a tool of
/// another dimension, ink with no palette). Every step made is valid in `design`.
std::vector<Operation> gestureSteps(EditorTool tool, const ToolSettings& s, const glm::dvec3& press,
                                    const glm::dvec3& release, const Genome& design, int sliceAxis = 2);
/// The same on any section plane of a solid (SlicePlane of Sampling.h, turned or across an
/// axis): `press` and `release` lie on it, and the strokes lie in it.
std::vector<Operation> gestureSteps(EditorTool tool, const ToolSettings& s, const glm::dvec3& press,
                                    const glm::dvec3& release, const Genome& design, const SlicePlane& plane);
/// The unit axis a solid's circle or sphere drawn on `plane` turns about: the panel's, else the
/// plane's normal.
glm::dvec3 turnAxis(const ToolSettings& s, const SlicePlane& plane);

/// How far apart a drawn path's points are kept, in design units (at the least).
inline constexpr double PathPointSpacing = 4.0;

/// The points of a free-hand drag as a path: points closer than `spacing` to the last one
/// kept dropped, the drag's end kept, inner points smoothed, consecutive points different.
std::vector<glm::dvec2> smoothedPath(const std::vector<glm::dvec3>& points, double spacing);

/// The points of a free-hand drag with a pen's pressure at each (`pressure` one value a point,
/// or empty: all 1), as smoothedPath thins and smooths them; the pressure of each point kept
/// goes with it (smoothed alike). Returns the path; `keptPressure` gets one value a path point.
std::vector<glm::dvec2> smoothedPath(const std::vector<glm::dvec3>& points,
                                     const std::vector<double>& pressure, double spacing,
                                     std::vector<double>& keptPressure);

/// The step a free-hand drag through `points` makes with a path tool (stylus): its smoothed
/// polyline, the panel's pull, sharpness, reach, tines and spacing, the pen's `pressure` (one
/// value in [0, 1] a point; empty, or all 1, for a mouse: the field left out), the fewest valid
/// steps. Empty for another tool, a solid, a drag too short, or a stroke that would need more
/// steps than a stylus may take (pathRefusal says why).
std::vector<Operation> pathSteps(EditorTool tool, const ToolSettings& s,
                                 const std::vector<glm::dvec3>& points, const Genome& design,
                                 const std::vector<double>& pressure = {});

/// Why the drag through `points` makes no step with a path tool although it is long enough (a
/// stroke needing more than MaxStylusSteps integration steps), in words for the status bar;
/// empty when pathSteps makes its step or the drag is simply too short.
std::string pathRefusal(EditorTool tool, const ToolSettings& s, const std::vector<glm::dvec3>& points,
                        const Genome& design, const std::vector<double>& pressure = {});

/// Whether the tool works on designs of this dimension (stretch and flow are flat only) and has
/// a gesture there.
bool toolAvailable(EditorTool tool, int dimension);
/// The kind of its gesture (the registry's; the drop patterns lay drops; Pick: None).
EditorGesture gestureOf(EditorTool tool);
/// Whether the tool panel gives the value of the parameter in `field` for this tool's gesture
/// (the drag sets the others; the panel's editor-only rows are not parameters).
bool panelSets(EditorTool tool, ParamField field);
/// The genome tool the gesture makes (Pick: none; Drop for the drop patterns).
Tool genomeTool(EditorTool tool);
/// Whether the tool lays ink (its steps go to `initial`).
bool laysInk(EditorTool tool);
/// A short stable name, a registry tool's JSON name or "drop-line", for object names and settings.
std::string_view toolId(EditorTool tool);
/// A drag shorter than this (design units) gives a stroke no direction: it makes nothing.
inline constexpr double MinStrokeLength = 1.0;

/// `design` with `ops` appended as EditorDocument::addStep places them: ink-laying tools that
/// `initial` allows at its end, the others at the end of `operations`.
Genome withSteps(Genome design, const std::vector<Operation>& ops);

} // namespace marbler::ui

#pragma once
/// The editor's tools as gestures: what a click or a drag on the canvas makes, as operations of
/// the genome. No widgets and no Qt: the canvas maps the mouse to design points and hands them
/// here, and tests check the steps alone.

#include "marbler/Genome.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace marbler::ui {

/// The tools of the editor's tool bar, in its order.
enum class EditorTool { Pick, Drop, Spray, DropLine, DropRings, DropScatter, Line, Comb, Wave, Circle, Vortex, Stretch, Flow };

/// What a drag does not set: the tool panel's values (ToolOptions.h).
struct ToolSettings {
    int color = 0;          ///< palette index of the ink laid
    double radius = 60;     ///< a clicked drop's radius (a drag sets it)
    double alpha = 60;      ///< a circle's largest shift (its turn along the rim)
    double spacing = 80, lambda = 24, wavelength = 250, core = 0; ///< comb, line, wave, circle, vortex
    double sprayRadius = 4; ///< a sprayed droplet's radius
    int sprayCount = 40;    ///< droplets a spray stroke lays
    double brush = 60;      ///< how far from the stroke droplets land
    int patternCount = 8;   ///< drops in a line, rings, scattered drops
    int teeth = 12;         ///< stretch: teeth across the design
    double power = 2;       ///< stretch: tooth profile
    double speed = 200, time = 1; ///< flow
    int field = 0;          ///< flow: 0 cells, 1 cavity
    std::uint64_t seed = 1; ///< spray and scatter positions (the same seed, the same drops)
    friend bool operator==(const ToolSettings&, const ToolSettings&) = default;
};

/// The steps a drag from `press` to `release` makes (design coordinates; for a solid, points in
/// the volume on the section plane across `sliceAxis`). A click is press == release. Returns
/// empty when the gesture makes nothing (a stroke too short to have a direction, a tool of
/// another dimension, ink with no palette). Every step made is valid in `design`.
std::vector<Operation> gestureSteps(EditorTool tool, const ToolSettings& s, const glm::dvec3& press,
                                    const glm::dvec3& release, const Genome& design, int sliceAxis = 2);

/// Whether the tool works on designs of this dimension (stretch and flow are flat only).
bool toolAvailable(EditorTool tool, int dimension);
/// The genome tool the gesture makes (Pick: none; Drop for the drop patterns).
Tool genomeTool(EditorTool tool);
/// Whether the tool lays ink (its steps go to `initial`).
bool laysInk(EditorTool tool);
/// A short stable name, "drop-line", for object names and settings.
std::string_view toolId(EditorTool tool);
/// A drag shorter than this (design units) gives a stroke no direction: it makes nothing.
inline constexpr double MinStrokeLength = 1.0;

/// `design` with `ops` appended as EditorDocument::addStep places them: ink-laying tools that
/// `initial` allows at its end, the others at the end of `operations`.
Genome withSteps(Genome design, const std::vector<Operation>& ops);

} // namespace marbler::ui

#include "editor/Gestures.h"

#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/Sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marbler::ui {

namespace {

/// The palette index a tool lays: the panel's, kept inside the palette.
int inkIndex(const ToolSettings& s, const Genome& design) {
    return std::clamp(s.color, 0, int(design.palette.size()) - 1);
}

Operation inkDrop(Tool tool, const glm::dvec3& centre, double radius, int color, const Genome& design) {
    Operation op = defaultOperation(tool, design.dimension, centre);
    op.radius = std::max(radius, 1e-3);
    op.color = color;
    return op;
}

/// The 2D angle of a drag, degrees clockwise on screen (design y grows downward).
double dragAngle(const glm::dvec3& d) {
    return std::atan2(d.y, d.x) * 180.0 / std::numbers::pi;
}

/// A solid's stroke in the section plane: `along` the drag, `across` it (both unit, in the plane,
/// across = plane normal x along, as a 2D angle's N is to its M).
struct SectionStroke {
    glm::dvec3 along, across;
};
SectionStroke sectionStroke(const glm::dvec3& d, const SlicePlane& plane) {
    const glm::dvec3 n = plane.normal();
    const glm::dvec3 along = glm::normalize(d - glm::dot(d, n) * n);
    return {along, glm::normalize(glm::cross(n, along))};
}

/// Sets a line's or comb's direction: the 2D angle, or in 3D the motion along the drag and the
/// `normal` (the tine's distance is measured along it) across the drag in the section plane. A
/// normal along the plane's axis would give every point of the section one distance to the
/// tine: the section would slide rigidly and nothing would be combed.
void setStrokeDirection(Operation& op, const glm::dvec3& d, const Genome& design, const SlicePlane& plane) {
    if (design.dimension == 3) {
        const SectionStroke stroke = sectionStroke(d, plane);
        op.direction = stroke.along;
        op.normal = stroke.across;
    } else {
        op.angle = dragAngle(d);
    }
}

} // namespace

std::vector<EditorTool> editorTools() {
    std::vector<EditorTool> tools{EditorTool::Pick};
    bool patterns = false;
    for (const ToolSpec& spec : allTools()) {
        if (spec.editor.gesture == EditorGesture::None) continue;
        if (!spec.laysInk && !patterns) {
            tools.insert(tools.end(), {EditorTool::DropLine, EditorTool::DropRings, EditorTool::DropScatter});
            patterns = true;
        }
        tools.push_back(spec.tool);
    }
    if (!patterns)
        tools.insert(tools.end(), {EditorTool::DropLine, EditorTool::DropRings, EditorTool::DropScatter});
    return tools;
}

Tool genomeTool(EditorTool tool) {
    return tool.inRegistry() ? tool.tool() : Tool::Drop;
}

bool laysInk(EditorTool tool) {
    return tool != EditorTool::Pick && toolSpec(genomeTool(tool)).laysInk;
}

EditorGesture gestureOf(EditorTool tool) {
    if (tool.inRegistry()) return toolSpec(tool.tool()).editor.gesture;
    switch (tool.own()) {
    case EditorOnly::Pick:
        return EditorGesture::None;
    case EditorOnly::DropLine:
    case EditorOnly::DropRings:
    case EditorOnly::DropScatter:
        return EditorGesture::Drop;
    }
    return EditorGesture::None;
}

bool toolAvailable(EditorTool tool, int dimension) {
    if (tool == EditorTool::Pick) return true;
    return gestureOf(tool) != EditorGesture::None && toolSpec(genomeTool(tool)).available(dimension);
}

bool panelSets(EditorTool tool, ParamField field) {
    if (!findParam(genomeTool(tool), field)) return false;
    using F = ParamField;
    switch (gestureOf(tool)) {
    case EditorGesture::None:
        return false;
    case EditorGesture::Drop:
        return field == F::Radius; // a click's radius
    case EditorGesture::Spray:
        return false; // the spray's own rows
    case EditorGesture::Stroke:
        return field == F::Lambda || field == F::Spacing;
    case EditorGesture::Wave:
        return field == F::Wavelength;
    case EditorGesture::Ring:
    case EditorGesture::Swirl:
        return field == F::Alpha || field == F::Lambda || field == F::Core;
    case EditorGesture::Teeth:
        return field == F::Power;
    case EditorGesture::Cell:
        return field == F::Field || field == F::Speed || field == F::Time;
    case EditorGesture::Path:
        // The drag draws the path (and a pen gives its pressure); the steps follow from the rest.
        return field == F::Alpha || field == F::Lambda || field == F::Reach || field == F::Tines ||
               field == F::Spacing;
    }
    return false;
}

std::string_view toolId(EditorTool tool) {
    if (tool.inRegistry()) return toolSpec(tool.tool()).name;
    switch (tool.own()) {
    case EditorOnly::Pick:
        return "pick";
    case EditorOnly::DropLine:
        return "drop-line";
    case EditorOnly::DropRings:
        return "drop-rings";
    case EditorOnly::DropScatter:
        return "drop-scatter";
    }
    return "pick";
}

Genome withSteps(Genome design, const std::vector<Operation>& ops) {
    for (const Operation& op : ops) {
        if (allowedInInitial(op.tool, design.dimension))
            design.initial.push_back(op);
        else
            design.operations.push_back(op);
    }
    return design;
}

glm::dvec3 turnAxis(const ToolSettings& s, const SlicePlane& plane) {
    if (s.axis) {
        const glm::dvec3 a = *s.axis;
        const double length = glm::length(a);
        if (length > 0.0 && std::isfinite(length)) return a / length;
    }
    return plane.normal();
}

std::vector<Operation> gestureSteps(EditorTool tool, const ToolSettings& s, const glm::dvec3& press,
                                    const glm::dvec3& release, const Genome& design, int sliceAxis) {
    return gestureSteps(tool, s, press, release, design, slicePlane(design.dimension, sliceAxis));
}

std::vector<Operation> gestureSteps(EditorTool tool, const ToolSettings& s, const glm::dvec3& press,
                                    const glm::dvec3& release, const Genome& design,
                                    const SlicePlane& plane) {
    if (tool == EditorTool::Pick || !toolAvailable(tool, design.dimension)) return {};
    if (laysInk(tool) && design.palette.empty()) return {};
    const int dim = design.dimension;
    const glm::dvec3 p = dim == 3 ? press : glm::dvec3(press.x, press.y, 0.0);
    const glm::dvec3 q = dim == 3 ? release : glm::dvec3(release.x, release.y, 0.0);
    const glm::dvec3 d = q - p;
    const double length = glm::length(d);
    const bool stroke = length >= MinStrokeLength;
    const glm::dvec3 u = plane.u(), v = plane.v();
    const int color = laysInk(tool) ? inkIndex(s, design) : 0;
    const int count = std::max(1, s.patternCount);
    std::vector<Operation> ops;

    if (!tool.inRegistry()) {
        switch (tool.own()) {
        case EditorOnly::Pick:
            break;
        case EditorOnly::DropLine: {
            // Evenly along the drag; a click drops them along a short row to the right.
            const glm::dvec3 along = stroke ? d : u * (2.0 * s.radius * (count - 1));
            for (int i = 0; i < count; ++i) {
                const double t = count == 1 ? 0.0 : double(i) / (count - 1);
                ops.push_back(inkDrop(Tool::Drop, p + t * along, s.radius, color, design));
            }
            break;
        }
        case EditorOnly::DropRings: {
            // n drops at one centre, inks alternating with the next of the palette: each pushes the
            // older ones outward, and by the area law (volume law in 3D) the last ring ends at the
            // drag's length.
            const double outer = stroke ? length : s.radius;
            const double r = outer / std::pow(double(count), dim == 3 ? 1.0 / 3.0 : 0.5);
            const int other = (color + 1) % int(design.palette.size());
            for (int i = 0; i < count; ++i)
                ops.push_back(inkDrop(Tool::Drop, p, r, i % 2 == 0 ? color : other, design));
            break;
        }
        case EditorOnly::DropScatter: {
            // Poisson-disk (dart throwing) in the disc of the drag, drops spaced at least `gap`
            // apart and half that wide, so none lands in another.
            const double outer = stroke ? length : s.radius * 4.0;
            const double gap = outer * std::sqrt(1.0 / count);
            Pcg32 rng(s.seed);
            std::vector<glm::dvec3> placed;
            for (int attempt = 0; attempt < 60 * count && int(placed.size()) < count; ++attempt) {
                const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
                const double r = outer * std::sqrt(rng.uniform());
                const glm::dvec3 at = p + r * (std::cos(a) * u + std::sin(a) * v);
                if (std::all_of(placed.begin(), placed.end(),
                                [&](const glm::dvec3& o) { return glm::length(o - at) >= gap; }))
                    placed.push_back(at);
            }
            for (const glm::dvec3& at : placed)
                ops.push_back(inkDrop(Tool::Drop, at, gap * 0.45, color, design));
            break;
        }
        }
        return ops;
    }

    // The registry says which kind of gesture makes the tool; each kind is written once here.
    const Tool made = tool.tool();
    switch (toolSpec(made).editor.gesture) {
    case EditorGesture::None:
        break;
    case EditorGesture::Drop:
        // A drop inside a drop needs nothing special: the new ink pushes the older outward.
        ops.push_back(inkDrop(made, p, stroke ? length : s.radius, color, design));
        break;
    case EditorGesture::Spray: {
        // Droplets scattered uniformly within `brush` of the stroke's path.
        Pcg32 rng(s.seed);
        const double brush = std::max(s.brush, 0.0);
        for (int i = 0; i < std::max(1, s.sprayCount); ++i) {
            const double t = rng.uniform();
            const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
            const double r = brush * std::sqrt(rng.uniform());
            const glm::dvec3 at = p + t * d + r * (std::cos(a) * u + std::sin(a) * v);
            ops.push_back(inkDrop(made, at, s.sprayRadius, color, design));
        }
        break;
    }
    case EditorGesture::Stroke: {
        if (!stroke) break;
        Operation op = defaultOperation(made, dim, p);
        setStrokeDirection(op, d, design, plane);
        op.alpha = length;
        op.lambda = std::max(s.lambda, 1e-3);
        op.spacing = std::max(s.spacing, 1e-3);
        ops.push_back(op);
        break;
    }
    case EditorGesture::Wave: {
        if (!stroke) break;
        Operation op = defaultOperation(made, dim, p);
        op.amplitude = glm::dvec2(length);
        op.wavelength = glm::dvec2(std::max(s.wavelength, 1e-3));
        if (dim == 3) {
            // The flat wave on the section, the same on every parallel section: the shift (3D
            // `normal`) along the drag, varying across it (`direction`), the egg-crate's second
            // term (along the plane's axis) off.
            const SectionStroke stroke = sectionStroke(d, plane);
            op.shape = WaveShape::Eggcrate;
            op.direction = stroke.across;
            op.normal = stroke.along;
            op.amplitude = {length, 0.0};
            op.phase = glm::dvec2(0.0);
        } else {
            op.angle = dragAngle(d);
        }
        ops.push_back(op);
        break;
    }
    case EditorGesture::Ring: {
        if (!stroke) break;
        // A solid's circle turns about the panel's axis (else across the section); a sphere's
        // radius is the drag's length on the section through its centre.
        Operation op = defaultOperation(made, dim, p);
        if (dim == 3) op.axis = turnAxis(s, plane);
        op.radius = length;
        op.alpha = s.alpha;
        op.lambda = std::max(s.lambda, 1e-3);
        op.core = std::max(s.core, 0.0);
        ops.push_back(op);
        break;
    }
    case EditorGesture::Swirl: {
        // The drag's length is the swirl's largest shift; a click swirls by the panel's.
        Operation op = defaultOperation(made, dim, p);
        if (dim == 3) op.axis = plane.normal();
        op.alpha = stroke ? length : s.alpha;
        op.lambda = std::max(s.lambda, 1e-3);
        op.core = std::max(s.core, 0.0);
        ops.push_back(op);
        break;
    }
    case EditorGesture::Teeth: {
        if (!stroke) break;
        // Teeth evenly across the whole design at any angle, about the origin.
        Operation op = defaultOperation(made, dim, p);
        op.angle = dragAngle(d);
        op.shift = length;
        op.power = std::max(s.power, 1e-3);
        const double half = std::hypot(design.size.x, design.size.y);
        const int n = std::clamp(s.teeth, 2, int(MaxTeeth));
        op.teeth.clear();
        if (design.wrap && dim == 2) {
            // A bath that wraps takes a pass along an axis whose teeth span the lattice's period
            // across it (docs/genome-format.md, "Wrapping bath"): the drag's nearest axis.
            op.angle = 90.0 * std::round(op.angle / 90.0);
            // Across the pass a half-drop's pass along x, or a brick's along y, repeats at half
            // the design (docs/genome-format.md, "Half-drop and brick repeats").
            const bool alongX = std::fmod(std::abs(op.angle), 180.0) == 0.0;
            double period = alongX ? design.size.y : design.size.x;
            if ((alongX && design.lattice == Lattice::HalfDrop) ||
                (!alongX && design.lattice == Lattice::Brick))
                period /= 2.0;
            for (int i = 0; i < n; ++i)
                op.teeth.push_back(i == n - 1 ? period : period * i / (n - 1));
        } else {
            for (int i = 0; i < n; ++i)
                op.teeth.push_back(-half + 2.0 * half * i / (n - 1));
        }
        ops.push_back(op);
        break;
    }
    case EditorGesture::Cell: {
        // The drag spans one cell (or the cavity) from its corner; a click keeps the default size.
        Operation op = defaultOperation(made, dim, p);
        op.center = p;
        if (stroke)
            op.extent = {std::max(std::abs(d.x), MinStrokeLength), std::max(std::abs(d.y), MinStrokeLength)};
        op.center = {std::min(p.x, q.x), std::min(p.y, q.y), 0.0};
        if (!stroke) op.center = p;
        op.field = s.field == 1 ? FlowField::Cavity : FlowField::Cells;
        op.speed = s.speed;
        op.time = s.time > 0 ? s.time : 1.0;
        op.steps = minimumFlowSteps(op);
        if (op.steps > MaxFlowSteps) break;
        ops.push_back(op);
        break;
    }
    case EditorGesture::Path: {
        // Press and release alone: a straight path (pathSteps takes every point of a drag).
        if (!stroke || dim != 2) break;
        std::vector<Operation> drawn = pathSteps(tool, s, {p, q}, design);
        ops.insert(ops.end(), drawn.begin(), drawn.end());
        break;
    }
    }
    return ops;
}

std::vector<glm::dvec2> smoothedPath(const std::vector<glm::dvec3>& points, double spacing) {
    std::vector<double> unused;
    return smoothedPath(points, {}, spacing, unused);
}

std::vector<glm::dvec2> smoothedPath(const std::vector<glm::dvec3>& points,
                                     const std::vector<double>& pressure, double spacing,
                                     std::vector<double>& keptPressure) {
    // The pressure rides along as a third coordinate; distances are measured in the plane.
    auto pressureAt = [&](std::size_t i) {
        return i < pressure.size() ? std::clamp(pressure[i], 0.0, 1.0) : 1.0;
    };
    std::vector<glm::dvec3> kept;
    spacing = std::max(spacing, 1e-3);
    auto plane = [](const glm::dvec3& p) { return glm::dvec2(p.x, p.y); };
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 at(points[i].x, points[i].y, pressureAt(i));
        if (!std::isfinite(at.x) || !std::isfinite(at.y) || !std::isfinite(at.z)) continue;
        if (kept.empty() || glm::length(plane(at) - plane(kept.back())) >= spacing) kept.push_back(at);
    }
    // The last point of the drag ends the path, unless it lies on the last one kept.
    if (!points.empty() && !kept.empty()) {
        const glm::dvec3 end(points.back().x, points.back().y, pressureAt(points.size() - 1));
        if (plane(end) != plane(kept.back()) && std::isfinite(end.x) && std::isfinite(end.y)) {
            if (kept.size() > 1 && glm::length(plane(end) - plane(kept.back())) < 0.5 * spacing)
                kept.back() = end;
            else
                kept.push_back(end);
        }
    }
    // A pointer's jitter smoothed away: each inner point moved halfway towards the middle of
    // its neighbours (ends kept).
    std::vector<glm::dvec3> smooth = kept;
    for (std::size_t i = 1; i + 1 < kept.size(); ++i)
        smooth[i] = 0.5 * kept[i] + 0.25 * (kept[i - 1] + kept[i + 1]);
    // Consecutive points stay different (the format's rule).
    std::vector<glm::dvec2> path;
    keptPressure.clear();
    for (const glm::dvec3& at : smooth)
        if (path.empty() || plane(at) != path.back()) {
            path.push_back(plane(at));
            keptPressure.push_back(std::clamp(at.z, 0.0, 1.0));
        }
    return path;
}

namespace {

/// The stylus step a free-hand drag draws, its steps the fewest valid (possibly more than a
/// stylus may take); nullopt where the drag draws nothing (see pathSteps).
std::optional<Operation> drawnStroke(EditorTool tool, const ToolSettings& s,
                                     const std::vector<glm::dvec3>& points, const Genome& design,
                                     const std::vector<double>& pressure) {
    if (!tool.inRegistry() || gestureOf(tool) != EditorGesture::Path || design.dimension != 2)
        return std::nullopt;
    // Points a few units apart: fine enough to follow a hand, coarse enough for the file; a
    // long drag spaces them wider so the path stays within the format's points.
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        length += glm::length(glm::dvec2(points[i] - points[i - 1]));
    const double spacing = std::max(PathPointSpacing, length / double(MaxPathPoints - 2));
    std::vector<double> kept;
    std::vector<glm::dvec2> path = smoothedPath(points, pressure, spacing, kept);
    if (path.size() < 2 || glm::length(path.back() - path.front()) + length < MinStrokeLength)
        return std::nullopt;
    Operation op = defaultOperation(tool.tool(), 2, points.front());
    op.path = std::move(path);
    // A mouse (or a pen pressed fully throughout) leaves the field out, as the writer does.
    if (std::all_of(kept.begin(), kept.end(), [](double p) { return p == 1.0; }))
        op.pressure.clear();
    else
        op.pressure = std::move(kept);
    // The panel's values, kept within the registry's ranges.
    if (std::isfinite(s.pull)) op.alpha = s.pull;
    op.lambda = std::isfinite(s.stylusLambda) ? std::max(s.stylusLambda, 1e-3) : op.lambda;
    op.reach = std::isfinite(s.reach) ? std::max(s.reach, 1e-3) : op.reach;
    op.tines = std::clamp(s.tines, 1, int(MaxTines));
    // A single stylus keeps the default spacing, so the file does not say a meaningless one.
    if (op.tines > 1 && std::isfinite(s.rakeSpacing)) op.spacing = std::max(s.rakeSpacing, 1e-3);
    op.steps = minimumStylusSteps(op);
    return op;
}

} // namespace

std::vector<Operation> pathSteps(EditorTool tool, const ToolSettings& s,
                                 const std::vector<glm::dvec3>& points, const Genome& design,
                                 const std::vector<double>& pressure) {
    std::optional<Operation> op = drawnStroke(tool, s, points, design, pressure);
    if (!op || op->steps > MaxStylusSteps) return {};
    return {*op};
}

std::string pathRefusal(EditorTool tool, const ToolSettings& s, const std::vector<glm::dvec3>& points,
                        const Genome& design, const std::vector<double>& pressure) {
    std::optional<Operation> op = drawnStroke(tool, s, points, design, pressure);
    if (!op || op->steps <= MaxStylusSteps) return {};
    return "This stroke would need more than " + std::to_string(MaxStylusSteps) +
           " integration steps, more than a stylus may take: draw it in shorter strokes, or lower its "
           "pull or raise its reach";
}

} // namespace marbler::ui

#include "OpPacking.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marbler::gl {
namespace {

// The registry's shader forms are the classes of tools.glsl (its "Record layout").
static_assert(static_cast<int>(ShaderForm::PushArea) == 0 && static_cast<int>(ShaderForm::PushVolume) == 1 &&
              static_cast<int>(ShaderForm::Shift) == 2 && static_cast<int>(ShaderForm::WaveShift) == 3 &&
              static_cast<int>(ShaderForm::Turn) == 4 && static_cast<int>(ShaderForm::Stretch) == 5 &&
              static_cast<int>(ShaderForm::Flow) == 6 && static_cast<int>(ShaderForm::Stylus) == 7);

/// One record's coefficients besides its centre, ink and form (see tools.glsl).
struct Coefficients {
    glm::dvec3 projected{0.0}, direction{0.0}, u{0.0}, v{0.0};
    double radial = 0.0, radius = 0.0;
    double p5[4] = {0, 0, 0, 0}, p6[3] = {0, 0, 0};
};

/// Line and comb: the shift along M by the distance along N (to the nearest tine of a comb).
void shiftCoefficients(const PreparedOp& op, double spacing, Coefficients& k) {
    k.direction = op.m;
    k.u = op.n;
    k.p5[0] = op.alphaLambda;
    k.p5[1] = op.lambda;
    k.p5[2] = spacing;
}

/// Circle, sphere and vortex: the turn about `axis` (2D: z), d = |rho - radius| with rho
/// measured across `projected` (zero: from the centre).
void turnCoefficients(const PreparedOp& op, const glm::dvec3& projected, double radius, Coefficients& k) {
    k.direction = op.dimension == 2 ? glm::dvec3(0.0, 0.0, 1.0) : op.a;
    k.projected = projected;
    k.radius = radius;
    k.p5[0] = op.alphaLambda;
    k.p5[1] = op.lambda;
    k.p6[2] = op.core2;
}

/// Flow: the field's axes, reciprocal sizes and kind, the step h (forward; the shader goes
/// back with -h), the number of steps, the speed and the fixed-point tolerance.
void flowCoefficients(const PreparedOp& op, Coefficients& k) {
    k.direction = op.m;
    k.u = op.n;
    k.v = glm::dvec3(1.0 / op.size[0], 1.0 / op.size[1], op.size[1] / op.size[0]);
    k.radius = op.field == FlowField::Cavity ? 1.0 : 0.0;
    k.p5[0] = op.step;
    k.p5[1] = op.steps;
    k.p5[2] = op.speed;
    k.p5[3] = FlowToleranceShare * (op.size[0] + op.size[1]);
}

/// Stylus: its shape (lambda, reach, spacing, tines), the step h, its segments appended to
/// `paths` and the fixed-point tolerance. Each segment gets the steps whose time
/// tau_i = i h + h / 2 lies in it (cum_s <= tau_i < cum_s+1, as Tools.cpp's stylusVelocity
/// finds the segment, in double), the stylus's place S and the pull c at the first of them, and
/// c's change a step: the shader then counts steps within the segment (tools.glsl, stylusBack),
/// and S = S_first + j h T keeps float precision along a long path.
void stylusCoefficients(const PreparedOp& op, const glm::dvec3& reference, std::vector<float>& paths,
                        Coefficients& k) {
    k.v = glm::dvec3(op.lambda, op.reach, op.spacing);
    k.radius = op.tines;
    const std::size_t first = paths.size() / 4;
    // No step, or no path: the stylus moves nothing (as Tools.cpp's maps).
    const std::size_t segments = op.steps > 0 && op.path.size() >= 2 ? op.path.size() - 1 : 0;
    const auto time = [&op](int i) { return i * op.step + 0.5 * op.step; };
    // The first step whose time is at or after the segment's start (the first: step 0).
    const auto firstStep = [&](std::size_t s) {
        if (s == 0) return 0;
        if (s == segments) return op.steps;
        const double start = op.cum[s];
        int i = static_cast<int>(std::clamp(std::ceil(start / op.step - 0.5), 0.0, double(op.steps)));
        while (i > 0 && time(i - 1) >= start)
            --i;
        while (i < op.steps && time(i) < start)
            ++i;
        return i;
    };
    int from = 0;
    for (std::size_t s = 0; s < segments; ++s) {
        const int to = firstStep(s + 1);
        const glm::dvec2 t = op.along[s];
        const double length = op.cum[s + 1] - op.cum[s], into = time(from) - op.cum[s];
        const glm::dvec2 place = op.path[s] + into * t - glm::dvec2(reference);
        const double slope = (op.pressure[s + 1] - op.pressure[s]) / length;
        const double pressure = op.pressure[s] + slope * into;
        paths.insert(paths.end(), {float(place.x), float(place.y), float(t.x), float(t.y), float(to - from),
                                   float(op.pull * pressure), float(op.pull * slope * op.step), 0.0f});
        from = to;
    }
    k.p5[0] = op.step;
    k.p5[1] = double(segments);
    k.p5[2] = FlowToleranceShare * (op.length + op.reach);
    k.p5[3] = double(first);
}

} // namespace

bool needsVersion2Forms(const std::vector<PreparedOp>& ops) {
    return std::any_of(ops.begin(), ops.end(), [](const PreparedOp& op) {
        return op.core2 > 0.0 || op.form == ShaderForm::Stretch || op.form == ShaderForm::Flow ||
               op.form == ShaderForm::Stylus;
    });
}

int stylusForm(const std::vector<PreparedOp>& ops) {
    int form = 0;
    for (const PreparedOp& op : ops)
        if (op.form == ShaderForm::Stylus) form = std::max(form, op.tines > 1 ? 2 : 1);
    return form;
}

double shaderWork(const std::vector<PreparedOp>& ops) {
    double work = 0.0;
    for (const PreparedOp& op : ops)
        work += op.form == ShaderForm::Stylus ? std::max(1.0, double(op.steps) * op.tines) : 1.0;
    return std::max(work, 1.0);
}

PackedOps packOps(const std::vector<PreparedOp>& ops, const glm::dvec3& reference) {
    PackedOps packed;
    std::vector<float>& out = packed.records;
    out.reserve(ops.size() * PackedOpFloats);
    auto put = [&out](const glm::dvec3& v, double w) {
        out.push_back(float(v.x));
        out.push_back(float(v.y));
        out.push_back(float(v.z));
        out.push_back(float(w));
    };
    // freq = 2 pi / wavelength; the shader wants cycles per unit to reduce the argument.
    const double cycles = 0.5 / std::numbers::pi;
    // The nearest stretch, flow or stylus at or before each record: where the shader's run of
    // version-1 forms stops (tools.glsl, traceColor).
    int lastVersion2 = -1;
    for (std::size_t index = 0; index < ops.size(); ++index) {
        const PreparedOp& op = ops[index];
        if (op.form == ShaderForm::Stretch || op.form == ShaderForm::Flow || op.form == ShaderForm::Stylus)
            lastVersion2 = int(index);
        const bool flat = op.dimension == 2;
        glm::dvec3 c = op.c - reference;
        if (flat) c.z = 0.0; // 2D points live at z = 0 whatever the reference
        const bool inks = op.color >= 0 && toolSpec(op.tool).laysInk;
        Coefficients k;
        // Every tool, no default: a tool added to the registry without its packing fails the
        // build (-Werror=switch).
        switch (op.tool) {
        case Tool::Drop:
            k.radius = op.r;
            k.p5[0] = op.rPow;
            break;
        case Tool::Spray:
            k.radius = op.r;
            break; // a push of strength 0: moves nothing
        case Tool::Cylinder:
            k.projected = op.a;
            k.radius = op.r;
            k.p5[0] = op.rPow;
            break;
        case Tool::Line:
            shiftCoefficients(op, 0.0, k);
            break;
        case Tool::Comb:
            shiftCoefficients(op, op.spacing, k);
            break;
        case Tool::Wave:
            if (flat) {
                k.direction = op.m;
                k.u = op.n;
            } else {
                k.direction = op.n;
                k.u = op.m;
                k.v = op.v;
                k.radial = op.shape == WaveShape::Ripple ? 1.0 : 0.0;
            }
            k.p5[0] = op.amp[0];
            k.p5[1] = flat || k.radial > 0.0 ? 0.0 : op.amp[1];
            k.p5[2] = op.freq[0] * cycles;
            k.p5[3] = op.freq[1] * cycles;
            k.p6[0] = op.phase[0];
            k.p6[1] = op.phase[1];
            break;
        case Tool::Circle:
            turnCoefficients(op, flat ? glm::dvec3(0.0) : op.a, op.r, k);
            break;
        case Tool::Sphere:
            turnCoefficients(op, glm::dvec3(0.0), op.r, k);
            break;
        case Tool::Vortex:
            turnCoefficients(op, glm::dvec3(0.0), 0.0, k);
            break; // d = rho
        case Tool::Stretch:
            // Teeth are distances along N from the origin, which the shader measures from the
            // origin too: they need no reference.
            k.direction = op.m;
            k.u = op.n;
            k.p5[0] = op.shift;
            k.p5[1] = op.power;
            k.p5[2] = double(packed.teeth.size());
            k.p5[3] = double(op.teeth.size());
            for (double t : op.teeth)
                packed.teeth.push_back(float(t));
            break;
        case Tool::Flow:
            flowCoefficients(op, k);
            break;
        case Tool::Stylus:
            stylusCoefficients(op, reference, packed.paths, k);
            break;
        }
        put(c, inks ? op.r * op.r : -1.0);
        put(k.projected, inks ? op.color : -1);
        put(k.direction, static_cast<double>(op.form));
        put(k.u, k.radial);
        put(k.v, k.radius);
        out.insert(out.end(), {float(k.p5[0]), float(k.p5[1]), float(k.p5[2]), float(k.p5[3])});
        out.insert(out.end(), {float(k.p6[0]), float(k.p6[1]), float(k.p6[2]), float(lastVersion2)});
    }
    return packed;
}

} // namespace marbler::gl

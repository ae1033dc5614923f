#include "OpPacking.h"

#include <numbers>

namespace marbler::gl {
namespace {

/// The shared forms of tools.glsl.
enum Form { PushSqrt = 0, PushCbrt = 1, Shift = 2, WaveShift = 3, Turn = 4 };

} // namespace

std::vector<float> packOps(const std::vector<PreparedOp>& ops, const glm::dvec3& reference) {
    std::vector<float> out;
    out.reserve(ops.size() * PackedOpFloats);
    auto put = [&out](const glm::dvec3& v, double w) {
        out.push_back(float(v.x));
        out.push_back(float(v.y));
        out.push_back(float(v.z));
        out.push_back(float(w));
    };
    // freq = 2 pi / wavelength; the shader wants cycles per unit to reduce the argument.
    const double cycles = 0.5 / std::numbers::pi;
    const glm::dvec3 zero(0.0), zAxis(0.0, 0.0, 1.0);
    for (const PreparedOp& op : ops) {
        const bool flat = op.dimension == 2;
        glm::dvec3 c = op.c - reference;
        if (flat) c.z = 0.0; // 2D points live at z = 0 whatever the reference
        const bool inks = op.color >= 0 && (op.tool == Tool::Drop || op.tool == Tool::Spray || op.tool == Tool::Cylinder);
        glm::dvec3 projected = zero, direction = zero, u = zero, v = zero;
        double form = PushSqrt, radial = 0.0, radius = 0.0;
        double p5[4] = {0, 0, 0, 0}, p6[2] = {0, 0};
        switch (op.tool) {
        case Tool::Drop:
            form = flat ? PushSqrt : PushCbrt;
            p5[0] = op.r2;
            break;
        case Tool::Spray: break; // a push of strength 0: moves nothing
        case Tool::Cylinder:
            projected = op.a;
            p5[0] = op.r2;
            break;
        case Tool::Line:
        case Tool::Comb:
            form = Shift;
            direction = op.m;
            u = op.n;
            p5[0] = op.alphaLambda;
            p5[1] = op.lambda;
            p5[2] = op.tool == Tool::Comb ? op.spacing : 0.0;
            break;
        case Tool::Wave:
            form = WaveShift;
            if (flat) {
                direction = op.m;
                u = op.n;
            } else {
                direction = op.n;
                u = op.m;
                v = op.v;
                radial = op.shape == WaveShape::Ripple ? 1.0 : 0.0;
            }
            p5[0] = op.amp[0];
            p5[1] = flat || radial > 0.0 ? 0.0 : op.amp[1];
            p5[2] = op.freq[0] * cycles;
            p5[3] = op.freq[1] * cycles;
            p6[0] = op.phase[0];
            p6[1] = op.phase[1];
            break;
        case Tool::Circle:
        case Tool::Sphere:
        case Tool::Vortex:
            form = Turn;
            direction = flat ? zAxis : op.a;
            if (op.tool == Tool::Circle && !flat) projected = op.a;
            radius = op.tool == Tool::Vortex ? 0.0 : op.r;
            p5[0] = op.alphaLambda;
            p5[1] = op.lambda;
            break;
        }
        put(c, inks ? op.r * op.r : -1.0);
        put(projected, inks ? op.color : -1);
        put(direction, form);
        put(u, radial);
        put(v, radius);
        out.insert(out.end(), {float(p5[0]), float(p5[1]), float(p5[2]), float(p5[3])});
        out.insert(out.end(), {float(p6[0]), float(p6[1]), 0.0f, 0.0f});
    }
    return out;
}

} // namespace marbler::gl

#include "OpPacking.h"

#include <numbers>

namespace marbler::gl {

std::vector<float> packOps(const std::vector<PreparedOp>& ops, const glm::dvec3& reference) {
    std::vector<float> out;
    out.reserve(ops.size() * PackedOpFloats);
    auto put = [&out](const glm::dvec3& v, double w) {
        out.push_back(float(v.x));
        out.push_back(float(v.y));
        out.push_back(float(v.z));
        out.push_back(float(w));
    };
    for (const PreparedOp& op : ops) {
        out.push_back(float(static_cast<int>(op.tool)));
        out.push_back(float(op.dimension));
        out.push_back(float(static_cast<int>(op.shape)));
        out.push_back(float(op.color));
        glm::dvec3 c = op.c - reference;
        if (op.dimension == 2) c.z = 0.0; // 2D points live at z = 0 whatever the reference
        put(c, op.r);
        put(op.m, op.r2);
        put(op.n, op.alphaLambda);
        put(op.v, op.lambda);
        put(op.a, op.spacing);
        // freq = 2 pi / wavelength; the shader wants cycles per unit to reduce the argument.
        const double cycles = 0.5 / std::numbers::pi;
        out.push_back(float(op.amp[0]));
        out.push_back(float(op.amp[1]));
        out.push_back(float(op.freq[0] * cycles));
        out.push_back(float(op.freq[1] * cycles));
        out.push_back(float(op.phase[0]));
        out.push_back(float(op.phase[1]));
        out.push_back(float(op.r * op.r));
        out.push_back(0.0f);
    }
    return out;
}

} // namespace marbler::gl

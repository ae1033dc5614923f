// The tools of genome-format.md in GLSL: inverse maps, ink tests and the colour rule, read from
// packed PreparedOp records (render/gl/src/OpPacking.cpp writes them, 8 vec4 each). This is the
// float twin of genome/src/Tools.cpp: keep the two in step.
//
// Every position here is relative to a reference point R chosen by the host near the pixels being
// drawn (op centres are packed as c - R in double before the cast to float). All maps depend on
// P - C only, so the shift is exact and keeps float precision where the samples are.
//
// Record layout:
//   head  = (tool, dimension, wave shape, ink colour or -1)
//   c     = (centre - R, radius)
//   m     = (motion direction M / wave u, r^2 (2D drop, cylinder) or r^3 (3D drop))
//   n     = (normal N / wave w, alpha * lambda)
//   v     = (wave v = w x u, lambda)
//   a     = (axis, comb spacing)
//   wave  = (amplitude 1, amplitude 2, 1 / wavelength 1, 1 / wavelength 2)
//   extra = (phase 1, phase 2 (radians), r^2 of the ink test, unused)

const int ToolDrop = 0;
const int ToolSpray = 1;
const int ToolCylinder = 2;
const int ToolLine = 3;
const int ToolComb = 4;
const int ToolWave = 5;
const int ToolCircle = 6;
const int ToolSphere = 7;
const int ToolVortex = 8;
const float TwoPi = 6.28318530717958647692;

struct Op {
    vec4 head;
    vec4 c;
    vec4 m;
    vec4 n;
    vec4 v;
    vec4 a;
    vec4 wave;
    vec4 extra;
};

// The genome is data, never code: a new design is a buffer upload, not a recompile.
layout(std430, binding = 0) readonly buffer OpBuffer { Op ops[]; };
uniform int uOpCount;

// Linear inks 0..15; [16] is the background.
uniform vec3 uInk[17];
// A 2D raster start, stretched over the design space (sRGB texture: filtered in linear light).
uniform bool uHasSource;
uniform sampler2D uSource;
uniform vec2 uDesignSize;
uniform vec3 uReference; // R, to turn relative positions back into design coordinates

float shiftFor(Op op, float d) { return op.n.w / (d + op.v.w); }

float combDistance(float t, float s) {
    float md = t - s * floor(t / s);
    return 0.5 * s - abs(md - 0.5 * s);
}

// The sine's argument reduced to one period before the multiplication by 2 pi, since GPU sines
// lose accuracy far from zero.
float waveSin(float t, float invLength, float phase) { return sin(TwoPi * fract(t * invLength) + phase); }

float waveShift(Op op, vec3 rel) {
    if (int(op.head.y) == 2) return op.wave.x * waveSin(dot(rel, op.n.xyz), op.wave.z, op.extra.x);
    float x = dot(rel, op.m.xyz);
    float y = dot(rel, op.v.xyz);
    if (int(op.head.z) == 1) return op.wave.x * waveSin(sqrt(x * x + y * y), op.wave.z, op.extra.x);
    return op.wave.x * waveSin(x, op.wave.z, op.extra.x) + op.wave.y * waveSin(y, op.wave.w, op.extra.y);
}

vec3 rotateAbout(vec3 rel, vec3 axis, float theta) {
    vec3 along = dot(rel, axis) * axis;
    vec3 across = rel - along;
    return along + across * cos(theta) + cross(axis, across) * sin(theta);
}

// Circle, sphere and vortex: turn about C (2D) or about the axis line through C (3D).
vec3 swirl(Op op, vec3 p, float sgn) {
    vec3 rel = p - op.c.xyz;
    int tool = int(op.head.x);
    bool flat2d = int(op.head.y) == 2;
    float rho = (tool == ToolCircle && !flat2d) ? length(rel - dot(rel, op.a.xyz) * op.a.xyz) : length(rel);
    if (!(rho > 0.0)) return p;
    float d = tool == ToolVortex ? rho : abs(rho - op.c.w);
    float theta = sgn * shiftFor(op, d) / rho;
    if (flat2d) {
        float cs = cos(theta), sn = sin(theta);
        return op.c.xyz + vec3(cs * rel.x - sn * rel.y, sn * rel.x + cs * rel.y, 0.0);
    }
    return op.c.xyz + rotateAbout(rel, op.a.xyz, theta);
}

// Drop (area or volume law) and cylinder: the radial push. factor - 1 is computed without the
// cancellation of sqrt(1 + s) - 1, which in float would cost most of the digits far from a drop.
vec3 push(Op op, vec3 p, float sgn) {
    vec3 rel = p - op.c.xyz;
    int tool = int(op.head.x);
    if (tool == ToolCylinder) rel -= dot(rel, op.a.xyz) * op.a.xyz;
    float len2 = dot(rel, rel);
    if (!(len2 > 0.0)) return p;
    float s;
    float grow;
    if (tool == ToolDrop && int(op.head.y) == 3) {
        s = max(-1.0, sgn * op.m.w / (len2 * sqrt(len2)));
        float f = pow(1.0 + s, 1.0 / 3.0);
        grow = s / (f * f + f + 1.0);
    } else {
        s = max(-1.0, sgn * op.m.w / len2);
        grow = s / (sqrt(1.0 + s) + 1.0);
    }
    return p + rel * grow;
}

vec3 inverseMap(Op op, vec3 q) {
    int tool = int(op.head.x);
    if (tool == ToolDrop || tool == ToolCylinder) return push(op, q, -1.0);
    if (tool == ToolLine) return q - shiftFor(op, abs(dot(q - op.c.xyz, op.n.xyz))) * op.m.xyz;
    if (tool == ToolComb) return q - shiftFor(op, combDistance(dot(q - op.c.xyz, op.n.xyz), op.a.w)) * op.m.xyz;
    if (tool == ToolWave) return q - waveShift(op, q - op.c.xyz) * (int(op.head.y) == 2 ? op.m.xyz : op.n.xyz);
    if (tool == ToolCircle || tool == ToolSphere || tool == ToolVortex) return swirl(op, q, -1.0);
    return q; // spray moves nothing
}

// Open boundary: a point on the rim is outside.
bool insideInk(Op op, vec3 p) {
    vec3 rel = p - op.c.xyz;
    if (int(op.head.x) == ToolCylinder) rel -= dot(rel, op.a.xyz) * op.a.xyz;
    return dot(rel, rel) < op.extra.z;
}

// The colour rule: back through time until an ink is hit. Returns the palette index or -1; p is
// left where the point came from (for the source image).
int traceColor(inout vec3 p) {
    for (int k = uOpCount - 1; k >= 0; --k) {
        Op op = ops[k];
        if (op.head.w >= 0.0 && insideInk(op, p)) return int(op.head.w);
        p = inverseMap(op, p);
    }
    return -1;
}

// The linear colour seen at p (relative to uReference).
vec3 inkColor(vec3 p) {
    int k = traceColor(p);
    if (k >= 0) return uInk[k];
    if (uHasSource) {
        vec2 w = (p + uReference).xy;
        if (w.x >= 0.0 && w.y >= 0.0 && w.x <= uDesignSize.x && w.y <= uDesignSize.y)
            return texture(uSource, w / uDesignSize).rgb;
    }
    return uInk[16];
}

float linearToSrgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

// Rounded to 8 bits here, not by the framebuffer, so the result is the spec's rounding on every
// driver (the target is an unsigned-integer texture).
uvec4 encodeSrgb8(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    vec3 e = vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
    return uvec4(uvec3(floor(e * 255.0 + 0.5)), 255u);
}

// The tools of genome-format.md in GLSL: inverse maps, ink tests and the colour rule, read from
// packed PreparedOp records (render/gl/src/OpPacking.cpp writes them, 7 vec4 each). This is the
// float twin of genome/src/Tools.cpp: keep the two in step.
//
// Every position here is relative to a reference point R chosen by the host near the pixels being
// drawn (op centres are packed as c - R in double before the cast to float). All maps depend on
// P - C only, so the shift is exact and keeps float precision where the samples are.
//
// Speed: a software rasteriser (llvmpipe) runs both sides of every branch whose condition varies
// between lanes or that it cannot prove uniform, so a switch over nine tools costs nine tools per
// operation. Instead every operation runs one branch-free body: the host packs each tool into the
// coefficients of three shared forms (radial push, translation along a direction, turn about an
// axis) and the body picks the form's result by the operation's class. The shared pieces (the
// distance to the centre or axis, the shift alpha lambda / (d + lambda), two sines that are the
// wave's two terms or the turn's sine and cosine) are computed once per operation.
//
// Record layout (classes, the registry's ShaderForm in genome/include/marbler/Params.h, which names
// each tool's: 0 push with a square root, 1 push with a cube root (3D drop),
// 2 translation by the distance-dependent shift (line, comb), 3 translation by the wave's shift,
// 4 turn (circle, sphere, vortex); spray is a push of strength 0):
//   o0 = (centre - R, r^2 of the ink test or -1 (no ink))
//   o1 = (axis projected out of the distance: cylinder, 3D circle; else 0, palette index or -1)
//   o2 = (move direction (translations) or turn axis, class)
//   o3 = (U: the distance axis (line, comb: N; wave: its first axis), 1 for a radial wave)
//   o4 = (V: the wave's second axis or 0, radius of the circle or sphere (0 for a vortex))
//   o5 = push: (r^2 or r^3, -, -, -); line, comb, turn: (alpha lambda, lambda, comb spacing or 0, -);
//        wave: (amplitude 1, amplitude 2 (0 for one term), 1 / wavelength 1, 1 / wavelength 2)
//   o6 = (wave phase 1, wave phase 2 (radians), -, -)

const float TwoPi = 6.28318530717958647692;
const float HalfPi = 1.57079632679489661923;
const int OpVec4s = 7;

// The genome is data, never code: a new design is a buffer upload, not a recompile. A buffer
// texture: llvmpipe fetches a texel for every lane at once, where a storage buffer read goes
// lane by lane.
uniform samplerBuffer uOps;
uniform int uOpCount;

// Linear inks 0..15; [16] is the background.
uniform vec3 uInk[17];
#if MARBLER_HAS_SOURCE
// A 2D raster start, stretched over the design space (sRGB texture: filtered in linear light).
uniform sampler2D uSource;
uniform vec2 uDesignSize;
uniform vec3 uReference; // R, to turn relative positions back into design coordinates
#endif

float combDistance(float t, float s) {
    float md = t - s * floor(t / s);
    return 0.5 * s - abs(md - 0.5 * s);
}

// The colour rule: back through time until an ink is hit. Returns the palette index or -1; p is
// left where the point came from (for the source image).
int traceColor(inout vec3 p) {
    int color = -1;
    for (int k = uOpCount - 1; k >= 0; --k) {
        int b = k * OpVec4s;
        vec4 o0 = texelFetch(uOps, b);
        vec4 o1 = texelFetch(uOps, b + 1);
        vec4 o2 = texelFetch(uOps, b + 2);
        vec4 o3 = texelFetch(uOps, b + 3);
        vec4 o4 = texelFetch(uOps, b + 4);
        vec4 o5 = texelFetch(uOps, b + 5);
        vec4 o6 = texelFetch(uOps, b + 6);
        int kind = int(o2.w);

        vec3 rel = p - o0.xyz;
        vec3 across = rel - dot(rel, o1.xyz) * o1.xyz; // rel itself where nothing is projected out
        float len2 = dot(across, across);
        // Open boundary: a point on the rim is outside (o0.w is -1 where the tool lays no ink).
        if (len2 < o0.w) {
            color = int(o1.w);
            break;
        }
        float rho = sqrt(len2);

        // Translations and turns: the distance d, the shift alpha lambda / (d + lambda).
        float t = dot(rel, o3.xyz);
        float d = kind == 4 ? abs(rho - o4.w) : (o5.z > 0.0 ? combDistance(t, o5.z) : abs(t));
        float shift = o5.x / (d + o5.y);
        float theta = -shift / rho;
        // The two sines: the wave's terms, or the turn's sine and cosine.
        float y = dot(rel, o4.xyz);
        float x = o3.w > 0.0 ? sqrt(t * t + y * y) : t;
        vec2 args = kind == 3 ? vec2(TwoPi * fract(x * o5.z) + o6.x, TwoPi * fract(y * o5.w) + o6.y)
                              : vec2(theta, theta + HalfPi);
        vec2 sines = sin(args);

        vec3 moved;
        if (kind <= 1) {
            // Drop (area or volume law) and cylinder: the radial push. factor - 1 is computed
            // without the cancellation of sqrt(1 + s) - 1, which in float would cost most of the
            // digits far from a drop.
#if MARBLER_DIMENSION == 3
            float s = max(-1.0, -o5.x / (kind == 1 ? len2 * rho : len2));
            float f = kind == 1 ? pow(1.0 + s, 1.0 / 3.0) : sqrt(1.0 + s);
            float grow = s / (kind == 1 ? f * f + f + 1.0 : f + 1.0);
#else
            float s = max(-1.0, -o5.x / len2);
            float grow = s / (sqrt(1.0 + s) + 1.0);
#endif
            moved = len2 > 0.0 ? p + across * grow : p;
        } else if (kind <= 3) {
            moved = p - (kind == 3 ? o5.x * sines.x + o5.y * sines.y : shift) * o2.xyz;
        } else {
            // Turn about the axis (2D: z) through the centre.
            vec3 side = rel - dot(rel, o2.xyz) * o2.xyz;
            vec3 turned = o0.xyz + (rel - side) + side * sines.y + cross(o2.xyz, side) * sines.x;
            moved = rho > 0.0 ? turned : p;
        }
        p = moved;
    }
    return color;
}

// The linear colour seen at p (relative to uReference).
vec3 inkColor(vec3 p) {
    int k = traceColor(p);
    if (k >= 0) return uInk[k];
#if MARBLER_HAS_SOURCE
    vec2 w = (p + uReference).xy;
    if (w.x >= 0.0 && w.y >= 0.0 && w.x <= uDesignSize.x && w.y <= uDesignSize.y)
        return texture(uSource, w / uDesignSize).rgb;
#endif
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

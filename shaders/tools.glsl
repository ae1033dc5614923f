// The tools of genome-format.md in GLSL: inverse maps, ink tests and the colour rule, read from
// packed PreparedOp records (render/gl/src/OpPacking.cpp writes them, 7 vec4 each). This is the
// float twin of genome/src/Tools.cpp: keep the two in step.
//
// Every position here is relative to a reference point R chosen by the host near the pixels being
// drawn (op centres are packed as c - R in double before the cast to float). All maps depend on
// P - C only, so the shift is exact and keeps float precision where the samples are.
//
// Speed: a software rasteriser (llvmpipe) runs both sides of every branch whose condition varies
// between lanes or that it cannot prove uniform, so a switch over the tools would cost every tool
// per operation. Instead every operation runs one branch-free body: the host packs each tool into
// the coefficients of three shared forms (radial push, translation along a direction, turn about
// an axis) and the body picks the form's result by the operation's class. The shared pieces (the
// distance to the centre or axis, the shift alpha lambda / (d + lambda), two sines that are the
// wave's two terms or the turn's sine and cosine) are computed once per operation.
//
// Record layout (classes, the registry's ShaderForm in genome/include/marbler/Params.h, which names
// each tool's: 0 push with a square root, 1 push with a cube root (3D drop),
// 2 translation by the distance-dependent shift (line, comb), 3 translation by the wave's shift,
// 4 turn (circle, sphere, vortex), 5 stretch, 6 flow, 7 stylus; spray is a push of strength 0):
//   o0 = (centre or origin - R, r^2 of the ink test or -1 (no ink))
//   o1 = (axis projected out of the distance: cylinder, 3D circle; else 0, palette index or -1)
//   o2 = (move direction (translations, stretch, flow: M) or turn axis, class)
//   o3 = (U: the distance axis (line, comb, stretch, flow: N; wave: its first axis), 1 for a
//        radial wave)
//   o4 = (V: the wave's second axis; flow: (1 / Lx, 1 / Ly, Ly / Lx); else 0,
//        radius of the circle or sphere (0 for a vortex) or of the ink (drop, spray, cylinder);
//        flow: 1 for the cavity, 0 for cells); stylus: (lambda, reach, spacing, tines)
//   o5 = push: (r^2 or r^3, -, -, -); line, comb, turn: (alpha lambda, lambda, comb spacing or 0, -);
//        wave: (amplitude 1, amplitude 2 (0 for one term), 1 / wavelength 1, 1 / wavelength 2);
//        stretch: (shift, power, first tooth in uTeeth, tooth count);
//        flow: (step h, steps, speed U, tolerance of the fixed-point iteration);
//        stylus: (step h, path segments, tolerance, its first segment's texel in uPaths)
//   o6 = (wave phase 1, wave phase 2 (radians), turn: core^2, the nearest stretch, flow or stylus
//        at or before this record (itself for one), -1 if none)
//
// Version 2's forms (stretch, flow, a turn's finite core) are compiled in only where a design
// has them (MARBLER_VERSION2), version 3's stylus, which runs among them, only where a design
// has one (MARBLER_STYLUS), and the bleed rule only where a design bleeds (MARBLER_BLEED): every
// other design runs the version-1 body, at the version-1 speed.

const float TwoPi = 6.28318530717958647692;
const float HalfPi = 1.57079632679489661923;
const float Pi = 3.14159265358979323846;
const int OpVec4s = 7;
// The most fixed-point iterations of one flow or stylus step (the CPU's double iteration takes
// up to 100; see FlowToleranceShare in render/gl/src/OpPacking.h).
const int FlowIterations = 16;

// The genome is data, never code: a new design is a buffer upload, not a recompile. A buffer
// texture: llvmpipe fetches a texel for every lane at once, where a storage buffer read goes
// lane by lane.
uniform samplerBuffer uOps;
uniform int uOpCount;
#if MARBLER_VERSION2
uniform samplerBuffer uTeeth; // every stretch's teeth (R32F), indexed by its record
#endif
#if MARBLER_STYLUS
uniform samplerBuffer uPaths; // every stylus's path segments (RGBA32F), indexed by its record
#endif
#if MARBLER_BLEED
uniform float uBleed; // the genome's bleed b > 0
#endif

// Linear inks 0..15; [16] is the background.
uniform vec3 uInk[17];
// A bath that wraps (docs/genome-format.md, "Wrapping bath"): (w, h, 1 / w, 1 / h), or all 0
// where it does not (then the wrap below subtracts 0 and changes nothing).
uniform vec4 uWrap;
// The wrap's lattice (Tools.h PreparedOp::wrapShift): (0, h / 2) half-drop, (w / 2, 0) brick,
// (0, 0) straight.
uniform vec2 uWrapShift;

// The nearest image over a half-drop or brick lattice of a difference d (Tools.h nearestImage):
// the nearest in each of three columns (half-drop) or rows (brick), the first of the closest.
vec2 latticeNearest(vec2 d) {
    bool brick = uWrapShift.x > 0.0;
    float a = brick ? d.y : d.x, b = brick ? d.x : d.y;
    float along = brick ? uWrap.y : uWrap.x, across = brick ? uWrap.x : uWrap.y;
    float drop = brick ? uWrapShift.x : uWrapShift.y;
    float i0 = floor(a / along + 0.5);
    vec2 best = vec2(0.0);
    float bestLen = 3.4e38;
    for (int k = -1; k <= 1; ++k) {
        float i = i0 + float(k);
        float ea = a - i * along;
        float eb = b - i * drop;
        eb -= across * floor(eb / across + 0.5);
        float len2 = ea * ea + eb * eb;
        if (len2 < bestLen) {
            bestLen = len2;
            best = vec2(ea, eb);
        }
    }
    return brick ? best.yx : best;
}
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

#if MARBLER_VERSION2
// Stretch: the shift s sin(pi tau)^p of a point at distance u along N from the origin, between
// the teeth q.z .. q.z + q.w - 1 of uTeeth (q = o5); 0 outside them. A binary search for the
// interval t_i <= u < t_{i+1}: ten fetches for a thousand teeth.
float stretchShift(float u, vec4 q) {
    int first = int(q.z);
    int lo = 0, hi = int(q.w) - 1;
    float tl = texelFetch(uTeeth, first).x, th = texelFetch(uTeeth, first + hi).x;
    bool between = u >= tl && u < th;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        float tm = texelFetch(uTeeth, first + mid).x;
        bool below = tm <= u;
        lo = below ? mid : lo;
        tl = below ? tm : tl;
        hi = below ? hi : mid;
        th = below ? th : tm;
    }
    // max: pi in float exceeds pi, so near the upper tooth the sine may come out just below 0.
    float sine = max(sin(Pi * (u - tl) / (th - tl)), 0.0);
    return between && sine > 0.0 ? q.x * pow(sine, q.y) : 0.0;
}

// The flow's velocity at local coordinates x, in those coordinates; k = o4, speed U.
vec2 flowVelocity(vec2 x, vec4 k, float speed) {
    vec2 st = x * k.xy; // x / Lx, y / Ly
    // Cells: psi = U (Ly / pi) sin(pi x / Lx) sin(pi y / Ly), the arguments reduced to a period.
    vec2 a = Pi * (st - 2.0 * floor(0.5 * st));
    vec2 sn = sin(a), cs = cos(a);
    vec2 cells = vec2(sn.x * cs.y, -k.z * cs.x * sn.y);
    // Cavity: psi = U Ly F(x / Lx) G(y / Ly) in the box, 0 outside.
    float s = st.x, t = st.y;
    float f = 16.0 * s * s * (1.0 - s) * (1.0 - s), df = 32.0 * s * (1.0 - s) * (1.0 - 2.0 * s);
    float g = 7.5 * t * t * (1.0 - t) * (1.0 - t) * (1.0 - t), dg = 7.5 * t * (1.0 - t) * (1.0 - t) * (2.0 - 5.0 * t);
    bool inBox = s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0;
    vec2 cavity = inBox ? vec2(f * dg, -k.z * df * g) : vec2(0.0);
    return speed * (k.w > 0.0 ? cavity : cells);
}

// Flow, backward: n implicit midpoint steps of -h from rel (relative to the origin) along the
// axes m, n, each solved by fixed-point iteration; returns the point relative to the origin.
vec3 flowBack(vec3 rel, vec3 m, vec3 n, vec4 k, vec4 q) {
    vec2 x = vec2(dot(rel, m), dot(rel, n));
    float h = -q.x;
    int steps = int(q.y);
    for (int step = 0; step < steps; ++step) {
        vec2 next = x + h * flowVelocity(x, k, q.z);
        for (int i = 0; i < FlowIterations; ++i) {
            vec2 again = x + h * flowVelocity(0.5 * (x + next), k, q.z);
            // The tolerance, or a few float steps of the point where those are larger.
            float tolerance = max(q.w, 4.0e-7 * (abs(again.x) + abs(again.y)));
            bool settled = length(again - next) < tolerance;
            next = again;
            if (settled) break;
        }
        x = next;
    }
    return x.x * m + x.y * n;
}
#endif

#if MARBLER_STYLUS
// The velocity of a stylus at R = P - S(tau) (genome-format.md, stylus): the sum over its tines
// of c w(u) / (1 + q^2) T - c lambda atan(q) w'(u) / l N, with shape = (lambda, reach l,
// spacing, tines). The tines lie along N, so u and the window w are one for all of them: only
// the sums over the tines loop.
vec2 stylusVelocity(vec2 r, vec2 t, float c, vec4 shape) {
    float u = dot(r, t) / shape.y;
    if (!(abs(u) < 1.0)) return vec2(0.0); // w = w' = 0
    vec2 n = vec2(-t.y, t.x);
#if MARBLER_STYLUS == 1
    // Every stylus of the design has one tine: no loop (see "Loops" at stylusBack).
    float q = dot(r, n) / shape.x;
    float across = 1.0 / (1.0 + q * q), turn = atan(q);
#else
    int tines = int(shape.w);
    // q of tine j: (R . N - o_j) / lambda, o_j = (j - (k - 1) / 2) spacing.
    float q0 = (dot(r, n) + 0.5 * float(tines - 1) * shape.z) / shape.x, dq = shape.z / shape.x;
    float across = 0.0, turn = 0.0;
    // Two tines a loop iteration: half the loop iterations (see "Loops" at stylusBack).
    for (int j = 0; j < tines; j += 2) {
        float q = q0 - float(j) * dq, next = q - dq;
        bool pair = j + 1 < tines;
        across += 1.0 / (1.0 + q * q) + (pair ? 1.0 / (1.0 + next * next) : 0.0);
        turn += atan(q) + (pair ? atan(next) : 0.0);
    }
#endif
    float one = 1.0 - u * u; // w = one^2, w' = -4 u one
    return (c * one * one * across) * t + (c * shape.x * 4.0 * u * one * turn / shape.y) * n;
}

// Stylus, backward from x (relative to R): its implicit midpoint steps newest first, each solved
// by fixed-point iteration from the spec's guess; q = o5 = (h, segments, tolerance, first texel
// in uPaths). Each segment is two texels (OpPacking.cpp, stylusCoefficients): (S at its first
// step, T), (its step count, c at its first step, c's change a step, -), so step j of a segment
// has the stylus at S + j h T. Only steps that find the stylus within reach along the track run:
// on a segment the track coordinate m = (x - S) . T is linear in the step, falling by h, so while
// x stands still the steps with |m| < l are an interval found in closed form, and every other
// step would leave x where it is (w = 0), as the spec allows.
//
// Loops: llvmpipe stops every loop of a shader invocation (a block of pixels, all its samples)
// once 65535 loop iterations have run in all, and the image is then wrong with no error. A
// stylus that drags ink runs thousands of steps, each a loop of fixed-point iterations (and of
// tines, for a rake: MARBLER_STYLUS 2, else 1 and no tine loop), so a long one can reach that.
// loopsWereCut() tells afterwards, and the host refuses such a render (GlRenderer.cpp).
vec2 stylusBack(vec2 x, vec4 shape, vec4 q) {
    float h = q.x, reach = shape.y;
    int first = int(q.w);
    for (int s = int(q.y) - 1; s >= 0; --s) {
        vec4 a = texelFetch(uPaths, first + 2 * s);
        vec4 b = texelFetch(uPaths, first + 2 * s + 1);
        vec2 t = a.zw;
        for (int j = int(b.x) - 1; j >= 0; --j) {
            // m at step j is along - j h. Step on to the newest step at or before j with m < l;
            // if m >= l there already, it stays so for every earlier step of the segment.
            float along = dot(x - a.xy, t);
            float top = min(float(j), ceil((along + reach) / h) - 1.0);
            if (top < 0.0 || along - top * h >= reach) break;
            j = int(top);
            vec2 place = a.xy + (float(j) * h) * t;
            float c = b.y + float(j) * b.z;
            vec2 next = x - h * stylusVelocity(x - place, t, c, shape);
            for (int i = 0; i < FlowIterations; ++i) {
                vec2 again = x - h * stylusVelocity(0.5 * (x + next) - place, t, c, shape);
                // The tolerance, or a few float steps of the point where those are larger.
                float tolerance = max(q.z, 4.0e-7 * (abs(again.x) + abs(again.y)));
                bool settled = length(again - next) < tolerance;
                next = again;
                if (settled) break;
            }
            x = next;
        }
    }
    return x;
}

uniform int uLoopProbe; // 2: a loop the compiler cannot unroll

// Whether the driver cut this invocation's loops short (llvmpipe's limit, see stylusBack): then
// a loop of two runs once.
bool loopsWereCut() {
    int runs = 0;
    for (int i = 0; i < uLoopProbe; ++i)
        runs += i + 1;
    return runs != 3;
}
#endif

// One version-1 form (classes 0 to 4) of the colour rule, operation k: stops the search (true,
// `color` set) where its ink holds the point, else pulls p back through it. With bleed, an ink
// that covers the point partly (0 < c < 1) does not stop the search: `blend` gathers c ink and
// `rest` keeps the share left for what lies beneath (the scalar rule is traceCovers in
// genome/src/Tools.cpp).
bool pullBack(int k, inout vec3 p, inout int color, inout vec3 blend, inout float rest) {
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
    // A wrapping bath: the nearest image of the centre (a spray's; no other form is allowed).
    if (uWrapShift.x > 0.0 || uWrapShift.y > 0.0)
        rel.xy = latticeNearest(rel.xy);
    else
        rel.xy -= uWrap.xy * floor(rel.xy * uWrap.zw + 0.5);
    vec3 across = rel - dot(rel, o1.xyz) * o1.xyz; // rel itself where nothing is projected out
    float len2 = dot(across, across);
#if MARBLER_BLEED
    // c = clamp(0.5 - e / b) at the edge distance e = rho - r; no ink: 0 (o1.w is -1).
    float cover = o1.w >= 0.0 ? clamp(0.5 - (sqrt(len2) - o4.w) / uBleed, 0.0, 1.0) : 0.0;
    if (cover >= 1.0) {
        color = int(o1.w);
        return true;
    }
    blend += (rest * cover) * uInk[max(int(o1.w), 0)];
    rest *= 1.0 - cover;
#else
    // Open boundary: a point on the rim is outside (o0.w is -1 where the tool lays no ink).
    if (len2 < o0.w) {
        color = int(o1.w);
        return true;
    }
#endif
    float rho = sqrt(len2);

    // Translations and turns: the distance d, the shift alpha lambda / (d + lambda).
    float t = dot(rel, o3.xyz);
    float d = kind == 4 ? abs(rho - o4.w) : (o5.z > 0.0 ? combDistance(t, o5.z) : abs(t));
    float shift = o5.x / (d + o5.y);
#if MARBLER_VERSION2
    // theta = l / sqrt(rho^2 + c^2): sqrt(len2 + 0) is rho itself, the version-1 turn.
    float theta = -shift / sqrt(len2 + o6.z);
#else
    float theta = -shift / rho;
#endif
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
    return false;
}

#if MARBLER_VERSION2
// A version-2 form (stretch, flow, stylus) of operation k: pulls p back through it (these lay no
// ink).
vec3 pullBackVersion2(int k, vec3 p) {
    int b = k * OpVec4s;
    vec4 o0 = texelFetch(uOps, b);
    vec4 o2 = texelFetch(uOps, b + 2);
    vec4 o3 = texelFetch(uOps, b + 3);
    vec4 o4 = texelFetch(uOps, b + 4);
    vec4 o5 = texelFetch(uOps, b + 5);
#if MARBLER_STYLUS
    if (int(o2.w) == 7) return vec3(stylusBack(p.xy, o4, o5), 0.0);
#endif
    vec3 rel = p - o0.xyz;
    float u = dot(rel, o3.xyz);
    // A wrapping bath: u modulo the period across the pass, into the teeth's span.
    float period = abs(o3.x) > 0.5 ? uWrap.x - uWrapShift.x : uWrap.y - uWrapShift.y;
    if (period > 0.0) {
        float first = texelFetch(uTeeth, int(o5.z)).x;
        u -= period * floor((u - first) / period);
    }
    return int(o2.w) == 5 ? p - stretchShift(u, o5) * o2.xyz
                          : o0.xyz + flowBack(rel, o2.xyz, o3.xyz, o4, o5);
}
#endif

// The colour rule: back through time until an ink is hit. Returns the palette index or -1; p is
// left where the point came from (for the source image).
int traceColor(inout vec3 p, inout vec3 blend, inout float rest) {
    int color = -1;
#if MARBLER_VERSION2
    // The stretches, flows and styluses cost far more than a version-1 form, and every lane would
    // pay for them at every operation if one body held them (see "Speed" above). So the
    // version-1 forms run in runs between them: o6.w of each record is the nearest of them at or
    // before it (-1: none), where the run stops and the version-2 body runs once.
    bool found = false;
    int k = uOpCount - 1;
    while (k >= 0 && !found) {
        int stop = int(texelFetch(uOps, k * OpVec4s + 6).w);
        for (; k > stop; --k) {
            if (pullBack(k, p, color, blend, rest)) {
                found = true;
                break;
            }
        }
        if (!found && k >= 0) {
            p = pullBackVersion2(k, p);
            --k;
        }
    }
#else
    for (int k = uOpCount - 1; k >= 0; --k)
        if (pullBack(k, p, color, blend, rest)) break;
#endif
    return color;
}

// The linear colour of the bath (or the source image) at p, where no ink was met.
vec3 bathColor(vec3 p) {
#if MARBLER_HAS_SOURCE
    vec2 w = (p + uReference).xy;
    if (w.x >= 0.0 && w.y >= 0.0 && w.x <= uDesignSize.x && w.y <= uDesignSize.y)
        return texture(uSource, w / uDesignSize).rgb;
#endif
    return uInk[16];
}

// The linear colour seen at p (relative to uReference).
vec3 inkColor(vec3 p) {
    vec3 blend = vec3(0.0);
    float rest = 1.0;
    int k = traceColor(p, blend, rest);
#if MARBLER_BLEED
    // colour = c0 ink0 + (1 - c0) (c1 ink1 + (1 - c1) (... beneath)), in linear light.
    return blend + rest * (k >= 0 ? uInk[k] : bathColor(p));
#else
    return k >= 0 ? uInk[k] : bathColor(p);
#endif
}

float linearToSrgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

// Rounded to 8 bits here, not by the framebuffer, so the result is the spec's rounding on every
// driver (the target is an unsigned-integer texture).
uvec4 encodeSrgb8(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    vec3 e = vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
    return uvec4(uvec3(floor(e * 255.0 + 0.5)), 255u);
}

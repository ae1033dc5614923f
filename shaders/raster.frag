#version 430 core
// 2D designs and 3D slices: both are a plane of the design space swept by the sample frame of
// Sampling.h (origin + (i + 0.5 + ox) du + (j + 0.5 + oy) dv), so one shader serves both.
#include "tools.glsl"

uniform vec3 uOrigin; // the tile's raster origin, relative to uReference
uniform vec3 uDu;
uniform vec3 uDv;
uniform int uSampleCount;
uniform vec2 uOffsets[64];
uniform float uWeights[64];

layout(location = 0) out uvec4 fragColor;

void main() {
    // Row j of the framebuffer is row j of the image: read back without a flip.
    vec2 ij = floor(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    for (int s = 0; s < uSampleCount; ++s) {
        vec3 p = uOrigin + (ij.x + 0.5 + uOffsets[s].x) * uDu + (ij.y + 0.5 + uOffsets[s].y) * uDv;
        sum += uWeights[s] * inkColor(p);
    }
    fragColor = encodeSrgb8(sum);
#if MARBLER_STYLUS
    // Alpha 0: the driver cut the loops short (tools.glsl, loopsWereCut); the host refuses it.
    if (loopsWereCut()) fragColor.a = 0u;
#endif
}

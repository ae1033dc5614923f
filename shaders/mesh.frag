#version 430 core
// Pass 2 of the deferred mesh render: per output pixel, the colour rule at each of the n x n
// G-buffer samples, lit (Lambert + Blinn), averaged in linear light with the clear colour where
// the object does not cover the sample. A solid design is coloured at the sample's point of its
// block; a flat one (MARBLER_DIMENSION 2) at the point its texture coordinates take in the
// design (Bake.h's FlatOnUvs: the design fitted into [0, 1]^2 by its longer side, centred), the
// background beyond the design's rectangle.
#include "tools.glsl"

uniform sampler2D uPositions;
uniform sampler2D uNormals;
uniform int uSupersample;
uniform vec3 uEye;         // relative to the box centre
uniform vec3 uLight;       // unit direction towards the key light
uniform vec3 uClear;       // linear
uniform bool uLighting;
#if MARBLER_DIMENSION == 2
uniform sampler2D uUvs;
uniform float uFlatSide; // the design length across the whole texture
uniform vec2 uFlatHalf;  // half the design's width and height
#endif

layout(location = 0) out uvec4 fragColor;

vec3 shade(vec3 albedo, vec3 position, vec3 normal) {
    if (!uLighting) return albedo;
    vec3 n = normalize(normal);
    vec3 view = normalize(uEye - position);
    if (dot(n, view) < 0.0) n = -n;
    float diffuse = max(dot(n, uLight), 0.0);
    vec3 halfway = normalize(uLight + view);
    float specular = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), 48.0) : 0.0;
    return albedo * (0.22 + 0.78 * diffuse) + vec3(0.12 * specular);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < uSupersample; ++j) {
        for (int i = 0; i < uSupersample; ++i) {
            ivec2 texel = pixel * uSupersample + ivec2(i, j);
            vec4 position = texelFetch(uPositions, texel, 0);
            if (position.w > 0.0) {
                vec3 normal = texelFetch(uNormals, texel, 0).xyz;
#if MARBLER_DIMENSION == 2
                // Relative to the design's centre, which is uReference here.
                vec2 q = (texelFetch(uUvs, texel, 0).xy - 0.5) * uFlatSide;
                vec3 albedo = all(lessThanEqual(abs(q), uFlatHalf)) ? inkColor(vec3(q, 0.0)) : uInk[16];
                sum += shade(albedo, position.xyz, normal);
#else
                sum += shade(inkColor(position.xyz), position.xyz, normal);
#endif
            } else {
                sum += uClear;
            }
        }
    }
    fragColor = encodeSrgb8(sum / float(uSupersample * uSupersample));
}

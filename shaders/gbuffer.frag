#version 430 core
// Pass 1: design-space position and normal per (supersampled) pixel, and the texture
// coordinates there (read by pass 2 for a flat design only); the marbling is left to pass 2 so
// each pixel runs the colour rule once per sample, not once per overdrawn fragment.
in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
uniform vec3 uEye;        // camera, relative to the box centre
uniform bool uCut;
uniform vec3 uCutNormal;  // points into the half that is cut away
uniform float uCutOffset; // relative to the box centre

layout(location = 0) out vec4 gPosition; // w = 1 where the object covers the pixel
layout(location = 1) out vec4 gNormal;
layout(location = 2) out vec2 gUv; // bound only for a flat design

void main() {
    if (uCut && dot(uCutNormal, vPosition) > uCutOffset) discard;
    vec3 position = vPosition;
    vec3 normal = normalize(vNormal);
    if (!gl_FrontFacing) {
        float eyeSide = dot(uCutNormal, uEye) - uCutOffset;
        if (uCut && eyeSide > 0.0) {
            // Seen through the cut: the first solid point on this ray lies on the plane, so the
            // cap shows the solid's colour there and the marbling runs on through the cut.
            vec3 ray = vPosition - uEye;
            float t = -eyeSide / dot(uCutNormal, ray);
            position = uEye + t * ray;
            normal = uCutNormal;
        } else {
            normal = -normal; // the inside of an open mesh
        }
    }
    gPosition = vec4(position, 1.0);
    gNormal = vec4(normal, 0.0);
    gUv = vUv;
}

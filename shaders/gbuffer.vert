#version 430 core
// Pass 1 of the deferred mesh render: the object, already fitted into the design box.
layout(location = 0) in vec3 aPosition; // the mesh's own units, centred on its bounding box
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;       // the mesh's own texture coordinates (flat designs)
uniform float uScale;          // the fit into the design box
uniform mat4 uViewProjection;  // design space relative to the box centre -> clip space
out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;

void main() {
    vPosition = aPosition * uScale; // design coordinates (relative to the box centre)
    vNormal = aNormal;
    vUv = aUv;
    gl_Position = uViewProjection * vec4(vPosition, 1.0);
}

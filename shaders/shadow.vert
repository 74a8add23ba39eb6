// Vertex stage of the shadow pass: bodies seen from the light.
layout(location = 0) in vec3 position;  // m, world

uniform mat4 light_view_projection;  // world → shadow-map clip space

void main() { gl_Position = light_view_projection * vec4(position, 1.0); }

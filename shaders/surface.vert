// Vertex stage of everything lit (the bodies and the floor): positions arrive in world coordinates,
// so there is no model matrix. The program builder prepends the #version line.
layout(location = 0) in vec3 position;  // m, world
layout(location = 1) in vec3 normal;    // unit, world
layout(location = 2) in vec3 pattern_coordinate;  // m, the body's first shape about its centroid (bodies only)

uniform mat4 view_projection;        // world → camera clip space
uniform mat4 light_view_projection;  // world → shadow-map clip space
uniform float shadow_normal_offset;  // m: where a surface looks itself up in the shadow map, pushed out
                                     // along its normal by a texel or two, so it does not shadow itself

out vec3 world_position;
out vec3 world_normal;
out vec4 light_space_position;
out vec3 pattern_position;

void main() {
  world_position = position;
  world_normal = normal;
  pattern_position = pattern_coordinate;
  // The floor has no normal attribute (it reads as 0): it casts nothing, so it needs no offset.
  light_space_position = light_view_projection * vec4(position + normal * shadow_normal_offset, 1.0);
  gl_Position = view_projection * vec4(position, 1.0);
}

// Fragment stage of a soft body: smooth shading from the interpolated per-vertex normals (lighting.glsl
// is prepended before this file).
uniform vec3 body_color;  // linear RGB

out vec4 fragment_color;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // a fold of the deforming surface seen from behind
  fragment_color = vec4(shade(body_color, n, 0.35, 64.0), 1.0);
}

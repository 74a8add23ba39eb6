// Fragment stage of a soft body: smooth shading from the interpolated per-vertex normals (lighting.glsl
// is prepended before this file).
uniform vec3 body_color;  // linear RGB
uniform int body_pattern; // 0 plain, 1 checker (8 × 4 cells by direction), 2 stripes (8 meridians)

in vec3 pattern_position;

out vec4 fragment_color;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // a fold of the deforming surface seen from behind
  vec3 albedo = body_color;
  if (body_pattern != 0 && dot(pattern_position, pattern_position) > 0.0) {
    // Cells fixed to the material: azimuth and polar angle of the direction from the body's first centroid.
    vec3 d = normalize(pattern_position);
    float around = (atan(d.z, d.x) / 6.2831853 + 0.5) * 8.0;
    float down = acos(clamp(d.y, -1.0, 1.0)) / 3.1415927 * 4.0;
    float cell = body_pattern == 1 ? floor(around) + floor(down) : floor(around);
    if (mod(cell, 2.0) > 0.5) albedo = mix(body_color, vec3(0.9), 0.75);
  }
  fragment_color = vec4(shade(albedo, n, 0.35, 64.0), 1.0);
}

// Fragment stage of the floor: an anti-aliased checkerboard that fades into the background with distance
// (lighting.glsl is prepended before this file).
uniform vec3 background;        // linear RGB, what the floor fades into
uniform float square_size;      // m, side of one checker square
uniform float fade_start;       // m from the camera where the fade begins
uniform float fade_end;         // m from the camera where only background is left
uniform vec3 light_square;      // linear RGB
uniform vec3 dark_square;       // linear RGB

out vec4 fragment_color;

// ∫₀ˣ odd(t) dt, where odd(t) is 1 when floor(t) is odd: one unit per whole period of 2 (floor(x/2)),
// plus the part of the current period past its first half.
float odd_integral(float x) {
  float periods = floor(x * 0.5);
  return periods + max(0.0, x - 2.0 * periods - 1.0);
}

// odd(t) averaged over a pixel's footprint [x − w/2, x + w/2] (a box filter): 0 or 1 up close, 1/2 far
// away, where a single sample would alias into moiré.
float filtered_odd(float x, float w) {
  return (odd_integral(x + 0.5 * w) - odd_integral(x - 0.5 * w)) / w;
}

void main() {
  vec2 cell = world_position.xz / square_size;
  vec2 footprint = max(fwidth(cell) * 1.5, vec2(1e-4));
  float a = filtered_odd(cell.x, footprint.x);
  float b = filtered_odd(cell.y, footprint.y);
  // "odd in x xor odd in z" is a + b − 2ab; that is linear in a and in b, so the box filter (separable)
  // passes through it exactly.
  float dark = a + b - 2.0 * a * b;
  vec3 albedo = mix(light_square, dark_square, dark);
  vec3 lit = shade_matte(albedo, vec3(0.0, 1.0, 0.0));
  float fade = smoothstep(fade_start, fade_end, distance(world_position, camera_position));
  fragment_color = vec4(mix(lit, background, fade), 1.0);
}

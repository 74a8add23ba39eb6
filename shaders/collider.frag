// Fragment stage of a collider: the floor's matte shading in the collider's colour, with its shadows, fading into
// the background with distance as the floor does (lighting.glsl is prepended before this file).
uniform vec3 collider_color;  // linear RGB
uniform vec3 background;      // linear RGB, what a far surface fades into
uniform float fade_start;     // m from the camera where the fade begins
uniform float fade_end;       // m from the camera where only background is left

out vec4 fragment_color;

void main() {
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // a plane seen from behind
  vec3 lit = shade_matte(collider_color, n);
  float fade = smoothstep(fade_start, fade_end, distance(world_position, camera_position));
  fragment_color = vec4(mix(lit, background, fade), 1.0);
}

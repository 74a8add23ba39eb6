// Lighting shared by body.frag and floor.frag (prepended to each): one directional light, Blinn-Phong
// diffuse and specular, an ambient floor, and a percentage-closer-filtered shadow map. Everything here is
// linear light; the sRGB framebuffer encodes the result once, on write.
uniform vec3 light_direction;  // unit; the way the light travels
uniform vec3 light_color;      // linear RGB
uniform float ambient;         // fraction of the light that reaches every surface
uniform vec3 camera_position;  // m, world
uniform bool shadows_enabled;
uniform sampler2DShadow shadow_map;  // depth compare on, linear filtering, cleared and bordered at depth 1

in vec3 world_position;
in vec3 world_normal;
in vec4 light_space_position;

// Fraction of the light that reaches this point: 1 lit, 0 fully shadowed. 2×2 taps half a texel either
// side of the point, each a hardware-compared bilinear lookup: together a tent filter over 3×3 texels.
// Looks the same as 3×3 taps at less than half the cost; llvmpipe runs both sides of a branch for a
// mixed group of fragments, so the taps are paid for wherever the shadow map is sampled.
float light_visibility() {
  if (!shadows_enabled) return 1.0;
  vec3 p = light_space_position.xyz / light_space_position.w * 0.5 + 0.5;  // clip → [0, 1] texture space
  // The light frustum is fitted around the casters only. A receiver beyond its far plane (the floor far
  // below a ball) is behind every caster: compared at depth 1, it is shadowed exactly where a caster was
  // drawn. One before the near plane is in front of them all and compares at 0 (lit).
  p.z = clamp(p.z, 0.0, 1.0);
  // Beside the map nothing casts: skip the taps (most of the floor, so this pays for itself).
  vec2 margin = 2.0 / vec2(textureSize(shadow_map, 0));
  if (any(lessThan(p.xy, -margin)) || any(greaterThan(p.xy, 1.0 + margin))) return 1.0;
  const float kDepthBias = 0.002;  // of the light frustum's depth; the shadow pass also offsets slopes
  vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
  float lit = 0.0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      lit += texture(shadow_map, vec3(p.xy + (vec2(dx, dy) - 0.5) * texel, p.z - kDepthBias));
    }
  }
  return lit / 4.0;
}

// Outgoing linear radiance of a matte surface (no highlight) with diffuse colour `albedo` and unit normal `n`.
vec3 shade_matte(vec3 albedo, vec3 n) {
  float n_dot_l = max(dot(n, -light_direction), 0.0);
  return light_color * albedo * (ambient + (1.0 - ambient) * n_dot_l * light_visibility());
}

// Outgoing linear radiance of a glossy surface with diffuse colour `albedo` and unit normal `n`.
vec3 shade(vec3 albedo, vec3 n, float specular_strength, float shininess) {
  vec3 to_light = -light_direction;
  vec3 to_eye = normalize(camera_position - world_position);
  float n_dot_l = max(dot(n, to_light), 0.0);
  vec3 halfway = normalize(to_light + to_eye);
  float specular = n_dot_l > 0.0 ? specular_strength * pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  float visible = light_visibility();
  vec3 diffuse = albedo * (ambient + (1.0 - ambient) * n_dot_l * visible);
  return light_color * (diffuse + specular * visible);
}

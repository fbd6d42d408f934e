"""GLSL sources: the shaded colour pass, the instance/depth pass and the depth-only
pass (sun shadow map and depth pre-pass). All positions are in the plan frame
(meters, z up). Every vertex shader computes ``gl_Position`` the same invariant way,
so a depth pre-pass and the shading pass agree to the bit.

The colour pass reads glTF's three PBR maps when a batch has them (``u_has_*``):
base colour (sRGB), metallicRoughness (linear; roughness = factor x G, metallic =
factor x B) and a tangent-space normal map (x, y scaled by ``u_nrm_scale``) in the frame
of the vertex tangent, made perpendicular to the interpolated normal per pixel. A
slope s of the map becomes s * s / (s + ``u_nrm_knee``): structural relief (mortar,
grout, weave, plank seams) keeps most of its strength while fine low noise (plaster
stipple) is calmed; mip-averaged normals are shorter, so distant relief is calmed too.
Each light sees the relief fade back to the surface normal as the light grazes the
surface (cosine of its incidence under ``u_relief_fade``): the room lights hang just
under the ceiling, which they would light at a few degrees where a real fixture sends
its light down, and there an unshadowed map turns a plaster ceiling into noise. The
depth and instance passes ignore all of them."""

from __future__ import annotations

SHADE_VERT = """
#version 330 core
uniform mat4 u_view_proj;
in vec3 in_pos;
in vec3 in_nrm;
in vec4 in_tan;
in vec2 in_uv;
in vec4 in_col;
in vec2 in_rm;
in vec3 in_emi;
in int in_room;
out vec3 v_emi;
out vec3 v_pos;
invariant gl_Position;
out vec3 v_nrm;
out vec4 v_tan;
out vec2 v_uv;
out vec4 v_col;
out vec2 v_rm;
flat out int v_room;
void main() {
    v_pos = in_pos;
    v_nrm = in_nrm;
    v_tan = in_tan;
    v_uv = in_uv;
    v_col = in_col;
    v_rm = in_rm;
    v_emi = in_emi;
    v_room = in_room;
    gl_Position = u_view_proj * vec4(in_pos, 1.0);
}
"""

SHADE_FRAG = """
#version 330 core
uniform vec3 u_eye;
uniform vec3 u_sun_dir;        // towards the sun
uniform vec3 u_sun_rgb;
uniform vec3 u_sky_rgb;        // hemisphere ambient from above
uniform vec3 u_ground_rgb;     // hemisphere ambient from below
uniform float u_indoor_ambient;
uniform sampler2D u_lights;    // row 0: position xyz + range, row 1: colour rgb
uniform int u_n_lights;
uniform sampler2D u_tex;
uniform bool u_has_tex;
uniform sampler2D u_mr_tex;    // glTF metallicRoughness: G roughness, B metallic
uniform bool u_has_mr;
uniform sampler2D u_nrm_tex;   // tangent-space normal map
uniform bool u_has_nrm;
uniform float u_nrm_scale;
uniform float u_nrm_knee;     // slopes well under this are damped (0: glTF's plain map)
uniform float u_relief_fade;  // a light's cos(incidence) under which its relief fades (0: never)
uniform sampler2DShadow u_shadow;
uniform mat4 u_shadow_mat;
uniform float u_exposure;
uniform float u_emissive;
in vec3 v_emi;
in vec3 v_pos;
in vec3 v_nrm;
in vec4 v_tan;
in vec2 v_uv;
in vec4 v_col;
in vec2 v_rm;
flat in int v_room;
out vec4 f_color;

vec3 srgb_to_linear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));
}
vec3 linear_to_srgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
vec3 aces(vec3 x) {  // Narkowicz's fit of the ACES filmic curve
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
float sun_visibility(vec3 n) {
    vec3 p = v_pos + n * 0.03;
    vec4 s = u_shadow_mat * vec4(p, 1.0);
    vec3 q = s.xyz / s.w * 0.5 + 0.5;
    if (any(lessThan(q.xy, vec2(0.0))) || any(greaterThan(q.xy, vec2(1.0)))) return 1.0;
    return texture(u_shadow, vec3(q.xy, q.z - 0.0015));  // 2x2 PCF by the sampler
}
vec3 relief_normal(vec3 n, vec3 ng, vec3 l) {  // the map's relief fades out in grazing light
    if (!u_has_nrm || u_relief_fade <= 0.0) return n;
    return normalize(mix(ng, n, clamp(dot(ng, l) / u_relief_fade, 0.0, 1.0)));
}
vec3 brdf(vec3 n, vec3 v, vec3 l, vec3 diffuse, vec3 f0, float rough) {
    float ndl = max(dot(n, l), 0.0);
    if (ndl <= 0.0) return vec3(0.0);
    vec3 h = normalize(l + v);
    float shininess = clamp(2.0 / max(pow(rough, 4.0), 1e-4) - 2.0, 1.0, 2048.0);
    float spec = (shininess + 8.0) / 25.13 * pow(max(dot(n, h), 0.0), shininess);
    return (diffuse + f0 * spec) * ndl;
}
void main() {
    vec3 base = v_col.rgb;
    if (u_has_tex) base *= srgb_to_linear(texture(u_tex, v_uv).rgb);
    vec2 rm = v_rm;
    if (u_has_mr) rm *= texture(u_mr_tex, v_uv).gb;
    float rough = clamp(rm.x, 0.05, 1.0);
    float metal = clamp(rm.y, 0.0, 1.0);
    vec3 ng = normalize(v_nrm);
    vec3 v = normalize(u_eye - v_pos);
    float side = dot(ng, v) < 0.0 ? -1.0 : 1.0;
    ng *= side;  // two-sided
    vec3 n = ng;
    if (u_has_nrm) {
        vec3 tn = texture(u_nrm_tex, v_uv).xyz * 2.0 - 1.0;
        vec3 t = v_tan.xyz - ng * dot(ng, v_tan.xyz);
        float tt = dot(t, t);
        if (tt > 1e-10) {  // no tangent (degenerate UVs): keep the normal
            t *= inversesqrt(tt);
            vec3 b = cross(ng, t) * (v_tan.w * side);  // the map's +y, seen from the front
            vec2 xy = tn.xy * u_nrm_scale;
            float slope = length(xy);
            xy *= slope / max(slope + u_nrm_knee, 1e-6);  // keep grout and weave, calm fine noise
            n = normalize(t * xy.x + b * xy.y + ng * max(tn.z, 0.0));
        }
    }
    vec3 diffuse = base * (1.0 - metal);
    vec3 f0 = mix(vec3(0.04), base, metal) * (1.0 - 0.7 * rough);

    bool indoor = v_room >= 0;
    float hemi = 0.5 + 0.5 * n.z;
    vec3 ambient = mix(u_ground_rgb, u_sky_rgb, hemi) * (indoor ? u_indoor_ambient : 1.0);
    vec3 color = base * ambient;
    color += brdf(relief_normal(n, ng, u_sun_dir), v, u_sun_dir, diffuse, f0, rough) * u_sun_rgb
             * sun_visibility(ng);
    if (indoor && v_room < u_n_lights) {
        vec4 lp = texelFetch(u_lights, ivec2(v_room, 0), 0);
        vec3 lc = texelFetch(u_lights, ivec2(v_room, 1), 0).rgb;
        vec3 d = lp.xyz - v_pos;
        float dist2 = dot(d, d);
        float falloff = 1.0 / (1.0 + dist2 / (lp.w * lp.w));
        vec3 l = d * inversesqrt(max(dist2, 1e-6));
        color += brdf(relief_normal(n, ng, l), v, l, diffuse, f0, rough) * lc * falloff;
    }
    color += v_emi * u_emissive;
    f_color = vec4(linear_to_srgb(aces(color * u_exposure)), v_col.a);
}
"""

AUX_VERT = """
#version 330 core
uniform mat4 u_view_proj;
uniform mat4 u_view;
in vec3 in_pos;
in int in_inst;
out float v_depth;
flat out int v_inst;
invariant gl_Position;
void main() {
    v_depth = -(u_view * vec4(in_pos, 1.0)).z;
    v_inst = in_inst;
    gl_Position = u_view_proj * vec4(in_pos, 1.0);
}
"""

AUX_FRAG = """
#version 330 core
in float v_depth;
flat in int v_inst;
out vec2 f_aux;  // (instance index + 1, depth along the optical axis in meters)
void main() {
    f_aux = vec2(float(v_inst + 1), v_depth);
}
"""

SHADOW_VERT = """
#version 330 core
uniform mat4 u_view_proj;
in vec3 in_pos;
invariant gl_Position;
void main() {
    gl_Position = u_view_proj * vec4(in_pos, 1.0);
}
"""

SHADOW_FRAG = """
#version 330 core
void main() {}
"""

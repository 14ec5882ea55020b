#version 330 core
// Eisemann & Décoret, Occlusion Textures for Plausible Soft Shadows (CGF 27(1), 2008):
// the slicing view of §3.4 and Figure 5. The modelview holds the light's frame times the
// object's model matrix: x along the light's first edge, y along its second, z the distance
// from the light's plane towards the scene. The centre of projection sits `cop` behind the
// light's centre on its axis, and the near window is fitted around the light: a point
// (x, y, z) lands at x·cop / (half_window.x · (z + cop)), which gl_Position's w = z + cop
// divides. Every occluder of the scene is thus "X-rayed" from the same point, whatever its
// slice.
// SUN 1 (§3.5, a source at infinity): the frame's z runs along the sun's light and the
// view is orthographic, (x, y) / half_window; `cop` is unused.
layout(location = 0) in vec4 position;

uniform mat4 ff_modelview;
// The centre of projection's distance behind the light's plane.
uniform float cop;
// The near window's half extents on the light's plane (≥ the light's).
uniform vec2 half_window;

out float depth;

void main() {
    vec4 q = ff_modelview * position;
    depth = q.z / q.w;
#if SUN
    gl_Position = vec4(q.xy / (half_window * q.w), 0.0, 1.0);
#else
    gl_Position = vec4(q.xy * cop / half_window, 0.0, q.z + cop * q.w);
#endif
}

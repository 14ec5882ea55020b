#version 330 core
// Eisemann & Décoret 2008, §3.5 (Figure 7, second step): the scene from the observer;
// each fragment needs its position in the light's frame (x, y along the light's edges,
// z the distance from the light's plane), which `eye_to_light` gives from the eye-space
// position the fixed-function modelview makes. The clip position is the one the
// generated programs compute (P · M multiplied on the CPU), so a DepthFunc(EQUAL) pass
// over the fixed-function dim pass matches.
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;

uniform mat4 ff_modelview;
uniform mat4 ff_modelview_projection;
uniform mat3 ff_normal_matrix;
uniform mat4 eye_to_light;

out vec3 light_frame;
out vec3 eye_position;
out vec3 eye_normal;

void main() {
    vec4 e = ff_modelview * position;
    light_frame = (eye_to_light * e).xyz / e.w;
    eye_position = e.xyz / e.w;
    eye_normal = ff_normal_matrix * normal;
    gl_Position = ff_modelview_projection * position;
}

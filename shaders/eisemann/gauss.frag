#version 330 core
// Eisemann & Décoret 2008, §3.5 (sunlight): "To capture the spherical shape we use a
// Gaussian instead of a box-filter." A Gaussian pyramid (Burt & Adelson 1983) in the
// occlusion texture's mipmap levels, one axis per pass: the texel p of the output is
//   Σ_{k=0..5} b_k · source(c + (k − 2) · axis),  b = [1 5 10 10 5 1] / 32,
// c = p with its coordinate along `axis` doubled: the taps are centred on the two source
// texels 2p and 2p + 1 that the output texel covers (decimation by two along the axis).
// Taps beyond the source read 0: nothing occludes outside the slicing window.
uniform sampler2D source;
uniform int source_level;
uniform int source_width;
uniform int source_height;
uniform int axis_x;
uniform int axis_y;

out vec4 blurred;

const float WEIGHTS[6] = float[6](1.0, 5.0, 10.0, 10.0, 5.0, 1.0);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 axis = ivec2(axis_x, axis_y);
    ivec2 c = p + p * axis;
    vec4 sum = vec4(0.0);
    for (int k = 0; k < 6; ++k) {
        ivec2 q = c + (k - 2) * axis;
        if (q.x >= 0 && q.y >= 0 && q.x < source_width && q.y < source_height) {
            sum += WEIGHTS[k] * texelFetch(source, q, source_level);
        }
    }
    blurred = sum / 32.0;
}
